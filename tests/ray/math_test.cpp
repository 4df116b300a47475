// lib/hider/ray/math.hpp against double: reciprocal square root (every table bucket), exact floor square
// root (equal to isqrt64), unit vectors (2 LSB of Q30), reflected directions, the mixed dot products.
#include <hider/ray/math.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include <doctest/doctest.h>

#include "support/fixed_print.hpp"

using namespace hider;
using namespace hider::ray;

namespace {

double q30(Q30 v) { return v.raw() / 1073741824.0; }

/// Largest |error| in Q30 LSB of unit_q30(x, y, z) against the exact unit vector.
double unit_error_lsb(int32_t x, int32_t y, int32_t z) {
    Vec3q30 u{};
    REQUIRE(unit_q30(x, y, z, u));
    const double len = std::sqrt(double(x) * x + double(y) * y + double(z) * z);
    const double e[3] = {q30(u.x) - x / len, q30(u.y) - y / len, q30(u.z) - z / len};
    return std::fmax(std::fabs(e[0]), std::fmax(std::fabs(e[1]), std::fabs(e[2]))) * 1073741824.0;
}

}  // namespace

TEST_CASE("rsqrt_q30 is within 2^-29 relative of 1/sqrt(x) in every table bucket") {
    double worst = 0;
    for (uint32_t bucket = 64; bucket < 256; ++bucket) {
        const uint32_t lo = bucket << 24;
        for (uint32_t x : {lo, lo + 1, lo + (1u << 23), lo + (1u << 24) - 1}) {
            const double exact = 1073741824.0 / std::sqrt(x / 4294967296.0);
            const double rel = std::fabs(rsqrt_q30(x) - exact) / exact;
            worst = std::fmax(worst, rel);
        }
    }
    std::mt19937 rng(7);
    for (int i = 0; i < 200000; ++i) {
        const uint32_t x = (rng() | 0x40000000u);
        const double exact = 1073741824.0 / std::sqrt(x / 4294967296.0);
        worst = std::fmax(worst, std::fabs(rsqrt_q30(x) - exact) / exact);
    }
    MESSAGE("worst relative error of rsqrt_q30: " << worst << " (2^" << std::log2(worst) << ")");
    CHECK(worst < std::ldexp(1.0, -29));
}

TEST_CASE("isqrt64 equals the bit-by-bit root exactly") {
    auto bits = [](uint64_t v) {  // the classic digit-by-digit root, as a reference
        uint64_t root = 0, bit = uint64_t{1} << 62;
        while (bit > v) bit >>= 2;
        for (; bit != 0; bit >>= 2) {
            if (v >= root + bit) {
                v -= root + bit;
                root = (root >> 1) + bit;
            } else {
                root >>= 1;
            }
        }
        return static_cast<uint32_t>(root);
    };
    CHECK(isqrt64(0) == 0);
    CHECK(isqrt64(1) == 1);
    CHECK(isqrt64(UINT64_MAX) == 0xFFFFFFFFu);
    for (uint64_t r : {uint64_t{1}, uint64_t{2}, uint64_t{3}, uint64_t{65535}, uint64_t{65536}, uint64_t{0xFFFFFFFFu},
                       uint64_t{0x80000000u}, uint64_t{12345678}}) {
        CHECK(isqrt64(r * r) == r);
        CHECK(isqrt64(r * r - 1) == r - 1);
        if (r < 0xFFFFFFFFu) CHECK(isqrt64(r * r + 2 * r) == r);  // (r + 1)^2 - 1
    }
    std::mt19937_64 rng(11);
    for (int i = 0; i < 200000; ++i) {
        const uint64_t v = rng() >> (rng() % 64);
        REQUIRE(isqrt64(v) == bits(v));
    }
    for (uint64_t v = 0; v < 100000; ++v) REQUIRE(isqrt64(v) == bits(v));
    for (uint64_t i = 0; i < 64; ++i) {  // both sides of every power of two
        const uint64_t p = uint64_t{1} << i;
        REQUIRE(isqrt64(p) == bits(p));
        REQUIRE(isqrt64(p - 1) == bits(p - 1));
        REQUIRE(isqrt64(p + 1) == bits(p + 1));
    }
}

TEST_CASE("unit_q30 is within 2 LSB of the exact unit vector at any length") {
    CHECK(unit_error_lsb(1, 0, 0) == 0);
    CHECK(unit_error_lsb(0, -5, 0) == 0);
    CHECK(unit_error_lsb(0, 0, INT32_MAX) == 0);
    CHECK(unit_error_lsb(1, 1, 1) <= 2);
    CHECK(unit_error_lsb(-INT32_MAX, INT32_MAX, -INT32_MAX) <= 2);
    Vec3q30 u{};
    CHECK_FALSE(unit_q30(0, 0, 0, u));
    std::mt19937 rng(3);
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        const int shift = static_cast<int>(rng() % 31);
        auto comp = [&] { return static_cast<int32_t>(static_cast<int64_t>(rng() % 0x7FFFFFFFu) - 0x3FFFFFFF) >> shift; };
        const int32_t x = comp(), y = comp(), z = comp();
        if (x == 0 && y == 0 && z == 0) continue;
        worst = std::fmax(worst, unit_error_lsb(x, y, z));
    }
    MESSAGE("worst unit_q30 error: " << worst << " LSB");
    CHECK(worst <= 2);
    SUBCASE("the length comes with it, within 1 + 2^-28 relative") {
        double worst_len = 0;
        for (int i = 0; i < 100000; ++i) {
            const int shift = static_cast<int>(rng() % 31);
            auto comp = [&] { return static_cast<int32_t>(static_cast<int64_t>(rng() % 0xFFFFFFFEu) - 0x7FFFFFFF) >> shift; };
            const int32_t x = comp(), y = comp(), z = comp();
            if (x == 0 && y == 0 && z == 0) continue;
            uint32_t len = 0;
            REQUIRE(unit_q30(x, y, z, u, &len));
            const double exact = std::sqrt(double(x) * x + double(y) * y + double(z) * z);
            worst_len = std::fmax(worst_len, (std::fabs(len - exact) - 1) / exact);
            CHECK(std::fabs(len - exact) <= 1 + exact * std::ldexp(1.0, -28));
        }
        MESSAGE("worst (|error| - 1) / length: " << worst_len);
    }
}

TEST_CASE("reflected directions match r = d - 2 (d.n) n within 3 LSB") {
    std::mt19937 rng(5);
    auto random_unit = [&] {
        Vec3q30 u{};
        while (!unit_q30(static_cast<int32_t>(rng() % 2000001) - 1000000, static_cast<int32_t>(rng() % 2000001) - 1000000,
                         static_cast<int32_t>(rng() % 2000001) - 1000000, u)) {
        }
        return u;
    };
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3q30 d = random_unit(), n = random_unit();
        const Vec3q30 r = reflect(d, n);
        const double dd[3] = {q30(d.x), q30(d.y), q30(d.z)}, nn[3] = {q30(n.x), q30(n.y), q30(n.z)};
        const double dn = dd[0] * nn[0] + dd[1] * nn[1] + dd[2] * nn[2];
        const double rr[3] = {q30(r.x), q30(r.y), q30(r.z)};
        for (int k = 0; k < 3; ++k) worst = std::fmax(worst, std::fabs(rr[k] - (dd[k] - 2 * dn * nn[k])) * 1073741824.0);
    }
    MESSAGE("worst reflect error: " << worst << " LSB");
    CHECK(worst <= 3);
    SUBCASE("a ray straight at a mirror comes straight back; a ray along it is unchanged") {
        const Vec3q30 down{Q30::from_raw(0), Q30::from_raw(-Q30::kOne), Q30::from_raw(0)};
        const Vec3q30 up{Q30::from_raw(0), Q30::from_raw(Q30::kOne), Q30::from_raw(0)};
        CHECK(reflect(down, up) == up);
        const Vec3q30 along{Q30::from_raw(Q30::kOne), Q30::from_raw(0), Q30::from_raw(0)};
        CHECK(reflect(along, up) == along);
    }
    SUBCASE("head-on along an axis with components 2^30 + 1 (unit_q30 gives them): 2 (d.n) n reaches 2^31") {
        // Before the 64-bit subtraction this overflowed int32 (UBSan: a mirror sphere seen from -15 on x).
        for (int axis = 0; axis < 3; ++axis)
            for (int32_t dc : {Q30::kOne - 2, Q30::kOne - 1, Q30::kOne, Q30::kOne + 1, Q30::kOne + 2})
                for (int32_t nc : {Q30::kOne - 2, Q30::kOne, Q30::kOne + 1, Q30::kOne + 2})
                    for (int sign : {1, -1}) {
                        int32_t dv[3] = {0, 0, 0}, nv[3] = {0, 0, 0};
                        dv[axis] = -sign * dc;
                        nv[axis] = sign * nc;
                        const Vec3q30 d{Q30::from_raw(dv[0]), Q30::from_raw(dv[1]), Q30::from_raw(dv[2])};
                        const Vec3q30 n{Q30::from_raw(nv[0]), Q30::from_raw(nv[1]), Q30::from_raw(nv[2])};
                        const Vec3q30 r = reflect(d, n);
                        const double dn = static_cast<double>(dv[axis]) * nv[axis] / 1073741824.0;
                        const double exact = dv[axis] - 2 * dn * nv[axis] / 1073741824.0;  // raw Q30
                        const int32_t rv[3] = {r.x.raw(), r.y.raw(), r.z.raw()};
                        INFO("axis ", axis, " d ", dv[axis], " n ", nv[axis]);
                        CHECK(std::fabs(rv[axis] - exact) <= 3);
                        CHECK(rv[(axis + 1) % 3] == 0);
                        CHECK(rv[(axis + 2) % 3] == 0);
                    }
    }
}

TEST_CASE("mixed dot products are exact and point_along rounds to nearest") {
    const Vec3q30 d{Q30::from_raw(Q30::kOne / 2), Q30::from_raw(-Q30::kOne / 4), Q30::from_raw(3)};
    const Vec3q16 v{Q16::from_raw(1 << 29), Q16::from_raw(-(1 << 29) + 1), Q16::from_raw(-7)};
    CHECK(dot_q46(d, v) == int64_t{1 << 29} * (Q30::kOne / 2) - int64_t{-(1 << 29) + 1} * (Q30::kOne / 4) - 21);
    CHECK(round_q46_to_q16((int64_t{5} << 30) + (int64_t{1} << 29)) == 6);  // half rounds up
    CHECK(round_q46_to_q16(-(int64_t{5} << 30) - (int64_t{1} << 29)) == -5);  // ties toward +inf
    const Vec3q16 p = point_along({Q16::from_int(1), Q16::from_int(2), Q16::from_int(3)}, Q16::from_int(2).raw(), d);
    CHECK(p.x == Q16::from_int(2));
    CHECK(p.y == Q16::from_ratio(3, 2));
    CHECK(p.z == Q16::from_int(3));  // 2 * 3 / 2^30 units rounds to 0
}

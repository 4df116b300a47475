// Fixed<F> and the integer helpers: exact raw results, the rounding rules, saturation, and accuracy
// against a double reference across the whole range (tolerances in LSBs).
#include <hider/fixed.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "support/fixed_print.hpp"

using hider::Fixed;
using hider::Q16;
using hider::Q30;

TEST_CASE("Q16: product truncates toward negative infinity") {
    const Q16 a = Q16::from_raw(98304);   // 1.5
    const Q16 b = Q16::from_raw(-147456); // -2.25
    CHECK((a * b).raw() == -221184);      // -3.375, exact
    SUBCASE("a tiny negative product rounds down to -1 LSB") {
        CHECK((Q16::from_raw(1) * Q16::from_raw(-1)).raw() == -1);
    }
    SUBCASE("a tiny positive product rounds down to 0") {
        CHECK((Q16::from_raw(1) * Q16::from_raw(1)).raw() == 0);
    }
}

TEST_CASE("div_round rounds to nearest with ties away from zero and saturates") {
    CHECK(hider::div_round(7, 2) == 4);
    CHECK(hider::div_round(-7, 2) == -4);
    CHECK(hider::div_round(5, 3) == 2);
    CHECK(hider::div_round(-5, 3) == -2);
    CHECK(hider::div_round(4, 3) == 1);
    CHECK(hider::div_round(7, -2) == -4);
    CHECK(hider::div_round(1, 0) == INT64_MAX);
    CHECK(hider::div_round(-1, 0) == INT64_MIN);
    CHECK(hider::div_round(0, 0) == 0);
    CHECK(hider::div_round(INT64_MIN, -1) == INT64_MAX);
    CHECK(hider::div_round(INT64_MAX, 1) == INT64_MAX);
    CHECK(hider::div_round(INT64_MAX, INT64_MAX) == 1);
    CHECK(hider::div_floor(-7, 2) == -4);
    CHECK(hider::div_floor(7, 2) == 3);
    CHECK(hider::div_floor(-8, 2) == -4);
}

TEST_CASE("div, recip and from_ratio are within half an LSB of the exact quotient") {
    std::mt19937 rng(12345);
    for (int i = 0; i < 20000; ++i) {
        const int32_t a = static_cast<int32_t>(rng());
        int32_t b = static_cast<int32_t>(rng()) >> (rng() % 24);
        if (b == 0) b = 1;
        const double exact = static_cast<double>(a) / b * 65536.0;
        const Q16 q = hider::div(Q16::from_raw(a), Q16::from_raw(b));
        if (std::fabs(exact) < 2147483647.0) {
            CHECK(std::fabs(q.raw() - exact) <= 0.5);
        } else {
            CHECK(q.raw() == (exact > 0 ? INT32_MAX : INT32_MIN));  // saturates
        }
    }
    CHECK(hider::div(Q16::from_int(1), Q16::from_raw(0)).raw() == INT32_MAX);
    CHECK(hider::div(Q16::from_int(-1), Q16::from_raw(0)).raw() == INT32_MIN);
    CHECK(hider::recip(Q16::from_int(4)).raw() == 16384);
    CHECK(hider::recip(Q16::from_raw(1)).raw() == INT32_MAX);  // 65536 does not fit Q16
    CHECK(hider::recip(Q16::from_raw(3)).raw() == 1431655765);  // 21845.333 -> nearest
    CHECK(hider::recip(Q16::from_int(-3)).raw() == -21845);    // -0.33333 -> nearest
    CHECK(Q16::from_ratio(1, 3).raw() == 21845);
    CHECK(Q16::from_ratio(2, 3).raw() == 43691);
    CHECK(Q16::from_ratio(-1, 2).raw() == -32768);
}

TEST_CASE("isqrt floors exactly over the whole 64-bit range") {
    CHECK(hider::isqrt64(0) == 0);
    CHECK(hider::isqrt64(1) == 1);
    CHECK(hider::isqrt64(3) == 1);
    CHECK(hider::isqrt64(4) == 2);
    CHECK(hider::isqrt64(UINT64_MAX) == 4294967295u);
    CHECK(hider::isqrt64(uint64_t{4294967295u} * 4294967295u) == 4294967295u);
    CHECK(hider::isqrt64(uint64_t{4294967295u} * 4294967295u - 1) == 4294967294u);
    std::mt19937_64 rng(7);
    for (int i = 0; i < 20000; ++i) {
        const uint64_t v = rng() >> (rng() % 64);
        const uint64_t r = hider::isqrt64(v);
        CHECK(r * r <= v);
        CHECK((r + 1) * (r + 1) > v);  // no overflow: r < 2^32
    }
    SUBCASE("Fixed isqrt is floor(sqrt) in the format, 0 for negatives") {
        CHECK(hider::isqrt(Q16::from_int(4)).raw() == 2 * 65536);
        CHECK(hider::isqrt(Q16::from_int(2)).raw() == 92681);  // 1.41421 -> floor(92681.9)
        CHECK(hider::isqrt(Q16::from_int(-4)).raw() == 0);
        CHECK(hider::isqrt(Q16::max()).raw() == 11863283);  // sqrt(32768) = 181.02 -> floor
    }
}

TEST_CASE("fixed_cast multiplies exactly upward, floors downward, saturates") {
    CHECK(hider::fixed_cast<30>(Q16::from_raw(3)).raw() == 3 << 14);
    CHECK(hider::fixed_cast<16>(Q30::from_raw(-1)).raw() == -1);
    CHECK(hider::fixed_cast<16>(Q30::from_raw((1 << 14) - 1)).raw() == 0);
    CHECK(hider::fixed_cast<30>(Q16::from_int(2)).raw() == INT32_MAX);
}

TEST_CASE("products match the double reference over the whole range to within 1 LSB (floor)") {
    std::mt19937 rng(99);
    for (int i = 0; i < 50000; ++i) {
        const int32_t a = static_cast<int32_t>(rng()) >> (rng() % 31);
        const int32_t b = static_cast<int32_t>(rng()) >> (rng() % 31);
        const long double exact = static_cast<long double>(a) * b / 65536.0L;
        if (std::fabs(static_cast<double>(exact)) >= 2147483647.0) continue;  // outside the format
        const Q16 p = Q16::from_raw(a) * Q16::from_raw(b);
        CHECK(static_cast<long double>(p.raw()) <= exact);
        CHECK(exact - p.raw() < 1.0L);
    }
    CHECK((Q16::max() * Q16::from_int(1)).raw() == INT32_MAX);
    CHECK((Q16::min() * Q16::from_int(1)).raw() == INT32_MIN);
    CHECK((Q16::min() * Q16::from_raw(32768)).raw() == INT32_MIN / 2);
}

TEST_CASE("floor_int and round_int at the edges of the range") {
    CHECK(Q16::from_raw(-1).floor_int() == -1);
    CHECK(Q16::from_raw(65535).floor_int() == 0);
    CHECK(Q16::from_raw(32768).round_int() == 1);
    CHECK(Q16::from_raw(-32768).round_int() == 0);
    CHECK(Q16::max().floor_int() == 32767);
    CHECK(Q16::min().floor_int() == -32768);
    CHECK(Q16::max().round_int() == 32768);
}

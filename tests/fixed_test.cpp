// Fixed<F> and the integer helpers: exact raw results, the rounding rules, saturation, and accuracy
// against a double reference across the whole range (tolerances in LSBs).
#include <hider/fixed.hpp>
#include <hider/int128.hpp>
#include <hider/view.hpp>

#include <algorithm>
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

// LongDivisor32 is udiv64_32 with a two-digit path for divisors below 2^16; Divisor32 is ARMv6-M's
// prepared reciprocal. Random divisors are often small, and 0xFFFF / 0x10000 straddle the two paths.
TEST_CASE_TEMPLATE("udiv64_32 and Divisor32 (the 32-bit targets' 64/32 divisions) are exact wherever the quotient fits 32 bits",
                   D, hider::LongDivisor32, hider::Divisor32) {
    std::mt19937_64 rng(2718);
    auto check = [](uint64_t n, uint32_t d) {
        const D div(d);
        uint32_t r = 0;
        const uint32_t q = div.divide(n, r);
        CHECK(div.value() == d);
        CHECK(q == n / d);
        CHECK(r == n % d);
    };
    for (int i = 0; i < 200000; ++i) {
        const uint32_t d = static_cast<uint32_t>(rng() >> (rng() % 64)) | 1u;
        const uint64_t hi = (rng() >> 32) % d;  // keeps n < d * 2^32
        check((hi << 32) | (rng() & 0xFFFFFFFFu), d);
    }
    check(0, 1);
    check(0xFFFFFFFFull, 1);
    check(0xFFFFFFFEFFFFFFFFull, 0xFFFFFFFFu);  // largest n for the largest d
    check(0x7FFFFFFF80000000ull, 0x80000000u);
    check(0x00000000FFFFFFFFull, 0x00010000u);
    check(0x0000FFFF00000000ull, 0x00010000u);
    for (uint32_t d : {1u, 2u, 3u, 7u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFFu})
        for (uint64_t k : {0ull, 1ull, 0xFFFFull, 0xFFFFFFFEull, 0xFFFFFFFFull}) {
            const uint64_t top = (uint64_t{d} << 32) - 1;  // largest n with a 32-bit quotient
            check(std::min<uint64_t>(k * d, top), d);
            check(std::min<uint64_t>(k * d + (d - 1), top), d);
            if (k * d > 0 && k * d <= top) check(k * d - 1, d);
        }
}

TEST_CASE("clz32 counts leading zeros") {
    CHECK(hider::clz32(1) == 31);
    CHECK(hider::clz32(0x80000000u) == 0);
    CHECK(hider::clz32(0x00010000u) == 15);
}

TEST_CASE("mul_wide equals the 64-bit product at the extremes") {
    CHECK(hider::mul_wide(INT32_MIN, INT32_MIN) == int64_t{1} << 62);
    CHECK(hider::mul_wide(INT32_MIN, INT32_MAX) == -(int64_t{1} << 31) * INT32_MAX);
    CHECK(hider::mul_wide(-1, -1) == 1);
    CHECK(hider::mul_wide_u(0xFFFFFFFFu, 0xFFFFFFFFu) == 0xFFFFFFFE00000001ull);
}

TEST_CASE("the ARMv6-M multiply by 16-bit parts equals the native 64-bit product") {
    std::mt19937_64 rng(31);
    for (int i = 0; i < 200000; ++i) {
        const auto a = static_cast<int32_t>(rng() >> (rng() % 33)), b = static_cast<int32_t>(rng() >> (rng() % 33));
        CHECK(hider::mul_wide_by_parts(a, b) == static_cast<int64_t>(a) * b);
        CHECK(hider::mul_wide_u_by_parts(static_cast<uint32_t>(a), static_cast<uint32_t>(b)) ==
              uint64_t{static_cast<uint32_t>(a)} * static_cast<uint32_t>(b));
    }
    CHECK(hider::mul_wide_by_parts(INT32_MIN, INT32_MIN) == int64_t{1} << 62);
    CHECK(hider::mul_wide_by_parts(INT32_MIN, -1) == int64_t{1} << 31);
    CHECK(hider::mul_wide_u_by_parts(0xFFFFFFFFu, 0xFFFFFFFFu) == 0xFFFFFFFE00000001ull);
}

TEST_CASE("div_round through udiv64_32 equals native division (the 32-bit targets' path)") {
    // Replays div_round's fast path on the host with the same operands it would see on a target.
    std::mt19937_64 rng(41);
    for (int i = 0; i < 100000; ++i) {
        const auto n = static_cast<int64_t>(rng()) >> (rng() % 40);
        auto d = static_cast<int32_t>(rng() >> (32 + rng() % 32));
        if (d == 0) d = 7;
        const uint64_t un = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
        const uint32_t ud = static_cast<uint32_t>(d < 0 ? -static_cast<int64_t>(d) : d);
        if ((un >> 32) >= ud) continue;
        uint32_t r = 0;
        uint64_t q = hider::udiv64_32(un, ud, r);
        if (r >= ud - r) ++q;
        const int64_t fast = ((n < 0) != (d < 0)) ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
        CHECK(fast == hider::div_round(n, d));
    }
}

TEST_CASE_TEMPLATE("the 32-bit targets' projection division equals div_round(n, 256 w)", D, hider::Divisor32,
                   hider::LongDivisor32) {
    std::mt19937_64 rng(53);
    for (int i = 0; i < 200000; ++i) {
        const auto n = static_cast<int64_t>(rng()) >> (1 + rng() % 40);
        const auto w = static_cast<int32_t>(rng() >> (33 + rng() % 31)) | 1;
        int64_t q = 0;
        if (!hider::detail::div_round_w256_by_parts(n, D(static_cast<uint32_t>(w)), q)) continue;
        CHECK(q == hider::div_round(n, int64_t{w} * 256));
    }
    int64_t q = 0;
    REQUIRE(hider::detail::div_round_w256_by_parts(128, D(1), q));
    CHECK(q == 1);  // 0.5 rounds away from zero
    REQUIRE(hider::detail::div_round_w256_by_parts(-128, D(1), q));
    CHECK(q == -1);
    REQUIRE(hider::detail::div_round_w256_by_parts(127, D(1), q));
    CHECK(q == 0);
}

TEST_CASE_TEMPLATE("div_round_prepared's 32-bit path equals div_round for every sign and tie", D, hider::Divisor32,
                   hider::LongDivisor32) {
    std::mt19937_64 rng(59);
    for (int i = 0; i < 200000; ++i) {
        const auto n = static_cast<int64_t>(rng()) >> (rng() % 63);
        const auto d = static_cast<uint32_t>(rng() >> (32 + rng() % 32)) | 1u;
        for (uint32_t dd : {d, d & ~1u ? d & ~1u : 2u}) {
            int64_t q = 0;
            if (!hider::div_round_prepared_by_parts(n, D(dd), q)) continue;
            CHECK(q == hider::div_round(n, int64_t{dd}));
            CHECK(hider::div_round_prepared(n, D(dd)) == q);
        }
    }
    int64_t q = 0;
    REQUIRE(hider::div_round_prepared_by_parts(5, D(2), q));
    CHECK(q == 3);
    REQUIRE(hider::div_round_prepared_by_parts(-5, D(2), q));
    CHECK(q == -3);
    CHECK_FALSE(hider::div_round_prepared_by_parts(int64_t{1} << 40, D(16), q));  // quotient past 32 bits
    CHECK(hider::div_round_prepared(int64_t{1} << 40, D(16)) == int64_t{1} << 36);  // then div_round
    CHECK(hider::div_round_prepared(-(int64_t{1} << 40) - 8, D(16)) == -(int64_t{1} << 36) - 1);
}

TEST_CASE("div_small_quotient equals native division whenever the quotient is below 2^15") {
    std::mt19937_64 rng(71);
    int taken = 0;
    auto check = [&taken](uint64_t m, uint32_t w) {
        uint32_t q = 0xDEADBEEFu;
        const bool ok = hider::div_small_quotient(m, w, q);
        CHECK(ok == (w < (uint32_t{1} << 30) && m / w < (uint64_t{1} << 15)));
        if (ok) {
            CHECK(q == m / w);
            ++taken;
        } else {
            CHECK(q == 0xDEADBEEFu);
        }
    };
    for (int i = 0; i < 300000; ++i) {
        const uint32_t w = static_cast<uint32_t>(rng() >> (34 + rng() % 30)) | 1u;  // 1 .. 2^30 - 1
        const uint64_t limit = uint64_t{w} << 15;
        check(rng() % (limit + limit / 8 + 1), w);  // mostly below the limit, some above
    }
    for (uint32_t w : {1u, 2u, 3u, 0xFFFFu, 0x10000u, 0x10001u, 0x1FFFFu, 0x12345678u, 0x3FFFFFFFu, 0x40000000u})
        for (uint64_t m : {uint64_t{0}, uint64_t{w} - 1, uint64_t{w}, (uint64_t{w} << 15) - 1, uint64_t{w} << 15,
                           (uint64_t{w} << 15) - w, (uint64_t{w} << 14) + w / 2})
            check(m, w);
    CHECK(taken > 200000);
}

TEST_CASE("reciprocal_word equals floor((2^64 - 1) / d) - 2^32 for every normalised divisor shape") {
    std::mt19937_64 rng(79);
    auto check = [](uint32_t d) {
        const uint64_t expected = ((uint64_t{~d} << 32) | 0xFFFFFFFFu) / d;  // < 2^32 for d >= 2^31
        CHECK(hider::reciprocal_word(d) == expected);
    };
    for (int i = 0; i < 500000; ++i) check(static_cast<uint32_t>(rng()) | 0x80000000u);
    for (uint32_t i = 0; i < 256; ++i) {  // every table bucket: both ends and the middle
        const uint32_t lo = 0x80000000u | (i << 23);
        for (uint32_t d : {lo, lo + 1, lo | 0x003FFFFFu, lo | 0x00400000u, lo | 0x007FFFFFu, lo | 0x007FFFFEu}) check(d);
    }
    for (uint32_t d : {0x80000000u, 0x80000001u, 0xFFFFFFFFu, 0xFFFFFFFEu, 0xFFFF0000u, 0x8000FFFFu, 0xC0000000u}) check(d);
}

TEST_CASE("the ARMv6-M 64-bit products by parts equal the native products") {
    std::mt19937_64 rng(67);
    for (int i = 0; i < 200000; ++i) {
        const uint64_t ub = rng() >> (rng() % 64);
        const auto ua = static_cast<uint32_t>(rng());
        CHECK(hider::mul_u32_u64_by_parts(ua, ub) == ua * ub);  // modulo 2^64, like the native product
        const auto a33 = static_cast<int64_t>(rng()) >> 32;     // |a| <= 2^31 ...
        const auto a33b = a33 * 2 + static_cast<int64_t>(rng() & 1);  // ... and up to 2^32 - 1
        const auto b16 = static_cast<int32_t>(static_cast<int64_t>(rng()) >> 49);  // |b| <= 2^14
        CHECK(hider::mul_i33_i16_by_parts(a33b, b16) == a33b * b16);
        CHECK(hider::mul_i33_i16(a33b, b16) == a33b * b16);
    }
    for (int i = 0; i < 200000; ++i) {
        const auto a = static_cast<int64_t>(rng()) >> (16 + rng() % 48);  // |a| <= 2^47
        const auto b = static_cast<int32_t>(static_cast<int64_t>(rng()) >> (49 + rng() % 15));  // |b| <= 2^14
        CHECK(hider::mul_i64_i16_by_parts(a, b) == a * b);
        CHECK(hider::mul_i64_i16(a, b) == a * b);
    }
    for (int64_t a : {INT64_MAX >> 15, INT64_MIN >> 15, int64_t{-1}, int64_t{0x7FFFFFFF}, -(int64_t{1} << 40)})
        for (int32_t b : {-16384, 16383, -8, 8, -1, 0})
            CHECK(hider::mul_i64_i16_by_parts(a, b) == a * b);
    for (int64_t a : {-(int64_t{1} << 32) + 1, (int64_t{1} << 32) - 1, int64_t{-1}, int64_t{65535}, int64_t{-65536}})
        for (int32_t b : {-32767, 32767, -1, 0, 1})
            CHECK(hider::mul_i33_i16_by_parts(a, b) == a * b);
    CHECK(hider::mul_i64_i16_by_parts(INT64_MAX, 1) == INT64_MAX);
    CHECK(hider::mul_i64_i16_by_parts(INT64_MIN, 1) == INT64_MIN);
}

static_assert(hider::div_floor32(INT32_MIN, 1) == INT32_MIN, "no overflow in the negative branch");
static_assert(hider::div_floor32(-1, 16) == -1 && hider::div_floor32(-16, 16) == -1 && hider::div_floor32(-17, 16) == -2,
              "floors toward minus infinity");

TEST_CASE("div_floor32 floors for every sign, including INT32_MIN") {
    std::mt19937_64 rng(83);
    auto floor_div = [](int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); };
    for (int i = 0; i < 300000; ++i) {
        const auto n = static_cast<int32_t>(rng() >> (rng() % 33));
        const auto d = static_cast<int32_t>((rng() >> (33 + rng() % 31)) | 1u);
        CHECK(hider::div_floor32(n, d) == floor_div(n, d));
    }
    for (int32_t n : {0, 1, -1, 15, -15, 16, -16, 17, -17, INT32_MAX, INT32_MIN, INT32_MIN + 1})
        for (int32_t d : {1, 2, 3, 16, 17, INT32_MAX})
            CHECK(hider::div_floor32(n, d) == floor_div(n, d));
}

TEST_CASE("mul128 of an Int128 by an int64 is exact wherever the product fits 128 bits") {
    using hider::Int128;
    using hider::mul128;
    std::mt19937_64 rng(12345);
    auto to128 = [](__int128 v) {
        Int128 r;
        r.lo = static_cast<uint64_t>(v);
        r.hi = static_cast<int64_t>(v >> 64);
        return r;
    };
    long checked = 0, wrong = 0;
    for (int i = 0; i < 200000; ++i) {
        // a of up to 100 bits, b of up to 126 minus a's bits (at most 63), both signs: the product fits.
        const int abits = 1 + static_cast<int>(rng() % 100);
        const int bbits = 1 + static_cast<int>(rng() % static_cast<uint64_t>(std::min(63, 126 - abits)));
        __int128 a = (static_cast<__int128>(rng()) << 64 | rng()) & ((static_cast<__int128>(1) << abits) - 1);
        int64_t b = static_cast<int64_t>(rng() & ((uint64_t{1} << bbits) - 1));
        if (rng() & 1) a = -a;
        if (rng() & 1) b = -b;
        const Int128 got = mul128(to128(a), b), want = to128(a * b);
        ++checked;
        wrong += got.lo != want.lo || got.hi != want.hi;
    }
    const __int128 as[4] = {0, -1, static_cast<__int128>(INT64_MIN), static_cast<__int128>(1) << 90};
    const int64_t bs[5] = {0, 1, -1, int64_t{1} << 30, -(int64_t{1} << 30)};
    for (const __int128 a : as)
        for (const int64_t b : bs) {
            const Int128 got = mul128(to128(a), b), want = to128(a * b);
            ++checked;
            wrong += got.lo != want.lo || got.hi != want.hi;
        }
    CHECK(checked > 200000);
    CHECK(wrong == 0);
}

// The exact arithmetic of a piece's outline (sort/outline.hpp): 128/64-bit division on every path a
// target takes, against the compiler's 128-bit integers. The outline itself is tested with Newell's
// cuts in sort_test.cpp (every point a rounded vertex of the exact region, with the plane's depth).
#include <hider/sort/outline.hpp>

#include <random>

#include <doctest/doctest.h>

using namespace hider;

TEST_CASE("detail::udiv64_by_32_steps divides as the CPU does, with a quotient of any width") {
    // The path of every 32-bit target (two 64/32-bit steps); the host divides natively.
    std::mt19937_64 rng(3);
    for (int i = 0; i < 300000; ++i) {
        const uint64_t n = rng() >> (rng() % 64);
        uint32_t d = static_cast<uint32_t>(rng() >> (32 + rng() % 32));
        if (d == 0) d = 1;
        uint32_t r = 0;
        const uint64_t q = detail::udiv64_by_32_steps(n, d, r);
        CHECK(q == n / d);
        CHECK(r == n % d);
    }
    uint32_t r = 0;
    CHECK(detail::udiv64_by_32_steps(~uint64_t{0}, 1, r) == ~uint64_t{0});
    CHECK(r == 0);
    CHECK(detail::udiv64_by_32_steps(~uint64_t{0}, 0xFFFFFFFFu, r) == 0x100000001u);
}

TEST_CASE("detail::udiv128_64 divides exactly for every divisor width") {
    std::mt19937_64 rng(11);
    long checked = 0;
    for (int i = 0; i < 300000; ++i) {
        uint64_t d = rng() >> (rng() % 64);
        if (d == 0) d = 1;
        const uint64_t u1 = (rng() >> (rng() % 64)) % d, u0 = i % 7 == 0 ? ~uint64_t{0} - rng() % 3 : rng();
        const unsigned __int128 n = (static_cast<unsigned __int128>(u1) << 64) | u0;
        uint64_t r = 0;
        const uint64_t q = detail::udiv128_64(u1, u0, d, r);
        CHECK(q == static_cast<uint64_t>(n / d));
        CHECK(r == static_cast<uint64_t>(n % d));
        ++checked;
    }
    CHECK(checked == 300000);
}

TEST_CASE("detail::div_round_128 rounds a 128-bit n / d to nearest exactly, and saturates out of range") {
    std::mt19937_64 rng(5);
    auto to128 = [](__int128 v) { Int128 r; r.lo = static_cast<uint64_t>(v); r.hi = static_cast<int64_t>(v >> 64); return r; };
    long checked = 0;
    for (int i = 0; i < 200000; ++i) {
        const int64_t d = static_cast<int64_t>(rng() >> (1 + rng() % 63)) | 1;  // 1 .. 2^63 - 1
        const __int128 q = static_cast<__int128>(static_cast<int64_t>(rng()) >> (29 + rng() % 35));  // |q| <= 2^34
        const __int128 n = q * d + static_cast<__int128>(static_cast<int64_t>(rng()) % d);
        const __int128 m = n < 0 ? -n : n;
        if (m >= static_cast<__int128>(d) << 34) continue;
        __int128 want = m / d;
        if (2 * (m % d) >= d) ++want;  // ties away from zero
        if (n < 0) want = -want;
        CHECK(detail::div_round_128(to128(n), d) == static_cast<int64_t>(want));
        ++checked;
    }
    CHECK(checked > 100000);
    CHECK(detail::div_round_128(to128(static_cast<__int128>(7) << 34), 7) == (int64_t{1} << 34));  // |n / d| = 2^34: saturated
    CHECK(detail::div_round_128(to128(-(static_cast<__int128>(1) << 100)), 3) == -(int64_t{1} << 34));
    CHECK(detail::div_round_128(to128(5), 2) == 3);
    CHECK(detail::div_round_128(to128(-5), 2) == -3);
}

// The outward quotient bounds behind the front-to-back walk's subtree rectangles (bsp/walk.hpp): a lower
// bound never above num / (256 w), an upper one never below it, and both close to it while the
// quotient is in the pixel range, against exact 128-bit arithmetic.
#include <hider/bsp/walk.hpp>

#include <random>

#include <doctest/doctest.h>

using namespace hider;

namespace {

// floor and ceil of num / (256 w), exactly.
__int128 exact_floor(int64_t num, int64_t w) {
    const __int128 n = num, d = __int128{w} * 256;
    __int128 q = n / d;
    if (q * d != n && n < 0) --q;
    return q;
}
__int128 exact_ceil(int64_t num, int64_t w) {
    const __int128 n = num, d = __int128{w} * 256;
    __int128 q = n / d;
    if (q * d != n && n > 0) ++q;
    return q;
}

}  // namespace

TEST_CASE("bound_over_256w bounds num / (256 w) from below and above, tightly in the pixel range") {
    std::mt19937_64 rng(7);
    const int64_t kTight = 1 << 14;  // quotients up to here (the coordinate limit) are within two units
    uint64_t tight_cases = 0;
    for (int i = 0; i < 400000; ++i) {
        const int nbits = static_cast<int>(rng() % 62), wbits = 1 + static_cast<int>(rng() % 62);
        int64_t num = static_cast<int64_t>(rng() >> (64 - nbits - 1 > 63 ? 0 : 63 - nbits));
        if (nbits == 0) num = static_cast<int64_t>(rng() % 3);
        if (rng() & 1) num = -num;
        int64_t w = static_cast<int64_t>(rng() >> (64 - wbits));
        if (w == 0) w = 1;
        const int64_t lo = detail::bound_over_256w<false>(num, w), hi = detail::bound_over_256w<true>(num, w);
        const __int128 f = exact_floor(num, w), c = exact_ceil(num, w);
        INFO("num ", num, " w ", w);
        // Never wrong: a quotient past 2^31 may be given as +-2^32 (the callers clamp far inside that).
        constexpr int64_t kSaturated = int64_t{1} << 32;
        REQUIRE((lo <= f || (lo == -kSaturated && f < -(int64_t{1} << 31))));
        REQUIRE((hi >= c || (hi == kSaturated && c > (int64_t{1} << 31))));
        REQUIRE(lo <= hi);
        if (f > -kTight && c < kTight && w >= (int64_t{1} << 16)) {  // views keep w far above 2^16 raw
            ++tight_cases;
            CHECK(f - lo <= 2);
            CHECK(hi - c <= 2);
        }
    }
    CHECK(tight_cases > 10000);
}

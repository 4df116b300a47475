// The walk arithmetic of bsp/walk.hpp against exact 128-bit arithmetic: the outward quotient bounds
// behind the front-to-back subtree rectangles (never above / below num / (256 w), close to it in the
// pixel range) and the eye's side of a node plane (its 32-bit filter and the exact fallback).
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

TEST_CASE("eye_side is the exact sign of n . (eye - origin): grid planes, huge normals, far eyes, eyes on the plane") {
    std::mt19937_64 rng(11);
    auto coord = [&](int64_t limit) { return static_cast<int32_t>(static_cast<int64_t>(rng() % (2 * limit - 1)) - (limit - 1)); };
    uint64_t on_plane = 0, near_plane = 0;
    for (int i = 0; i < 300000; ++i) {
        const int kind = static_cast<int>(rng() % 4);
        Vec3q16 origin{Q16::from_raw(coord(kBspWorldLimitRaw)), Q16::from_raw(coord(kBspWorldLimitRaw)),
                       Q16::from_raw(coord(kBspWorldLimitRaw))};
        BspNode n{};
        n.origin = 0;
        // Normals of every size bsp_load accepts (|n| < 2^62), most of them those of grid planes (< 2^57).
        const int bits = kind == 0 ? 62 : static_cast<int>(1 + rng() % 57);
        for (auto& c : n.n) c = static_cast<int64_t>(rng() >> (64 - bits)) * ((rng() & 1) != 0 ? 1 : -1);
        if (n.n[0] == 0 && n.n[1] == 0 && n.n[2] == 0) n.n[0] = 1;
        // Eyes anywhere in int32 (kind 1), or near the origin and the plane (kinds 2, 3).
        Vec3q16 eye;
        if (kind == 1) {
            eye = {Q16::from_raw(static_cast<int32_t>(rng())), Q16::from_raw(static_cast<int32_t>(rng())),
                   Q16::from_raw(static_cast<int32_t>(rng()))};
        } else {
            const int32_t r = kind == 3 ? 64 : (int32_t{1} << 30) - (int32_t{1} << 27);
            eye = {Q16::from_raw(origin.x.raw() + coord(r)), Q16::from_raw(origin.y.raw() + coord(r)),
                   Q16::from_raw(origin.z.raw() + coord(r))};
        }
        if (kind == 3 && (rng() & 3) == 0) {  // on the plane: a normal orthogonal to d
            const int64_t d0 = int64_t{eye.x.raw()} - origin.x.raw(), d1 = int64_t{eye.y.raw()} - origin.y.raw(),
                          d2 = int64_t{eye.z.raw()} - origin.z.raw();
            n.n[0] = d1 - d2;
            n.n[1] = d2 - d0;
            n.n[2] = d0 - d1;
            if (n.n[0] == 0 && n.n[1] == 0 && n.n[2] == 0) continue;
        }
        BspTree tree;
        tree.vertices = {&origin, 1};
        const __int128 exact = __int128{n.n[0]} * (int64_t{eye.x.raw()} - origin.x.raw()) +
                               __int128{n.n[1]} * (int64_t{eye.y.raw()} - origin.y.raw()) +
                               __int128{n.n[2]} * (int64_t{eye.z.raw()} - origin.z.raw());
        const int want = exact > 0 ? 1 : exact < 0 ? -1 : 0;
        on_plane += want == 0;
        near_plane += kind == 3;
        INFO("n ", n.n[0], " ", n.n[1], " ", n.n[2], " eye ", eye.x.raw(), " ", eye.y.raw(), " ", eye.z.raw());
        REQUIRE(detail::eye_side(tree, n, eye) == want);
    }
    CHECK(on_plane > 1000);
    CHECK(near_plane > 10000);
}

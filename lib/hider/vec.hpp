// 3-vectors over fixed point: Vec3<Q16> for positions (world and view units), Vec3<Q30> for unit
// directions, Normal14 (int16 Q14) for the per-face unit normals stored with a mesh.
#pragma once
#include <hider/fixed.hpp>

namespace hider {

template <class T>
struct Vec3 {
    T x, y, z;
    friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend constexpr bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
};
using Vec3q16 = Vec3<Q16>;
using Vec3q30 = Vec3<Q30>;

/// Unit normal with int16 components in Q14 (16384 = 1.0); (0,0,0) marks a degenerate face.
struct Normal14 {
    int16_t x, y, z;
};

/// A vector of raw 64-bit components, for exact intermediate products.
struct Vec3i64 {
    int64_t x, y, z;
};

/// Exact cross product of two raw Q16 difference vectors (components below 2^30 in magnitude).
constexpr Vec3i64 cross_raw(Vec3q16 a, Vec3q16 b) {
    return {mul_wide(a.y.raw(), b.z.raw()) - mul_wide(a.z.raw(), b.y.raw()),
            mul_wide(a.z.raw(), b.x.raw()) - mul_wide(a.x.raw(), b.z.raw()),
            mul_wide(a.x.raw(), b.y.raw()) - mul_wide(a.y.raw(), b.x.raw())};
}

/// Scales v to unit length in Q30 (error <= 3 LSB per component). Returns false for the zero vector.
constexpr bool normalize(Vec3i64 v, Vec3q30& out) {
    const uint64_t ax = static_cast<uint64_t>(abs_value(v.x));
    const uint64_t ay = static_cast<uint64_t>(abs_value(v.y));
    const uint64_t az = static_cast<uint64_t>(abs_value(v.z));
    const uint64_t m = max(ax, max(ay, az));
    if (m == 0) return false;
    // Bring the largest component into [2^29, 2^30): squares then sum below 2^62.
    const int shift = 34 - clz64(m);  // m has 64 - clz bits; target 30 bits
    int64_t c[3] = {v.x, v.y, v.z};
    for (int64_t& e : c) e = shift >= 0 ? (e >> shift) : e * (int64_t{1} << -shift);
    const uint64_t len2 = static_cast<uint64_t>(c[0] * c[0]) + static_cast<uint64_t>(c[1] * c[1]) +
                          static_cast<uint64_t>(c[2] * c[2]);
    const int64_t len = isqrt64(len2);
    if (len == 0) return false;
    out = {Q30::from_raw(saturate32(div_round(c[0] * Q30::kOne, len))),
           Q30::from_raw(saturate32(div_round(c[1] * Q30::kOne, len))),
           Q30::from_raw(saturate32(div_round(c[2] * Q30::kOne, len)))};
    return true;
}

/// Unit normal of triangle (p0, p1, p2) by the right-hand rule, rounded to Q14; zero if degenerate.
/// Precondition: coordinates within the world range (|raw| < 2^29), so edge vectors stay below 2^30.
constexpr Normal14 face_normal(Vec3q16 p0, Vec3q16 p1, Vec3q16 p2) {
    Vec3q30 n{};
    if (!normalize(cross_raw(p1 - p0, p2 - p0), n)) return {0, 0, 0};
    auto to14 = [](Q30 c) { return static_cast<int16_t>((c.raw() + (1 << 15)) >> 16); };
    return {to14(n.x), to14(n.y), to14(n.z)};
}

}  // namespace hider

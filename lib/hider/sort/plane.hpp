// Newell's plane tests on screen polygons: exact plane-side tests (128-bit sums of products) with a
// slack for the grid rounding of cut points (outline.hpp). The cut of a polygon by another's plane is
// in cut.hpp, the crossing it follows in crossing.hpp.
#pragma once
#include <hider/sort/outline.hpp>

namespace hider {

/// Plane of a screen triangle, oriented so that side() > 0 means farther (larger z) than the plane.
struct ScreenPlane {
    int64_t a, b, c;  ///< coefficients of x, y, z (c > 0 for any triangle with nonzero area)
    ScreenVertex origin;
    bool narrow;      ///< |a|, |b| < 2^45 and c < 2^29: every side() fits int64 (most triangles of a small frame)
};

/// The plane of polygon p: its (parent) triangle's, which every piece of it shares. It is the plane the
/// rasterizer steps depth through, so the tests below decide on exactly what is drawn.
inline ScreenPlane plane_of(const ScreenPoly& p) {
    const int64_t dx1 = p.v[1].x - p.v[0].x, dy1 = p.v[1].y - p.v[0].y, dz1 = int64_t{p.v[1].z} - p.v[0].z;
    const int64_t dx2 = p.v[2].x - p.v[0].x, dy2 = p.v[2].y - p.v[0].y, dz2 = int64_t{p.v[2].z} - p.v[0].z;
    ScreenPlane pl{dy1 * dz2 - dz1 * dy2, dz1 * dx2 - dx1 * dz2, dx1 * dy2 - dy1 * dx2, p.v[0], false};
    if (pl.c < 0) { pl.a = -pl.a; pl.b = -pl.b; pl.c = -pl.c; }
    // |x - x0|, |y - y0| < 2^16 and |z - z0| < 2^32: each product then stays below 2^61, the sum below 2^63.
    pl.narrow = abs_value(pl.a) < (int64_t{1} << 45) && abs_value(pl.b) < (int64_t{1} << 45) && pl.c < (int64_t{1} << 29);
    return pl;
}

/// Exact signed distance (scaled) of v (a ScreenVertex or an OutlinePoint) from the plane: > 0 farther,
/// 0 on it, < 0 nearer.
template <class V>
inline Int128 side(const ScreenPlane& pl, const V& v) {
    return mul128(pl.a, v.x - pl.origin.x) + mul128(pl.b, v.y - pl.origin.y) + mul128(pl.c, int64_t{v.z} - pl.origin.z);
}

/// How far side() can put a point cut onto the plane once rounded to the grid: half a subpixel in x and
/// y, and three depth units in z (its depth is the plane's at the exact point, rounded: half a unit, with room).
inline Int128 rounding_slack(const ScreenPlane& pl) {
    return mul128(abs_value(pl.a) + abs_value(pl.b), 1).shr(1) + mul128(pl.c, 3);
}

/// Side of v: +1 farther, -1 nearer, 0 on the plane or within `slack` of it (a vertex shared with the
/// plane's triangle is exactly on it). A narrow plane decides in 64 bits, with the same result.
template <class V>
inline int classify(const ScreenPlane& pl, const Int128& slack, const V& v) {
    if (pl.narrow) {
        const int64_t d = pl.a * (v.x - pl.origin.x) + pl.b * (v.y - pl.origin.y) + pl.c * (int64_t{v.z} - pl.origin.z);
        const int64_t t = static_cast<int64_t>(slack.lo);  // slack < 2^47 for a narrow plane
        return d > t ? 1 : (d < -t ? -1 : 0);
    }
    const Int128 d = side(pl, v);
    if ((d - slack).sign() > 0) return 1;
    if ((d + slack).sign() < 0) return -1;
    return 0;
}

namespace detail {
/// Number of significant bits of |v| (0 for 0). Precondition: |v| < 2^127.
inline int magnitude_bits(const Int128& v) {
    const Int128 m = v.sign() < 0 ? -v : v;
    if (m.hi != 0) return 128 - clz64(static_cast<uint64_t>(m.hi));
    return 64 - clz64(m.lo);
}

/// floor(v / 2^s) for 0 <= s < 128 and a result that fits int64.
inline int64_t shift_down(const Int128& v, int s) {
    if (s == 0) return static_cast<int64_t>(v.lo);
    if (s < 64) return static_cast<int64_t>(v.shr(s).lo);
    return v.hi >> (s - 64);
}

}  // namespace detail

/// Side of an outline: -1 if every vertex is nearer than the plane or on it, +1 if every one is farther
/// or on it (a polygon in the plane gives +1), 0 if it straddles the plane or the side is not certain.
/// A whole triangle is classified exactly: its vertices are where the rasterizer draws them, and a
/// surface closer to a parallel one than half a subpixel's depth slope must not be taken for coplanar
/// (the later one would be drawn on top). A piece's outline has cut points rounded to the grid: a
/// vertex beyond the rounding slack has its side, one exactly on the plane is on it, and one within the
/// slack but off the plane makes the side uncertain (0: the caller's trial cut decides). Taken for "on
/// the plane", such vertices put a piece of a nearly parallel stack wholly behind a plane it crosses.
inline int side_of(const ScreenPlane& pl, const Outline& o) {
    bool near = false, far = false, unsure = false;
    if (!o.rounded) {
        for (int i = 0; i < o.count; ++i) {
            const int s = classify(pl, Int128{}, o.v[i]);
            near = near || s < 0;
            far = far || s > 0;
        }
    } else if (pl.narrow) {  // as classify(): 64 bits, the same result
        const int64_t slack = static_cast<int64_t>(rounding_slack(pl).lo);
        for (int i = 0; i < o.count; ++i) {
            const OutlinePoint& v = o.v[i];
            const int64_t d = pl.a * (v.x - pl.origin.x) + pl.b * (v.y - pl.origin.y) + pl.c * (int64_t{v.z} - pl.origin.z);
            far = far || d > slack;
            near = near || d < -slack;
            unsure = unsure || (d != 0 && d <= slack && d >= -slack);
        }
    } else {
        const Int128 slack = rounding_slack(pl);
        for (int i = 0; i < o.count; ++i) {
            const Int128 d = side(pl, o.v[i]);
            const bool beyond_far = (d - slack).sign() > 0, beyond_near = (d + slack).sign() < 0;
            far = far || beyond_far;
            near = near || beyond_near;
            unsure = unsure || (!beyond_far && !beyond_near && d.sign() != 0);
        }
    }
    if ((near && far) || unsure) return 0;
    return near ? -1 : 1;
}

/// The side of the plane named `plane` (plane_name()) that a cut of p's chain put it on (+1 far, -1
/// near), or 0 when no cut of p came from that plane.
inline int known_side(const ScreenPoly& p, Span<const PieceCut> cuts, uint32_t plane) {
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev)
        if ((cuts[c].plane & ~kCutFar) == plane) return (cuts[c].plane & kCutFar) != 0 ? 1 : -1;
    return 0;
}

}  // namespace hider

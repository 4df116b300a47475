// Sutherland-Hodgman clipping of a triangle in homogeneous view space (before the divide) against the
// near and far planes and the x/y guard band (Blinn & Newell 1978). Intersections are always computed
// from the outside vertex toward the inside one, so triangles sharing an edge get identical points.
#pragma once
#include <hider/view.hpp>

namespace hider {

/// A convex polygon produced by clipping one triangle: 3 + 6 vertices for exact arithmetic; the
/// extra room absorbs rounding, and writes past it are dropped rather than overflowing.
struct ClipPolygon {
    static constexpr int kMaxVertices = 16;
    ViewPoint v[kMaxVertices];
    int count = 0;
};

namespace detail {
/// Point on segment (out -> in) where the plane distance is zero; d_out < 0 <= d_in.
inline ViewPoint intersect(const ViewPoint& out, const ViewPoint& in, int64_t d_out, int64_t d_in) {
    uint64_t num = static_cast<uint64_t>(-d_out);
    uint64_t den = static_cast<uint64_t>(d_in) + num;
    while (den >= (uint64_t{1} << 31)) { num >>= 1; den >>= 1; }  // t = num / den keeps 30+ bits
    const int64_t t_q30 = div_round(static_cast<int64_t>(num << 30), static_cast<int64_t>(den));
    auto lerp = [t_q30](int32_t a, int32_t b) {
        return static_cast<int32_t>(a + (((int64_t{b} - a) * t_q30 + (int64_t{1} << 29)) >> 30));
    };
    return {lerp(out.x, in.x), lerp(out.y, in.y), lerp(out.w, in.w)};
}
}  // namespace detail

/// Clips triangle (a, b, c) against every plane in `planes` (ClipPlane bits), near first.
/// The result may be empty (count < 3). No allocation; the polygon lives in `out`.
inline void clip_triangle(const View& view, const ViewPoint& a, const ViewPoint& b, const ViewPoint& c,
                          uint8_t planes, ClipPolygon& out) {
    ClipPolygon tmp;
    ClipPolygon* src = &out;
    ClipPolygon* dst = &tmp;
    src->v[0] = a; src->v[1] = b; src->v[2] = c;
    src->count = 3;
    for (int bit = 0; bit < kClipPlaneCount; ++bit) {
        const uint8_t plane = static_cast<uint8_t>(1u << bit);
        if ((planes & plane) == 0) continue;
        dst->count = 0;
        for (int i = 0; i < src->count; ++i) {
            const ViewPoint& p = src->v[i];
            const ViewPoint& q = src->v[(i + 1) % src->count];
            const int64_t dp = clip_distance(view, p, plane), dq = clip_distance(view, q, plane);
            if (dp >= 0 && dst->count < ClipPolygon::kMaxVertices) dst->v[dst->count++] = p;
            if ((dp >= 0) != (dq >= 0) && dst->count < ClipPolygon::kMaxVertices)
                dst->v[dst->count++] = dp < 0 ? detail::intersect(p, q, dp, dq) : detail::intersect(q, p, dq, dp);
        }
        swap_values(src, dst);
        if (src->count < 3) break;
    }
    if (src != &out) out = *src;
}

}  // namespace hider

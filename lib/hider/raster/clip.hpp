// Clip codes and Sutherland-Hodgman clipping of a triangle in homogeneous view space (before the
// divide) against the near and far planes and the x/y guard band (Blinn & Newell 1978). Intersections
// are always computed from the outside vertex toward the inside one, so triangles sharing an edge get
// identical points. for_each_clipped() hands a mesh triangle's drawable screen triangles to a caller.
#pragma once
#include <hider/int128.hpp>
#include <hider/mesh.hpp>

namespace hider {

/// Clip planes (bits of ScreenVertex::outside).
enum ClipPlane : uint8_t {
    kClipNear = 1, kClipFar = 2, kClipLeft = 4, kClipRight = 8, kClipTop = 16, kClipBottom = 32,
};
constexpr int kClipPlaneCount = 6;

/// w kGuardBand 256 (|X| <= G  <=>  |x k| <= G w 256), one 32x32->64 product.
inline int64_t guard_of(int32_t w) { return mul_wide(w, kGuardBand * 256); }

/// Signed distance of p to clip plane `plane` (one bit), >= 0 inside; exact in int64.
inline int64_t clip_distance(const View& v, const ViewPoint& p, uint8_t plane) {
    const int64_t guard = guard_of(p.w);
    switch (plane) {
        case kClipNear: return int64_t{p.w} - v.near_raw;
        case kClipFar: return int64_t{v.far_raw} - p.w;
        case kClipLeft: return guard + mul_wide(p.x, v.k_q8);
        case kClipRight: return guard - mul_wide(p.x, v.k_q8);
        case kClipTop: return guard - mul_wide(p.y, v.k_q8);
        default: return guard + mul_wide(p.y, v.k_q8);
    }
}

/// The set of clip planes p lies outside of (0 = inside the view volume and the guard band).
inline uint8_t outcode(const View& v, const ViewPoint& p, const ScaledXY& s) {
    uint8_t code = 0;
    if (p.w < v.near_raw) code |= kClipNear;
    if (p.w > v.far_raw) code |= kClipFar;
    const int64_t guard = guard_of(p.w);
    if (s.xk < -guard) code |= kClipLeft;
    if (s.xk > guard) code |= kClipRight;
    if (s.yk > guard) code |= kClipTop;
    if (s.yk < -guard) code |= kClipBottom;
    return code;
}
inline uint8_t outcode(const View& v, const ViewPoint& p) { return outcode(v, p, scaled_xy(v, p)); }


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

namespace detail {
/// Whether the plane of triangle (p0, p1, p2), in view space, passes within about 4 raw units of the eye
/// (the origin): |n . a| <= 4 max|n_i| for n = (b - a) x (c - a), exact in 128 bits. Rounding to view
/// space moves each vertex by a raw unit or two, so such a triangle may be one the eye sees exactly
/// edge-on; clipped at the near plane, that rounding would open a wedge across the screen, where the
/// BSP's exact eye test and ray casting show nothing. Out of line, taking the world points: its 128-bit
/// temporaries and the view points stay off the frame of the clip path (the band renderer's deepest stack).
__attribute__((noinline)) inline bool plane_through_eye(const View& view, const Vec3q16& p0, const Vec3q16& p1,
                                                        const Vec3q16& p2) {
    const ViewPoint a = to_view_point(view, p0), b = to_view_point(view, p1), c = to_view_point(view, p2);
    const int64_t av[3] = {a.x, a.y, a.w};
    const int64_t e1[3] = {int64_t{b.x} - a.x, int64_t{b.y} - a.y, int64_t{b.w} - a.w};
    const int64_t e2[3] = {int64_t{c.x} - a.x, int64_t{c.y} - a.y, int64_t{c.w} - a.w};
    Int128 d{}, bound{};  // d = n . a (|d| < 2^98), bound = max |n_i|
    for (int i = 0; i < 3; ++i) {  // one loop body: the 128-bit products appear once in the code
        const int j = i == 2 ? 0 : i + 1, k = j == 2 ? 0 : j + 1;
        const Int128 n = mul128(e1[j], e2[k]) - mul128(e1[k], e2[j]);  // |n_i| < 2^65
        d = d + mul128(n, av[i]);
        const Int128 m = n.sign() < 0 ? -n : n;
        if ((m - bound).sign() > 0) bound = m;
    }
    bound = bound + bound;
    bound = bound + bound;  // 4 max|n_i|: the plane within 4 raw units, at least within 4 / sqrt(3)
    const Int128 ad = d.sign() < 0 ? -d : d;
    return (ad - bound).sign() <= 0;
}
}  // namespace detail

/// Calls piece(a, b, c) for each drawable screen triangle of the triangle (i0, i1, i2) of `positions`:
/// the triangle itself, or the fan of its clipped polygon (vertices from project_vertices() in
/// `verts`). A triangle crossing the near plane whose plane passes within about 4 raw units of the eye
/// (detail::plane_through_eye()) is seen edge-on and gives none. Counts outside and clipped triangles in
/// `st` (FrameStats, or anything with those two counters: a caller that does not need them keeps 56
/// bytes off the stack).
template <class Counts, class Piece>
void for_each_clipped(const View& view, Span<const Vec3q16> positions, Span<const ScreenVertex> verts, uint32_t i0,
                      uint32_t i1, uint32_t i2, Counts& st, Piece&& piece) {
    const ScreenVertex& a = verts[i0];
    const ScreenVertex& b = verts[i1];
    const ScreenVertex& c = verts[i2];
    if ((a.outside() & b.outside() & c.outside()) != 0) { ++st.triangles_outside; return; }
    const uint8_t planes = a.outside() | b.outside() | c.outside();
    if (planes == 0) { piece(a, b, c); return; }
    ++st.triangles_clipped;
    if ((planes & kClipNear) != 0 && detail::plane_through_eye(view, positions[i0], positions[i1], positions[i2]))
        return;  // seen edge-on: nothing
    ClipPolygon poly;
    clip_triangle(view, to_view_point(view, positions[i0]), to_view_point(view, positions[i1]), to_view_point(view, positions[i2]),
                  planes, poly);
    if (poly.count < 3) return;
    const ScreenVertex first = project(view, poly.v[0]);
    ScreenVertex prev = project(view, poly.v[1]);
    for (int i = 2; i < poly.count; ++i) {
        const ScreenVertex next = project(view, poly.v[i]);
        piece(first, prev, next);
        prev = next;
    }
}

/// for_each_clipped() for mesh triangle t.
template <class Counts, class Piece>
void for_each_clipped(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, size_t t, Counts& st,
                      Piece&& piece) {
    const Tri& tri = mesh.tris[t];
    for_each_clipped(view, mesh.positions, verts, tri.v[0], tri.v[1], tri.v[2], st, static_cast<Piece&&>(piece));
}

}  // namespace hider

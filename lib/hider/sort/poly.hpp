// Triangles in screen space for the object-space algorithms (painter, Newell, reverse painter):
// snapped x, y and the same affine depth z the z-buffer interpolates, so their planes are exactly the
// planes the z-buffer steps through. Plane-side tests are exact (128-bit), splitting keeps face ids.
#pragma once
#include <hider/int128.hpp>
#include <hider/raster/paint.hpp>
#include <hider/raster/vertices.hpp>

namespace hider {

/// One triangle (or split piece) in screen space: 52 bytes on every target.
struct ScreenPoly {
    ScreenVertex v[3];
    uint32_t zmin, zmax;   ///< depth extent
    int16_t xmin, xmax, ymin, ymax;  ///< bounding box, subpixels
    uint32_t tri;          ///< mesh triangle it comes from (colour and id)
    uint32_t moved_at;     ///< Newell: the output position it was last moved to (kNotMoved if never)
    uint8_t flags;         ///< kPolyFront
};
static_assert(sizeof(ScreenPoly) == 52, "ScreenPoly layout is documented in README.md");
constexpr uint8_t kPolyFront = 1;  ///< counter-clockwise on the image
constexpr uint32_t kNotMoved = 0xFFFFFFFFu;

/// Fills the extents of p from its vertices.
inline void update_extents(ScreenPoly& p) {
    p.zmin = min(p.v[0].z, min(p.v[1].z, p.v[2].z));
    p.zmax = max(p.v[0].z, max(p.v[1].z, p.v[2].z));
    p.xmin = min(p.v[0].x, min(p.v[1].x, p.v[2].x));
    p.xmax = max(p.v[0].x, max(p.v[1].x, p.v[2].x));
    p.ymin = min(p.v[0].y, min(p.v[1].y, p.v[2].y));
    p.ymax = max(p.v[0].y, max(p.v[1].y, p.v[2].y));
}

/// Appends the drawable screen triangles of `mesh` to `out`: clipped pieces, back faces removed when
/// cull is set, zero-area triangles and those covering no pixel centre of the frame skipped.
/// When `out` fills, the rest are dropped and counted (st.status = capacity_exceeded).
inline void build_polys(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, bool cull,
                        BoundedList<ScreenPoly>& out, FrameStats& st) {
    FrameView<Grey8Format> whole;  // geometry only: bounds of the full frame
    whole.width = view.width;
    whole.height = view.height;
    whole.y0 = 0;
    whole.y1 = view.height;
    const BandBounds bb = band_bounds(whole);
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        ++st.triangles_in;
        for_each_clipped(view, mesh, verts, t, st, [&](const ScreenVertex& a, const ScreenVertex& b,
                                                             const ScreenVertex& c) {
            const int32_t area = TriangleRaster::signed_area(a, b, c);
            if (area == 0) return;
            if (cull && area > 0) { ++st.triangles_culled; return; }
            if (misses_band(screen_box(a, b, c), bb)) return;
            ScreenPoly p{{a, b, c}, 0, 0, 0, 0, 0, 0, static_cast<uint32_t>(t), kNotMoved,
                         static_cast<uint8_t>(area < 0 ? kPolyFront : 0)};
            update_extents(p);
            if (!out.push_back(p)) st.status = Status::capacity_exceeded;
        });
    }
}

namespace detail {
/// Sets `tr` up for polygon p when p can touch the band; [y0, y1) are then its rows inside the band.
template <class Frame>
__attribute__((always_inline)) inline bool setup_in_band(const ScreenPoly& p, const BandBounds& bb, const Frame& frame,
                                                         TriangleRaster& tr, int32_t& y0, int32_t& y1) {
    if (p.ymax < bb.y_first || p.ymin > bb.y_last) return false;
    if (!tr.setup(p.v[0], p.v[1], p.v[2], frame.width, frame.height)) return false;
    y0 = max(frame.y0, tr.first_row());
    y1 = min(frame.y1, tr.end_row());
    return true;
}
}  // namespace detail

/// Plane of a screen triangle, oriented so that side() > 0 means farther (larger z) than the plane.
struct ScreenPlane {
    int64_t a, b, c;  ///< coefficients of x, y, z (c > 0 for any triangle with nonzero area)
    ScreenVertex origin;
};

inline ScreenPlane plane_of(const ScreenPoly& p) {
    const int64_t dx1 = p.v[1].x - p.v[0].x, dy1 = p.v[1].y - p.v[0].y, dz1 = int64_t{p.v[1].z} - p.v[0].z;
    const int64_t dx2 = p.v[2].x - p.v[0].x, dy2 = p.v[2].y - p.v[0].y, dz2 = int64_t{p.v[2].z} - p.v[0].z;
    ScreenPlane pl{dy1 * dz2 - dz1 * dy2, dz1 * dx2 - dx1 * dz2, dx1 * dy2 - dy1 * dx2, p.v[0]};
    if (pl.c < 0) { pl.a = -pl.a; pl.b = -pl.b; pl.c = -pl.c; }
    return pl;
}

/// Exact signed distance (scaled) of v from the plane: > 0 farther, 0 on it, < 0 nearer.
inline Int128 side(const ScreenPlane& pl, const ScreenVertex& v) {
    return mul128(pl.a, v.x - pl.origin.x) + mul128(pl.b, v.y - pl.origin.y) +
           mul128(pl.c, int64_t{v.z} - pl.origin.z);
}

/// Half a grid step of the plane's distance: how far a vertex cut onto the plane can sit from it after
/// rounding to the 1/16-pixel, 1-LSB grid ((|a| + |b| + |c|) / 2, exact).
inline Int128 rounding_slack(const ScreenPlane& pl) {
    const Int128 sum = mul128(abs_value(pl.a), 1) + mul128(abs_value(pl.b), 1) + mul128(pl.c, 1);
    return sum.shr(1);
}

/// Side of v: +1 farther, -1 nearer, 0 on the plane or within the rounding slack of it. Exact integer
/// arithmetic; the slack absorbs the rounding of cut vertices to the grid (the quantised cut parameter
/// can add a little more, which side_of's collapse fallback covers), while shared vertices and
/// coplanar neighbours are exactly on the plane.
inline int classify(const ScreenPlane& pl, const Int128& slack, const ScreenVertex& v) {
    const Int128 d = side(pl, v);
    if ((d - slack).sign() > 0) return 1;
    if ((d + slack).sign() < 0) return -1;
    return 0;
}

/// True when the projections of p and q share no pixel centre interior: some edge of one has all
/// vertices of the other on its outer side or on it (separating axis; exact in int32).
inline bool projections_disjoint(const ScreenPoly& p, const ScreenPoly& q) {
    auto separated_by = [](const ScreenPoly& s, const ScreenPoly& o) {
        const int32_t area = TriangleRaster::signed_area(s.v[0], s.v[1], s.v[2]);
        for (int i = 0; i < 3; ++i) {
            const ScreenVertex& a = s.v[i];
            const ScreenVertex& b = s.v[next3(i)];
            bool all_out = true;
            for (const ScreenVertex& v : o.v) {
                const int32_t e = (b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x);
                // Inside is where e has the sign of the area; outside or on the line separates.
                if ((area > 0 && e > 0) || (area < 0 && e < 0)) { all_out = false; break; }
            }
            if (all_out) return true;
        }
        return false;
    };
    return separated_by(p, q) || separated_by(q, p);
}

/// Splits p by the plane into at most three triangles written to out[]; returns their count, or 0
/// when p does not straddle the plane. Each intersection is computed from the far vertex toward the
/// near one, so both pieces sharing a cut get identical points. Pieces keep tri and the front flag.
/// When rounding collapses one side to nothing, it returns 0 and *survivor tells the side left
/// (+1 far, -1 near): the polygon then lies on that side for every pixel centre.
inline int split_by_plane(const ScreenPoly& p, const ScreenPlane& pl, ScreenPoly (&out)[3], int* survivor = nullptr) {
    if (survivor != nullptr) *survivor = 0;
    Int128 d[3];
    int sgn[3];
    const Int128 slack = rounding_slack(pl);
    for (int i = 0; i < 3; ++i) { d[i] = side(pl, p.v[i]); sgn[i] = classify(pl, slack, p.v[i]); }
    const bool has_far = sgn[0] > 0 || sgn[1] > 0 || sgn[2] > 0;
    const bool has_near = sgn[0] < 0 || sgn[1] < 0 || sgn[2] < 0;
    if (!has_far || !has_near) return 0;
    auto cut = [&](int i, int j) {  // point on edge (i, j) where the plane crosses; sgn[i] != sgn[j], both nonzero
        const int f = sgn[i] > 0 ? i : j, n = f == i ? j : i;
        Int128 num = d[f], den = d[f] - d[n];  // num > 0, den > num
        while (!(den.hi == 0 && den.lo < (uint64_t{1} << 31))) { num = num.shr(1); den = den.shr(1); }
        const int64_t t_q30 = div_round(static_cast<int64_t>(num.lo << 30), static_cast<int64_t>(den.lo));
        auto lerp = [t_q30](int64_t a, int64_t b) { return a + (((b - a) * t_q30 + (int64_t{1} << 29)) >> 30); };
        ScreenVertex r;
        r.x = static_cast<int16_t>(lerp(p.v[f].x, p.v[n].x));
        r.y = static_cast<int16_t>(lerp(p.v[f].y, p.v[n].y));
        r.z = static_cast<uint32_t>(lerp(p.v[f].z, p.v[n].z));
        return r;
    };
    // Walk the triangle in order, emitting the polygon on each side (Sutherland-Hodgman, two outputs).
    ScreenVertex far_poly[4], near_poly[4];
    int nf = 0, nn = 0;
    for (int i = 0; i < 3; ++i) {
        const int j = next3(i);
        if (sgn[i] >= 0) far_poly[nf++] = p.v[i];
        if (sgn[i] <= 0) near_poly[nn++] = p.v[i];
        if (sgn[i] * sgn[j] < 0) {
            const ScreenVertex c = cut(i, j);
            far_poly[nf++] = c;
            near_poly[nn++] = c;
        }
    }
    int count = 0;
    auto emit = [&](const ScreenVertex* poly, int n) {
        for (int k = 1; k + 1 < n; ++k) {
            ScreenPoly q = p;
            q.v[0] = poly[0];
            q.v[1] = poly[k];
            q.v[2] = poly[k + 1];
            q.moved_at = kNotMoved;
            if (TriangleRaster::signed_area(q.v[0], q.v[1], q.v[2]) == 0) continue;  // rounded to a sliver of nothing
            update_extents(q);
            out[count++] = q;
        }
    };
    emit(far_poly, nf);
    const int far_count = count;
    emit(near_poly, nn);
    if (far_count > 0 && count > far_count) return count;
    if (survivor != nullptr) *survivor = far_count > 0 ? 1 : (count > 0 ? -1 : 0);
    return 0;  // rounding collapsed one side: no real cut
}

/// -1 if every vertex of p is on the near side of the plane or on it, +1 if every one is on the far
/// side or on it, 0 if p straddles the plane. (A polygon lying in the plane gives +1.) A straddle so
/// thin that cutting would leave nothing on one side counts as the other side (see split_by_plane).
inline int side_of(const ScreenPlane& pl, const ScreenPoly& p) {
    const Int128 slack = rounding_slack(pl);
    bool near = false, far = false;
    for (const ScreenVertex& v : p.v) {
        const int s = classify(pl, slack, v);
        near = near || s < 0;
        far = far || s > 0;
    }
    if (!(near && far)) return near ? -1 : 1;
    ScreenPoly pieces[3];
    int survivor = 0;
    return split_by_plane(p, pl, pieces, &survivor) != 0 ? 0 : survivor;
}

}  // namespace hider

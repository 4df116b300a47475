// Drawing a BSP tree (load.hpp) without recursion and without a depth buffer (Fuchs, Kedem & Naylor 1980).
// At each node the eye's side of the plane decides the order: back to front draws the far subtree, the
// node's triangles, then the near subtree, painting every pixel; front to back draws them the other way
// round with the coverage bits of raster/coverage.hpp, writes each pixel once, skips a subtree whose
// screen box is outside the band or already covered (Doom's R_CheckBBox), and stops when the band is
// full. Triangles in a node's plane are skipped when the eye is in that plane (edge-on), and back faces
// fall out of the same side test. On a closed surface whose cells hider-bsp labelled, only the faces
// that can be seen from the eye's cell are drawn (bsp_visible_faces()), culling or not. The walk keeps
// its pending work in a caller stack of bsp_stack_entries(depth) uint32 entries (one per level).
#pragma once
#include <hider/bsp/cells.hpp>
#include <hider/raster/paint.hpp>
#include <hider/raster/clip.hpp>
#include <hider/raster/vertices.hpp>

namespace hider {

/// The faces a walk draws: front faces when culling, else those bsp_visible_faces() allows.
inline BspFaces bsp_walk_faces(const View& view, const Vec3q16& eye, const BspTree& tree, const DrawOptions& opt,
                               Span<uint32_t> stack) {
    return opt.cull ? BspFaces::front : bsp_visible_faces(view, eye, tree, stack);
}

namespace detail {

/// Bounds on p / w for 0 <= p < 2^63 and 0 < w < 2^63 by one 32/32-bit division of both shifted right
/// until p fits 31 bits: kUp gives at least p / w, else at most it (and at least 0). Near the quotient
/// when w keeps many bits after the shift (the relative error is about 2^s / w); past 2^31, 2^32.
template <bool kUp>
inline int64_t bound_div(uint64_t p, uint64_t w) {
    const uint32_t high = static_cast<uint32_t>(p >> 31);
    const int s = high == 0 ? 0 : 32 - clz32(high);  // p >> s < 2^31
    const uint32_t ps = static_cast<uint32_t>(p >> s) + (kUp ? 1u : 0u);
    const uint64_t ws64 = (w >> s) + (kUp ? 0u : 1u);
    if (ws64 > 0xFFFFFFFFu) return kUp ? 1 : 0;  // p / w < 1/2
    const uint32_t ws = static_cast<uint32_t>(ws64);
    if (ws == 0) return int64_t{1} << 32;
    const uint32_t q = ps / ws;
    return kUp && q * ws != ps ? int64_t{q} + 1 : int64_t{q};
}

/// A value at most num / (256 w) (kUp false) or at least it (kUp true), for any num and 0 < w < 2^63:
/// num / 256 lies in [t, t + 1) with t = floor(num / 256), and bound_div() bounds t / w from below or
/// (t + 1) / w from above. A quotient past 2^31 may come back as +-2^32, which the callers clamp to the
/// coordinate limit like the quotient itself, so the pixel rectangle built from them is never too small.
template <bool kUp>
inline int64_t bound_over_256w(int64_t num, int64_t w) {
    const int64_t t = (num >> 8) + (kUp ? 1 : 0);
    const uint64_t uw = static_cast<uint64_t>(w);
    return t >= 0 ? bound_div<kUp>(static_cast<uint64_t>(t), uw) : -bound_div<!kUp>(static_cast<uint64_t>(-t), uw);
}

/// Where a subtree's box lies against a band: outside it (skip), reaching the near plane (its projection
/// is unbounded), or in front of the eye with a pixel rectangle computed on request.
struct SubtreeBox {
    int64_t cx, cy, cw;  ///< the box centre in view space (w = -z, towards the scene)
    int64_t ex, ey, ew;  ///< its half extents in view space, rounded up
    bool outside;        ///< no point of the box projects into the band (or the box is out of depth range)
    bool near;           ///< the box reaches the near plane: treat it as covering the whole band
    bool inside;         ///< every point of the box lies in the depth range and projects into the band (if asked)
};

/// What subtree_box() needs of a view and a band, prepared once per walk: |R| of the view's rotation
/// (for the boxes' half extents) and the coefficients of the four planes through the eye and the band's
/// edges, each widened by a pixel. Borrows `view`.
struct BoxBand {
    BoxBand(const View& v, const BandBounds& bb)
        : view(v),
          k(v.k_q8),
          k_abs(abs_value(v.k_q8)),
          x_lo(256 * (bb.x_first - kSubpixel)),
          x_hi(256 * (bb.x_last + kSubpixel)),
          y_lo(256 * (bb.y_first - kSubpixel)),
          y_hi(256 * (bb.y_last + kSubpixel)),
          x_lo_abs(abs_value(x_lo)),
          x_hi_abs(abs_value(x_hi)),
          y_lo_abs(abs_value(y_lo)),
          y_hi_abs(abs_value(y_hi)) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) rot_abs[i][j] = abs_value(v.to_view.rot.m[i][j].raw());
    }
    const View& view;
    int32_t rot_abs[3][3];            ///< |R|, Q30
    int32_t k, k_abs;                 ///< view.k_q8 and its magnitude
    int32_t x_lo, x_hi, y_lo, y_hi;  ///< 256 times the band's edges in subpixels, a pixel outwards
    int32_t x_lo_abs, x_hi_abs, y_lo_abs, y_hi_abs;
};

/// Half extent ((|r| . e) >> 30) + 2 of a box along the view axis of row |r| of |R| (the view
/// transform's own flooring included). With |r_k| < 2^31 and |e_k| < 2^27 (int16 boxes) its magnitude
/// stays below 3 2^28 + 2.
__attribute__((always_inline)) inline int32_t box_extent(const int32_t (&r)[3], const int32_t (&e)[3]) {
    return static_cast<int32_t>((mul32(r[0], e[0]) + mul32(r[1], e[1]) + mul32(r[2], e[2])) >> 30) + 2;
}

/// Node n's subtree box against the band, with no division: the box is rotated into view space as a
/// centre and half extents (|R| e), then tested against the depth range and the four planes through
/// the eye and the band's edges (a point projects left of column x when x k - 256 X w < 0, and so on),
/// each widened by a pixel so that rounded vertex positions stay inside. kInside: also whether the whole
/// box lies inside (SubtreeBox::inside; else it stays false).
template <bool kInside = false>
inline SubtreeBox subtree_box(const BoxBand& t, const BspNode& n) {
    const View& view = t.view;
    SubtreeBox b{};
    // The centre and half extents in raw Q16: (min + max) 2^11 and (max - min) 2^11, below 2^28 and 2^27.
    constexpr int32_t kHalfUnit = int32_t{1} << (kBspBoxShift - 1);
    const int32_t c[3] = {(n.box_min[0] + n.box_max[0]) * kHalfUnit, (n.box_min[1] + n.box_max[1]) * kHalfUnit,
                          (n.box_min[2] + n.box_max[2]) * kHalfUnit};
    const int32_t e[3] = {(n.box_max[0] - n.box_min[0]) * kHalfUnit, (n.box_max[1] - n.box_min[1]) * kHalfUnit,
                          (n.box_max[2] - n.box_min[2]) * kHalfUnit};
    const Vec3q16 cv = apply_inline(view.to_view, {Q16::from_raw(c[0]), Q16::from_raw(c[1]), Q16::from_raw(c[2])});
    const int32_t cx = cv.x.raw(), cy = cv.y.raw(), cz = cv.z.raw();
    const int32_t ex = box_extent(t.rot_abs[0], e), ey = box_extent(t.rot_abs[1], e), ew = box_extent(t.rot_abs[2], e);
    b.cx = cx;
    b.cy = cy;
    b.cw = -int64_t{cz};
    b.ex = ex;
    b.ey = ey;
    b.ew = ew;
    if (b.cw + b.ew < view.near_raw || b.cw - b.ew > view.far_raw) {  // wholly out of depth range
        b.outside = true;
        return b;
    }
    if (b.cw - b.ew <= view.near_raw) {
        b.near = true;
        return b;
    }
    // X = x k / (256 w), Y = -y k / (256 w) in centre-relative subpixels; w > 0 over the whole box. Each
    // plane's linear form a v + c w is largest over the box at a cv + c cw + |a| ev + |c| ew and least at
    // a cv + c cw - |a| ev - |c| ew: 32x32-bit products (each below 2^61). A centre at w = 2^31, outside
    // int32, keeps the box (never wrongly skipped, never taken as wholly inside); the extents always fit.
    if (cz == INT32_MIN) return b;
    const int32_t cw = -cz;
    // The forms' terms at the centre (a v with a = +-k; c w with c = -x_lo, x_hi, -y_lo, y_hi) and spreads.
    const int64_t kx = mul32(t.k, cx), ky = mul32(t.k, cy);
    const int64_t kx_spread = mul32(t.k_abs, ex), ky_spread = mul32(t.k_abs, ey);
    const int64_t left = mul32(t.x_lo, cw), right = mul32(t.x_hi, cw);
    const int64_t top = mul32(t.y_lo, cw), bottom = mul32(t.y_hi, cw);
    const int64_t left_spread = kx_spread + mul32(t.x_lo_abs, ew), right_spread = kx_spread + mul32(t.x_hi_abs, ew);
    const int64_t top_spread = ky_spread + mul32(t.y_lo_abs, ew), bottom_spread = ky_spread + mul32(t.y_hi_abs, ew);
    b.outside = kx - left + left_spread < 0 ||        // left of the first column: x k < 256 x_lo w
                right - kx + right_spread < 0 ||      // right of the last: x k > 256 x_hi w
                -ky - top + top_spread < 0 ||         // above the first row: -y k < 256 y_lo w
                ky + bottom + bottom_spread < 0;      // below the last: -y k > 256 y_hi w
    if constexpr (kInside) {
        b.inside = !b.outside && b.cw + b.ew <= view.far_raw && kx - left - left_spread >= 0 &&
                   right - kx - right_spread >= 0 && -ky - top - top_spread >= 0 && ky + bottom - bottom_spread >= 0;
    }
    return b;
}

/// subtree_box() for one node (a walk prepares its BoxBand once).
template <bool kInside = false>
inline SubtreeBox subtree_box(const View& view, const BspNode& n, const BandBounds& bb) {
    return subtree_box<kInside>(BoxBand(view, bb), n);
}

/// The pixels of rows [band_y0, band_y1) that a box subtree_box() did not reject can cover: the whole
/// band when it reaches the near plane, else x/w and y/w bounded at the box's nearest and farthest w.
inline PixelRect subtree_rect(const View& view, const SubtreeBox& b, const BandBounds& bb, int32_t band_y0, int32_t band_y1) {
    if (b.near) return {0, (bb.x_last - bb.x_first) / kSubpixel + 1, band_y0, band_y1};
    const int64_t w_near = b.cw - b.ew, w_far = b.cw + b.ew;
    const int64_t xl = b.cx - b.ex, xh = b.cx + b.ex, yl = b.cy - b.ey, yh = b.cy + b.ey;
    const int64_t k = view.k_q8;
    // Extremes at the nearest or farthest w by the coordinate's sign, bounded outwards.
    auto lo_over = [&](int64_t v) { return bound_over_256w<false>(v * k, v >= 0 ? w_far : w_near); };
    auto hi_over = [&](int64_t v) { return bound_over_256w<true>(v * k, v >= 0 ? w_near : w_far); };
    ScreenBox box{static_cast<int32_t>(clamp<int64_t>(lo_over(xl) - 1, -kCoordLimit, kCoordLimit)),
                  static_cast<int32_t>(clamp<int64_t>(hi_over(xh) + 1, -kCoordLimit, kCoordLimit)),
                  static_cast<int32_t>(clamp<int64_t>(-hi_over(yh) - 1, -kCoordLimit, kCoordLimit)),
                  static_cast<int32_t>(clamp<int64_t>(-lo_over(yl) + 1, -kCoordLimit, kCoordLimit))};
    return pixel_rect(box, bb, band_y0, band_y1);
}

/// The unit normal of a triangle of node n, along n or (back) against it, for headlight shading.
constexpr Normal14 node_normal(const BspNode& n, bool back) {
    return {static_cast<int16_t>(back ? -n.normal[0] : n.normal[0]), static_cast<int16_t>(back ? -n.normal[1] : n.normal[1]),
            static_cast<int16_t>(back ? -n.normal[2] : n.normal[2])};
}

/// Sets up one triangle (or clipped piece) of a node and paints its rows of the band: every pixel, or with
/// kCoverage only those `cov` does not hold yet (a piece whose box is covered is not set up). Flat colours
/// are set up without a depth plane. Counts the triangle drawn, its fragments and the pixels written.
template <bool kCoverage, class Format, class Depth>
__attribute__((always_inline)) inline void draw_node_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                                              const BspNode& n, bool back, bool front, uint32_t face,
                                                              const FrameView<Format, Depth>& frame, const BandBounds& bb,
                                                              const DrawOptions& opt, const FaceShading& shading, Coverage* cov,
                                                              FrameStats& st) {
    if constexpr (kCoverage) {  // hidden behind what is drawn: no set-up
        if (cov->covered(pixel_rect(screen_box(a, b, c), bb, frame.y0, frame.y1))) return;
    }
    TriangleRaster tr;
    const int32_t area = TriangleRaster::signed_area(a, b, c);
    if (area == 0) return;
    if (!(opt.shade != Shade::depth ? tr.setup_flat(a, b, c, area, frame.width, frame.height, bb)
                                    : tr.setup(a, b, c, area, frame.width, frame.height, bb)))
        return;
    const int32_t y0 = max(frame.y0, tr.first_row()), y1 = min(frame.y1, tr.end_row());
    if (y0 >= y1) return;
    ++st.triangles_drawn;
    const Normal14 normal = node_normal(n, back);
    if constexpr (kCoverage) {
        uint32_t written = 0;
        st.fragments += with_face_shader<Format>(opt, shading, face, normal, front, [&](const auto& shader) {
            return paint_rows_uncovered(tr, y0, y1, frame, shader, *cov, written);
        });
        st.pixels_written += written;
    } else {
        const uint32_t fragments = with_face_shader<Format>(opt, shading, face, normal, front,
                                                            [&](const auto& shader) { return paint_rows(tr, y0, y1, frame, shader); });
        st.fragments += fragments;
        st.pixels_written += fragments;
    }
}

/// The shared walk. kFrontToBack: near subtree first, coverage, skipping covered subtrees and stopping
/// when the band is full; else far subtree first, painting over.
template <bool kFrontToBack, class Format, class Depth>
FrameStats walk_bsp(const View& view, const Vec3q16& eye, const BspTree& tree, Span<ScreenVertex> verts,
                    const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> stack, Coverage* cov) {
    FrameStats st;
    if (!frame_matches(view, frame) || verts.size() < tree.vertices.size() ||
        stack.size() < bsp_stack_entries(tree.max_depth)) {
        st.status = Status::invalid_argument;
        return st;
    }
    if (tree.nodes.empty()) return st;
    // A node whose first subtree is being drawn waits in the stack (one entry per level at most) for its
    // triangles and then its other subtree, with kFront when the eye is on its front side and kPlane when
    // the eye is in its plane (so the side is computed once; bsp_load() keeps indices below 2^30).
    constexpr uint32_t kFront = 0x80000000u, kPlane = 0x40000000u, kIndex = kPlane - 1;
    const FaceShading shading(view, opt);
    const BandBounds bb = band_bounds(frame);
    const BoxBand box_band(view, bb);
    const VertexProjector project(view);
    const BspFaces faces = bsp_walk_faces(view, eye, tree, opt, stack);
    size_t top = 0;
    uint32_t next = 0;  // the node to enter, or kBspNone: resume the top of the stack
    for (;;) {
        if constexpr (kFrontToBack) {
            if (cov->full()) break;
        }
        uint32_t entry;
        if (next != kBspNone) {  // enter the node: its first subtree now, its triangles and other subtree later
            const BspNode& n = tree.nodes[next];
            ++st.nodes_visited;
            const SubtreeBox box = subtree_box(box_band, n);
            bool skip = box.outside;
            if constexpr (kFrontToBack) {
                if (!skip) {
                    const PixelRect r = subtree_rect(view, box, bb, frame.y0, frame.y1);
                    skip = r.x0 >= r.x1 || r.y0 >= r.y1 || cov->covered(r);
                }
            }
            if (skip) {
                ++st.subtrees_skipped;
                next = kBspNone;
                continue;
            }
            const int side = eye_side(tree, n, eye);
            entry = next | (side > 0 ? kFront : 0) | (side == 0 ? kPlane : 0);
            const uint32_t near = n.child[side >= 0 ? 0 : 1], far = n.child[side >= 0 ? 1 : 0];
            const uint32_t first = kFrontToBack ? near : far, last = kFrontToBack ? far : near;
            if (first != kBspNone) {
                // The eye in the plane sees every triangle of it edge-on: nothing to draw.
                if ((side != 0 && n.count != 0) || last != kBspNone) stack[top++] = entry;
                next = first;
                continue;
            }
        } else {
            if (top == 0) break;
            entry = stack[--top];
        }
        const BspNode& n = tree.nodes[entry & kIndex];
        const bool eye_front = (entry & kFront) != 0;
        if ((entry & kPlane) == 0) {
            for (uint32_t t = n.first; t < n.first + n.count; ++t) {
                const BspTriangle& tri = tree.triangles[t];
                const bool back = (tri.face & kBspFaceBack) != 0;
                const bool front = eye_front != back;  // the eye is on the triangle's own front side
                if (!bsp_draws(faces, front)) {  // culled, or hidden by the closed surface
                    ++st.triangles_culled;
                    continue;
                }
                const uint32_t face = tri.face & kBspFaceMask;
                for (uint32_t v : tri.v)
                    if (unprojected(verts[v])) project(tree.vertices[v], verts[v]);
                for_each_clipped(view, tree.vertices, Span<const ScreenVertex>{verts.data(), verts.size()}, tri.v[0], tri.v[1], tri.v[2], st,
                                 [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
                                     draw_node_triangle<kFrontToBack>(a, b, c, n, back, front, face, frame, bb, opt, shading, cov, st);
                                 });
            }
        }
        const bool side_front = (entry & (kFront | kPlane)) != 0;  // side >= 0
        next = n.child[side_front == kFrontToBack ? 1 : 0];  // the far subtree front to back, else the near one
    }
    return st;
}

}  // namespace detail

/// How far (raw Q16, per axis) the view transform may put the walk's eye from the view's origin: the
/// roundings of apply_inverse() and compose() move it by a few tens of raw units at most.
constexpr int32_t kBspEyeSlackRaw = 256;

/// The checks every BSP walk makes of its view and eye before it starts (out of line, once a call):
/// check_view_range() for the cube of kBspWorldLimitRaw, which holds every vertex and node box of a
/// loaded tree (out_of_range where a model transform carries it so far that view coordinates could
/// wrap: a margin beyond the tree itself), and that the view transform takes `eye` to the view's origin
/// within kBspEyeSlackRaw, exactly in 64 bits (invalid_argument otherwise: the world eye under a model
/// transform, or an apply_inverse() that wrapped, would order the tree from the wrong side).
__attribute__((noinline)) inline Status check_bsp_view(const View& view, const Vec3q16& eye) {
    const Status s = check_view_range(view.to_view, kBspWorldLimitBits);
    if (s != Status::ok) return s;
    const Vec3i64 at = apply_wide(view.to_view, eye);
    const int64_t c[3] = {at.x, at.y, at.z};
    for (const int64_t e : c)
        if (e < -kBspEyeSlackRaw || e > kBspEyeSlackRaw) return Status::invalid_argument;
    return Status::ok;
}

/// Draws `tree` back to front into the band (the caller cleared it); `eye` is the camera's eye in the
/// tree's coordinates: as make_view took it, or with a model transform (view = with_model(v, model))
/// apply_inverse(model, eye), since the side tests compare it with the tree's planes (check_bsp_view()
/// refuses an eye the view does not put at its origin, such as the world eye under a turned model). `verts` (one per tree vertex) holds the vertices projected
/// for the same view: either all of them by project_vertices() (needed for Shade::depth's range), or,
/// marked once per frame by mark_unprojected(), each projected here when a triangle first needs it (a
/// walk that skips most of the tree projects only what it draws). `stack` holds
/// bsp_stack_entries(tree.max_depth) entries.
/// Returns check_bsp_view()'s errors (nothing drawn), then invalid_argument for an unusable frame, too
/// few vertices or too small a stack. Counts nodes visited and subtrees skipped.
template <class Format, class Depth>
FrameStats draw_bsp(const View& view, const Vec3q16& eye, const BspTree& tree, Span<ScreenVertex> verts,
                    const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> stack) {
    FrameStats st;  // checked here, not in the walk, whose loop then keeps its registers
    st.status = check_bsp_view(view, eye);
    if (st.status != Status::ok) return st;
    return detail::walk_bsp<false>(view, eye, tree, verts, frame, opt, stack, nullptr);
}

/// draw_bsp() front to back: each pixel of the band is written at most once, covered subtrees are
/// skipped unseen and the walk stops when the band is full. `coverage`: rows * coverage_words(width).
template <class Format, class Depth>
FrameStats draw_bsp_front(const View& view, const Vec3q16& eye, const BspTree& tree, Span<ScreenVertex> verts,
                          const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> stack,
                          Span<uint32_t> coverage) {
    FrameStats st;
    st.status = check_bsp_view(view, eye);  // as draw_bsp()
    if (st.status != Status::ok) return st;
    Coverage cov;
    if (!cov.reset(coverage, frame.width, frame.y0, frame.y1)) {
        st.status = Status::invalid_argument;
        return st;
    }
    return detail::walk_bsp<true>(view, eye, tree, verts, frame, opt, stack, &cov);
}

}  // namespace hider

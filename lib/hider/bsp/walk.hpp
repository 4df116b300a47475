// Drawing a BSP tree (load.hpp) without recursion and without a depth buffer (Fuchs, Kedem & Naylor 1980).
// At each node the eye's side of the plane decides the order: back to front draws the far subtree, the
// node's triangles, then the near subtree, painting every pixel; front to back draws them the other way
// round with the coverage bits of raster/coverage.hpp, writes each pixel once, skips a subtree whose
// screen box is outside the band or already covered (Doom's R_CheckBBox), and stops when the band is
// full. Triangles in a node's plane are skipped when the eye is in that plane (edge-on), and back faces
// fall out of the same side test. The walk keeps its pending work in a caller stack of
// bsp_stack_entries(depth) uint32 entries.
#pragma once
#include <hider/bsp/load.hpp>
#include <hider/int128.hpp>
#include <hider/raster/paint.hpp>

namespace hider {

namespace detail {

/// The eye's side of node n's plane: +1 front (the normal's side), -1 back, 0 in the plane. Exact.
inline int eye_side(const BspTree& tree, const BspNode& n, const Vec3q16& eye) {
    const Vec3q16& o = tree.vertices[n.origin];
    const Int128 s = mul128(n.n[0], int64_t{eye.x.raw()} - o.x.raw()) + mul128(n.n[1], int64_t{eye.y.raw()} - o.y.raw()) +
                     mul128(n.n[2], int64_t{eye.z.raw()} - o.z.raw());
    return s.sign();
}

/// floor(a / b) and ceil(a / b) for b > 0 (int64).
inline int64_t floor_div64(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
inline int64_t ceil_div64(int64_t a, int64_t b) { return -floor_div64(-a, b); }

/// The pixels of rows [band_y0, band_y1) that node n's subtree box can cover: empty when the box lies
/// behind the near plane, past the far plane or beside the band; the whole band when the box reaches
/// the near plane (its projection is then unbounded). The box is rotated into view space as a centre and
/// half extents (|R| e), then x/w and y/w are bounded at the box's nearest and farthest w.
inline PixelRect subtree_rect(const View& view, const BspNode& n, const BandBounds& bb, int32_t band_y0, int32_t band_y1) {
    const PixelRect band{0, (bb.x_last - bb.x_first) / kSubpixel + 1, band_y0, band_y1};
    int32_t c[3], e[3];
    for (int k = 0; k < 3; ++k) {
        const int32_t lo = n.box_min[k] * (int32_t{1} << kBspBoxShift), hi = n.box_max[k] * (int32_t{1} << kBspBoxShift);
        c[k] = lo + (hi - lo) / 2;
        e[k] = hi - c[k];
    }
    const Vec3q16 cv = apply(view.to_view, {Q16::from_raw(c[0]), Q16::from_raw(c[1]), Q16::from_raw(c[2])});
    int64_t ev[3];
    for (int i = 0; i < 3; ++i) {
        int64_t sum = 0;
        for (int k = 0; k < 3; ++k) sum += int64_t{abs_value(view.to_view.rot.m[i][k].raw())} * e[k];
        ev[i] = (sum >> 30) + 2;  // rounded up, plus the view transform's own flooring
    }
    const int64_t w_near = -int64_t{cv.z.raw()} - ev[2], w_far = -int64_t{cv.z.raw()} + ev[2];
    if (w_far < view.near_raw || w_near > view.far_raw) return {0, 0, 0, 0};  // wholly out of depth range
    if (w_near <= view.near_raw) return band;  // reaches the near plane: no bound
    const int64_t xl = cv.x.raw() - ev[0], xh = cv.x.raw() + ev[0], yl = cv.y.raw() - ev[1], yh = cv.y.raw() + ev[1];
    const int64_t k = view.k_q8;
    // X = x k / (256 w), Y = -y k / (256 w): extremes at the nearest or farthest w by the coordinate's sign.
    auto lo_over = [&](int64_t v) { return floor_div64(v * k, 256 * (v >= 0 ? w_far : w_near)); };
    auto hi_over = [&](int64_t v) { return ceil_div64(v * k, 256 * (v >= 0 ? w_near : w_far)); };
    ScreenBox box{static_cast<int32_t>(clamp<int64_t>(lo_over(xl) - 1, -kCoordLimit, kCoordLimit)),
                  static_cast<int32_t>(clamp<int64_t>(hi_over(xh) + 1, -kCoordLimit, kCoordLimit)),
                  static_cast<int32_t>(clamp<int64_t>(-hi_over(yh) - 1, -kCoordLimit, kCoordLimit)),
                  static_cast<int32_t>(clamp<int64_t>(-lo_over(yl) + 1, -kCoordLimit, kCoordLimit))};
    return pixel_rect(box, bb, band_y0, band_y1);
}

/// The shared walk. kFrontToBack: near subtree first, coverage, skipping covered subtrees and stopping
/// when the band is full; else far subtree first, painting over.
template <bool kFrontToBack, class Format, class Depth>
FrameStats walk_bsp(const View& view, const Vec3q16& eye, const BspTree& tree, Span<const ScreenVertex> verts,
                    const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> stack, Coverage* cov) {
    FrameStats st;
    if (!frame_matches(view, frame) || verts.size() < tree.vertices.size() ||
        stack.size() < bsp_stack_entries(tree.max_depth)) {
        st.status = Status::invalid_argument;
        return st;
    }
    if (tree.nodes.empty()) return st;
    constexpr uint32_t kDraw = 0x80000000u;  // stack entry: draw this node's triangles (its subtrees are queued)
    const FaceShading shading(view, opt);
    const BandBounds bb = band_bounds(frame);
    size_t top = 0;
    stack[top++] = 0;
    while (top != 0) {
        if constexpr (kFrontToBack) {
            if (cov->full()) break;
        }
        const uint32_t entry = stack[--top];
        const BspNode& n = tree.nodes[entry & ~kDraw];
        if ((entry & kDraw) == 0) {  // enter the node: queue its subtrees around its own triangles
            ++st.nodes_visited;
            const PixelRect r = subtree_rect(view, n, bb, frame.y0, frame.y1);
            bool skip = r.x0 >= r.x1 || r.y0 >= r.y1;
            if constexpr (kFrontToBack) skip = skip || cov->covered(r);
            if (skip) {
                ++st.subtrees_skipped;
                continue;
            }
            const int side = eye_side(tree, n, eye);
            const uint32_t near = n.child[side >= 0 ? 0 : 1], far = n.child[side >= 0 ? 1 : 0];
            const uint32_t first = kFrontToBack ? far : near, then = kFrontToBack ? near : far;  // then is drawn first
            if (first != kBspNone) stack[top++] = first;
            stack[top++] = entry | kDraw;
            if (then != kBspNone) stack[top++] = then;
            continue;
        }
        const int side = eye_side(tree, n, eye);
        if (side == 0) continue;  // the eye is in the plane: every triangle of it is seen edge-on
        for (uint32_t t = n.first; t < n.first + n.count; ++t) {
            const BspTriangle& tri = tree.triangles[t];
            const bool back = (tri.face & kBspFaceBack) != 0;
            const bool front = (side > 0) != back;  // the eye is on the triangle's own front side
            if (opt.cull && !front) continue;
            const Normal14 normal{static_cast<int16_t>(back ? -n.normal[0] : n.normal[0]),
                                  static_cast<int16_t>(back ? -n.normal[1] : n.normal[1]),
                                  static_cast<int16_t>(back ? -n.normal[2] : n.normal[2])};
            const uint32_t face = tri.face & kBspFaceMask;
            for_each_clipped(view, tree.vertices, verts, tri.v[0], tri.v[1], tri.v[2], st,
                             [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
                                 TriangleRaster tr;
                                 const int32_t area = TriangleRaster::signed_area(a, b, c);
                                 if (area == 0 || !tr.setup(a, b, c, area, frame.width, frame.height, bb)) return;
                                 const int32_t y0 = max(frame.y0, tr.first_row()), y1 = min(frame.y1, tr.end_row());
                                 if (y0 >= y1) return;
                                 ++st.triangles_drawn;
                                 uint32_t written = 0;
                                 const uint32_t fragments = with_face_shader<Format>(
                                     opt, shading, face, normal, front, [&](const auto& shader) {
                                         if constexpr (kFrontToBack) return paint_rows_uncovered(tr, y0, y1, frame, shader, *cov, written);
                                         else return written = paint_rows(tr, y0, y1, frame, shader);
                                     });
                                 st.fragments += fragments;
                                 st.pixels_written += written;
                             });
        }
    }
    return st;
}

}  // namespace detail

/// Draws `tree` back to front into the band (the caller cleared it and projected tree.vertices into
/// `verts` with project_vertices() for the same view); `eye` is the camera's eye (world, as make_view
/// took it). `stack` holds bsp_stack_entries(tree.max_depth) entries. Returns invalid_argument for an
/// unusable frame, too few vertices or too small a stack. Counts nodes visited and subtrees skipped.
template <class Format, class Depth>
FrameStats draw_bsp(const View& view, const Vec3q16& eye, const BspTree& tree, Span<const ScreenVertex> verts,
                    const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> stack) {
    return detail::walk_bsp<false>(view, eye, tree, verts, frame, opt, stack, nullptr);
}

/// draw_bsp() front to back: each pixel of the band is written at most once, covered subtrees are
/// skipped unseen and the walk stops when the band is full. `coverage`: rows * coverage_words(width).
template <class Format, class Depth>
FrameStats draw_bsp_front(const View& view, const Vec3q16& eye, const BspTree& tree, Span<const ScreenVertex> verts,
                          const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> stack,
                          Span<uint32_t> coverage) {
    Coverage cov;
    if (!cov.reset(coverage, frame.width, frame.y0, frame.y1)) {
        FrameStats st;
        st.status = Status::invalid_argument;
        return st;
    }
    return detail::walk_bsp<true>(view, eye, tree, verts, frame, opt, stack, &cov);
}

}  // namespace hider

// Back to front with one walk per frame: order_bsp() walks the tree once (walk.hpp's order, side tests,
// edge-on and back-face rules) and writes the nodes to draw into a caller list, each with the rows its
// triangles can touch; draw_bsp_list() then paints one band from that list, skipping in two compares the
// nodes that cannot reach it. Together they give draw_bsp()'s bytes in every band, without walking the
// tree (and testing its subtree boxes) once per band. Flat shading is set up with no depth plane.
#pragma once
#include <hider/bsp/walk.hpp>

namespace hider {

/// One node of the back-to-front order, 8 bytes:
///   node   bits 0-28: tree node index; bit 30 (kBspListFront): the eye on the front side of its plane;
///          bit 31 (kBspListNoBack) / bit 29 (kBspListNoFront): draw none of its triangles whose back
///          (front) side the eye is on (culling, or bsp_visible_faces())
///   y0 y1  rows [y0, y1) of the frame its drawn triangles can touch (the whole frame when one of them
///          needs clipping at the near plane or the guard band)
struct BspDrawEntry {
    uint32_t node;
    int16_t y0, y1;
};
static_assert(sizeof(BspDrawEntry) == 8, "BspDrawEntry layout is documented above and in README.md");
constexpr uint32_t kBspListFront = 0x40000000u;
constexpr uint32_t kBspListNoBack = 0x80000000u;
constexpr uint32_t kBspListNoFront = 0x20000000u;
constexpr uint32_t kBspListIndex = kBspListNoFront - 1;

namespace detail {

/// The whole frame of a view as a band.
struct WholeFrame {
    int32_t width, height, y0, y1;
};

/// Projects what node n's triangles drawn with `faces` need and returns the rows [y0, y1) their pixel
/// centres can lie on (not clamped to the frame; empty when there are none); counts the others (culled,
/// hidden) and wholly outside triangles in st.
inline void node_rows(const View& view, const PreparedTransform& to_view, const BspTree& tree, const BspNode& n, bool eye_front,
                      Span<ScreenVertex> verts, BspFaces faces, const BandBounds& bb, int32_t& y0, int32_t& y1,
                      FrameStats& st) {
    y0 = view.height;
    y1 = 0;
    for (uint32_t t = n.first; t < n.first + n.count; ++t) {
        const BspTriangle& tri = tree.triangles[t];
        if (!bsp_draws(faces, eye_front != ((tri.face & kBspFaceBack) != 0))) {  // culled, or hidden
            ++st.triangles_culled;
            continue;
        }
        for (uint32_t v : tri.v)
            if (unprojected(verts[v])) project_vertex(view, to_view, tree.vertices[v], verts[v]);
        const ScreenVertex &a = verts[tri.v[0]], &b = verts[tri.v[1]], &c = verts[tri.v[2]];
        if ((a.outside() & b.outside() & c.outside()) != 0) {
            ++st.triangles_outside;
            continue;
        }
        if ((a.outside() | b.outside() | c.outside()) != 0) {  // clipped: its pieces may reach any row
            y0 = 0;
            y1 = view.height;
            continue;
        }
        // Rows whose centres lie between the lowest and highest vertex (as pixel_rect() counts them); a
        // triangle left or right of the frame is rejected later, by its set-up.
        const int32_t y_min = min<int32_t>(a.y, min<int32_t>(b.y, c.y)), y_max = max<int32_t>(a.y, max<int32_t>(b.y, c.y));
        y0 = min(y0, (y_min - bb.y_origin + kSubpixel - 1) >> kSubpixelBits);
        y1 = max(y1, ((y_max - bb.y_origin) >> kSubpixelBits) + 1);
    }
}

}  // namespace detail

/// Walks `tree` once for the frame of `view` (eye as for draw_bsp()) and writes into `list` (cleared
/// first) the nodes to draw back to front: those with a triangle that is not culled, not wholly outside
/// the view volume and covers a pixel centre's row. `verts` as for draw_bsp(): projected, or marked by
/// mark_unprojected() and projected here as needed (then left for draw_bsp_list()). Subtrees whose box
/// lies outside the frame are skipped. Counts nodes visited, subtrees skipped, triangles culled and
/// wholly outside (once per frame). A full list: capacity_exceeded, the walk goes on and
/// `list.size() + list.dropped()` entries were needed; the list then lacks the nearest nodes.
/// Returns invalid_argument (list empty) for an unusable view, too few vertices or too small a stack,
/// or a tree with more than 2^29 - 1 nodes, after check_bsp_view()'s errors as draw_bsp(). Borrows
/// everything for the call.
inline FrameStats order_bsp(const View& view, const Vec3q16& eye, const BspTree& tree, Span<ScreenVertex> verts,
                            const DrawOptions& opt, Span<uint32_t> stack, BoundedList<BspDrawEntry>& list) {
    FrameStats st;
    list.clear();
    st.status = check_bsp_view(view, eye);  // as draw_bsp()
    if (st.status != Status::ok) return st;
    if (view.width < 1 || view.height < 1 || view.width > kMaxFrameSide || view.height > kMaxFrameSide ||
        verts.size() < tree.vertices.size() ||
        stack.size() < bsp_stack_entries(tree.max_depth) || tree.nodes.size() > kBspListIndex) {
        st.status = Status::invalid_argument;
        return st;
    }
    if (tree.nodes.empty()) return st;
    // Stack entries as in walk_bsp(): a node whose far subtree is being listed waits for its triangles
    // and near subtree, with kBspListFront (the eye on its front side), kPlane (in its plane) and kInside
    // (its box, hence every box below it, lies wholly inside the frame).
    constexpr uint32_t kPlane = kBspListNoFront, kInside = kBspListNoBack;
    const BandBounds bb = band_bounds(detail::WholeFrame{view.width, view.height, 0, view.height});
    const detail::BoxBand box_band(view, bb);
    const PreparedTransform to_view(view.to_view);
    const BspFaces faces = bsp_walk_faces(view, eye, tree, opt, stack);
    const uint32_t rule = faces == BspFaces::front ? kBspListNoBack : faces == BspFaces::back ? kBspListNoFront : 0;
    size_t top = 0;
    uint32_t next = 0, next_inside = 0;  // the node to enter (kBspNone: resume the stack's top) and its kInside
    for (;;) {
        uint32_t entry;
        if (next != kBspNone) {
            const BspNode& n = tree.nodes[next];
            ++st.nodes_visited;
            uint32_t inside = next_inside;
            if (inside == 0) {
                const detail::SubtreeBox box = detail::subtree_box<true>(box_band, n);
                if (box.outside) {
                    ++st.subtrees_skipped;
                    next = kBspNone;
                    continue;
                }
                // A box wholly inside the frame holds its subtrees' boxes (each node's box bounds its subtree), so
                // they are inside too: one box test per path instead of one per node, the same skips.
                if (box.inside) inside = kInside;
            }
            const int side = detail::eye_side(tree, n, eye);
            entry = next | inside | (side > 0 ? kBspListFront : 0) | (side == 0 ? kPlane : 0);
            const uint32_t near = n.child[side >= 0 ? 0 : 1], far = n.child[side >= 0 ? 1 : 0];
            next_inside = inside;
            if (far != kBspNone) {  // listed first
                if ((side != 0 && n.count != 0) || near != kBspNone) stack[top++] = entry;  // not edge-on, or more to come
                next = far;
                continue;
            }
        } else {
            if (top == 0) break;
            entry = stack[--top];
        }
        const BspNode& n = tree.nodes[entry & kBspListIndex];
        if ((entry & kPlane) == 0 && n.count != 0) {
            int32_t y0 = 0, y1 = 0;
            detail::node_rows(view, to_view, tree, n, (entry & kBspListFront) != 0, verts, faces, bb, y0, y1, st);
            y0 = max<int32_t>(y0, 0);
            y1 = min(y1, view.height);
            if (y0 < y1 &&
                !list.push_back({(entry & (kBspListIndex | kBspListFront)) | rule, static_cast<int16_t>(y0), static_cast<int16_t>(y1)}))
                st.status = Status::capacity_exceeded;
        }
        next = n.child[(entry & (kBspListFront | kPlane)) != 0 ? 0 : 1];  // the near subtree
        next_inside = entry & kInside;
    }
    return st;
}

namespace detail {

/// What draw_bsp_list() hands to the drawing of each listed node.
template <class Format, class Depth>
struct ListBand {
    const View& view;
    const BspTree& tree;
    Span<const ScreenVertex> verts;
    const FrameView<Format, Depth>& frame;
    const DrawOptions& opt;
    FaceShading shading;
    BandBounds bb;
};

/// Draws the triangles of node n into the band (the eye on its front side when eye_front). Out of line:
/// the list loop around it keeps its few values in registers.
template <class Format, class Depth>
__attribute__((noinline)) void draw_listed_node(const ListBand<Format, Depth>& lb, const BspNode& n, uint32_t entry, FrameStats& st) {
    const bool eye_front = (entry & kBspListFront) != 0;
    for (uint32_t t = n.first; t < n.first + n.count; ++t) {
        const BspTriangle& tri = lb.tree.triangles[t];
        const bool back = (tri.face & kBspFaceBack) != 0;
        const bool front = eye_front != back;  // the eye is on the triangle's own front side
        if ((entry & (front ? kBspListNoFront : kBspListNoBack)) != 0) continue;  // counted by order_bsp()
        const ScreenVertex &va = lb.verts[tri.v[0]], &vb = lb.verts[tri.v[1]], &vc = lb.verts[tri.v[2]];
        if ((va.outside() & vb.outside() & vc.outside()) != 0) continue;  // likewise
        const uint32_t face = tri.face & kBspFaceMask;
        auto draw = [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
            draw_node_triangle<false>(a, b, c, n, back, front, face, lb.frame, lb.bb, lb.opt, lb.shading, nullptr, st);
        };
        if ((va.outside() | vb.outside() | vc.outside()) == 0) draw(va, vb, vc);  // for_each_clipped()'s common case
        else for_each_clipped(lb.view, lb.tree.vertices, lb.verts, tri.v[0], tri.v[1], tri.v[2], st, draw);
    }
}

}  // namespace detail

/// Paints the band from `list` (order_bsp() for the same view, tree, vertices and options; the caller
/// cleared the band; which faces are drawn, culled or hidden, is in the entries, not in opt.cull):
/// draw_bsp()'s pixels and order, and its counts of triangles drawn, fragments and
/// pixels written. Clipped triangles are counted in every band their entry's rows reach (draw_bsp() counts
/// them where its subtree boxes reach: the same on a whole-frame band). Flat colours are set up without a
/// depth plane. On a tree whose node boxes do not nest (hider-bsp's always do; bsp_load() does not check
/// it) the list may keep subtrees that draw_bsp() would skip, never reading out of bounds. Returns
/// invalid_argument for an unusable frame, too few vertices, or an entry naming no node of the tree
/// (drawing stops there).
template <class Format, class Depth>
FrameStats draw_bsp_list(const View& view, const BspTree& tree, Span<const ScreenVertex> verts, Span<const BspDrawEntry> list,
                         const FrameView<Format, Depth>& frame, const DrawOptions& opt) {
    FrameStats st;
    if (!frame_matches(view, frame) || verts.size() < tree.vertices.size()) {
        st.status = Status::invalid_argument;
        return st;
    }
    const detail::ListBand<Format, Depth> lb{view, tree, verts, frame, opt, FaceShading(view, opt), band_bounds(frame)};
    const int32_t band_y0 = frame.y0, band_y1 = frame.y1;
    const size_t nodes = tree.nodes.size();
    for (const BspDrawEntry *e = list.data(), *const end = e + list.size(); e != end; ++e) {
        if (e->y1 <= band_y0 || e->y0 >= band_y1) continue;  // no row in the band
        const uint32_t index = e->node & kBspListIndex;
        if (index >= nodes) {
            st.status = Status::invalid_argument;
            break;
        }
        detail::draw_listed_node(lb, tree.nodes[index], e->node, st);
    }
    return st;
}

}  // namespace hider

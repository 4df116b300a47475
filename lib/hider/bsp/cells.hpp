// Closed surfaces: which faces can be seen from the eye's cell of a tree whose cells hider-bsp labelled
// (BspNode::cells, format.hpp). From a cell of the surface's lowest winding number (outside a solid)
// the nearest surface along any ray is entered through its front, so only front faces can be seen;
// from one of the highest (inside) only back faces. The walks then draw only those: the same pixels as
// drawing both sides, with about half the triangles.
#pragma once
#include <hider/bsp/side.hpp>
#include <hider/screen.hpp>
#include <hider/view.hpp>

namespace hider {

/// Which faces a walk draws: both sides, or only those whose front (back) side the eye is on.
enum class BspFaces : uint8_t { both, front, back };

namespace detail {

/// The label of the eye's cell: front (lowest winding number), back (highest) or both (unlabelled, or
/// the eye in a node's plane). One side test per level (bsp_load(): children only forward, so it ends).
inline BspFaces eye_cell_faces(const BspTree& tree, const Vec3q16& eye) {
    for (uint32_t i = 0;;) {
        const BspNode& n = tree.nodes[i];
        const int side = eye_side(tree, n, eye);
        if (side == 0) return BspFaces::both;
        const int c = side > 0 ? 0 : 1;
        if (n.child[c] != kBspNone) {
            i = n.child[c];
            continue;
        }
        if ((n.cells & (kBspCellLowest << c)) != 0) return BspFaces::front;
        if ((n.cells & (kBspCellHighest << c)) != 0) return BspFaces::back;
        return BspFaces::both;
    }
}

/// At least the distance from the eye to any point before the near plane that a frame pixel's ray
/// crosses, plus kBspCellMarginRaw: such a ray meets the near plane within |x| + |y| <= near (W + H) 8
/// subpixels / k of the view axis (a pixel to spare each way), and the L1 sum bounds the distance.
inline int64_t near_reach(const View& view) {
    const int64_t spread = int64_t{view.width + view.height} * (kSubpixel / 2) + 2 * kSubpixel;
    return view.near_raw + (int64_t{view.near_raw} * spread * 256 + view.k_q8 - 1) / view.k_q8 + kBspCellMarginRaw;
}

/// True when the eye lies more than `reach` from node n's plane: |n.(eye - o)| > 2 max|n_i| reach, as
/// |n| < 2 max|n_i| (bsp_load() keeps |n_i| < 2^62); exact in 128 bits.
inline bool far_from_plane(const BspTree& tree, const BspNode& n, const Vec3q16& eye, int64_t reach) {
    Int128 s = plane_value(tree, n, eye);
    if (s.sign() < 0) s = -s;
    int64_t m = 0;
    for (int64_t c : n.n) m = max(m, c < 0 ? -c : c);
    return (s - mul128(m, 2 * reach)).sign() > 0;
}

/// Whether a tree triangle may lie within `reach` of the eye: its box meets the eye's box and the eye is
/// not farther than `reach` from its node's plane (hider-bsp keeps triangles within a few raw units of
/// it, well inside kBspCellMarginRaw). Subtrees whose box misses the eye's are skipped.
inline bool surface_near(const BspTree& tree, const Vec3q16& eye, int64_t reach, Span<uint32_t> stack) {
    const int64_t e[3] = {eye.x.raw(), eye.y.raw(), eye.z.raw()};
    int64_t lo[3], hi[3];   // the eye's box, raw
    int32_t blo[3], bhi[3];  // and in node box units, rounded outwards
    for (int k = 0; k < 3; ++k) {
        lo[k] = e[k] - reach;
        hi[k] = e[k] + reach;
        blo[k] = static_cast<int32_t>(max<int64_t>(lo[k] >> kBspBoxShift, INT16_MIN));
        bhi[k] = static_cast<int32_t>(min<int64_t>(-((-hi[k]) >> kBspBoxShift), INT16_MAX));
    }
    size_t top = 0;
    stack[top++] = 0;
    while (top != 0) {  // one waiting sibling per level above, plus the two children just pushed: at most depth
        const BspNode& n = tree.nodes[stack[--top]];
        bool meets = true;
        for (int k = 0; k < 3; ++k) meets = meets && n.box_min[k] <= bhi[k] && n.box_max[k] >= blo[k];
        if (!meets) continue;
        if (n.count != 0 && !far_from_plane(tree, n, eye, reach)) {
            for (uint32_t t = n.first; t < n.first + n.count; ++t) {
                bool near = true;
                for (int k = 0; k < 3 && near; ++k) {
                    int32_t tmin = INT32_MAX, tmax = INT32_MIN;
                    for (uint32_t v : tree.triangles[t].v) {
                        const Vec3q16& p = tree.vertices[v];
                        const int32_t c = k == 0 ? p.x.raw() : (k == 1 ? p.y.raw() : p.z.raw());
                        tmin = min(tmin, c);
                        tmax = max(tmax, c);
                    }
                    near = tmin <= hi[k] && tmax >= lo[k];
                }
                if (near) return true;
            }
        }
        for (uint32_t c : n.child)
            if (c != kBspNone) stack[top++] = c;
    }
    return false;
}

}  // namespace detail

/// The faces the eye can see in a tree whose cells hider-bsp labelled: from a cell of the surface's
/// lowest winding number only front faces, from one of the highest only back faces, the same pixels as
/// drawing both. Holds only while no surface lies between the eye and the near plane where a pixel's ray
/// crosses it (the near plane would cut that surface away), so the answer is both when a tree triangle
/// may lie within that reach (plus kBspCellMarginRaw), when the eye lies in a node's plane or in an
/// unlabelled cell, or when `stack` holds fewer than bsp_stack_entries(depth) entries. `view` is
/// make_view()'s for a camera whose eye is `eye`, in the tree's world (no model transform: the reach is
/// measured in the tree's units). Cost: one side test per level down to the eye's cell, then the subtree
/// boxes that meet the eye's box (none when the eye is away from the surface).
inline BspFaces bsp_visible_faces(const View& view, const Vec3q16& eye, const BspTree& tree, Span<uint32_t> stack) {
    if (tree.nodes.empty() || view.k_q8 <= 0 || view.near_raw <= 0 || stack.size() < bsp_stack_entries(tree.max_depth))
        return BspFaces::both;
    const BspFaces faces = detail::eye_cell_faces(tree, eye);
    if (faces == BspFaces::both || detail::surface_near(tree, eye, detail::near_reach(view), stack)) return BspFaces::both;
    return faces;
}

/// Whether a walk drawing `faces` draws a triangle whose own front side the eye is on (`front`).
constexpr bool bsp_draws(BspFaces faces, bool front) { return faces == BspFaces::both || front == (faces == BspFaces::front); }

}  // namespace hider

// Bounding-volume hierarchy over a Mesh in one flat array, built offline (tools/common/bvh_build.*) and
// checked once by validate_bvh(); the walkers then trust it. Nodes are in pre-order: an inner node's
// first child is the next node, its second child is `first`. The walk keeps a caller-sized stack of
// the far children it postpones (near child first, ordered by where the ray enters each box) and skips
// any box the ray enters beyond the nearest hit so far, so a ray costs about O(log n) box tests and a
// few triangle tests. No recursion; the stack needs header.max_depth entries.
#pragma once
#include <hider/mesh.hpp>
#include <hider/ray/triangle.hpp>
#include <hider/status.hpp>

namespace hider::ray {

constexpr uint32_t kBvhMagic = 0x48564248u;  ///< "HBVH" in a little-endian dump
constexpr uint16_t kBvhVersion = 1;

/// One node, 32 bytes:
///   lo[3], hi[3]  raw Q16 box, lo <= hi per axis, holding every triangle below the node
///   first         inner node: index of the second child (the first child is this index + 1)
///                 leaf: index of its first entry in Bvh::triangles
///   count         0 for an inner node; a leaf's number of triangles (entries first .. first + count - 1)
struct BvhNode {
    int32_t lo[3];
    int32_t hi[3];
    uint32_t first;
    uint32_t count;
};
static_assert(sizeof(BvhNode) == 32, "BvhNode is a 32-byte baked record");

/// magic, version, the longest root-to-leaf path in nodes, and the array lengths.
struct BvhHeader {
    uint32_t magic;
    uint16_t version;
    uint16_t max_depth;
    uint32_t node_count;
    uint32_t triangle_count;  ///< entries of Bvh::triangles: exactly the mesh's triangles
};
static_assert(sizeof(BvhHeader) == 16, "BvhHeader is a 16-byte baked record");

/// Borrowed views of a baked hierarchy (const data in flash on a device).
struct Bvh {
    BvhHeader header{};
    Span<const BvhNode> nodes;
    Span<const uint32_t> triangles;  ///< triangle indices of the mesh, leaf by leaf
};

/// A postponed node of a walk (validation keeps the node's depth in `t_enter`).
struct BvhStackEntry {
    uint32_t node;
    int32_t t_enter;
};

namespace detail {
inline bool box_inside(const BvhNode& inner, const BvhNode& outer) {
    for (int i = 0; i < 3; ++i)
        if (inner.lo[i] < outer.lo[i] || inner.hi[i] > outer.hi[i]) return false;
    return true;
}
inline bool point_inside(const Vec3q16& p, const BvhNode& n) {
    const int32_t c[3] = {p.x.raw(), p.y.raw(), p.z.raw()};
    for (int i = 0; i < 3; ++i)
        if (c[i] < n.lo[i] || c[i] > n.hi[i]) return false;
    return true;
}
/// A leaf's entries: indices in range and every vertex inside the leaf's box.
inline bool leaf_valid(const Bvh& bvh, const Mesh& mesh, const BvhNode& n) {
    for (uint32_t k = n.first; k < n.first + n.count; ++k) {
        const uint32_t t = bvh.triangles[k];
        if (t >= mesh.tris.size()) return false;
        for (uint16_t v : mesh.tris[t].v)
            if (v >= mesh.positions.size() || !point_inside(mesh.positions[v], n)) return false;
    }
    return true;
}
}  // namespace detail

/// Checks `bvh` against `mesh` once: magic and version (bad_data), sizes (triangle_arrays_fit() too), the
/// pre-order tree shape, every index, every triangle listed once (by the entries' power sums: a
/// triangle left out could never be hit), boxes nested and holding their triangles, the root inside the world
/// cube (out_of_range), the recorded depth (bad_data if the tree is deeper). capacity_exceeded when stack.size() < max_depth.
/// Cost O(nodes + triangles); uses `stack` as scratch.
inline Status validate_bvh(const Bvh& bvh, const Mesh& mesh, Span<BvhStackEntry> stack) {
    const BvhHeader& h = bvh.header;
    if (h.magic != kBvhMagic || h.version != kBvhVersion || h.node_count == 0 || h.max_depth == 0 ||
        bvh.nodes.size() != h.node_count || bvh.triangles.size() != h.triangle_count || h.triangle_count != mesh.tris.size())
        return Status::bad_data;
    if (stack.size() < h.max_depth) return Status::capacity_exceeded;
    if (!triangle_arrays_fit(mesh)) return Status::bad_data;  // cast_row() reads a normal and an id per hit
    const BvhNode& root = bvh.nodes[0];
    for (int i = 0; i < 3; ++i)
        if (root.lo[i] <= -kRayWorldLimitRaw || root.hi[i] >= kRayWorldLimitRaw) return Status::out_of_range;
    uint32_t next_node = 0, next_entry = 0;
    size_t sp = 0;
    stack[sp++] = {0, 1};
    while (sp > 0) {
        const BvhStackEntry e = stack[--sp];
        if (e.node != next_node || e.t_enter > h.max_depth) return Status::bad_data;  // not pre-order, or too deep
        ++next_node;
        const BvhNode& n = bvh.nodes[e.node];
        for (int i = 0; i < 3; ++i)
            if (n.lo[i] > n.hi[i]) return Status::bad_data;
        if (n.count == 0) {
            const uint32_t c1 = e.node + 1, c2 = n.first;
            if (c2 <= c1 || c2 >= h.node_count) return Status::bad_data;
            if (!detail::box_inside(bvh.nodes[c1], n) || !detail::box_inside(bvh.nodes[c2], n)) return Status::bad_data;
            if (sp + 2 > stack.size()) return Status::bad_data;  // deeper than max_depth allows
            stack[sp++] = {c2, e.t_enter + 1};
            stack[sp++] = {c1, e.t_enter + 1};
        } else {
            if (n.first != next_entry || n.count > h.triangle_count - n.first) return Status::bad_data;
            if (!detail::leaf_valid(bvh, mesh, n)) return Status::bad_data;
            next_entry += n.count;
        }
    }
    if (next_node != h.node_count || next_entry != h.triangle_count) return Status::bad_data;
    // Every triangle listed once: the entries' sums of first, second and third powers equal those of
    // 0 .. T - 1 (modulo 2^64). Damage to three entries or fewer always changes one of them: two
    // different multisets agree on these sums only with four or more elements changed, and below 2^20
    // triangles what three changes move a sum by stays under 2^62, so it cannot vanish modulo 2^64.
    uint64_t d1 = 0, d2 = 0, d3 = 0;
    for (uint32_t k = 0; k < h.triangle_count; ++k) {
        const uint64_t a = bvh.triangles[k], b = k;
        d1 += a - b;
        d2 += a * a - b * b;
        d3 += a * a * a - b * b * b;
    }
    return d1 == 0 && d2 == 0 && d3 == 0 ? Status::ok : Status::bad_data;
}

/// How far the hierarchy's root box reaches from `origin` on any axis (raw): what sets the triangle
/// test's vertex grid for rays from there (triangle_grid_shift()).
inline uint32_t bvh_reach(const Bvh& bvh, const Vec3q16& origin) {
    const BvhNode& root = bvh.nodes[0];
    const int32_t o[3] = {origin.x.raw(), origin.y.raw(), origin.z.raw()};
    uint32_t reach = 0;
    for (int i = 0; i < 3; ++i)
        reach = max(reach, static_cast<uint32_t>(max(abs_value(int64_t{root.lo[i]} - o[i]), abs_value(int64_t{root.hi[i]} - o[i]))));
    return reach;
}

/// bvh_triangle_ray() without the tie rule (complete_triangle_ray()): what the walk's box tests need.
inline TriangleRay bvh_triangle_ray_grid(const Bvh& bvh, const Ray& ray) {
    return triangle_ray_grid(ray, bvh_reach(bvh, ray.origin));
}

/// The triangle test's per-ray constants for rays against this hierarchy: the grid is set by how far
/// the root box reaches from the origin (every walk of the same ray uses the same grid).
inline TriangleRay bvh_triangle_ray(const Bvh& bvh, const Ray& ray) {
    TriangleRay tr = bvh_triangle_ray_grid(bvh, ray);
    complete_triangle_ray(tr);
    return tr;
}

/// What a walk did (for benchmarks and tests).
struct BvhCounters {
    uint32_t boxes = 0;      ///< box tests
    uint32_t triangles = 0;  ///< triangle tests
};

/// One walk's request: the segment t_min < t <= t_max of `ray`, back faces skipped when `cull`, and
/// triangle `skip` ignored (the one a secondary ray leaves; UINT32_MAX for none).
struct BvhQuery {
    Ray ray;
    int32_t t_min;
    int32_t t_max;
    bool cull;
    uint32_t skip;
};

/// Nearest triangle of `mesh` on the query's segment (kAnyHit: the first one found, for shadow rays).
/// Ties in t go to the smaller triangle index, as the z-buffer's first-drawn-wins. Precondition:
/// validate_bvh(bvh, mesh, stack) == ok (the stack is at least max_depth deep) and the ray origin lies in
/// the world cube. Returns whether a triangle was hit; `tri` and `hit` describe it.
template <bool kAnyHit = false>
bool bvh_walk(const Bvh& bvh, const Mesh& mesh, const BvhQuery& q, Span<BvhStackEntry> stack, uint32_t& tri,
              TriangleHit& hit, BvhCounters* counters = nullptr) {
    const BvhNode* nodes = bvh.nodes.data();
    // The boxes are tested along the ray the triangle test sees: its Q18 direction (at grazing angles
    // the rounding moves a hit far along the ray) and its vertex grid (a box reaches one step lower).
    TriangleRay tr = bvh_triangle_ray_grid(bvh, q.ray);
    Ray seen;
    set_ray(seen, q.ray.origin, {Q30::from_raw(tr.d18[0] * 4096), Q30::from_raw(tr.d18[1] * 4096), Q30::from_raw(tr.d18[2] * 4096)});
    BoxRay br = make_box_ray(seen, q.t_max);
    br.grid_slack = (int32_t{1} << tr.shift) - 1;
    int32_t best_t = q.t_max, te = 0;
    uint32_t boxes = 1, tests = 0;
    bool found = false;
    if (!intersect_box(br, nodes[0].lo, nodes[0].hi, q.t_min, best_t, te)) {
        if (counters != nullptr) counters->boxes += boxes;
        return false;
    }
    complete_triangle_ray(tr);
    uint32_t node = 0;
    size_t sp = 0;
    for (;;) {
        const BvhNode& n = nodes[node];
        if (n.count != 0) {
            for (uint32_t k = n.first; k < n.first + n.count; ++k) {
                const uint32_t t = bvh.triangles[k];
                if (t == q.skip) continue;
                const Tri& v = mesh.tris[t];
                TriangleHit th{};
                ++tests;
                if (!intersect_triangle(tr, mesh.positions[v.v[0]], mesh.positions[v.v[1]], mesh.positions[v.v[2]], q.t_min,
                                        best_t, q.cull, th))
                    continue;
                if (found && th.t_q16 == best_t && t > tri) continue;  // tie: the smaller index stays
                found = true;
                best_t = th.t_q16;
                tri = t;
                hit = th;
                if (kAnyHit) break;
            }
            if (kAnyHit && found) break;
        } else {
            const uint32_t c1 = node + 1, c2 = n.first;
            int32_t t1 = 0, t2 = 0;
            const bool h1 = intersect_box(br, nodes[c1].lo, nodes[c1].hi, q.t_min, best_t, t1);
            const bool h2 = intersect_box(br, nodes[c2].lo, nodes[c2].hi, q.t_min, best_t, t2);
            boxes += 2;
            if (h1 && h2) {
                HIDER_ASSERT(sp < stack.size());
                const bool first_near = t1 <= t2;
                stack[sp++] = {first_near ? c2 : c1, first_near ? t2 : t1};
                node = first_near ? c1 : c2;
                continue;
            }
            if (h1 || h2) {
                node = h1 ? c1 : c2;
                continue;
            }
        }
        while (sp > 0 && stack[sp - 1].t_enter > best_t) --sp;  // entered beyond the nearest hit
        if (sp == 0) break;
        node = stack[--sp].node;
    }
    if (counters != nullptr) {
        counters->boxes += boxes;
        counters->triangles += tests;
    }
    return found;
}

}  // namespace hider::ray

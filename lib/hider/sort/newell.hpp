// Newell, Newell & Sancha (1972): start from the painter's order by farthest depth, and for each
// polygon P whose depth range overlaps the next ones run the tests cheapest first (x extents, y
// extents, P behind Q's plane, Q in front of P's plane, projections disjoint). When all fail, move Q
// before P if the swapped tests allow it; a second move of the same Q means a cycle, and that, or
// piercing, is resolved by cutting one polygon by the other's plane (pieces keep the face id).
// The plane tests are exact (128-bit integer), so shared edges and coplanar neighbours never split.
#pragma once
#include <hider/sort/painter.hpp>

namespace hider {

struct NewellStats {
    uint32_t pair_tests = 0;  ///< (P, Q) pairs whose depth ranges overlapped
    uint32_t moves = 0;       ///< Q moved before P
    uint32_t splits = 0;      ///< polygons cut by another's plane
    uint32_t unresolved = 0;  ///< pairs left in painter order because no cut was possible
    uint32_t dropped = 0;     ///< cuts not made because the pool was full
};

namespace detail {
/// Inserts index `idx` into order[from..) keeping that range sorted by zmax, farthest first (stable).
inline void insert_sorted(BoundedList<uint32_t>& order, size_t from, const BoundedList<ScreenPoly>& polys, uint32_t idx) {
    size_t pos = from;
    const uint32_t z = polys[idx].zmax;
    while (pos < order.size() && polys[order[pos]].zmax >= z) ++pos;
    order.insert(pos, idx);  // cannot fail: order has room for every polygon of the pool
}
}  // namespace detail

/// Reorders `order` (a painter order by farthest depth over polys) so that no polygon is drawn after
/// one it lies in front of, cutting polygons into the free capacity of `polys` as needed.
/// Precondition: order.capacity() >= polys.capacity(). When a cut does not fit, the pair keeps its
/// painter order, NewellStats::dropped counts it and the result is capacity_exceeded; the frame still
/// draws. Cost: O(n k) pair tests for k depth-overlapping neighbours; O(n^2) at worst.
inline Status newell_order(BoundedList<ScreenPoly>& polys, BoundedList<uint32_t>& order, NewellStats& ns) {
    if (order.capacity() < polys.capacity()) return Status::invalid_argument;
    Status status = Status::ok;
    // Cuts polys[idx] (now at order[pos]) by plane; pieces go back into order[from..) by depth.
    auto cut = [&](uint32_t idx, size_t pos, size_t from, const ScreenPlane& plane) {
        ScreenPoly pieces[3];
        const int n = split_by_plane(polys[idx], plane, pieces);
        if (n == 0) return false;
        if (polys.size() + static_cast<size_t>(n - 1) > polys.capacity()) {
            ++ns.dropped;
            status = Status::capacity_exceeded;
            return false;
        }
        ++ns.splits;
        order.erase(pos);
        polys[idx] = pieces[0];
        detail::insert_sorted(order, from, polys, idx);
        for (int k = 1; k < n; ++k) {
            polys.push_back(pieces[k]);
            detail::insert_sorted(order, from, polys, static_cast<uint32_t>(polys.size() - 1));
        }
        return true;
    };
    size_t i = 0;
    while (i < order.size()) {
        bool restart = false;
        for (size_t j = i + 1; j < order.size() && !restart; ++j) {
            const uint32_t pi = order[i], qi = order[j];
            const ScreenPoly& p = polys[pi];
            const ScreenPoly& q = polys[qi];
            if (q.zmax <= p.zmin) break;  // order[i+1..) is sorted by zmax: no later depth overlap
            ++ns.pair_tests;
            if (p.xmax <= q.xmin || q.xmax <= p.xmin) continue;  // (1) no shared pixel centre possible
            if (p.ymax <= q.ymin || q.ymax <= p.ymin) continue;  // (2)
            const ScreenPlane qp = plane_of(q), pp = plane_of(p);
            const int p_vs_q = side_of(qp, p), q_vs_p = side_of(pp, q);
            if (p_vs_q > 0) continue;                  // (3) P wholly behind Q's plane
            if (q_vs_p < 0) continue;                  // (4) Q wholly in front of P's plane
            if (projections_disjoint(p, q)) continue;  // (5)
            if ((q_vs_p > 0 || p_vs_q < 0) && (q.flags & kPolyMarked) == 0) {  // (3') or (4'): Q goes first
                for (size_t k = j; k > i; --k) order[k] = order[k - 1];
                order[i] = qi;
                polys[qi].flags |= kPolyMarked;
                ++ns.moves;
                restart = true;
            } else if (cut(pi, i, i, qp) || cut(qi, j, i + 1, pp)) {  // cycle or piercing
                restart = true;
            } else {
                ++ns.unresolved;
            }
        }
        if (!restart) ++i;
    }
    return status;
}

}  // namespace hider

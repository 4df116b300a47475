// Newell, Newell & Sancha (1972): start from the painter's order by farthest depth, and for each
// polygon P whose depth range overlaps the next ones run the tests cheapest first (x extents, y
// extents, P behind Q's plane, Q in front of P's plane, projections disjoint). When all fail, move Q
// before P if the swapped tests allow it. A polygon moved twice to the same output position means a
// cycle of overlaps, broken by cutting P by Q's plane or Q by P's (when neither crosses the other's
// plane the pair stays in painter order and is counted as unresolved). Piercing polygons are cut by
// each other's planes. Pieces keep the face id.
// Plane tests are exact 128-bit sums with a half-grid-step slack for rounded cut vertices (poly.hpp).
#pragma once
#include <hider/sort/painter.hpp>

namespace hider {

struct NewellStats {
    uint32_t pair_tests = 0;  ///< (P, Q) pairs whose depth ranges overlapped
    uint32_t moves = 0;       ///< Q moved before P
    uint32_t splits = 0;      ///< polygons cut by another's plane
    uint32_t cycles = 0;      ///< cycles of overlap found (each broken by a cut when possible)
    uint32_t unresolved = 0;  ///< pairs left in painter order because no cut was possible
    uint32_t dropped = 0;     ///< cuts not made because the pool was full
};

namespace detail {

/// State of one run of newell_order over caller storage.
class Newell {
public:
    Newell(BoundedList<ScreenPoly>& polys, BoundedList<uint32_t>& order, NewellStats& ns)
        : polys_(polys), order_(order), ns_(ns) {}

    Status run() {
        size_t i = 0;
        while (i < order_.size()) {
            if (!step(i)) ++i;  // nothing changed: order[i] is final
        }
        return status_;
    }

private:
    /// Tests the candidate order[i] against the polygons after it; true when the order changed.
    bool step(size_t i) {
        for (size_t j = i + 1; j < order_.size(); ++j) {
            const uint32_t pi = order_[i], qi = order_[j];
            const ScreenPoly& p = polys_[pi];
            const ScreenPoly& q = polys_[qi];
            if (q.zmax <= p.zmin) return false;  // order[i+1..) is sorted by zmax: no later depth overlap
            ++ns_.pair_tests;
            if (p.xmax <= q.xmin || q.xmax <= p.xmin) continue;  // (1) no shared pixel centre possible
            if (p.ymax <= q.ymin || q.ymax <= p.ymin) continue;  // (2)
            const ScreenPlane qp = plane_of(q), pp = plane_of(p);
            const int p_vs_q = side_of(qp, p);
            if (p_vs_q > 0) continue;                  // (3) P wholly behind Q's plane
            const int q_vs_p = side_of(pp, q);
            if (q_vs_p < 0) continue;                  // (4) Q wholly in front of P's plane
            if (projections_disjoint(p, q)) continue;  // (5)
            if (q_vs_p > 0 || p_vs_q < 0) {            // (3') or (4'): Q must be drawn before P
                if (q.moved_at != i) {
                    // Q becomes the candidate; P goes back to its depth position, so order[i+1..)
                    // stays sorted by zmax and the early stop above stays valid.
                    order_.erase(j);
                    order_[i] = qi;
                    insert_sorted(i + 1, pi);
                    polys_[qi].moved_at = static_cast<uint32_t>(i);
                    ++ns_.moves;
                    return true;
                }
                ++ns_.cycles;
                if (cut(i, i, qp) || cut(j, i + 1, pp)) return true;
            } else if (cut(i, i, qp) || cut(j, i + 1, pp)) {  // piercing: both straddle
                return true;
            }
            ++ns_.unresolved;
        }
        return false;
    }

    /// Cuts the polygon at order[pos] by plane; pieces go back into order[from..) by depth.
    bool cut(size_t pos, size_t from, const ScreenPlane& plane) {
        const uint32_t idx = order_[pos];
        ScreenPoly pieces[3];
        const int n = split_by_plane(polys_[idx], plane, pieces);
        if (n == 0) return false;
        if (polys_.size() + static_cast<size_t>(n - 1) > polys_.capacity()) {
            ++ns_.dropped;
            status_ = Status::capacity_exceeded;
            return false;
        }
        ++ns_.splits;
        order_.erase(pos);
        polys_[idx] = pieces[0];
        insert_sorted(from, idx);
        for (int k = 1; k < n; ++k) {
            polys_.push_back(pieces[k]);
            insert_sorted(from, static_cast<uint32_t>(polys_.size() - 1));
        }
        return true;
    }

    /// Inserts idx into order[from..) keeping that range sorted by zmax, farthest first (stable).
    void insert_sorted(size_t from, uint32_t idx) {
        size_t pos = from;
        const uint32_t z = polys_[idx].zmax;
        while (pos < order_.size() && polys_[order_[pos]].zmax >= z) ++pos;
        const bool inserted = order_.insert(pos, idx);  // order.size() <= polys.size() <= capacity
        HIDER_ASSERT(inserted);
        (void)inserted;
    }

    BoundedList<ScreenPoly>& polys_;
    BoundedList<uint32_t>& order_;
    NewellStats& ns_;
    Status status_ = Status::ok;
};

}  // namespace detail

/// Reorders `order` (a painter order by farthest depth over polys) so that no polygon is drawn after
/// one it lies in front of, cutting polygons into the free capacity of `polys` as needed.
/// Preconditions (else invalid_argument): order.capacity() >= polys.capacity(), and order holds at most
/// polys.size() indices, each below polys.size(). When a cut does not
/// fit, the pair keeps its painter order, NewellStats::dropped counts it and the result is
/// capacity_exceeded; the frame still draws. Cost: O(n k) pair tests for k depth-overlapping
/// neighbours, O(n^2) at worst.
inline Status newell_order(BoundedList<ScreenPoly>& polys, BoundedList<uint32_t>& order, NewellStats& ns) {
    if (order.capacity() < polys.capacity() || order.size() > polys.size()) return Status::invalid_argument;
    for (size_t k = 0; k < order.size(); ++k)
        if (order[k] >= polys.size()) return Status::invalid_argument;
    return detail::Newell(polys, order, ns).run();
}

}  // namespace hider

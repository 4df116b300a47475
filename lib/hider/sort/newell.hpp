// Newell, Newell & Sancha (1972). Polygons leave farthest first (largest zmax): from the depth-sorted input,
// or from a heap for the polygons that wait again (moved back, or pieces of a cut): newell_queue.hpp. The
// candidate P is compared with every waiting Q whose screen box can overlap its own (a grid, grid.hpp) and
// whose depth range overlaps, cheapest test first: boxes, P behind Q's plane, Q in front of P's plane,
// projections disjoint. When all fail and Q must come first, Q becomes the candidate and P waits again; a Q
// moved twice in one chain of moves means a cycle, cut by the plane between them. Polygons that pierce each
// other are cut along their intersection when first compared, both of them. A cut makes two pieces that keep
// their parent's exact edges (cut.hpp, raster/piece.hpp: no cracks), and each piece remembers the plane that
// cut it and its side of it, so no pair is cut twice. A cycle no cut breaks is ordered by the pixel centres
// its pairs share (pixel_order.hpp): its closing pair stays as found when they agree, else the cycle is
// broken at a pair of it they allow. Work is bounded: the caller's pools bound the pieces, a budget the pair
// tests. Plane tests are exact 128-bit sums with a slack for the rounding of cut points; polygons of one face
// (NewellOptions) are never ordered against each other.
#pragma once
#include <hider/sort/cut.hpp>
#include <hider/sort/grid.hpp>
#include <hider/sort/newell_queue.hpp>
#include <hider/sort/newell_types.hpp>
#include <hider/sort/piece_box.hpp>
#include <hider/sort/pixel_order.hpp>

namespace hider {

namespace detail {

/// One run of newell_order over caller storage; candidates come from the queue it extends.
class Newell : private NewellQueue {
public:
    Newell(BoundedList<ScreenPoly>& polys, BoundedList<PieceCut>& cuts, const NewellScratch& s, BoundedList<uint32_t>& order,
           NewellStats& ns, uint64_t budget, Span<const uint32_t> faces, int32_t width, int32_t height)
        : NewellQueue(polys, s), cuts_(cuts), order_(order), ns_(ns), budget_(budget), faces_(faces), width_(width),
          height_(height) {}

    Status run(const ScreenGrid& grid_setup) {
        grid_ = grid_setup;
        const Span<const SortKey> sorted = start();
        for (size_t i = sorted.size(); i-- > 0;)  // nearest first: each goes to its cell's head
            grid_.insert(sorted[i].index, polys_[sorted[i].index], polys_.data());
        uint32_t cur = kNone;
        for (;;) {
            if (cur == kNone && (cur = next()) == kNone) break;
            if (ns_.budget_exhausted) {
                finish(cur);
                cur = kNone;
                continue;
            }
            cur = step(cur);
        }
        return status_;
    }

private:
    /// One polygon to cut in two.
    struct Cut {
        uint32_t id = kNone;
        ScreenPoly far, near;
        PieceCut far_cut, near_cut;
        bool inexact = false;  ///< CutResult::cut_inexact
    };

    /// The candidate, with its outline and plane computed when a first pair needs them.
    struct Candidate {
        ScreenPoly poly;
        Outline outline;
        ScreenPlane plane;
        bool ready;
    };

    /// What comparing the candidate with the waiting polygons decided.
    struct Action {
        enum Kind : uint8_t { none, move, cut, restart } kind = none;
        uint32_t q = kNone;  ///< move, restart: the polygon that becomes the candidate
        Cut cuts[2];
        int count = 0;  ///< cut: how many of cuts[] to make
    };

    /// Examines candidate cur; returns the next candidate (kNone: take the next from the heap).
    uint32_t step(uint32_t cur) {
        if (chain_len_ == 0) s_.chain[chain_len_++] = cur;
        const ScreenPoly p = polys_[cur];
        Candidate cand;  // its outline and plane once a pair needs them (no clearing: they are written first)
        cand.poly = p;
        cand.ready = false;
        Action act;
        grid_.query(p, polys_.data(), [&](uint32_t qi) { return qi != cur && compare(cur, cand, qi, act); });
        switch (act.kind) {
            case Action::none:
                finish(cur);
                return kNone;
            case Action::move:  // Q becomes the candidate; P waits again at its depth
                dequeue(act.q);
                push(cur);
                polys_[act.q].moved_at = chain_;
                if (chain_len_ == s_.chain.size()) {
                    // Only the chain's first candidate, not marked moved when it started the chain, can
                    // join it twice: N + 1 entries with a full pool. Its first entry is never read again
                    // (cycles are found from the chain's end), so it makes room.
                    for (size_t i = 1; i < chain_len_; ++i) s_.chain[i - 1] = s_.chain[i];
                    --chain_len_;
                    tried_lo_ = tried_hi_ = 0;  // break_cycle()'s record names positions, now shifted
                }
                s_.chain[chain_len_++] = act.q;
                ++ns_.moves;
                return act.q;
            case Action::restart:  // a cycle broken at a pair its pixels order: q starts a fresh chain
                dequeue(act.q);
                push(cur);
                new_chain();
                s_.chain[chain_len_++] = act.q;
                return act.q;
            case Action::cut: {
                bool cur_cut = false;
                for (int i = 0; i < act.count; ++i) {
                    const Cut& c = act.cuts[i];
                    cur_cut = cur_cut || c.id == cur;
                    if (c.inexact) {
                        ++ns_.inexact_cuts;
                        status_ = Status::capacity_exceeded;
                    }
                    replace(c.id, c.far, c.near, c.far_cut, c.near_cut, c.id != cur);
                }
                return cur_cut ? kNone : cur;
            }
        }
        return kNone;
    }

    /// Tests the pair (P = polys[cur], Q = polys[qi]); true (with act filled) when the order must change.
    bool compare(uint32_t cur, Candidate& cand, uint32_t qi, Action& act) {
        const ScreenPoly& p = cand.poly;
        const ScreenPoly& q = polys_[qi];
        if (q.zmax <= p.zmin) return false;  // Q wholly nearer than P (or level with it)
        if (ns_.budget_exhausted) return false;
        if (++ns_.pair_tests > budget_) {
            ns_.budget_exhausted = true;
            status_ = Status::capacity_exceeded;
            return false;
        }
        if (p.xmax <= q.xmin || q.xmax <= p.xmin) return false;  // (1) no shared pixel centre possible
        if (p.ymax <= q.ymin || q.ymax <= p.ymin) return false;  // (2)
        if (!faces_.empty() && faces_[p.tri] == faces_[q.tri]) return false;  // one flat face
        if (reorder_count_ != 0 && reordered(cur, qi)) return false;  // its pixels allow P first (break_by_pixels)
        if (!cand.ready) {
            outline_of(p, cuts(), cand.outline);
            cand.plane = plane_of(p);
            cand.ready = true;
        }
        const Outline& po = cand.outline;
        const ScreenPlane& pp = cand.plane;
        const ScreenPlane qp = plane_of(q);
        Cut& pc = act.cuts[0];
        Cut& qc = act.cuts[1];
        CutResult p_cut = CutResult::no_line, q_cut = CutResult::no_line;
        const int p_side = side_known_or_classified(p, po, qp, plane_name(q));
        if (p_side > 0) return false;  // (3) P wholly behind Q's plane
        Outline qo;  // only now: a piece's outline costs its cuts' clipping
        outline_of(q, cuts(), qo);
        const int q_side = side_known_or_classified(q, qo, pp, plane_name(p));
        if (q_side < 0) return false;                    // (4) Q wholly in front of P's plane
        if (projections_disjoint(po, qo)) return false;  // (5)
        // One that straddles the other's plane is cut there on trial (after (5): most such pairs are
        // neighbours in a mesh, which share no pixel): a cut that leaves nothing on one side decides the side.
        const int p_vs_q = p_side != 0 ? p_side : side_by_cut(p, qp, plane_name(q), p_cut, pc);
        if (p_vs_q > 0) return false;  // (3)
        const int q_vs_p = q_side != 0 ? q_side : side_by_cut(q, pp, plane_name(p), q_cut, qc);
        if (q_vs_p < 0) return false;  // (4)
        bool too_deep = p_cut == CutResult::too_deep || q_cut == CutResult::too_deep;
        bool cycle = false;
        act.count = 0;
        if (q_vs_p > 0 || p_vs_q < 0) {  // (3') or (4'): Q must be drawn before P
            if (q.moved_at != chain_) {
                act.kind = Action::move;
                act.q = qi;
                return true;
            }
            ++ns_.cycles;  // a cycle: cut one of them by the other's plane, or another pair of the cycle
            cycle = true;
            if (made(p_cut)) take(act, cur, pc);
            else if (made(q_cut)) take(act, qi, qc);
            else too_deep = !break_cycle(qi, act) && (too_deep || cycle_too_deep_);
        } else {  // piercing: each straddles the other's plane, so cut both along their intersection
            if (made(p_cut)) take(act, cur, pc);
            if (made(q_cut)) take(act, qi, qc);
        }
        if (act.count != 0) {
            const size_t pieces = static_cast<size_t>(act.count);
            if (polys_.size() + pieces <= polys_.capacity() && cuts_.size() + 2 * pieces <= cuts_.capacity()) {
                act.kind = Action::cut;
                return true;
            }
            ++ns_.dropped;
            status_ = Status::capacity_exceeded;
        } else if (!too_deep) {
            // Nothing cuts the pair: keep the order found if its shared pixels agree, or break the cycle
            // at another pair of it whose pixels do.
            if (spend_tests(1) && drawn_under(p, q, cuts(), width_, height_)) {
                ++ns_.pixel_ordered;
                return false;
            }
            if (cycle && break_by_pixels(qi, act)) {
                ++ns_.pixel_ordered;
                return true;
            }
            status_ = Status::capacity_exceeded;  // the order found draws a shared pixel wrong
        }
        ++ns_.unresolved;
        if (too_deep) {
            ++ns_.too_deep;
            status_ = Status::capacity_exceeded;
        }
        act.count = 0;
        return false;
    }

    static bool made(CutResult r) { return r == CutResult::cut || r == CutResult::cut_inexact; }

    /// Adds polygon id's cut c to the action (the first slot keeps P's cut until then).
    static void take(Action& act, uint32_t id, const Cut& c) {
        if (&act.cuts[act.count] != &c) act.cuts[act.count] = c;
        act.cuts[act.count++].id = id;
    }

    /// A cycle closed at Q (in the chain) whose pair with the candidate cannot be cut as it stands:
    /// cuts the first pair of the cycle (a polygon and the one moved before it, or Q and the candidate)
    /// where one straddles the other's plane, first beyond the rounding slack, then exactly (the slack may
    /// hide a small crossing, which keeps the cycle closed); failing that, any two polygons of the cycle,
    /// within the pair-test budget. False when none does. The pairs of the longest earlier search of the
    /// same chain that found no cut are skipped (no polygon of a chain changes until it ends), so a long
    /// chain that closes cycle after cycle does not pay for its square each time.
    bool break_cycle(uint32_t q, Action& act);

    /// Counts n pair tests (a pixel test is one); false, counting none, when they would pass the budget
    /// (status set).
    bool spend_tests(uint32_t n);

    bool reordered(uint32_t a, uint32_t b) const;

    /// A cycle closed at Q that no cut breaks, and whose closing pair's pixels disagree with the order
    /// found: finds a polygon of the chain that its pixels allow before the one moved before it, and
    /// restarts from it (act: restart) with that pair kept in scratch.reorders, exempt from the tests
    /// while both wait. False when none does or reorders is full.
    bool break_by_pixels(uint32_t q, Action& act);

    /// Cuts polygon x by the plane of polygon y when x straddles it (beyond the slack, or exactly)
    /// and the cut leaves something on both sides; adds the cut to act (in its next slot). A cut refused
    /// for a piece at kMaxPieceCuts sets cycle_too_deep_.
    bool cut_straddling(uint32_t x, uint32_t y, bool exact, Action& act);

    /// True when x's outline has vertices on both sides of pl, beyond the rounding slack unless `exact`.
    /// Out of line, so that its outline is off the stack while cut_straddling() cuts.
    __attribute__((noinline)) bool straddles(const ScreenPoly& x, const ScreenPlane& pl, bool exact) const {
        Outline ox;
        outline_of(x, cuts(), ox);
        const Int128 slack = exact ? Int128{} : rounding_slack(pl);
        bool near = false, far = false;
        for (int k = 0; k < ox.count; ++k) {
            const int s = classify(pl, slack, ox.v[k]);
            near = near || s < 0;
            far = far || s > 0;
        }
        return near && far;
    }

    /// x's side of plane pl (named `plane`, plane_name()), outline xo: known from x's cuts, else
    /// classified (0: it straddles the plane).
    int side_known_or_classified(const ScreenPoly& x, const Outline& xo, const ScreenPlane& pl, uint32_t plane) const {
        const int known = known_side(x, cuts(), plane);
        return known != 0 ? known : side_of(pl, xo);
    }

    /// The side of x, which straddles plane pl, from the cut along it (pieces into far/near): a cut that
    /// leaves nothing of nonzero area on one side decides the side, else 0. `cut` tells how the try went.
    int side_by_cut(const ScreenPoly& x, const ScreenPlane& pl, uint32_t plane, CutResult& cut, Cut& pieces) {
        cut = cut_polygon(x, cuts(), pl, plane, width_, height_, pieces.far, pieces.near, pieces.far_cut, pieces.near_cut);
        pieces.inexact = cut == CutResult::cut_inexact;
        if (cut == CutResult::far_only) return 1;
        if (cut == CutResult::near_only) return -1;
        return 0;
    }

    /// Puts the two pieces of polygon `id` in its place: the far one in its slot, the near one in a
    /// fresh slot, both back in the grid and the heap.
    void replace(uint32_t id, const ScreenPoly& far, const ScreenPoly& near, const PieceCut& far_cut, const PieceCut& near_cut,
                 bool in_heap) {
        grid_.remove(id, polys_[id]);
        if (in_heap) dequeue(id);
        ScreenPoly f = far, n = near;  // boxes that hold every pixel the pieces draw
        piece_box(polys_[id], cuts(), far_cut.line, f);
        piece_box(polys_[id], cuts(), near_cut.line, n);
        polys_[id] = f;
        polys_[id].cut = static_cast<uint32_t>(cuts_.size());
        cuts_.push_back(far_cut);
        n.cut = static_cast<uint32_t>(cuts_.size());
        cuts_.push_back(near_cut);
        const bool added = polys_.push_back(n);  // room checked by compare
        HIDER_ASSERT(added);
        (void)added;
        const uint32_t other = static_cast<uint32_t>(polys_.size() - 1);
        ++ns_.splits;
        new_chain();  // the pieces start a fresh chain of moves
        grid_.insert(id, polys_[id], polys_.data());
        grid_.insert(other, polys_[other], polys_.data());
        push(id);
        push(other);
    }

    void finish(uint32_t id) {
        const bool added = order_.push_back(id);  // order.capacity() >= polys.capacity()
        HIDER_ASSERT(added);
        (void)added;
        for (size_t i = 0; i < reorder_count_;)  // a pair with a polygon drawn is never tested again
            if (s_.reorders[i] == id || s_.reorders[i + 1] == id) {
                reorder_count_ -= 2;
                s_.reorders[i] = s_.reorders[reorder_count_];
                s_.reorders[i + 1] = s_.reorders[reorder_count_ + 1];
            } else {
                i += 2;
            }
        grid_.remove(id, polys_[id]);
        new_chain();
    }

    /// Ends the chain of moves (a polygon drawn, a cut, a restart): the next candidate starts another.
    void new_chain() {
        ++chain_;
        chain_len_ = 0;
        tried_lo_ = tried_hi_ = 0;  // nothing tried in it yet
    }

    // always_inline: at -Os it would otherwise become a call, paid at every use in the pair tests.
    __attribute__((always_inline)) Span<const PieceCut> cuts() const { return {cuts_.data(), cuts_.size()}; }

    BoundedList<PieceCut>& cuts_;
    BoundedList<uint32_t>& order_;
    NewellStats& ns_;
    uint64_t budget_;
    Span<const uint32_t> faces_;
    int32_t width_, height_;
    ScreenGrid grid_;
    /// Moves since the last output or cut form a chain (Q before P, R before Q, ...): a polygon moved
    /// twice in one chain closes a cycle. A polygon's moved_at holds the chain it was last moved in.
    uint32_t chain_ = 0;
    size_t chain_len_ = 0;  ///< the chain's polygons are scratch.chain[0..chain_len_), the candidate last
    bool cycle_too_deep_ = false;  ///< break_cycle() met a straddling polygon too deep to cut
    /// The longest search of this chain by break_cycle() that found no cut: scratch.chain[tried_lo_..tried_hi_).
    size_t tried_lo_ = 0, tried_hi_ = 0;
    size_t reorder_count_ = 0;  ///< entries of scratch.reorders in use (pairs a, b: a may go before b)
    Status status_ = Status::ok;
};

}  // namespace detail

/// Orders polys[0..n) back to front into `order` (cleared first) so that no polygon is drawn after one
/// it lies in front of, cutting polygons into the free capacity of `polys` (and two `cuts` records per
/// cut) as needed. Paint the result with paint_in_order() or paint_front_to_back(), passing `cuts`.
/// Errors (nothing done): invalid_argument when order, the scratch arrays or the frame size of `view`
/// do not fit polys.capacity() (NewellScratch), or opt.face_ids does not cover every polygon's tri.
/// When a pool fills, a piece reaches kMaxPieceCuts, or a cycle that no cut breaks finds neither its
/// closing pair's shared pixels in the order found nor room in scratch.reorders, that pair keeps the
/// order found, and when the pair-test budget runs out the rest go in depth order: the result is then
/// capacity_exceeded and NewellStats says which; the frame still draws. Cost: one grid
/// query per candidate, pair tests only for overlapping boxes; at most the budget of pair tests, and
/// an input triangle cut by k planes makes at most (k^2 + k + 2) / 2 pieces. Precondition: polys come
/// from build_polys() (no piece) or from an earlier newell_order() with this same `cuts` pool.
inline Status newell_order(const View& view, BoundedList<ScreenPoly>& polys, BoundedList<PieceCut>& cuts,
                           const NewellScratch& scratch, BoundedList<uint32_t>& order, NewellStats& ns,
                           const NewellOptions& opt = {}) {
    const size_t cap = polys.capacity();
    ScreenGrid grid;
    if (order.capacity() < cap || scratch.keys.size() < polys.size() || scratch.sort_scratch.size() < polys.size() ||
        scratch.heap.size() < cap || scratch.heap_pos.size() < cap ||
        scratch.links.size() / 2 < cap || scratch.chain.size() < cap || !grid.reset(view.width, view.height, scratch.cells, scratch.links))
        return Status::invalid_argument;
    order.clear();
    const uint64_t budget = opt.max_pair_tests != 0 ? opt.max_pair_tests : kNewellTestsPerPolygon * cap + 65536;
    for (size_t i = 0; i < polys.size() && !opt.face_ids.empty(); ++i)
        if (polys[i].tri >= opt.face_ids.size()) return Status::invalid_argument;
    return detail::Newell(polys, cuts, scratch, order, ns, budget, opt.face_ids, view.width, view.height).run(grid);
}

}  // namespace hider

#include <hider/sort/newell_cycles.hpp>  // the bodies of the cycle-breaking members

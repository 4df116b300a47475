// The cycle breaking of Newell's algorithm (newell.hpp): the bodies of detail::Newell's members that
// break a cycle of moves no cut of its closing pair breaks: by cutting another pair of the cycle where one
// straddles the other's plane (break_cycle, cut_straddling), else by the pixels its pairs
// share (break_by_pixels, with the reorders they leave). Part of newell.hpp, which includes it; include
// that header, not this one.
#pragma once
#include <hider/sort/newell.hpp>

namespace hider::detail {

inline bool Newell::break_cycle(uint32_t q, Action& act) {
    cycle_too_deep_ = false;
    size_t j = chain_len_;
    while (j-- > 0 && s_.chain[j] != q) {}
    HIDER_ASSERT(j < chain_len_);  // q is always in the chain (moved in it)
    if (j >= chain_len_) return false;  // kept safe all the same
    // Pairs within tried_lo_..tried_hi_ of this chain failed before, and would again.
    const auto tried = [this](size_t a, size_t b) { return a >= tried_lo_ && b < tried_hi_; };  // a < b
    for (int exact = 0; exact < 2; ++exact)
        for (size_t i = j; i < chain_len_; ++i) {
            const uint32_t x = s_.chain[i], y = i + 1 < chain_len_ ? s_.chain[i + 1] : q;  // the last pair closes the cycle
            if (i + 1 < chain_len_ ? tried(i, i + 1) : tried(j, i)) continue;
            if (cut_straddling(x, y, exact != 0, act) || cut_straddling(y, x, exact != 0, act)) return true;
        }
    // Then any two polygons of the cycle (each try counts as a pair test: a long cycle costs its square).
    for (int exact = 0; exact < 2; ++exact)
        for (size_t i = j; i < chain_len_; ++i)
            for (size_t k = i + 2; k < chain_len_; ++k) {
                if (i == j && k + 1 == chain_len_) continue;  // the pair that closes the cycle, tried above
                if (tried(i, k)) continue;
                if (!spend_tests(2)) return false;
                const uint32_t x = s_.chain[i], y = s_.chain[k];
                if (cut_straddling(x, y, exact != 0, act) || cut_straddling(y, x, exact != 0, act)) return true;
            }
    if (!cycle_too_deep_ && chain_len_ - j > tried_hi_ - tried_lo_) {
        tried_lo_ = j;
        tried_hi_ = chain_len_;
    }
    return false;
}

inline bool Newell::spend_tests(uint32_t n) {
    if (ns_.pair_tests + n > budget_) {
        ns_.budget_exhausted = true;
        status_ = Status::capacity_exceeded;
        return false;
    }
    ns_.pair_tests += n;
    return true;
}

inline bool Newell::reordered(uint32_t a, uint32_t b) const {
    for (size_t i = 0; i < reorder_count_; i += 2)
        if (s_.reorders[i] == a && s_.reorders[i + 1] == b) return true;
    return false;
}

inline bool Newell::break_by_pixels(uint32_t q, Action& act) {
    if (reorder_count_ + 2 > s_.reorders.size()) return false;
    size_t j = chain_len_;
    while (j > 0 && s_.chain[j - 1] != q) --j;
    HIDER_ASSERT(j > 0);  // q is always in the chain (moved in it)
    if (j-- == 0) return false;  // kept safe all the same
    for (size_t i = j; i + 1 < chain_len_; ++i) {
        const uint32_t x = s_.chain[i], y = s_.chain[i + 1];  // y was moved before x
        if (!spend_tests(1)) return false;
        if (!drawn_under(polys_[x], polys_[y], cuts(), width_, height_)) continue;
        s_.reorders[reorder_count_++] = x;
        s_.reorders[reorder_count_++] = y;
        ns_.reorders_peak = max(ns_.reorders_peak, static_cast<uint32_t>(reorder_count_));
        act.kind = Action::restart;
        act.q = x;
        return true;
    }
    return false;
}

inline bool Newell::cut_straddling(uint32_t x, uint32_t y, bool exact, Action& act) {
    const ScreenPoly &px = polys_[x], &py = polys_[y];
    if (known_side(px, cuts(), plane_name(py)) != 0) return false;
    const ScreenPlane pl = plane_of(py);
    if (!straddles(px, pl, exact)) return false;
    Cut& c = act.cuts[act.count];
    const CutResult r = cut_polygon(px, cuts(), pl, plane_name(py), width_, height_, c.far, c.near, c.far_cut, c.near_cut);
    cycle_too_deep_ = cycle_too_deep_ || r == CutResult::too_deep;
    if (!made(r)) return false;
    c.inexact = r == CutResult::cut_inexact;
    take(act, x, c);
    return true;
}

}  // namespace hider::detail

// Newell's candidate queue (newell.hpp): polygons leave farthest first (largest zmax, then lower index),
// from the input sorted once by depth (radix sort) merged with an indexed binary max-heap of the
// polygons that wait again (moved back behind another, or pieces of a cut). Three counts of its own; the
// arrays are the caller's NewellScratch (keys, sort_scratch, heap, heap_pos).
#pragma once
#include <hider/sort/newell_types.hpp>
#include <hider/sort/painter.hpp>

namespace hider::detail {

class NewellQueue {
public:
    static constexpr uint32_t kNone = 0xFFFFFFFFu;

    NewellQueue(BoundedList<ScreenPoly>& polys, const NewellScratch& s) : polys_(polys), s_(s) {}

    /// Sorts the pool's polygons by depth: all of them wait in the sorted input, none moved in a chain of
    /// this run (an earlier run's chain numbers would close cycles that are not there). Returns it,
    /// farthest first.
    Span<const SortKey> start() {
        n_ = polys_.size();
        for (uint32_t i = 0; i < n_; ++i) {
            s_.keys[i] = {~polys_[i].zmax, i};  // ascending ~zmax: farthest first, ties by index
            s_.heap_pos[i] = kPending;
            polys_[i].moved_at = kNotMoved;
        }
        radix_sort({s_.keys.data(), n_}, {s_.sort_scratch.data(), n_});
        return {s_.keys.data(), n_};
    }

    /// The next candidate: the farther of the sorted input's next waiting polygon and the heap's top
    /// (kNone when both are empty). Input entries of polygons moved or cut since are skipped.
    uint32_t next() {
        while (pend_ < n_ && s_.heap_pos[s_.keys[pend_].index] != kPending) ++pend_;
        if (pend_ < n_ && (heap_size_ == 0 || before(s_.keys[pend_].index, s_.heap[0]))) {
            const uint32_t id = s_.keys[pend_++].index;
            s_.heap_pos[id] = kNone;
            return id;
        }
        return heap_size_ != 0 ? pop() : kNone;
    }

    /// Puts polygon id (out of the queue) back to wait, at its zmax now.
    void push(uint32_t id) {
        place(heap_size_++, id);
        sift_up(heap_size_ - 1);
    }

    /// Takes polygon id out of the queue (it is the candidate, or about to be cut).
    void dequeue(uint32_t id) {
        const size_t pos = s_.heap_pos[id];
        s_.heap_pos[id] = kNone;
        if (pos == kPending) return;  // its sorted-input entry is now stale
        if (pos == --heap_size_) return;
        const uint32_t last = s_.heap[heap_size_];
        place(pos, last);
        sift_up(pos);
        sift_down(s_.heap_pos[last]);
    }

protected:
    BoundedList<ScreenPoly>& polys_;
    const NewellScratch& s_;

private:
    // heap_pos[id] is id's position in the heap, kPending while it waits in the sorted input, kNone for
    // the candidate or one already out.
    static constexpr uint32_t kPending = 0xFFFFFFFEu;

    /// Heap order: the larger zmax first, then the lower index.
    bool before(uint32_t a, uint32_t b) const {
        const uint32_t za = polys_[a].zmax, zb = polys_[b].zmax;
        return za > zb || (za == zb && a < b);
    }
    void place(size_t pos, uint32_t id) {
        s_.heap[pos] = id;
        s_.heap_pos[id] = static_cast<uint32_t>(pos);
    }
    void sift_up(size_t pos) {
        const uint32_t id = s_.heap[pos];
        while (pos > 0 && before(id, s_.heap[(pos - 1) / 2])) {
            place(pos, s_.heap[(pos - 1) / 2]);
            pos = (pos - 1) / 2;
        }
        place(pos, id);
    }
    void sift_down(size_t pos) {
        const uint32_t id = s_.heap[pos];
        for (;;) {
            size_t child = 2 * pos + 1;
            if (child >= heap_size_) break;
            if (child + 1 < heap_size_ && before(s_.heap[child + 1], s_.heap[child])) ++child;
            if (!before(s_.heap[child], id)) break;
            place(pos, s_.heap[child]);
            pos = child;
        }
        place(pos, id);
    }
    uint32_t pop() {
        const uint32_t top = s_.heap[0];
        s_.heap_pos[top] = kNone;
        if (--heap_size_ != 0) {
            place(0, s_.heap[heap_size_]);
            sift_down(0);
        }
        return top;
    }

    size_t n_ = 0;          ///< polygons in the sorted input (the built ones)
    size_t pend_ = 0;       ///< next entry of the sorted input
    size_t heap_size_ = 0;
};

}  // namespace hider::detail

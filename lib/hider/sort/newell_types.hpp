// Newell's caller-facing types (newell.hpp): the statistics a run reports, its options (face ids, the
// pair-test budget) and the scratch arrays the caller owns, with the sizes newell_order() checks.
#pragma once
#include <hider/sort/painter.hpp>  // SortKey

namespace hider {

struct NewellStats {
    uint64_t pair_tests = 0;        ///< pairs whose boxes may overlap and whose depth ranges overlap, and
                                    ///< two per pair of a cycle tried for a cut beyond its consecutive pairs
    uint32_t moves = 0;             ///< Q moved before P
    uint32_t splits = 0;            ///< polygons cut in two by another's plane
    uint32_t cycles = 0;            ///< cycles of overlap found (each broken by a cut when possible)
    uint32_t unresolved = 0;        ///< pairs left in the order found: no cut, and their shared pixels
                                    ///< disagree (a cycle with NewellScratch::reorders full, or a piercing pair
                                    ///< no line cuts), or the limits below (all capacity_exceeded)
    uint32_t pixel_ordered = 0;     ///< pairs no cut could order, ordered by the pixel centres they share
    uint32_t reorders_peak = 0;     ///< most words of NewellScratch::reorders in use at once: when no pair
                                    ///< is unresolved, an array of this size repeats the run (sizing it)
    uint32_t dropped = 0;           ///< cuts not made because the polygon or cut pool was full
    uint32_t too_deep = 0;          ///< cuts not made because a piece already had kMaxPieceCuts cuts
    uint32_t inexact_cuts = 0;      ///< cuts made along a line that puts a pixel centre on the wrong side
                                    ///< of the plane (CutResult::cut_inexact; capacity_exceeded)
    bool budget_exhausted = false;  ///< the pair-test budget ran out; the rest went in depth order
};

/// Default pair-test budget per polygon of the pool (see NewellOptions).
constexpr uint64_t kNewellTestsPerPolygon = 1024;

struct NewellOptions {
    /// The face of each mesh triangle (e.g. Mesh::ids), or empty. Polygons of one face are taken as
    /// coplanar and never ordered against each other (nor cut): a fan of a large flat face costs no cuts.
    /// Give one face only to triangles whose vertices lie exactly on one plane (a folded quad's two
    /// triangles can hide each other, and would be drawn in depth order).
    Span<const uint32_t> face_ids;
    /// Most pair tests one call may run; 0 = kNewellTestsPerPolygon x polys.capacity() + 65536.
    /// Past it the remaining polygons go out in depth order, and the result is capacity_exceeded.
    uint64_t max_pair_tests = 0;
};

/// Caller memory of newell_order() besides the pools, for a polygon pool of capacity N holding n polygons.
struct NewellScratch {
    Span<SortKey> keys;       ///< >= n (the polygons sorted by depth once, radix_sort)
    Span<SortKey> sort_scratch;  ///< >= n
    Span<uint32_t> heap;      ///< >= N
    Span<uint32_t> heap_pos;  ///< >= N
    Span<uint32_t> links;     ///< >= 2 N (the grid)
    Span<uint32_t> cells;     ///< >= grid_cells(width, height)
    Span<uint32_t> chain;     ///< >= N (the polygons of the current chain of moves)
    /// Two entries per pair at which a cycle was broken by its pixels while both wait (any size, 0 too;
    /// kNewellReorders is plenty: a cycle that finds it full stays unresolved, capacity_exceeded).
    Span<uint32_t> reorders;
};

/// NewellScratch::reorders entries for 8 pairs at once (README.md says what the sweeps needed).
constexpr size_t kNewellReorders = 16;

}  // namespace hider

// The curve drawer's hot loop (CurveDrawer::walk, horizon.hpp): along projected points, extend the
// pending column's extent while the curve stays in it; at a step into the next column to the right
// (shorter than 16 pixels) interpolate the curve at the boundary, close the column and, unless it lies
// wholly between the horizons, queue it (column, rows) for C++ to draw after the walk; any other step
// goes back to C++ (cross()). Queueing changes nothing: a later column's hidden test may then see a
// horizon not yet widened by a queued one, but only its own column's horizons matter to it, and drawing
// re-reads them. Portable C++, except on ARMv6-M, where GCC at -Os spills the walk's state: there a
// Thumb-1 loop keeps it in registers. Both give the same results (firmware/horizoncheck compares them on random curves).
#pragma once
#include <hider/asm_v6m.hpp>
#include <hider/horizon/point.hpp>

namespace hider::horizon {

/// State of the walk. The field order is the ARMv6-M loop's contract (static_assert below). Points
/// have |y| < 2^15; p[-1] is the point before p and lies in column col (so a step into the next
/// column is shorter than 32).
struct WalkKernel {
    const PlotPoint* p;      ///< next point
    const PlotPoint* end;
    int32_t col;             ///< pending column: p[-1].x >> 4
    int32_t ymin, ymax;      ///< its extent so far
    const int16_t* upper;    ///< horizons
    const int16_t* lower;
    uint32_t width;          ///< columns with horizons
    const uint32_t* slope;   ///< ceil(2^24 / d), d < 256
    int32_t* runs;           ///< queue of closed columns not hidden: (lo, column, hi) triples
    int32_t* runs_end;       ///< room ends here (a multiple of 3 after runs)
};
static_assert(sizeof(void*) != 4 || (offsetof(WalkKernel, upper) == 20 && offsetof(WalkKernel, slope) == 32 &&
                                     offsetof(WalkKernel, runs) == 36 && offsetof(WalkKernel, runs_end) == 40),
              "walk kernel layout");

/// Result of a walk: every point walked; the queue is full (the walk goes on after it is drawn); the
/// step to p[0] needs CurveDrawer::cross() (p, col, ymin, ymax unchanged for it). Each may leave runs queued.
enum WalkResult : int { kWalkDone = 0, kWalkRunsFull = 1, kWalkCross = 2 };

/// The walk in C++.
inline int walk_kernel_portable(WalkKernel& k) {
    while (k.p != k.end) {
        const int32_t x = k.p->x, y = k.p->y, c = x >> 4;
        if (c == k.col) {
            k.ymin = min(k.ymin, y);
            k.ymax = max(k.ymax, y);
            ++k.p;
            continue;
        }
        if (c != k.col + 1) return kWalkCross;
        const int32_t lx = k.p[-1].x, ly = k.p[-1].y;
        const uint32_t dx = static_cast<uint32_t>(x - lx);  // in [1, 31]: p[-1] lies in column col
        const int32_t t = static_cast<int32_t>((static_cast<uint32_t>(c * 16 - lx) * k.slope[dx]) >> 9);
        const int32_t yb = ly + (((y - ly) * t) >> 15);
        const int32_t closed = k.col, ymin = min(k.ymin, yb), ymax = max(k.ymax, yb);
        k.col = c;
        k.ymin = min(yb, y);
        k.ymax = max(yb, y);
        ++k.p;
        if (static_cast<uint32_t>(closed) < k.width) {
            int32_t lo = (ymin + 7) >> 4, hi = (ymax - 8) >> 4;
            if (lo > hi) lo = hi = (ymin + ymax) >> 5;
            if (lo < k.upper[closed] || hi > k.lower[closed]) {
                k.runs[0] = lo;
                k.runs[1] = closed;
                k.runs[2] = hi;
                k.runs += 3;
                if (k.runs == k.runs_end) return kWalkRunsFull;
            }
        }
    }
    return kWalkDone;
}

#if defined(HIDER_ARMV6M)
/// walk_kernel_portable() in Thumb-1. r0 p, r4 col, r5 ymin, r6 ymax, r1 r2 r3 r7 scratch; r8 end,
/// r9 upper, r10 lower, r11 width, r12 slope, lr scratch; the state pointer at [sp].
HIDER_NAKED inline int walk_kernel_v6m(WalkKernel*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
        "push   {r0}\n\t"
        "ldr    r1, [r0, #4]\n\t"         // end
        "mov    r8, r1\n\t"
        "ldr    r1, [r0, #20]\n\t"        // upper
        "mov    r9, r1\n\t"
        "ldr    r1, [r0, #24]\n\t"        // lower
        "mov    r10, r1\n\t"
        "ldr    r1, [r0, #28]\n\t"        // width
        "mov    r11, r1\n\t"
        "ldr    r1, [r0, #32]\n\t"        // slope
        "mov    r12, r1\n\t"
        "ldr    r4, [r0, #8]\n\t"         // col
        "ldr    r5, [r0, #12]\n\t"        // ymin
        "ldr    r6, [r0, #16]\n\t"        // ymax
        "ldr    r0, [r0, #0]\n"           // p
        "1:\n\t"                          // next point
        "cmp    r0, r8\n\t"
        "beq    9f\n\t"
        "ldm    r0!, {r1, r2}\n\t"        // x y
        "asrs   r3, r1, #4\n\t"
        "cmp    r3, r4\n\t"
        "bne    3f\n\t"
        "cmp    r2, r5\n\t"               // same column: widen the extent
        "bge    2f\n\t"
        "movs   r5, r2\n\t"
        "b      1b\n"
        "2:\n\t"
        "cmp    r2, r6\n\t"
        "ble    1b\n\t"
        "movs   r6, r2\n\t"
        "b      1b\n"
        "3:\n\t"                          // another column: only the next one to the right here
        "subs   r7, r3, r4\n\t"
        "cmp    r7, #1\n\t"
        "bne    8f\n\t"
        "mov    lr, r2\n\t"               // y
        "mov    r7, r0\n\t"
        "subs   r7, #16\n\t"
        "ldm    r7, {r2, r7}\n\t"         // lx ly
        "subs   r1, r1, r2\n\t"           // dx, in [1, 31]
        "lsls   r3, r3, #4\n\t"
        "subs   r3, r3, r2\n\t"           // 16 c - lx
        "lsls   r1, r1, #2\n\t"
        "mov    r2, r12\n\t"
        "ldr    r1, [r2, r1]\n\t"         // slope[dx]
        "muls   r1, r3, r1\n\t"
        "lsrs   r1, r1, #9\n\t"           // t
        "mov    r2, lr\n\t"               // y
        "subs   r3, r2, r7\n\t"           // dy
        "muls   r3, r1, r3\n\t"
        "asrs   r3, r3, #15\n\t"
        "adds   r3, r3, r7\n\t"           // yb
        "cmp    r3, r5\n\t"
        "bge    4f\n\t"
        "movs   r5, r3\n"
        "4:\n\t"
        "cmp    r3, r6\n\t"
        "ble    5f\n\t"
        "movs   r6, r3\n"
        "5:\n\t"                          // close column r4 (extent r5..r6); r2 y, r3 yb live
        "cmp    r4, r11\n\t"
        "bhs    7f\n\t"                   // no horizons there (outside the frame)
        "adds   r1, r5, #7\n\t"
        "asrs   r1, r1, #4\n\t"           // lo
        "movs   r7, r6\n\t"
        "subs   r7, #8\n\t"
        "asrs   r7, r7, #4\n\t"           // hi
        "cmp    r1, r7\n\t"
        "ble    6f\n\t"
        "adds   r1, r5, r6\n\t"
        "asrs   r1, r1, #5\n\t"
        "movs   r7, r1\n"                 // lo = hi = the middle row
        "6:\n\t"
        "lsls   r5, r4, #1\n\t"
        "mov    r6, r9\n\t"
        "ldrsh  r6, [r6, r5]\n\t"         // upper
        "cmp    r1, r6\n\t"
        "blt    10f\n\t"
        "mov    r6, r10\n\t"
        "ldrsh  r6, [r6, r5]\n\t"         // lower
        "cmp    r7, r6\n\t"
        "bgt    10f\n"
        "7:\n\t"                          // open the next column: extent yb..y
        "adds   r4, r4, #1\n\t"
        "movs   r5, r3\n\t"
        "movs   r6, r3\n\t"
        "cmp    r2, r3\n\t"
        "bge    71f\n\t"
        "movs   r5, r2\n\t"
        "b      1b\n"
        "71:\n\t"
        "movs   r6, r2\n\t"
        "b      1b\n"
        "10:\n\t"                         // not hidden: queue (lo, column, hi), open the next column
        "ldr    r5, [sp]\n\t"
        "ldr    r6, [r5, #36]\n\t"        // runs
        "stm    r6!, {r1, r4, r7}\n\t"
        "str    r6, [r5, #36]\n\t"
        "ldr    r7, [r5, #40]\n\t"        // runs_end
        "subs   r7, r7, r6\n\t"           // room left
        "adds   r4, r4, #1\n\t"
        "movs   r5, r3\n\t"
        "movs   r6, r3\n\t"
        "cmp    r2, r3\n\t"
        "bge    11f\n\t"
        "movs   r5, r2\n\t"
        "b      12f\n"
        "11:\n\t"
        "movs   r6, r2\n"
        "12:\n\t"
        "cmp    r7, #0\n\t"
        "bne    1b\n\t"
        "movs   r3, #1\n\t"               // queue full
        "b      20f\n"
        "8:\n\t"                          // cross(): back to the point
        "subs   r0, #8\n\t"
        "movs   r3, #2\n\t"
        "b      20f\n"
        "9:\n\t"
        "movs   r3, #0\n"
        "20:\n\t"
        "pop    {r1}\n\t"
        "str    r0, [r1, #0]\n\t"
        "str    r4, [r1, #8]\n\t"
        "str    r5, [r1, #12]\n\t"
        "str    r6, [r1, #16]\n\t"
        "movs   r0, r3\n\t"
        HIDER_V6M_RESTORE_ALL);
}
#endif

/// Runs the walk (Thumb-1 on ARMv6-M, else the portable loop).
inline int run_walk_kernel(WalkKernel& k) {
#if defined(HIDER_ARMV6M)
    return walk_kernel_v6m(&k);
#else
    return walk_kernel_portable(k);
#endif
}

}  // namespace hider::horizon

// The z-buffer's row kernel for its most common case: a flat-coloured triangle that stays inside the
// frame's columns, 16-bit pixels (RGB565) over a 16-bit depth buffer. One call runs `rows` rows: each
// row's depth-tested span [lpx, rpx) from depth lz, then both edges step as exact DDAs (the same
// arithmetic as TriangleRaster::scan_rows) and the depth row advances by the stride.
//
// run_row_kernel() is portable C++ on hosts and hand-scheduled assembly on the chips
// (row_kernel_asm.hpp: Thumb-2 for ARMv7-M, Thumb-1 for ARMv6-M, RV32): at -Os GCC cannot keep the two
// edges and the span in registers across rows; the assembly does, and writes the same bytes. The firmware
// tests compare its frames with the host's, and firmware/kernelcheck runs it against
// run_row_kernel_portable() on random states.
#pragma once
#include <hider/base.hpp>

namespace hider {

/// Per-triangle state of the row kernel; a call runs some rows and leaves the state of the next row here,
/// so a triangle can be drawn in several calls (halves, bands). Edges are kept in depth-row bytes: x is
/// twice the boundary pixel (the span is [lx, rx) / 2) and step is what x moves from one depth row's
/// start to the next's, the stride included (2 q + stride), so a row needs no pointer of its own; g is
/// the error term biased by -a, in [-a, 0), stepped per row by g += m, x += step, then one correction
/// (g >= 0: g -= a, x -= 2, and the left depth z -= dzdx): the add's sign flag decides it. The field
/// order is the assembly loops' contract (load-multiples and offsets), checked by the static_asserts.
struct RowKernel {
    int32_t lx, lg;
    uint32_t lz;
    int32_t rx, rg;
    int32_t la, lm, lstep;
    uint32_t ldz;            ///< left depth step per row (dz/dy + q dz/dx)
    int32_t ra, rm, rstep;
    uint32_t dzdx;           ///< depth step per pixel (spans, and the left edge's correction)
    uint32_t color;          ///< RGB565 in the low half
};

// The assembly loops' offsets (32-bit pointers).
static_assert(sizeof(void*) != 4 || (offsetof(RowKernel, la) == 20 && offsetof(RowKernel, ldz) == 32 &&
                                     offsetof(RowKernel, ra) == 36 && offsetof(RowKernel, dzdx) == 48 &&
                                     offsetof(RowKernel, color) == 52 && sizeof(RowKernel) == 56),
              "row kernel layout");

/// Where the kernel draws: constants of a frame or band (the layout is the assembly loops' contract).
struct KernelTarget {
    intptr_t color_offset;  ///< bytes from a depth element to its pixel's colour
    int32_t stride_bytes;   ///< bytes from one depth row to the next
};
static_assert(sizeof(void*) != 4 || (offsetof(KernelTarget, stride_bytes) == 4), "kernel target layout");

/// A triangle for the row kernel from row `row` on (kernel_triangle.hpp sets it up). Until `mid`, the
/// short edge is the one above the middle vertex; from `mid` on, `next` (kernel form: x, g - a, a, m,
/// step) replaces it. A left one takes its depth and depth step from the edge it replaces on the middle
/// row, the depth plane being affine modulo 2^32 (next_edge_depth()). Rows end at `end`. The layout is
/// the assembly's contract. (The ARMv7-M band loop's resumes leave `row` as it was, and the edges of a
/// triangle that ends in the band as they come: nothing reads them again there.)
struct KernelTriangle {
    RowKernel k;
    int16_t top;  ///< the triangle's first row, unclamped
    int16_t row, mid, end;
    int32_t next_x, next_g, next_a, next_m, next_step;
    uint16_t tri;    ///< the mesh triangle (binned.hpp keeps carried set-ups in mesh order)
    bool next_left;  ///< `next` is the left edge (the long edge runs on the right)
};
static_assert(sizeof(void*) != 4 || (offsetof(KernelTriangle, top) == 56 && offsetof(KernelTriangle, next_x) == 64 &&
                                     offsetof(KernelTriangle, next_step) == 80 && offsetof(KernelTriangle, tri) == 84 &&
                                     offsetof(KernelTriangle, next_left) == 86 && sizeof(KernelTriangle) == 88),
              "kernel triangle layout");

/// The depth and depth step of the lower short edge on the left, from the left edge it replaces on the
/// middle row: z and dz of that edge there, its step and the new one (2 q + stride, the same stride),
/// and the two edges' byte offsets in the row. The plane is affine modulo 2^32 (plane.hpp), so these
/// are exactly plane.at() at the new edge and dz/dy + q dz/dx for its q.
struct NextDepth {
    uint32_t z, dz;
};
__attribute__((always_inline)) inline NextDepth next_edge_depth(uint32_t z, uint32_t dz, uint32_t dzdx, int32_t old_x,
                                                                int32_t new_x, int32_t old_step, int32_t new_step) {
    return {z + dzdx * static_cast<uint32_t>((new_x - old_x) >> 1), dz + dzdx * static_cast<uint32_t>((new_step - old_step) >> 1)};
}

/// The asm operands of the row loops' edge constants and lower short edge, by field (the Thumb-1 and RV32
/// loops address them from the record; the Thumb-2 one from its right edge, HIDER_V7M_ROWS_OPERANDS).
#define HIDER_ROW_LOOP_OPERANDS                                                                             \
    [la] "i"(offsetof(RowKernel, la)), [lm] "i"(offsetof(RowKernel, lm)),                                  \
    [lstep] "i"(offsetof(RowKernel, lstep)), [ldz] "i"(offsetof(RowKernel, ldz)),                          \
    [ra] "i"(offsetof(RowKernel, ra)), [rm] "i"(offsetof(RowKernel, rm)),                                  \
    [rstep] "i"(offsetof(RowKernel, rstep)), [n_left] "i"(offsetof(KernelTriangle, next_left)),            \
    [n_x] "i"(offsetof(KernelTriangle, next_x)), [n_g] "i"(offsetof(KernelTriangle, next_g)),              \
    [n_a] "i"(offsetof(KernelTriangle, next_a)), [n_m] "i"(offsetof(KernelTriangle, next_m)),              \
    [n_step] "i"(offsetof(KernelTriangle, next_step))

/// The row loop in C++: `rows` >= 1 rows from depth row `zrow` of target `t`; leaves k's edges and
/// depth on the next row and returns that row's depth pointer.
// kernel_setup() fills the fields only for triangles with rows, which GCC cannot tie to the calls here:
// it reports them as maybe uninitialised once inlined (a false positive). Clang has no such warning: the
// first two lines keep either compiler quiet about the other's names.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpragmas"
#pragma GCC diagnostic ignored "-Wunknown-warning-option"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
inline uint16_t* run_row_kernel_portable(RowKernel& k, uint16_t* zrow, int32_t rows, const KernelTarget& t) {
    const intptr_t color_offset = t.color_offset;
    const uintptr_t base = reinterpret_cast<uintptr_t>(zrow);
    uintptr_t lp = base + static_cast<uintptr_t>(k.lx), rp = base + static_cast<uintptr_t>(k.rx);
    int32_t lg = k.lg, rg = k.rg;
    uint32_t lz = k.lz;
    const uint32_t dz = k.dzdx;
    const uint16_t color = static_cast<uint16_t>(k.color);
    for (int32_t n = rows; n != 0; --n) {
        if (lp < rp) {  // depth elements [lp, rp), colour color_offset bytes after each
            uint32_t z = lz;
            uintptr_t p = lp;
            do {
                uint16_t* const zp = reinterpret_cast<uint16_t*>(p);
                const uint16_t depth = static_cast<uint16_t>(z >> 16);
                if (depth < *zp) {
                    *zp = depth;
                    *reinterpret_cast<uint16_t*>(p + static_cast<uintptr_t>(color_offset)) = color;
                }
                z += dz;
                p += 2;
            } while (p != rp);
        }
        lg += k.lm;
        lp += static_cast<uintptr_t>(k.lstep);
        lz += k.ldz;
        if (lg >= 0) { lg -= k.la; lp -= 2; lz -= dz; }
        rg += k.rm;
        rp += static_cast<uintptr_t>(k.rstep);
        if (rg >= 0) { rg -= k.ra; rp -= 2; }
    }
    const uintptr_t next = base + static_cast<uintptr_t>(rows) * static_cast<uintptr_t>(t.stride_bytes);
    k.lx = static_cast<int32_t>(lp - next);
    k.lg = lg;
    k.lz = lz;
    k.rx = static_cast<int32_t>(rp - next);
    k.rg = rg;
    return reinterpret_cast<uint16_t*>(next);
}

/// Draws rows [t.row, min(t.end, row_stop)) of a set-up triangle into target `target` from depth row
/// `zrow` (that of t.row), switching to the lower short edge on the middle row (also when a call
/// starts there), and leaves t on the next row. Returns the depth pointer of that row. The portable twin
/// of the assembly kernels.
inline uint16_t* run_kernel_triangle_portable(KernelTriangle& t, uint16_t* zrow, int32_t row_stop, const KernelTarget& target) {
    const int32_t stop = min<int32_t>(t.end, row_stop);
    if (t.row < t.mid) {  // rows above the middle vertex
        const int32_t upper_end = min<int32_t>(t.mid, stop);
        if (t.row < upper_end) {
            zrow = run_row_kernel_portable(t.k, zrow, upper_end - t.row, target);
            t.row = static_cast<int16_t>(upper_end);
        }
        if (t.row < t.mid) return zrow;  // stopped above the middle row
        if (t.mid < t.end) {  // on the middle row (perhaps a later call's first): the lower short edge takes over
            RowKernel& k = t.k;
            if (t.next_left) {
                const NextDepth d = next_edge_depth(k.lz, k.ldz, k.dzdx, k.lx, t.next_x, k.lstep, t.next_step);
                k.lx = t.next_x; k.lg = t.next_g; k.la = t.next_a; k.lm = t.next_m; k.lstep = t.next_step;
                k.lz = d.z;
                k.ldz = d.dz;
            } else {
                k.rx = t.next_x; k.rg = t.next_g; k.ra = t.next_a; k.rm = t.next_m; k.rstep = t.next_step;
            }
        }
    }
    if (t.row < stop) {
        zrow = run_row_kernel_portable(t.k, zrow, stop - t.row, target);
        t.row = static_cast<int16_t>(stop);
    }
    return zrow;
}
#pragma GCC diagnostic pop

}  // namespace hider

#include <hider/raster/row_kernel_asm.hpp>  // the assembly kernels and run_kernel_triangle()

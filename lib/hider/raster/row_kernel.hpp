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
    int32_t stride_bytes;    ///< bytes from one depth row to the next
    uint32_t dzdx;           ///< depth step per pixel (spans, and the left edge's correction)
    uint32_t color;          ///< RGB565 in the low half
};

// The assembly loops' offsets (32-bit pointers).
static_assert(sizeof(void*) != 4 || (offsetof(RowKernel, la) == 20 && offsetof(RowKernel, ldz) == 32 &&
                                     offsetof(RowKernel, ra) == 36 && offsetof(RowKernel, stride_bytes) == 48 &&
                                     offsetof(RowKernel, dzdx) == 52 && offsetof(RowKernel, color) == 56),
              "row kernel layout");

/// The kernel in C++: `rows` rows from depth row `zrow`, colour `color_offset` bytes from each depth
/// element; leaves k's edges and depth on the next row and returns that row's depth pointer.
// kernel_setup() fills the fields only for triangles with rows, which GCC cannot tie to the calls here:
// it reports them as maybe uninitialised once inlined (a false positive).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
inline uint16_t* run_row_kernel_portable(RowKernel& k, uint16_t* zrow, int32_t rows, intptr_t color_offset) {
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
    const uintptr_t next = base + static_cast<uintptr_t>(rows) * static_cast<uintptr_t>(k.stride_bytes);
    k.lx = static_cast<int32_t>(lp - next);
    k.lg = lg;
    k.lz = lz;
    k.rx = static_cast<int32_t>(rp - next);
    k.rg = rg;
    return reinterpret_cast<uint16_t*>(next);
}
#pragma GCC diagnostic pop

}  // namespace hider

#include <hider/raster/row_kernel_asm.hpp>  // the assembly kernels and run_row_kernel()

// The z-buffer's row kernel for its most common case: a flat-coloured triangle that stays inside the
// frame's columns, 16-bit pixels (RGB565) over a 16-bit depth buffer. One call runs `rows` rows: each
// row's depth-tested span [lpx, rpx) from depth lz, then both edges step as exact DDAs (the same
// arithmetic as TriangleRaster::scan_rows) and the depth row advances by the stride.
//
// run_row_kernel() is portable C++, except on Cortex-M: a hand-scheduled Thumb-2 loop on ARMv7-M (M3/M4)
// and a Thumb-1 loop on ARMv6-M (M0/M0+). At -Os GCC cannot keep the two edges, the row pointer and the
// span in registers across rows (about 60 instructions a row on the M3 with the span as a call, 45 of
// them outside the pixels); the assembly keeps the variables in registers and reloads constants with
// load-multiples (21 a row outside the pixels on the M3), writing the same bytes. The firmware tests compare its
// frames with the host's, and firmware/kernelcheck runs it against run_row_kernel_portable() on random
// states.
#pragma once
#include <hider/base.hpp>

namespace hider {

/// State of the row kernel. The field order is the assembly loops' contract (load-multiples and
/// offsets), checked by the static_asserts below. Edges: px is the boundary pixel and g the error term
/// biased by -a, in [-a, 0), stepped per row by g += m, px += q, then one correction (g >= 0: g -= a,
/// px -= 1, and the left depth z -= dzdx); the bias lets the add's sign flag decide the correction.
struct RowKernel {
    int32_t lpx, lg;
    uint32_t lz;
    int32_t rpx, rg;
    int32_t rows;            ///< rows to run, >= 1
    int32_t la, lm, lq;
    uint32_t ldz;            ///< left depth step per row (dz/dy + q dz/dx)
    int32_t ra, rm, rq;
    int32_t stride_bytes;    ///< bytes from one depth row to the next
    uint32_t dzdx;           ///< depth step per pixel, for the left edge's correction
    uint16_t* zrow;          ///< depth row of the current row
    uint32_t dz;             ///< depth step per pixel in spans (= dzdx)
    intptr_t color_offset;   ///< bytes from a pixel's depth to its colour
    uint32_t color;          ///< RGB565 in the low half
};

// The assembly loops' offsets (32-bit pointers).
static_assert(sizeof(void*) != 4 || (offsetof(RowKernel, rows) == 20 && offsetof(RowKernel, la) == 24 &&
                                     offsetof(RowKernel, ldz) == 36 && offsetof(RowKernel, ra) == 40 &&
                                     offsetof(RowKernel, stride_bytes) == 52 && offsetof(RowKernel, dzdx) == 56 &&
                                     offsetof(RowKernel, zrow) == 60 && offsetof(RowKernel, dz) == 64 &&
                                     offsetof(RowKernel, color_offset) == 68 && offsetof(RowKernel, color) == 72),
              "row kernel layout");

/// The kernel in C++: k.rows rows, then k's edges, depth and zrow are those of the next row.
// TriangleRaster::scan_kernel() sets the left and the right edge in branches on which side the long
// edge is; GCC cannot pair them and reports the fields as maybe uninitialised here (false positive).
// Clang has no such warning: the first two lines keep either compiler quiet about the other's names.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpragmas"
#pragma GCC diagnostic ignored "-Wunknown-warning-option"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
inline void run_row_kernel_portable(RowKernel& k) {
    int32_t lpx = k.lpx, lg = k.lg, rpx = k.rpx, rg = k.rg;
    uint32_t lz = k.lz;
    uint16_t* zrow = k.zrow;
    const uint32_t dz = k.dz;
    const uint16_t color = static_cast<uint16_t>(k.color);
    for (int32_t n = k.rows; n != 0; --n) {
        if (lpx < rpx) {
            uint16_t* const crow = reinterpret_cast<uint16_t*>(reinterpret_cast<uintptr_t>(zrow) +
                                                               static_cast<uintptr_t>(k.color_offset));
            uint32_t z = lz;
            int32_t x = lpx;
            do {
                const uint16_t depth = static_cast<uint16_t>(z >> 16);
                if (depth < zrow[x]) {
                    zrow[x] = depth;
                    crow[x] = color;
                }
                z += dz;
            } while (++x != rpx);
        }
        lg += k.lm;
        lpx += k.lq;
        lz += k.ldz;
        if (lg >= 0) { lg -= k.la; --lpx; lz -= k.dzdx; }
        rg += k.rm;
        rpx += k.rq;
        if (rg >= 0) { rg -= k.ra; --rpx; }
        zrow = reinterpret_cast<uint16_t*>(reinterpret_cast<uintptr_t>(zrow) + static_cast<uintptr_t>(k.stride_bytes));
    }
    k.lpx = lpx; k.lg = lg; k.lz = lz; k.rpx = rpx; k.rg = rg; k.zrow = zrow;
}
#pragma GCC diagnostic pop

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// run_row_kernel_portable() in Thumb-2. Registers: r0 the right edge's constants (offset 40), with
/// the left edge's just below (load-multiple decrement-before), r1..r5 lpx lg lz rpx rg, r6 rows left,
/// r7 zrow, r8 dz, r10 colour. Pixel loop: indexes back from the span's end (r7 depth, r9 colour) with
/// r11 = -(pixels left) counting up to 0, lr z, r12 scratch (9 instructions a written pixel, 6 a
/// rejected one). Per row outside the pixels: 21 instructions, plus 4 and 2 for edge corrections.
__attribute__((naked, noinline)) inline void run_row_kernel_v7m(RowKernel*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "ldm    r0, {r1-r6}\n\t"           // lpx lg lz rpx rg rows
        "ldr    r7, [r0, #60]\n\t"        // zrow
        "ldr    r8, [r0, #64]\n\t"        // dz
        "ldr    r10, [r0, #72]\n\t"       // colour
        "add    r0, r0, #40\n"            // r0: the right edge's constants (offset 40)
        "1:\n\t"                           // row
        "cmp    r1, r4\n\t"
        "bge    3f\n\t"                    // empty span
        "ldr    r9, [r0, #28]\n\t"        // colour offset (68)
        "add    r7, r7, r4, lsl #1\n\t"    // depth row + 2 rpx (restored after the span)
        "add    r9, r9, r7\n\t"            // colour row + 2 rpx
        "sub    r11, r1, r4\n\t"           // x = lpx - rpx: negative, counts up to 0
        "mov    lr, r3\n"                  // z = lz
        "2:\n\t"                           // pixel
        "ldrh   r12, [r7, r11, lsl #1]\n\t"
        "cmp    r12, lr, lsr #16\n\t"
        "bls    4f\n\t"                    // stored depth <= ours: keep it
        "lsr    r12, lr, #16\n\t"
        "strh   r12, [r7, r11, lsl #1]\n\t"
        "strh   r10, [r9, r11, lsl #1]\n"
        "4:\n\t"
        "add    lr, lr, r8\n\t"
        "adds   r11, r11, #1\n\t"
        "bne    2b\n\t"
        "sub    r7, r7, r4, lsl #1\n"
        "3:\n\t"                           // left edge: g += m, px += q, z += dz_row, then correct
        "ldmdb  r0, {r9, r11, r12, lr}\n\t" // la lm lq ldz (offset 24)
        "adds   r2, r2, r11\n\t"
        "add    r1, r1, r12\n\t"
        "add    r3, r3, lr\n\t"
        "bmi    5f\n\t"                    // g < 0: no correction
        "sub    r2, r2, r9\n\t"
        "sub    r1, r1, #1\n\t"
        "ldr    r9, [r0, #16]\n\t"        // dzdx (56)
        "sub    r3, r3, r9\n"
        "5:\n\t"                           // right edge, then the next depth row
        "ldm    r0, {r9, r11, r12, lr}\n\t" // ra rm rq stride (offset 40)
        "adds   r5, r5, r11\n\t"
        "add    r4, r4, r12\n\t"
        "bmi    6f\n\t"
        "sub    r5, r5, r9\n\t"
        "sub    r4, r4, #1\n"
        "6:\n\t"
        "add    r7, r7, lr\n\t"
        "subs   r6, r6, #1\n\t"
        "bne    1b\n\t"
        "sub    r0, r0, #40\n\t"
        "stm    r0, {r1-r5}\n\t"
        "str    r7, [r0, #60]\n\t"
        "pop    {r4-r11, pc}\n");
}
#endif

#if defined(__ARM_ARCH_6M__)
/// run_row_kernel_portable() in Thumb-1 (Cortex-M0/M0+: eight low registers, no conditional execution).
/// Between rows r0 holds the state, r1..r5 lpx lg lz rpx rg, r12 the state again, r10 zrow, r11 the
/// zrow that ends the run, lr the stride, r9 dz, r8 the colour offset; the edge constants are loaded where
/// used. A span parks lpx..rpx in the state with one store-multiple; its pixel loop indexes back from
/// the span's end (r6 depth, r2 colour) with r1 = -2 (pixels left) counting up to 0, r3 z, r4 colour
/// (9 instructions a written pixel, 7 a rejected one).
__attribute__((naked, noinline)) inline void run_row_kernel_v6m(RowKernel*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r7, lr}\n\t"
        "mov    r4, r8\n\t"
        "mov    r5, r9\n\t"
        "mov    r6, r10\n\t"
        "mov    r7, r11\n\t"
        "push   {r4-r7}\n\t"
        "mov    r12, r0\n\t"
        "ldr    r1, [r0, #52]\n\t"        // stride bytes
        "mov    lr, r1\n\t"
        "ldr    r2, [r0, #60]\n\t"        // zrow
        "mov    r10, r2\n\t"
        "ldr    r3, [r0, #20]\n\t"        // rows
        "muls   r3, r1, r3\n\t"
        "adds   r3, r3, r2\n\t"
        "mov    r11, r3\n\t"              // zrow after the last row
        "ldr    r1, [r0, #64]\n\t"        // dz
        "mov    r9, r1\n\t"
        "ldr    r1, [r0, #68]\n\t"        // colour offset
        "mov    r8, r1\n\t"
        "ldm    r0!, {r1-r5}\n\t"         // lpx lg lz rpx rg
        "mov    r0, r12\n"
        "1:\n\t"                          // row
        "cmp    r1, r4\n\t"
        "bge    3f\n\t"                   // empty span
        "stm    r0!, {r1-r4}\n\t"         // park lpx lg lz rpx; r0 = state + 16
        "subs   r1, r1, r4\n\t"
        "lsls   r1, r1, #1\n\t"           // x: bytes from the span's end, negative, counts up to 0
        "lsls   r4, r4, #1\n\t"
        "mov    r6, r10\n\t"
        "adds   r6, r6, r4\n\t"           // depth row + 2 rpx
        "mov    r2, r8\n\t"
        "adds   r2, r2, r6\n\t"           // colour row + 2 rpx
        "ldr    r4, [r0, #56]\n"           // colour (offset 72)
        "2:\n\t"                          // pixel
        "ldrh   r7, [r6, r1]\n\t"
        "lsrs   r0, r3, #16\n\t"
        "cmp    r7, r0\n\t"
        "bls    4f\n\t"                   // stored depth <= ours: keep it
        "strh   r0, [r6, r1]\n\t"
        "strh   r4, [r2, r1]\n"
        "4:\n\t"
        "add    r3, r9\n\t"
        "adds   r1, r1, #2\n\t"
        "bne    2b\n\t"
        "mov    r0, r12\n\t"
        "ldm    r0!, {r1-r4}\n\t"         // lpx lg lz rpx back
        "mov    r0, r12\n"
        "3:\n\t"                          // left edge: px += q, z += dz_row, g += m, then correct
        "ldr    r6, [r0, #32]\n\t"        // lq
        "adds   r1, r1, r6\n\t"
        "ldr    r6, [r0, #36]\n\t"        // ldz
        "adds   r3, r3, r6\n\t"
        "ldr    r6, [r0, #28]\n\t"        // lm
        "adds   r2, r2, r6\n\t"
        "bmi    5f\n\t"                   // g < 0: no correction
        "ldr    r6, [r0, #24]\n\t"        // la
        "subs   r2, r2, r6\n\t"
        "subs   r1, r1, #1\n\t"
        "ldr    r6, [r0, #56]\n\t"        // dzdx
        "subs   r3, r3, r6\n"
        "5:\n\t"                          // right edge
        "ldr    r6, [r0, #48]\n\t"        // rq
        "adds   r4, r4, r6\n\t"
        "ldr    r6, [r0, #44]\n\t"        // rm
        "adds   r5, r5, r6\n\t"
        "bmi    6f\n\t"
        "ldr    r6, [r0, #40]\n\t"        // ra
        "subs   r5, r5, r6\n\t"
        "subs   r4, r4, #1\n"
        "6:\n\t"                          // next depth row
        "add    r10, lr\n\t"
        "cmp    r10, r11\n\t"
        "bne    1b\n\t"
        "stm    r0!, {r1-r5}\n\t"         // lpx lg lz rpx rg
        "mov    r0, r12\n\t"
        "mov    r1, r10\n\t"
        "str    r1, [r0, #60]\n\t"        // zrow
        "pop    {r4-r7}\n\t"
        "mov    r8, r4\n\t"
        "mov    r9, r5\n\t"
        "mov    r10, r6\n\t"
        "mov    r11, r7\n\t"
        "pop    {r4-r7, pc}\n");
}
#endif

/// Runs k.rows >= 1 rows of the kernel (Thumb-2 on ARMv7-M, Thumb-1 on ARMv6-M, else the portable loop).
/// Preconditions (the assembly loops rely on them): rows >= 1 and stride_bytes != 0.
inline void run_row_kernel(RowKernel& k) {
    HIDER_ASSERT(k.rows >= 1 && k.stride_bytes != 0);
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    run_row_kernel_v7m(&k);
#elif defined(__ARM_ARCH_6M__)
    run_row_kernel_v6m(&k);
#else
    run_row_kernel_portable(k);
#endif
}

}  // namespace hider

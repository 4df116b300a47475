// The z-buffer's row kernel for its most common case: a flat-coloured triangle that stays inside the
// frame's columns, 16-bit pixels (RGB565) over a 16-bit depth buffer. One call runs `rows` rows: each
// row's depth-tested span [lpx, rpx) from depth lz, then both edges step as exact DDAs (the same
// arithmetic as TriangleRaster::scan_rows) and the depth row advances by the stride.
//
// run_row_kernel() is portable C++; on ARMv7-M (Cortex-M3/M4) it is a hand-scheduled Thumb-2 loop. At -Os
// GCC cannot keep the two edges, the row pointer and the span in registers across rows (about 60
// instructions a row with the span as a call, 45 of them outside the pixels); the assembly keeps every
// variable in a register and reloads the constants with load-multiples (about 27 a row), writing the
// same bytes. The firmware tests compare its frames with the host's, and firmware/selftest runs it
// against run_row_kernel_portable() on random edges.
#pragma once
#include <hider/base.hpp>

namespace hider {

/// State of the row kernel. The field order is the ARMv7-M loop's contract (load-multiples), checked
/// by the static_asserts below. Edges: px is the boundary pixel, g the error term in [0, a), stepped
/// per row by g += m, px += q, then one correction (g >= a: g -= a, px -= 1, and the left depth z -= dzdx).
struct RowKernel {
    int32_t lpx, lg;
    uint32_t lz;
    int32_t rpx, rg;
    int32_t rows;            ///< rows to run, >= 1
    int32_t la, lm, lq;
    uint32_t ldz, dzdx;      ///< left depth step per row (dz/dy + q dz/dx) and per pixel
    int32_t ra, rm, rq;
    int32_t stride_bytes;    ///< bytes from one depth row to the next
    uint16_t* zrow;          ///< depth row of the current row
    uint32_t dz;             ///< depth step per pixel (= dzdx)
    intptr_t color_offset;   ///< bytes from a pixel's depth to its colour
    uint32_t color;          ///< RGB565 in the low half
};

// The Thumb-2 loop's offsets (32-bit pointers).
static_assert(sizeof(void*) != 4 || (offsetof(RowKernel, rows) == 20 && offsetof(RowKernel, la) == 24 &&
                                     offsetof(RowKernel, ra) == 44 && offsetof(RowKernel, stride_bytes) == 56 &&
                                     offsetof(RowKernel, zrow) == 60 && offsetof(RowKernel, dz) == 64 &&
                                     offsetof(RowKernel, color) == 72),
              "row kernel layout");

/// The kernel in C++: k.rows rows, then k's edges, depth and zrow are those of the next row.
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
        if (lg >= k.la) { lg -= k.la; --lpx; lz -= k.dzdx; }
        rg += k.rm;
        rpx += k.rq;
        if (rg >= k.ra) { rg -= k.ra; --rpx; }
        zrow = reinterpret_cast<uint16_t*>(reinterpret_cast<uintptr_t>(zrow) + static_cast<uintptr_t>(k.stride_bytes));
    }
    k.lpx = lpx; k.lg = lg; k.lz = lz; k.rpx = rpx; k.rg = rg; k.zrow = zrow;
}

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// run_row_kernel_portable() in Thumb-2. Registers: r0 the state, r1..r5 lpx lg lz rpx rg, r6 rows
/// left, r7 zrow; per row the constants come back with one load-multiple per edge. Pixel loop: r11 x,
/// lr z, r12 scratch, r8 dz, r9 colour row, r10 colour (10 instructions a written pixel, 7 a rejected).
__attribute__((naked, noinline)) inline void run_row_kernel_v7m(RowKernel*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "ldm    r0, {r1-r6}\n\t"           // lpx lg lz rpx rg rows
        "ldr    r7, [r0, #60]\n"           // zrow
        "1:\n\t"                           // row
        "cmp    r1, r4\n\t"
        "bge    3f\n\t"                    // empty span
        "add    lr, r0, #64\n\t"
        "ldm    lr, {r8-r10}\n\t"          // dz, colour offset, colour
        "add    r9, r9, r7\n\t"            // colour row
        "mov    r11, r1\n\t"               // x = lpx
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
        "add    r11, r11, #1\n\t"
        "cmp    r11, r4\n\t"
        "bne    2b\n"
        "3:\n\t"                           // left edge: g += m, px += q, z += dz_row, then correct
        "add    lr, r0, #24\n\t"
        "ldm    lr, {r8-r12}\n\t"          // la lm lq ldz dzdx
        "add    r2, r2, r9\n\t"
        "add    r1, r1, r10\n\t"
        "add    r3, r3, r11\n\t"
        "cmp    r2, r8\n\t"
        "blt    5f\n\t"
        "sub    r2, r2, r8\n\t"
        "sub    r1, r1, #1\n\t"
        "sub    r3, r3, r12\n"
        "5:\n\t"                           // right edge, then the next depth row
        "add    lr, r0, #44\n\t"
        "ldm    lr, {r8-r11}\n\t"          // ra rm rq stride
        "add    r5, r5, r9\n\t"
        "add    r4, r4, r10\n\t"
        "cmp    r5, r8\n\t"
        "blt    6f\n\t"
        "sub    r5, r5, r8\n\t"
        "sub    r4, r4, #1\n"
        "6:\n\t"
        "add    r7, r7, r11\n\t"
        "subs   r6, r6, #1\n\t"
        "bne    1b\n\t"
        "stm    r0, {r1-r5}\n\t"
        "str    r7, [r0, #60]\n\t"
        "pop    {r4-r11, pc}\n");
}
#endif

/// Whether the z-buffer uses the kernel on this target. Not on ARMv6-M: with eight low registers the
/// portable loop spills more than the per-row span call it replaces (measured: torus 320x240 on the
/// Cortex-M0+ 2,307,935 with the span call, 2,467,354 through the kernel).
#if defined(__ARM_ARCH_6M__)
constexpr bool kUseRowKernel = false;
#else
constexpr bool kUseRowKernel = true;
#endif

/// Runs k.rows >= 1 rows of the kernel (Thumb-2 on ARMv7-M, else the portable loop).
inline void run_row_kernel(RowKernel& k) {
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    run_row_kernel_v7m(&k);
#else
    run_row_kernel_portable(k);
#endif
}

}  // namespace hider

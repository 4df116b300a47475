// run_kernel_triangle_portable() (row_kernel.hpp) in Thumb-2 for ARMv7-M, and its row loop as a macro
// (HIDER_V7M_ROWS) that the band loop's resumes share (band_loop_asm.hpp). Part of row_kernel_asm.hpp:
// include that header (or row_kernel.hpp), not this one.
#pragma once
#include <hider/raster/row_kernel.hpp>

namespace hider {

#if defined(HIDER_ARMV7M)
/// HIDER_V7M_PIXEL(entry, skip): one pixel of HIDER_V7M_ROWS's 16-pixel turn, entered at local label
/// `entry`: the depth at r9 (post-incremented) against z = lr's top half, on a pass both stores (colour at
/// r9 + r7, r10), then z += dzdx (r8); r12 scratch.
#define HIDER_V7M_PIXEL(entry, skip) \
    #entry ":\n\t" \
    "ldrh   r12, [r9], #2\n\t" \
    "cmp    r12, lr, lsr #16\n\t" \
    "bls    " #skip "f\n\t"                 /* stored depth <= ours: keep it */ \
    "lsr    r12, lr, #16\n\t" \
    "strh   r12, [r9, #-2]\n\t" \
    "strh   r10, [r9, r7]\n" \
    #skip ":\n\t" \
    "add    lr, lr, r8\n"

/// HIDER_V7M_ROWS: the row loop of run_kernel_triangle_v7m(), shared with draw_band_v7m()'s resumes
/// (band_loop_asm.hpp) and kernel_draw_v7m(). Entry: r0 the record + ra, r1..r5 lp lg lz rp rg, r6 rows
/// before a switch, r7 the colour offset less 2, r8 dzdx, r10 the colour; on the stack (its callers'
/// HIDER_V7M_ROWS_STACK) the middle row's depth pointer, the rows after the switch (-1: none; -1 again
/// after a switch) and the depth row after the last. Exit: the record (r0)
/// holds the next row's edges and depth, r12 that row's depth pointer (every other register clobbered).
/// r6 must be at least 1 (the row loop tests after its first row). A span of 0 to 16 pixels (one unsigned
/// compare) enters a straight run of 16 pixels by a table branch at the (17 - n)-th and falls out of it
/// into the edge steps; a longer one takes a 16-pixel loop entered Duff-style, a reversed one (rp < lp)
/// none. Uses local labels 71..79, 98, 99, 100..116 and 200..215, the operands ra, n_left, n_x, n_g, n_a,
/// lstep_ra, and rows_sp, rows_sp4, rows_sp8 (HIDER_V7M_ROWS_STACK).
#define HIDER_V7M_ROWS \
    "72:\n\t"                                /* row */ \
    "sub    r11, r4, r1\n\t"                 /* rp - lp: twice the pixels */ \
    "cmp    r11, #32\n\t" \
    "bhi    73f\n\t"                         /* more than 16, or rp < lp */ \
    "mov    r9, r1\n\t"                      /* p = lp */ \
    "mov    lr, r3\n\t"                      /* z = lz */ \
    "tbh    [pc, r11, lsl #1]\n"              /* n pixels: the halfword at 4 n */ \
    "99:\n\t" \
    ".hword (74f - 99b) / 2, 0, (215f - 99b) / 2, 0, (214f - 99b) / 2, 0, (213f - 99b) / 2, 0\n\t" \
    ".hword (212f - 99b) / 2, 0, (211f - 99b) / 2, 0, (210f - 99b) / 2, 0, (209f - 99b) / 2, 0\n\t" \
    ".hword (208f - 99b) / 2, 0, (207f - 99b) / 2, 0, (206f - 99b) / 2, 0, (205f - 99b) / 2, 0\n\t" \
    ".hword (204f - 99b) / 2, 0, (203f - 99b) / 2, 0, (202f - 99b) / 2, 0, (201f - 99b) / 2, 0\n\t" \
    ".hword (200f - 99b) / 2\n" \
    HIDER_V7M_PIXEL(200, 116)                 \
    HIDER_V7M_PIXEL(201, 116)                 \
    HIDER_V7M_PIXEL(202, 116)                 \
    HIDER_V7M_PIXEL(203, 116)                 \
    HIDER_V7M_PIXEL(204, 116)                 \
    HIDER_V7M_PIXEL(205, 116)                 \
    HIDER_V7M_PIXEL(206, 116)                 \
    HIDER_V7M_PIXEL(207, 116)                 \
    HIDER_V7M_PIXEL(208, 116)                 \
    HIDER_V7M_PIXEL(209, 116)                 \
    HIDER_V7M_PIXEL(210, 116)                 \
    HIDER_V7M_PIXEL(211, 116)                 \
    HIDER_V7M_PIXEL(212, 116)                 \
    HIDER_V7M_PIXEL(213, 116)                 \
    HIDER_V7M_PIXEL(214, 116)                 \
    HIDER_V7M_PIXEL(215, 116)                 \
    "74:\n\t"                                /* left edge: g += m, p += step, z += dz_row, then correct */ \
    "ldmdb  r0, {r9, r11, r12, lr}\n\t"      /* la lm lstep ldz */ \
    "adds   r2, r2, r11\n\t" \
    "add    r1, r1, r12\n\t" \
    "add    r3, r3, lr\n\t" \
    "bmi    71f\n\t"                         /* g < 0: no correction */ \
    "sub    r2, r2, r9\n\t" \
    "sub    r1, r1, #2\n\t" \
    "sub    r3, r3, r8\n"                    /* z -= dzdx */ \
    "71:\n\t"                                /* right edge */ \
    "ldm    r0, {r9, r11, r12}\n\t"          /* ra rm rstep */ \
    "adds   r5, r5, r11\n\t" \
    "add    r4, r4, r12\n\t" \
    "bmi    76f\n\t" \
    "sub    r5, r5, r9\n\t" \
    "sub    r4, r4, #2\n" \
    "76:\n\t" \
    "subs   r6, r6, #1\n\t" \
    "bne    72b\n\t" \
    "ldr    r6, [sp, %[rows_sp4]]\n\t"      /* rows after the switch */ \
    "cmp    r6, #0\n\t" \
    "blt    78f\n\t"                         /* no switch in this call */ \
    "ldr    r12, [sp, %[rows_sp]]\n\t"      /* the middle row */ \
    "ldrb   r9, [r0, %[n_left]]\n\t" \
    "cmp    r9, #0\n\t" \
    "beq    77f\n\t" \
    "ldr    r9, [r0, %[n_x]]\n\t"            /* the lower edge on the left */ \
    "add    r9, r12, r9\n\t" \
    "sub    r1, r9, r1\n\t" \
    "asr    r1, r1, #1\n\t"                  /* its px less the old edge's */ \
    "mla    r3, r1, r8, r3\n\t"              /* its z (next_edge_depth()) */ \
    "mov    r1, r9\n\t" \
    "add    r9, r0, %[n_a]\n\t" \
    "ldm    r9, {r9, r11, r12}\n\t"          /* a m step */ \
    "ldrd   r2, lr, [r0, %[lstep_ra]]\n\t"   /* the old step and depth step */ \
    "sub    r2, r12, r2\n\t" \
    "asr    r2, r2, #1\n\t"                  /* its q less the old edge's */ \
    "mla    lr, r2, r8, lr\n\t"              /* its depth step */ \
    "ldr    r2, [r0, %[n_g]]\n\t" \
    "stmdb  r0, {r9, r11, r12, lr}\n\t"      /* la lm lstep ldz */ \
    "b      79f\n" \
    "77:\n\t" \
    "ldr    r9, [r0, %[n_x]]\n\t"            /* the lower edge on the right */ \
    "add    r4, r12, r9\n\t" \
    "ldr    r5, [r0, %[n_g]]\n\t" \
    "add    r9, r0, %[n_a]\n\t" \
    "ldm    r9, {r9, r11, r12}\n\t" \
    "stm    r0, {r9, r11, r12}\n"            /* ra rm rstep */ \
    "79:\n\t" \
    "mov    r9, #-1\n\t" \
    "str    r9, [sp, %[rows_sp4]]\n\t"      /* switched */ \
    "cmp    r6, #0\n\t" \
    "bne    72b\n\t" \
    "b      78f\n" \
    "73:\n\t"                                /* more than 16 pixels, or rp < lp */ \
    "cmp    r11, #0\n\t" \
    "blt    74b\n\t"                         /* none */ \
    "mov    r9, r1\n\t" \
    "mov    lr, r3\n\t" \
    "ubfx   r11, r11, #1, #4\n\t"            /* pixels mod 16: where to enter the 16-pixel turn */ \
    "tbb    [pc, r11]\n"                      \
    "98:\n\t"                                \
    ".byte  (100f - 98b) / 2, (115f - 98b) / 2, (114f - 98b) / 2, (113f - 98b) / 2\n\t" \
    ".byte  (112f - 98b) / 2, (111f - 98b) / 2, (110f - 98b) / 2, (109f - 98b) / 2\n\t" \
    ".byte  (108f - 98b) / 2, (107f - 98b) / 2, (106f - 98b) / 2, (105f - 98b) / 2\n\t" \
    ".byte  (104f - 98b) / 2, (103f - 98b) / 2, (102f - 98b) / 2, (101f - 98b) / 2\n" \
    HIDER_V7M_PIXEL(100, 116)                 \
    HIDER_V7M_PIXEL(101, 116)                 \
    HIDER_V7M_PIXEL(102, 116)                 \
    HIDER_V7M_PIXEL(103, 116)                 \
    HIDER_V7M_PIXEL(104, 116)                 \
    HIDER_V7M_PIXEL(105, 116)                 \
    HIDER_V7M_PIXEL(106, 116)                 \
    HIDER_V7M_PIXEL(107, 116)                 \
    HIDER_V7M_PIXEL(108, 116)                 \
    HIDER_V7M_PIXEL(109, 116)                 \
    HIDER_V7M_PIXEL(110, 116)                 \
    HIDER_V7M_PIXEL(111, 116)                 \
    HIDER_V7M_PIXEL(112, 116)                 \
    HIDER_V7M_PIXEL(113, 116)                 \
    HIDER_V7M_PIXEL(114, 116)                 \
    HIDER_V7M_PIXEL(115, 116)                 \
    "cmp    r9, r4\n\t"                      \
    "bne    100b\n\t"                        \
    "b      74b\n"                            \
    "78:\n\t" \
    "ldr    r12, [sp, %[rows_sp8]]\n\t"     /* the depth row after the last */ \
    "sub    r1, r1, r12\n\t"                 /* back to offsets in that row */ \
    "sub    r4, r4, r12\n\t" \
    "sub    r0, r0, %[ra]\n\t" \
    "stm    r0, {r1-r5}\n\t"

/// HIDER_V7M_ROWS_STACK(at): where HIDER_V7M_ROWS finds its three stack words (the middle row's depth
/// pointer, the rows after the switch, the depth row after the last): at sp + at, + 4, + 8.
#define HIDER_V7M_ROWS_STACK(at) [rows_sp] "i"(at), [rows_sp4] "i"((at) + 4), [rows_sp8] "i"((at) + 8)

/// HIDER_V7M_ROWS's operands relative to ra (its callers give [ra] too).
#define HIDER_V7M_ROWS_OPERANDS \
    [n_left] "i"(offsetof(KernelTriangle, next_left) - offsetof(RowKernel, ra)), \
    [n_x] "i"(offsetof(KernelTriangle, next_x) - offsetof(RowKernel, ra)), \
    [n_g] "i"(offsetof(KernelTriangle, next_g) - offsetof(RowKernel, ra)), \
    [n_a] "i"(offsetof(KernelTriangle, next_a) - offsetof(RowKernel, ra)), \
    [lstep_ra] "i"(offsetof(RowKernel, lstep) - offsetof(RowKernel, ra))

/// Thumb-2. In the row loop: r0 the right edge's constants (offset 36) with the left edge's just below
/// (load-multiple decrement-before) and `next` above, r1..r5 lp lg lz rp rg, r6 rows left in this
/// phase, r7 colour offset less 2, r8 dz, r10 colour; on the stack the middle row's depth pointer, the
/// rows after the switch (-1: none) and the depth row after the last. Pixels as HIDER_V7M_ROWS says
/// (a span of n <= 16 in a straight run entered at its (17 - n)-th pixel, longer ones 16 a turn): r9 the
/// depth pointer, post-incremented, ending at rp (r4), the colour at r9 + r7, lr z, r12 scratch.
HIDER_NAKED inline uint16_t* run_kernel_triangle_v7m(KernelTriangle*, uint16_t*, int32_t,
                                                                          const KernelTarget*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "ldrsh  r4, [r0, %[row]]\n\t"
        "ldrsh  r6, [r0, %[end]]\n\t"
        "ldrsh  r5, [r0, %[mid]]\n\t"
        "cmp    r6, r2\n\t"
        "it     gt\n\t"
        "movgt  r6, r2\n\t"                 // stop = min(end, row_stop)
        "subs   r2, r6, r4\n\t"             // n rows
        "ble    95f\n\t"
        "strh   r6, [r0, %[row]]\n\t"       // the row after this call
        "ldrd   r9, r12, [r3]\n\t"          // colour offset, stride
        "mov    r6, r2\n\t"                 // rows before a switch: all
        "mov    r8, #-1\n\t"                // rows after it: none
        "subs   r7, r5, r4\n\t"             // m = mid - row
        "ble    1f\n\t"                     // on or below the middle row
        "ldrsh  r11, [r0, %[end]]\n\t"
        "cmp    r5, r11\n\t"
        "bge    1f\n\t"                     // no lower short edge
        "cmp    r7, r2\n\t"
        "bgt    1f\n\t"                     // the middle row lies past this call
        "mov    r6, r7\n\t"
        "sub    r8, r2, r7\n\t"
        "mla    r7, r7, r12, r1\n"           // the middle row's depth row
        "1:\n\t"
        "mla    r11, r2, r12, r1\n\t"       // the depth row after the last
        "push   {r7, r8, r11}\n\t"
        "sub    r7, r9, #2\n\t"             // colour offset, less the post-increment
        "mov    r9, r1\n\t"
        "ldrd   r8, r10, [r0, %[dzdx]]\n\t" // dzdx, colour
        "ldm    r0, {r1-r5}\n\t"            // lx lg lz rx rg
        "add    r1, r1, r9\n\t"             // lp
        "add    r4, r4, r9\n\t"             // rp
        "add    r0, r0, %[ra]\n"            // r0: the right edge's constants
        HIDER_V7M_ROWS
        "add    sp, sp, #12\n\t"
        "mov    r0, r12\n\t"
        "pop    {r4-r11, pc}\n"
        "95:\n\t"
        "mov    r0, r1\n\t"                 // nothing to draw
        "pop    {r4-r11, pc}\n"
        :
        : [row] "i"(offsetof(KernelTriangle, row)), [mid] "i"(offsetof(KernelTriangle, mid)),
          [end] "i"(offsetof(KernelTriangle, end)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [ra] "i"(offsetof(RowKernel, ra)),
          HIDER_V7M_ROWS_OPERANDS, HIDER_V7M_ROWS_STACK(0));
}
#endif

}  // namespace hider

// run_kernel_triangle_portable() (row_kernel.hpp) in assembly for the chips: Thumb-2 (ARMv7-M), Thumb-1
// (ARMv6-M) and RV32. One call draws a triangle's rows up to a stop row, switching to the lower short
// edge on the middle row. Both edges are kept as pointers into the current depth row (x + the row's
// start, stepped by x's step, which holds the stride), so a row costs the span's set-up, two edge steps
// and the loop: no depth-row pointer of its own. Spans index back from their end with a negative byte
// count up to 0 (Thumb-1) or walk a pointer (Thumb-2, post-incremented; RV32, which has no
// register-offset addressing). Also defines
// run_kernel_triangle(), which picks the kernel for the target; row_kernel.hpp includes this header at
// its end. firmware/kernelcheck compares each with the portable twin on random states.
#pragma once
#include <hider/raster/row_kernel.hpp>

namespace hider {

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// HIDER_V7M_ROWS: the row loop of run_kernel_triangle_v7m(), shared with draw_band_v7m()'s resumes
/// (band_loop_asm.hpp). Entry: r0 the record + ra, r1..r5 lp lg lz rp rg, r6 rows before a switch, r7
/// the colour offset less 2, r8 dzdx, r10 the colour; at sp the middle row's depth pointer, the rows after the
/// switch (-1: none) and the depth row after the last. Exit: the record (r0) holds the next row's edges
/// and depth, r12 that row's depth pointer (every other register clobbered). r6 must be at least 1 (the
/// row loop tests after its first row). Uses local labels 69..79 and the operands ra, n_left, n_x, n_g,
/// n_a, n_z, n_dz.
#define HIDER_V7M_ROWS \
    "72:\n\t"                                /* row */ \
    "subs   r11, r4, r1\n\t"                 /* rp - lp: twice the pixels */ \
    "ble    74f\n\t"                         /* empty span */ \
    "mov    r9, r1\n\t"                      /* p = lp */ \
    "mov    lr, r3\n\t"                      /* z = lz */ \
    "lsls   r11, r11, #31\n\t"               /* C: an odd number of pixels */ \
    "bcs    70f\n"                           /* the first one alone */ \
    "73:\n\t"                                /* two pixels */ \
    "ldrh   r12, [r9], #2\n\t" \
    "cmp    r12, lr, lsr #16\n\t" \
    "bls    75f\n\t"                         /* stored depth <= ours: keep it */ \
    "lsr    r12, lr, #16\n\t" \
    "strh   r12, [r9, #-2]\n\t" \
    "strh   r10, [r9, r7]\n" \
    "75:\n\t" \
    "add    lr, lr, r8\n" \
    "70:\n\t" \
    "ldrh   r12, [r9], #2\n\t" \
    "cmp    r12, lr, lsr #16\n\t" \
    "bls    69f\n\t" \
    "lsr    r12, lr, #16\n\t" \
    "strh   r12, [r9, #-2]\n\t" \
    "strh   r10, [r9, r7]\n" \
    "69:\n\t" \
    "add    lr, lr, r8\n\t" \
    "cmp    r9, r4\n\t" \
    "bne    73b\n" \
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
    "ldr    r6, [sp, #4]\n\t"                /* rows after the switch */ \
    "cmp    r6, #0\n\t" \
    "blt    78f\n\t"                         /* no switch in this call */ \
    "ldr    r12, [sp]\n\t"                   /* the middle row */ \
    "ldrb   r9, [r0, %[n_left]]\n\t" \
    "cmp    r9, #0\n\t" \
    "beq    77f\n\t" \
    "ldr    r9, [r0, %[n_x]]\n\t"            /* the lower edge on the left */ \
    "add    r1, r12, r9\n\t" \
    "ldr    r2, [r0, %[n_g]]\n\t" \
    "ldr    r3, [r0, %[n_z]]\n\t" \
    "add    r9, r0, %[n_a]\n\t" \
    "ldm    r9, {r9, r11, r12}\n\t"          /* a m step */ \
    "ldr    lr, [r0, %[n_dz]]\n\t" \
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
    "str    r9, [sp, #4]\n\t"                /* switched */ \
    "cmp    r6, #0\n\t" \
    "bne    72b\n" \
    "78:\n\t" \
    "ldr    r12, [sp, #8]\n\t"               /* the depth row after the last */ \
    "sub    r1, r1, r12\n\t"                 /* back to offsets in that row */ \
    "sub    r4, r4, r12\n\t" \
    "sub    r0, r0, %[ra]\n\t" \
    "stm    r0, {r1-r5}\n\t"

/// Thumb-2. In the row loop: r0 the right edge's constants (offset 36) with the left edge's just below
/// (load-multiple decrement-before) and `next` above, r1..r5 lp lg lz rp rg, r6 rows left in this
/// phase, r7 colour offset less 2, r8 dz, r10 colour; on the stack the middle row's depth pointer, the
/// rows after the switch (-1: none) and the depth row after the last. Pixel loop, two pixels a turn
/// (an odd span enters at the second): r9 the depth pointer, post-incremented, ending at rp (r4), the
/// colour at r9 + r7, lr z, r12 scratch (7 instructions a written pixel, 4 a rejected one, 2 a pair).
/// Per row outside the pixels: 17, plus 3 and 2 for edge corrections.
__attribute__((naked, noinline)) inline uint16_t* run_kernel_triangle_v7m(KernelTriangle*, uint16_t*, int32_t,
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
          [n_left] "i"(offsetof(KernelTriangle, next_left) - offsetof(RowKernel, ra)),
          [n_x] "i"(offsetof(KernelTriangle, next_x) - offsetof(RowKernel, ra)),
          [n_g] "i"(offsetof(KernelTriangle, next_g) - offsetof(RowKernel, ra)),
          [n_a] "i"(offsetof(KernelTriangle, next_a) - offsetof(RowKernel, ra)),
          [n_z] "i"(offsetof(KernelTriangle, next_z) - offsetof(RowKernel, ra)),
          [n_dz] "i"(offsetof(KernelTriangle, next_dz) - offsetof(RowKernel, ra)));
}
#endif

#if defined(__ARM_ARCH_6M__)
/// Thumb-1 (Cortex-M0/M0+: eight low registers, no conditional execution). In the row loop r0 holds
/// the state, r1..r5 lp lg lz rp rg, r7 rows left in this phase, r12 the state again, r8 the colour
/// offset, r9 dz, r10 the colour; on the stack the middle row's depth pointer, the rows after the switch
/// (-1: none), the depth row after the last. Edge constants are loaded where used. A span parks lp lg lz
/// and the row count in the state with one store-multiple; its pixel loop indexes back from the span's
/// end (r4 depth, r1 colour) with r6 = lp - rp counting up to 0, r3 z, r7 colour (9 instructions a
/// written pixel, 7 a rejected one).
__attribute__((naked, noinline)) inline uint16_t* run_kernel_triangle_v6m(KernelTriangle*, uint16_t*, int32_t,
                                                                          const KernelTarget*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r7, lr}\n\t"
        "mov    r4, r8\n\t"
        "mov    r5, r9\n\t"
        "mov    r6, r10\n\t"
        "mov    r7, r11\n\t"
        "push   {r4-r7}\n\t"
        "sub    sp, sp, #16\n\t"            // middle row, rows after the switch, last row, target
        "str    r3, [sp, #12]\n\t"
        "ldrh   r4, [r0, %[row]]\n\t"
        "sxth   r4, r4\n\t"
        "ldrh   r6, [r0, %[end]]\n\t"
        "sxth   r6, r6\n\t"
        "cmp    r6, r2\n\t"
        "ble    1f\n\t"
        "mov    r6, r2\n"                   // stop = min(end, row_stop)
        "1:\n\t"
        "subs   r2, r6, r4\n\t"             // n rows
        "ble    95f\n\t"
        "strh   r6, [r0, %[row]]\n\t"       // the row after this call
        "mov    r6, r2\n\t"                 // rows before a switch: all
        "movs   r7, #0\n\t"
        "mvns   r7, r7\n\t"                 // rows after it: none (-1)
        "ldrh   r5, [r0, %[mid]]\n\t"
        "sxth   r5, r5\n\t"
        "subs   r4, r5, r4\n\t"             // m = mid - row
        "ble    2f\n\t"                     // on or below the middle row
        "ldrh   r3, [r0, %[end]]\n\t"
        "sxth   r3, r3\n\t"
        "cmp    r5, r3\n\t"
        "bge    2f\n\t"                     // no lower short edge
        "cmp    r4, r2\n\t"
        "bgt    2f\n\t"                     // the middle row lies past this call
        "mov    r6, r4\n\t"
        "subs   r7, r2, r4\n"
        "2:\n\t"
        "str    r7, [sp, #4]\n\t"
        "ldr    r3, [sp, #12]\n\t"          // target
        "ldr    r5, [r3, #4]\n\t"           // stride
        "muls   r4, r5, r4\n\t"
        "adds   r4, r4, r1\n\t"
        "str    r4, [sp]\n\t"               // the middle row's depth pointer (with a switch)
        "muls   r2, r5, r2\n\t"
        "adds   r2, r2, r1\n\t"
        "str    r2, [sp, #8]\n\t"           // the depth row after the last
        "ldr    r4, [r3]\n\t"
        "mov    r8, r4\n\t"                 // colour offset
        "ldr    r4, [r0, %[dzdx]]\n\t"
        "mov    r9, r4\n\t"
        "ldr    r4, [r0, %[color]]\n\t"
        "mov    r10, r4\n\t"
        "mov    r12, r0\n\t"
        "mov    r7, r6\n\t"                 // rows of this phase
        "mov    r6, r1\n\t"
        "ldm    r0!, {r1-r5}\n\t"           // lx lg lz rx rg
        "mov    r0, r12\n\t"
        "adds   r1, r1, r6\n\t"             // lp
        "adds   r4, r4, r6\n"               // rp
        "3:\n\t"                            // row
        "subs   r6, r1, r4\n\t"             // lp - rp: negative, counts up to 0
        "bge    5f\n\t"                     // empty span
        "stm    r0!, {r1, r2, r3, r7}\n\t"  // park lp lg lz rows
        "mov    r1, r8\n\t"
        "adds   r1, r1, r4\n\t"             // the colour end
        "mov    r7, r10\n"                  // colour
        "4:\n\t"                            // pixel
        "ldrh   r2, [r4, r6]\n\t"
        "lsrs   r0, r3, #16\n\t"
        "cmp    r2, r0\n\t"
        "bls    6f\n\t"                     // stored depth <= ours: keep it
        "strh   r0, [r4, r6]\n\t"
        "strh   r7, [r1, r6]\n"
        "6:\n\t"
        "add    r3, r9\n\t"
        "adds   r6, r6, #2\n\t"
        "bne    4b\n\t"
        "mov    r0, r12\n\t"
        "ldm    r0!, {r1, r2, r3, r7}\n\t"  // lp lg lz rows back
        "mov    r0, r12\n"
        "5:\n\t"                            // left edge: p += step, z += dz_row, g += m, then correct
        "ldr    r6, [r0, %[lstep]]\n\t"
        "adds   r1, r1, r6\n\t"
        "ldr    r6, [r0, %[ldz]]\n\t"
        "adds   r3, r3, r6\n\t"
        "ldr    r6, [r0, %[lm]]\n\t"
        "adds   r2, r2, r6\n\t"
        "bmi    7f\n\t"                     // g < 0: no correction
        "ldr    r6, [r0, %[la]]\n\t"
        "subs   r2, r2, r6\n\t"
        "subs   r1, r1, #2\n\t"
        "mov    r6, r9\n\t"
        "subs   r3, r3, r6\n"               // z -= dzdx
        "7:\n\t"                            // right edge
        "ldr    r6, [r0, %[rstep]]\n\t"
        "adds   r4, r4, r6\n\t"
        "ldr    r6, [r0, %[rm]]\n\t"
        "adds   r5, r5, r6\n\t"
        "bmi    8f\n\t"
        "ldr    r6, [r0, %[ra]]\n\t"
        "subs   r5, r5, r6\n\t"
        "subs   r4, r4, #2\n"
        "8:\n\t"
        "subs   r7, r7, #1\n\t"
        "bne    3b\n\t"
        "ldr    r7, [sp, #4]\n\t"           // rows after the switch
        "cmp    r7, #0\n\t"
        "blt    90f\n\t"                    // no switch in this call
        "movs   r6, %[n_left]\n\t"
        "ldrb   r6, [r0, r6]\n\t"
        "cmp    r6, #0\n\t"
        "ldr    r6, [sp]\n\t"               // the middle row
        "beq    9f\n\t"
        "ldr    r1, [r0, %[n_x]]\n\t"       // the lower edge on the left
        "adds   r1, r1, r6\n\t"
        "ldr    r2, [r0, %[n_a]]\n\t"
        "str    r2, [r0, %[la]]\n\t"
        "ldr    r2, [r0, %[n_m]]\n\t"
        "str    r2, [r0, %[lm]]\n\t"
        "ldr    r2, [r0, %[n_step]]\n\t"
        "str    r2, [r0, %[lstep]]\n\t"
        "ldr    r2, [r0, %[n_dz]]\n\t"
        "str    r2, [r0, %[ldz]]\n\t"
        "ldr    r3, [r0, %[n_z]]\n\t"
        "ldr    r2, [r0, %[n_g]]\n\t"
        "b      10f\n"
        "9:\n\t"
        "ldr    r4, [r0, %[n_x]]\n\t"       // the lower edge on the right
        "adds   r4, r4, r6\n\t"
        "ldr    r5, [r0, %[n_a]]\n\t"
        "str    r5, [r0, %[ra]]\n\t"
        "ldr    r5, [r0, %[n_m]]\n\t"
        "str    r5, [r0, %[rm]]\n\t"
        "ldr    r5, [r0, %[n_step]]\n\t"
        "str    r5, [r0, %[rstep]]\n\t"
        "ldr    r5, [r0, %[n_g]]\n"
        "10:\n\t"
        "movs   r6, #0\n\t"
        "mvns   r6, r6\n\t"
        "str    r6, [sp, #4]\n\t"           // switched
        "cmp    r7, #0\n\t"
        "bne    3b\n"
        "90:\n\t"
        "ldr    r6, [sp, #8]\n\t"           // the depth row after the last
        "subs   r1, r1, r6\n\t"             // back to offsets in that row
        "subs   r4, r4, r6\n\t"
        "stm    r0!, {r1-r5}\n\t"
        "mov    r0, r6\n\t"
        "b      96f\n"
        "95:\n\t"
        "mov    r0, r1\n"                   // nothing to draw
        "96:\n\t"
        "add    sp, sp, #16\n\t"
        "pop    {r4-r7}\n\t"
        "mov    r8, r4\n\t"
        "mov    r9, r5\n\t"
        "mov    r10, r6\n\t"
        "mov    r11, r7\n\t"
        "pop    {r4-r7, pc}\n"
        :
        : [row] "i"(offsetof(KernelTriangle, row)), [mid] "i"(offsetof(KernelTriangle, mid)),
          [end] "i"(offsetof(KernelTriangle, end)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [color] "i"(offsetof(RowKernel, color)), [la] "i"(offsetof(RowKernel, la)), [lm] "i"(offsetof(RowKernel, lm)),
          [lstep] "i"(offsetof(RowKernel, lstep)), [ldz] "i"(offsetof(RowKernel, ldz)), [ra] "i"(offsetof(RowKernel, ra)),
          [rm] "i"(offsetof(RowKernel, rm)), [rstep] "i"(offsetof(RowKernel, rstep)),
          [n_left] "i"(offsetof(KernelTriangle, next_left)), [n_x] "i"(offsetof(KernelTriangle, next_x)),
          [n_g] "i"(offsetof(KernelTriangle, next_g)), [n_a] "i"(offsetof(KernelTriangle, next_a)),
          [n_m] "i"(offsetof(KernelTriangle, next_m)), [n_step] "i"(offsetof(KernelTriangle, next_step)),
          [n_z] "i"(offsetof(KernelTriangle, next_z)), [n_dz] "i"(offsetof(KernelTriangle, next_dz)));
}
#endif

#if defined(__riscv) && __riscv_xlen == 32
/// RV32. In the row loop: a0 the state, a4..a7 lp lg lz rp, t0 rg, t1..t5 lm lstep ldz rm rstep, t6 dz,
/// s0 the colour, a2 rows left in this phase, a3 the colour offset; la and ra are loaded by the
/// corrections; on the stack the middle row's depth pointer, the rows after the switch (-1: none) and
/// the depth row after the last. Pixel loop, two pixels a pass after an odd one: s1 walks the depth
/// elements up to rp, s2 z, a1 and s3 scratch (8 instructions a written pixel, 5 a rejected one, one
/// more for the odd pixel). Per row outside the pixels: 15, plus 4 and 3 for edge corrections.
__attribute__((naked, noinline)) inline uint16_t* run_kernel_triangle_rv32(KernelTriangle*, uint16_t*, int32_t,
                                                                           const KernelTarget*) {
    __asm__ volatile(
        "lh     t0, %[row](a0)\n\t"
        "lh     t1, %[end](a0)\n\t"
        "lh     t2, %[mid](a0)\n\t"
        "bge    a2, t1, 1f\n\t"
        "mv     t1, a2\n"                   // stop = min(end, row_stop)
        "1:\n\t"
        "sub    a2, t1, t0\n\t"             // n rows
        "blez   a2, 95f\n\t"
        "sh     t1, %[row](a0)\n\t"         // the row after this call
        "mv     t3, a2\n\t"                 // rows before a switch: all
        "li     t4, -1\n\t"                 // rows after it: none
        "sub    t5, t2, t0\n\t"             // m = mid - row
        "blez   t5, 2f\n\t"                 // on or below the middle row
        "lh     t6, %[end](a0)\n\t"
        "bge    t2, t6, 2f\n\t"             // no lower short edge
        "blt    a2, t5, 2f\n\t"             // the middle row lies past this call
        "mv     t3, t5\n\t"
        "sub    t4, a2, t5\n"
        "2:\n\t"
        "addi   sp, sp, -32\n\t"
        "sw     s0, 0(sp)\n\t"
        "sw     s1, 4(sp)\n\t"
        "sw     s2, 8(sp)\n\t"
        "sw     s3, 12(sp)\n\t"
        "sw     t4, 16(sp)\n\t"             // rows after the switch
        "lw     t0, 4(a3)\n\t"              // stride
        "lw     a3, 0(a3)\n\t"              // colour offset
        "mul    t5, t5, t0\n\t"
        "add    t5, t5, a1\n\t"
        "sw     t5, 20(sp)\n\t"             // the middle row's depth pointer (with a switch)
        "mul    t0, t0, a2\n\t"
        "add    t0, t0, a1\n\t"
        "sw     t0, 24(sp)\n\t"             // the depth row after the last
        "mv     a2, t3\n\t"                 // rows of this phase
        "lw     a4, 0(a0)\n\t"              // lx
        "lw     a5, 4(a0)\n\t"              // lg
        "lw     a6, 8(a0)\n\t"              // lz
        "lw     a7, 12(a0)\n\t"             // rx
        "lw     t0, 16(a0)\n\t"             // rg
        "add    a4, a4, a1\n\t"             // lp
        "add    a7, a7, a1\n\t"             // rp
        "lw     t1, %[lm](a0)\n\t"
        "lw     t2, %[lstep](a0)\n\t"
        "lw     t3, %[ldz](a0)\n\t"
        "lw     t4, %[rm](a0)\n\t"
        "lw     t5, %[rstep](a0)\n\t"
        "lw     t6, %[dzdx](a0)\n\t"
        "lw     s0, %[color](a0)\n"
        "3:\n\t"                            // row
        "bgeu   a4, a7, 5f\n\t"             // empty span
        "mv     s1, a4\n\t"
        "mv     s2, a6\n\t"                 // z = lz
        "sub    a1, a7, a4\n\t"
        "andi   a1, a1, 2\n\t"
        "beqz   a1, 4f\n\t"                 // an even count: pairs only
        "lhu    a1, 0(s1)\n\t"              // the odd pixel
        "srli   s3, s2, 16\n\t"
        "bgeu   s3, a1, 11f\n\t"            // stored depth <= ours: keep it
        "sh     s3, 0(s1)\n\t"
        "add    s3, s1, a3\n\t"
        "sh     s0, 0(s3)\n"
        "11:\n\t"
        "add    s2, s2, t6\n\t"
        "addi   s1, s1, 2\n\t"
        "beq    s1, a7, 5f\n"
        "4:\n\t"                            // two pixels
        "lhu    a1, 0(s1)\n\t"
        "srli   s3, s2, 16\n\t"
        "bgeu   s3, a1, 12f\n\t"
        "sh     s3, 0(s1)\n\t"
        "add    s3, s1, a3\n\t"
        "sh     s0, 0(s3)\n"
        "12:\n\t"
        "add    s2, s2, t6\n\t"
        "lhu    a1, 2(s1)\n\t"
        "srli   s3, s2, 16\n\t"
        "bgeu   s3, a1, 13f\n\t"
        "sh     s3, 2(s1)\n\t"
        "add    s3, s1, a3\n\t"
        "sh     s0, 2(s3)\n"
        "13:\n\t"
        "add    s2, s2, t6\n\t"
        "addi   s1, s1, 4\n\t"
        "bne    s1, a7, 4b\n"
        "5:\n\t"                            // left edge: g += m, p += step, z += dz_row, then correct
        "add    a5, a5, t1\n\t"
        "add    a4, a4, t2\n\t"
        "add    a6, a6, t3\n\t"
        "bltz   a5, 7f\n\t"                 // g < 0: no correction
        "lw     a1, %[la](a0)\n\t"
        "sub    a5, a5, a1\n\t"
        "addi   a4, a4, -2\n\t"
        "sub    a6, a6, t6\n"               // z -= dzdx
        "7:\n\t"                            // right edge
        "add    t0, t0, t4\n\t"
        "add    a7, a7, t5\n\t"
        "bltz   t0, 8f\n\t"
        "lw     a1, %[ra](a0)\n\t"
        "sub    t0, t0, a1\n\t"
        "addi   a7, a7, -2\n"
        "8:\n\t"
        "addi   a2, a2, -1\n\t"
        "bnez   a2, 3b\n\t"
        "lw     a2, 16(sp)\n\t"             // rows after the switch
        "bltz   a2, 90f\n\t"                // no switch in this call
        "lw     a1, 20(sp)\n\t"             // the middle row
        "lbu    s1, %[n_left](a0)\n\t"
        "lw     s2, %[n_x](a0)\n\t"
        "add    s2, s2, a1\n\t"
        "lw     s3, %[n_g](a0)\n\t"
        "lw     a1, %[n_a](a0)\n\t"
        "beqz   s1, 9f\n\t"
        "mv     a4, s2\n\t"                 // the lower edge on the left
        "mv     a5, s3\n\t"
        "lw     a6, %[n_z](a0)\n\t"
        "sw     a1, %[la](a0)\n\t"
        "lw     t1, %[n_m](a0)\n\t"
        "sw     t1, %[lm](a0)\n\t"
        "lw     t2, %[n_step](a0)\n\t"
        "sw     t2, %[lstep](a0)\n\t"
        "lw     t3, %[n_dz](a0)\n\t"
        "sw     t3, %[ldz](a0)\n\t"
        "j      10f\n"
        "9:\n\t"
        "mv     a7, s2\n\t"                 // the lower edge on the right
        "mv     t0, s3\n\t"
        "sw     a1, %[ra](a0)\n\t"
        "lw     t4, %[n_m](a0)\n\t"
        "sw     t4, %[rm](a0)\n\t"
        "lw     t5, %[n_step](a0)\n\t"
        "sw     t5, %[rstep](a0)\n"
        "10:\n\t"
        "li     a1, -1\n\t"
        "sw     a1, 16(sp)\n\t"             // switched
        "bnez   a2, 3b\n"
        "90:\n\t"
        "lw     a1, 24(sp)\n\t"             // the depth row after the last
        "sub    a4, a4, a1\n\t"             // back to offsets in that row
        "sub    a7, a7, a1\n\t"
        "sw     a4, 0(a0)\n\t"
        "sw     a5, 4(a0)\n\t"
        "sw     a6, 8(a0)\n\t"
        "sw     a7, 12(a0)\n\t"
        "sw     t0, 16(a0)\n\t"
        "mv     a0, a1\n\t"
        "lw     s0, 0(sp)\n\t"
        "lw     s1, 4(sp)\n\t"
        "lw     s2, 8(sp)\n\t"
        "lw     s3, 12(sp)\n\t"
        "addi   sp, sp, 32\n\t"
        "ret\n"
        "95:\n\t"
        "mv     a0, a1\n\t"                 // nothing to draw
        "ret\n"
        :
        : [row] "i"(offsetof(KernelTriangle, row)), [mid] "i"(offsetof(KernelTriangle, mid)),
          [end] "i"(offsetof(KernelTriangle, end)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [color] "i"(offsetof(RowKernel, color)), [la] "i"(offsetof(RowKernel, la)), [lm] "i"(offsetof(RowKernel, lm)),
          [lstep] "i"(offsetof(RowKernel, lstep)), [ldz] "i"(offsetof(RowKernel, ldz)), [ra] "i"(offsetof(RowKernel, ra)),
          [rm] "i"(offsetof(RowKernel, rm)), [rstep] "i"(offsetof(RowKernel, rstep)),
          [n_left] "i"(offsetof(KernelTriangle, next_left)), [n_x] "i"(offsetof(KernelTriangle, next_x)),
          [n_g] "i"(offsetof(KernelTriangle, next_g)), [n_a] "i"(offsetof(KernelTriangle, next_a)),
          [n_m] "i"(offsetof(KernelTriangle, next_m)), [n_step] "i"(offsetof(KernelTriangle, next_step)),
          [n_z] "i"(offsetof(KernelTriangle, next_z)), [n_dz] "i"(offsetof(KernelTriangle, next_dz)));
}
#endif

/// Draws rows [t.row, min(t.end, row_stop)) of a set-up triangle into target `target` from depth row
/// `zrow` (that of t.row), switching to the lower short edge on the middle row, and leaves t on the next
/// row; returns the depth pointer of that row (Thumb-2 on ARMv7-M, Thumb-1 on ARMv6-M, RV32, else
/// run_kernel_triangle_portable()).
__attribute__((always_inline)) inline uint16_t* run_kernel_triangle(KernelTriangle& t, uint16_t* zrow, int32_t row_stop,
                                                                    const KernelTarget& target) {
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    return run_kernel_triangle_v7m(&t, zrow, row_stop, &target);
#elif defined(__ARM_ARCH_6M__)
    return run_kernel_triangle_v6m(&t, zrow, row_stop, &target);
#elif defined(__riscv) && __riscv_xlen == 32
    return run_kernel_triangle_rv32(&t, zrow, row_stop, &target);
#else
    return run_kernel_triangle_portable(t, zrow, row_stop, target);
#endif
}

}  // namespace hider

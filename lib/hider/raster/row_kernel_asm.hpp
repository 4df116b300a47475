// run_row_kernel_portable() (row_kernel.hpp) in assembly for the chips: Thumb-2 (ARMv7-M), Thumb-1
// (ARMv6-M) and RV32. Each keeps both edges as pointers into the current depth row (x + the row's start,
// stepped by x's step, which holds the stride), so a row costs the span's set-up, two edge steps and the
// loop: no depth-row pointer of its own. Spans index back from their end with a negative byte count up
// to 0 (ARM) or walk a pointer (RV32, which has no register-offset addressing). Also defines
// run_row_kernel(), which picks the kernel for the target; row_kernel.hpp includes this header at its
// end. firmware/kernelcheck compares each with the portable loop on random states.
#pragma once
#include <hider/raster/row_kernel.hpp>

namespace hider {

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// Thumb-2. Registers: r0 the right edge's constants (offset 36) with the left edge's just below
/// (load-multiple decrement-before), r1..r5 lp lg lz rp rg, r6 rows left, r7 colour offset, r8 dz,
/// r10 colour; the next depth row on the stack. Pixel loop: r11 = lp - rp counting up to 0, r4 and r9
/// the depth and colour ends, lr z, r12 scratch (9 instructions a written pixel, 6 a rejected one). Per
/// row outside the pixels: 15, plus 3 and 2 for edge corrections.
__attribute__((naked, noinline)) inline uint16_t* run_row_kernel_v7m(RowKernel*, uint16_t*, int32_t, intptr_t) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "ldr    r12, [r0, %[stride]]\n\t"
        "mla    r12, r2, r12, r1\n\t"
        "push   {r12}\n\t"                  // the depth row after the last
        "mov    r6, r2\n\t"                 // rows
        "mov    r7, r3\n\t"                 // colour offset
        "mov    r9, r1\n\t"                 // depth row
        "ldr    r8, [r0, %[dzdx]]\n\t"
        "ldr    r10, [r0, %[color]]\n\t"
        "ldm    r0, {r1-r5}\n\t"            // lx lg lz rx rg
        "add    r1, r1, r9\n\t"             // lp
        "add    r4, r4, r9\n\t"             // rp
        "add    r0, r0, %[ra]\n"            // r0: the right edge's constants
        "1:\n\t"                            // row
        "subs   r11, r1, r4\n\t"            // lp - rp: negative, counts up to 0
        "bge    3f\n\t"                     // empty span
        "add    r9, r4, r7\n\t"             // the colour end
        "mov    lr, r3\n"                   // z = lz
        "2:\n\t"                            // pixel
        "ldrh   r12, [r4, r11]\n\t"
        "cmp    r12, lr, lsr #16\n\t"
        "bls    4f\n\t"                     // stored depth <= ours: keep it
        "lsr    r12, lr, #16\n\t"
        "strh   r12, [r4, r11]\n\t"
        "strh   r10, [r9, r11]\n"
        "4:\n\t"
        "add    lr, lr, r8\n\t"
        "adds   r11, r11, #2\n\t"
        "bne    2b\n"
        "3:\n\t"                            // left edge: g += m, p += step, z += dz_row, then correct
        "ldmdb  r0, {r9, r11, r12, lr}\n\t" // la lm lstep ldz
        "adds   r2, r2, r11\n\t"
        "add    r1, r1, r12\n\t"
        "add    r3, r3, lr\n\t"
        "bmi    5f\n\t"                     // g < 0: no correction
        "sub    r2, r2, r9\n\t"
        "sub    r1, r1, #2\n\t"
        "sub    r3, r3, r8\n"               // z -= dzdx
        "5:\n\t"                            // right edge
        "ldm    r0, {r9, r11, r12}\n\t"     // ra rm rstep
        "adds   r5, r5, r11\n\t"
        "add    r4, r4, r12\n\t"
        "bmi    6f\n\t"
        "sub    r5, r5, r9\n\t"
        "sub    r4, r4, #2\n"
        "6:\n\t"
        "subs   r6, r6, #1\n\t"
        "bne    1b\n\t"
        "pop    {r12}\n\t"
        "sub    r1, r1, r12\n\t"            // back to offsets in the next row
        "sub    r4, r4, r12\n\t"
        "sub    r0, r0, %[ra]\n\t"
        "stm    r0, {r1-r5}\n\t"
        "mov    r0, r12\n\t"
        "pop    {r4-r11, pc}\n"
        :
        : [stride] "i"(offsetof(RowKernel, stride_bytes)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [color] "i"(offsetof(RowKernel, color)), [ra] "i"(offsetof(RowKernel, ra)));
}
#endif

#if defined(__ARM_ARCH_6M__)
/// Thumb-1 (Cortex-M0/M0+: eight low registers, no conditional execution). Between rows r0 holds the
/// state, r1..r5 lp lg lz rp rg, r7 rows left, r12 the state again, r8 the colour offset, r9 dz, r10 the
/// colour, r11 the next depth row; edge constants are loaded where used. A span parks lp lg lz and the
/// row count in the state with one store-multiple; its pixel loop indexes back from the span's end (r4
/// depth, r1 colour) with r6 = lp - rp counting up to 0, r3 z, r7 colour (9 instructions a written
/// pixel, 7 a rejected one).
__attribute__((naked, noinline)) inline uint16_t* run_row_kernel_v6m(RowKernel*, uint16_t*, int32_t, intptr_t) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r7, lr}\n\t"
        "mov    r4, r8\n\t"
        "mov    r5, r9\n\t"
        "mov    r6, r10\n\t"
        "mov    r7, r11\n\t"
        "push   {r4-r7}\n\t"
        "mov    r12, r0\n\t"
        "mov    r8, r3\n\t"                 // colour offset
        "ldr    r4, [r0, %[stride]]\n\t"
        "muls   r4, r2, r4\n\t"
        "adds   r4, r4, r1\n\t"
        "mov    r11, r4\n\t"                // the depth row after the last
        "ldr    r4, [r0, %[dzdx]]\n\t"
        "mov    r9, r4\n\t"
        "ldr    r4, [r0, %[color]]\n\t"
        "mov    r10, r4\n\t"
        "mov    r7, r2\n\t"                 // rows
        "mov    r6, r1\n\t"                 // depth row
        "ldm    r0!, {r1-r5}\n\t"           // lx lg lz rx rg
        "mov    r0, r12\n\t"
        "adds   r1, r1, r6\n\t"             // lp
        "adds   r4, r4, r6\n"               // rp
        "1:\n\t"                            // row
        "subs   r6, r1, r4\n\t"             // lp - rp: negative, counts up to 0
        "bge    3f\n\t"                     // empty span
        "stm    r0!, {r1, r2, r3, r7}\n\t"  // park lp lg lz rows
        "mov    r1, r8\n\t"
        "adds   r1, r1, r4\n\t"             // the colour end
        "mov    r7, r10\n"                  // colour
        "2:\n\t"                            // pixel
        "ldrh   r2, [r4, r6]\n\t"
        "lsrs   r0, r3, #16\n\t"
        "cmp    r2, r0\n\t"
        "bls    4f\n\t"                     // stored depth <= ours: keep it
        "strh   r0, [r4, r6]\n\t"
        "strh   r7, [r1, r6]\n"
        "4:\n\t"
        "add    r3, r9\n\t"
        "adds   r6, r6, #2\n\t"
        "bne    2b\n\t"
        "mov    r0, r12\n\t"
        "ldm    r0!, {r1, r2, r3, r7}\n\t"  // lp lg lz rows back
        "mov    r0, r12\n"
        "3:\n\t"                            // left edge: p += step, z += dz_row, g += m, then correct
        "ldr    r6, [r0, %[lstep]]\n\t"
        "adds   r1, r1, r6\n\t"
        "ldr    r6, [r0, %[ldz]]\n\t"
        "adds   r3, r3, r6\n\t"
        "ldr    r6, [r0, %[lm]]\n\t"
        "adds   r2, r2, r6\n\t"
        "bmi    5f\n\t"                     // g < 0: no correction
        "ldr    r6, [r0, %[la]]\n\t"
        "subs   r2, r2, r6\n\t"
        "subs   r1, r1, #2\n\t"
        "mov    r6, r9\n\t"
        "subs   r3, r3, r6\n"               // z -= dzdx
        "5:\n\t"                            // right edge
        "ldr    r6, [r0, %[rstep]]\n\t"
        "adds   r4, r4, r6\n\t"
        "ldr    r6, [r0, %[rm]]\n\t"
        "adds   r5, r5, r6\n\t"
        "bmi    6f\n\t"
        "ldr    r6, [r0, %[ra]]\n\t"
        "subs   r5, r5, r6\n\t"
        "subs   r4, r4, #2\n"
        "6:\n\t"
        "subs   r7, r7, #1\n\t"
        "bne    1b\n\t"
        "mov    r6, r11\n\t"
        "subs   r1, r1, r6\n\t"             // back to offsets in the next row
        "subs   r4, r4, r6\n\t"
        "stm    r0!, {r1-r5}\n\t"
        "mov    r0, r11\n\t"
        "pop    {r4-r7}\n\t"
        "mov    r8, r4\n\t"
        "mov    r9, r5\n\t"
        "mov    r10, r6\n\t"
        "mov    r11, r7\n\t"
        "pop    {r4-r7, pc}\n"
        :
        : [stride] "i"(offsetof(RowKernel, stride_bytes)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [color] "i"(offsetof(RowKernel, color)), [la] "i"(offsetof(RowKernel, la)), [lm] "i"(offsetof(RowKernel, lm)),
          [lstep] "i"(offsetof(RowKernel, lstep)), [ldz] "i"(offsetof(RowKernel, ldz)), [ra] "i"(offsetof(RowKernel, ra)),
          [rm] "i"(offsetof(RowKernel, rm)), [rstep] "i"(offsetof(RowKernel, rstep)));
}
#endif

#if defined(__riscv) && __riscv_xlen == 32
/// RV32. Registers: a0 the state, a4..a7 lp lg lz rp, t0 rg, t1..t5 lm lstep ldz rm rstep, t6 dz, s0 the
/// colour, a2 rows left, a3 the colour offset; la and ra are loaded by the corrections. Pixel loop: s1
/// walks the depth elements up to rp, s2 z, a1 and s3 scratch (9 instructions a written pixel, 6 a
/// rejected one). Per row outside the pixels: 12, plus 4 and 3 for edge corrections.
__attribute__((naked, noinline)) inline uint16_t* run_row_kernel_rv32(RowKernel*, uint16_t*, int32_t, intptr_t) {
    __asm__ volatile(
        "addi   sp, sp, -32\n\t"
        "sw     s0, 0(sp)\n\t"
        "sw     s1, 4(sp)\n\t"
        "sw     s2, 8(sp)\n\t"
        "sw     s3, 12(sp)\n\t"
        "lw     t0, %[stride](a0)\n\t"
        "mul    t0, t0, a2\n\t"
        "add    t0, t0, a1\n\t"
        "sw     t0, 16(sp)\n\t"             // the depth row after the last
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
        "1:\n\t"                            // row
        "bgeu   a4, a7, 3f\n\t"             // empty span
        "mv     s1, a4\n\t"
        "mv     s2, a6\n"                   // z = lz
        "2:\n\t"                            // pixel
        "lhu    a1, 0(s1)\n\t"
        "srli   s3, s2, 16\n\t"
        "bgeu   s3, a1, 4f\n\t"             // stored depth <= ours: keep it
        "sh     s3, 0(s1)\n\t"
        "add    s3, s1, a3\n\t"
        "sh     s0, 0(s3)\n"
        "4:\n\t"
        "add    s2, s2, t6\n\t"
        "addi   s1, s1, 2\n\t"
        "bne    s1, a7, 2b\n"
        "3:\n\t"                            // left edge: g += m, p += step, z += dz_row, then correct
        "add    a5, a5, t1\n\t"
        "add    a4, a4, t2\n\t"
        "add    a6, a6, t3\n\t"
        "bltz   a5, 5f\n\t"                 // g < 0: no correction
        "lw     a1, %[la](a0)\n\t"
        "sub    a5, a5, a1\n\t"
        "addi   a4, a4, -2\n\t"
        "sub    a6, a6, t6\n"               // z -= dzdx
        "5:\n\t"                            // right edge
        "add    t0, t0, t4\n\t"
        "add    a7, a7, t5\n\t"
        "bltz   t0, 6f\n\t"
        "lw     a1, %[ra](a0)\n\t"
        "sub    t0, t0, a1\n\t"
        "addi   a7, a7, -2\n"
        "6:\n\t"
        "addi   a2, a2, -1\n\t"
        "bnez   a2, 1b\n\t"
        "lw     a1, 16(sp)\n\t"
        "sub    a4, a4, a1\n\t"             // back to offsets in the next row
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
        :
        : [stride] "i"(offsetof(RowKernel, stride_bytes)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [color] "i"(offsetof(RowKernel, color)), [la] "i"(offsetof(RowKernel, la)), [lm] "i"(offsetof(RowKernel, lm)),
          [lstep] "i"(offsetof(RowKernel, lstep)), [ldz] "i"(offsetof(RowKernel, ldz)), [ra] "i"(offsetof(RowKernel, ra)),
          [rm] "i"(offsetof(RowKernel, rm)), [rstep] "i"(offsetof(RowKernel, rstep)));
}
#endif

/// Runs rows >= 1 rows of the kernel from depth row `zrow` (Thumb-2 on ARMv7-M, Thumb-1 on ARMv6-M,
/// RV32, else the portable loop) and returns the next row's depth pointer. Precondition (the assembly
/// loops rely on it): rows >= 1.
__attribute__((always_inline)) inline uint16_t* run_row_kernel(RowKernel& k, uint16_t* zrow, int32_t rows,
                                                               intptr_t color_offset) {
    HIDER_ASSERT(rows >= 1);
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    return run_row_kernel_v7m(&k, zrow, rows, color_offset);
#elif defined(__ARM_ARCH_6M__)
    return run_row_kernel_v6m(&k, zrow, rows, color_offset);
#elif defined(__riscv) && __riscv_xlen == 32
    return run_row_kernel_rv32(&k, zrow, rows, color_offset);
#else
    return run_row_kernel_portable(k, zrow, rows, color_offset);
#endif
}

}  // namespace hider

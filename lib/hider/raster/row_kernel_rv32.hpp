// run_kernel_triangle_portable() (row_kernel.hpp) in RV32IM. Part of row_kernel_asm.hpp: include that
// header (or row_kernel.hpp), not this one.
#pragma once
#include <hider/raster/row_kernel.hpp>

namespace hider {

#if defined(HIDER_RV32_ASM)
/// HIDER_RV32_ROWS: the row loop of run_kernel_triangle_rv32(), shared with resume_carried_rv32()
/// (band_resume.hpp), from the first row (label 3) through the lower short edge's switch; it ends
/// at local label 90, which its caller defines (the state's store-back). Registers and stack words as
/// run_kernel_triangle_rv32() says; offsets from HIDER_ROW_LOOP_OPERANDS (row_kernel.hpp).
#define HIDER_RV32_ROWS \
    "3:\n\t"                            /* row */                                                     \
    "bgeu   a4, a7, 5f\n\t"             /* empty span */                                              \
    "mv     s1, a4\n\t"                                                                               \
    "mv     s2, a6\n\t"                 /* z = lz */                                                  \
    "sub    a1, a7, a4\n\t"                                                                           \
    "andi   a1, a1, 2\n\t"                                                                            \
    "beqz   a1, 4f\n\t"                 /* an even count: pairs only */                               \
    "lhu    a1, 0(s1)\n\t"              /* the odd pixel */                                           \
    "srli   s3, s2, 16\n\t"                                                                           \
    "bgeu   s3, a1, 11f\n\t"            /* stored depth <= ours: keep it */                           \
    "sh     s3, 0(s1)\n\t"                                                                            \
    "add    s3, s1, a3\n\t"                                                                           \
    "sh     s0, 0(s3)\n"                                                                              \
    "11:\n\t"                                                                                         \
    "add    s2, s2, t6\n\t"                                                                           \
    "addi   s1, s1, 2\n\t"                                                                            \
    "beq    s1, a7, 5f\n"                                                                             \
    "4:\n\t"                            /* two pixels */                                              \
    "lhu    a1, 0(s1)\n\t"                                                                            \
    "srli   s3, s2, 16\n\t"                                                                           \
    "bgeu   s3, a1, 12f\n\t"                                                                          \
    "sh     s3, 0(s1)\n\t"                                                                            \
    "add    s3, s1, a3\n\t"                                                                           \
    "sh     s0, 0(s3)\n"                                                                              \
    "12:\n\t"                                                                                         \
    "add    s2, s2, t6\n\t"                                                                           \
    "lhu    a1, 2(s1)\n\t"                                                                            \
    "srli   s3, s2, 16\n\t"                                                                           \
    "bgeu   s3, a1, 13f\n\t"                                                                          \
    "sh     s3, 2(s1)\n\t"                                                                            \
    "add    s3, s1, a3\n\t"                                                                           \
    "sh     s0, 2(s3)\n"                                                                              \
    "13:\n\t"                                                                                         \
    "add    s2, s2, t6\n\t"                                                                           \
    "addi   s1, s1, 4\n\t"                                                                            \
    "bne    s1, a7, 4b\n"                                                                             \
    "5:\n\t"                            /* left edge: g += m, p += step, z += dz_row, then correct */ \
    "add    a5, a5, t1\n\t"                                                                           \
    "add    a4, a4, t2\n\t"                                                                           \
    "add    a6, a6, t3\n\t"                                                                           \
    "bltz   a5, 7f\n\t"                 /* g < 0: no correction */                                    \
    "lw     a1, %[la](a0)\n\t"                                                                        \
    "sub    a5, a5, a1\n\t"                                                                           \
    "addi   a4, a4, -2\n\t"                                                                           \
    "sub    a6, a6, t6\n"               /* z -= dzdx */                                               \
    "7:\n\t"                            /* right edge */                                              \
    "add    t0, t0, t4\n\t"                                                                           \
    "add    a7, a7, t5\n\t"                                                                           \
    "bltz   t0, 8f\n\t"                                                                               \
    "lw     a1, %[ra](a0)\n\t"                                                                        \
    "sub    t0, t0, a1\n\t"                                                                           \
    "addi   a7, a7, -2\n"                                                                             \
    "8:\n\t"                                                                                          \
    "addi   a2, a2, -1\n\t"                                                                           \
    "bnez   a2, 3b\n\t"                                                                               \
    "lw     a2, 16(sp)\n\t"             /* rows after the switch */                                   \
    "bltz   a2, 90f\n\t"                /* no switch in this call */                                  \
    "lw     a1, 20(sp)\n\t"             /* the middle row */                                          \
    "lbu    s1, %[n_left](a0)\n\t"                                                                    \
    "lw     s2, %[n_x](a0)\n\t"                                                                       \
    "add    s2, s2, a1\n\t"                                                                           \
    "lw     s3, %[n_g](a0)\n\t"                                                                       \
    "lw     a1, %[n_a](a0)\n\t"                                                                       \
    "beqz   s1, 9f\n\t"                                                                               \
    "sub    s1, s2, a4\n\t"             /* the lower edge on the left */                              \
    "srai   s1, s1, 1\n\t"              /* its px less the old edge's */                              \
    "mul    s1, s1, t6\n\t"                                                                           \
    "add    a6, a6, s1\n\t"             /* its z (next_edge_depth()) */                               \
    "mv     a4, s2\n\t"                                                                               \
    "mv     a5, s3\n\t"                                                                               \
    "sw     a1, %[la](a0)\n\t"                                                                        \
    "lw     t1, %[n_m](a0)\n\t"                                                                       \
    "sw     t1, %[lm](a0)\n\t"                                                                        \
    "lw     s1, %[n_step](a0)\n\t"                                                                    \
    "sub    s2, s1, t2\n\t"                                                                           \
    "srai   s2, s2, 1\n\t"              /* its q less the old edge's */                               \
    "mul    s2, s2, t6\n\t"                                                                           \
    "add    t3, t3, s2\n\t"             /* its depth step */                                          \
    "mv     t2, s1\n\t"                                                                               \
    "sw     t2, %[lstep](a0)\n\t"                                                                     \
    "sw     t3, %[ldz](a0)\n\t"                                                                       \
    "j      10f\n"                                                                                    \
    "9:\n\t"                                                                                          \
    "mv     a7, s2\n\t"                 /* the lower edge on the right */                             \
    "mv     t0, s3\n\t"                                                                               \
    "sw     a1, %[ra](a0)\n\t"                                                                        \
    "lw     t4, %[n_m](a0)\n\t"                                                                       \
    "sw     t4, %[rm](a0)\n\t"                                                                        \
    "lw     t5, %[n_step](a0)\n\t"                                                                    \
    "sw     t5, %[rstep](a0)\n"                                                                       \
    "10:\n\t"                                                                                         \
    "li     a1, -1\n\t"                                                                               \
    "sw     a1, 16(sp)\n\t"             /* switched */                                                \
    "bnez   a2, 3b\n"

/// HIDER_RV32_STORE_STATE: the row loop's edges and depth back into record a0 (lx lg lz rx rg), the edges
/// as offsets in depth row a1 (the row after the last drawn). Shared by run_kernel_triangle_rv32() and
/// resume_carried_rv32().
#define HIDER_RV32_STORE_STATE \
    "sub    a4, a4, a1\n\t"             /* back to offsets in that row */ \
    "sub    a7, a7, a1\n\t" \
    "sw     a4, 0(a0)\n\t" \
    "sw     a5, 4(a0)\n\t" \
    "sw     a6, 8(a0)\n\t" \
    "sw     a7, 12(a0)\n\t" \
    "sw     t0, 16(a0)\n\t"

/// HIDER_RV32_ROWS's operands (its callers add their own).
#define HIDER_RV32_ROWS_OPERANDS HIDER_ROW_LOOP_OPERANDS

/// RV32. In the row loop: a0 the state, a4..a7 lp lg lz rp, t0 rg, t1..t5 lm lstep ldz rm rstep, t6 dz,
/// s0 the colour, a2 rows left in this phase, a3 the colour offset; la and ra are loaded by the
/// corrections; on the stack the middle row's depth pointer, the rows after the switch (-1: none) and
/// the depth row after the last. Pixel loop, two pixels a pass after an odd one: s1 walks the depth
/// elements up to rp, s2 z, a1 and s3 scratch (8 instructions a written pixel, 5 a rejected one, one
/// more for the odd pixel). Per row outside the pixels: 15, plus 4 and 3 for edge corrections.
HIDER_NAKED inline uint16_t* run_kernel_triangle_rv32(KernelTriangle*, uint16_t*, int32_t,
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
        HIDER_RV32_ROWS
        "90:\n\t"
        "lw     a1, 24(sp)\n\t"             // the depth row after the last
        HIDER_RV32_STORE_STATE
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
          [color] "i"(offsetof(RowKernel, color)), HIDER_RV32_ROWS_OPERANDS);
}
#endif

}  // namespace hider

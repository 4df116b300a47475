// run_kernel_triangle_portable() (row_kernel.hpp) in Thumb-1 for ARMv6-M (Cortex-M0/M0+).
// Part of row_kernel_asm.hpp: include that header (or row_kernel.hpp), not this one.
#pragma once
#include <hider/asm_v6m.hpp>
#include <hider/raster/row_kernel.hpp>

namespace hider {

#if defined(HIDER_ARMV6M)
/// HIDER_V6M_ROWS: the row loop of run_kernel_triangle_v6m(), shared with resume_carried_v6m()
/// (band_resume.hpp), from the first row (label 3) through the lower short edge's switch; it ends at
/// local label 90, which its caller defines (the state's store-back). Registers and stack words as
/// run_kernel_triangle_v6m() says; offsets from HIDER_ROW_LOOP_OPERANDS (row_kernel.hpp).
#define HIDER_V6M_ROWS \
    "3:\n\t"                            /* row */                                                     \
    "subs   r6, r1, r4\n\t"             /* lp - rp: negative, counts up to 0 */                       \
    "bge    5f\n\t"                     /* empty span */                                              \
    "stm    r0!, {r1, r2, r3, r7}\n\t"  /* park lp lg lz rows */                                      \
    "mov    r1, r8\n\t"                                                                               \
    "adds   r1, r1, r4\n\t"             /* the colour end */                                          \
    "mov    r7, r10\n"                  /* colour */                                                  \
    "4:\n\t"                            /* pixel */                                                   \
    "ldrh   r2, [r4, r6]\n\t"                                                                         \
    "lsrs   r0, r3, #16\n\t"                                                                          \
    "cmp    r2, r0\n\t"                                                                               \
    "bls    6f\n\t"                     /* stored depth <= ours: keep it */                           \
    "strh   r0, [r4, r6]\n\t"                                                                         \
    "strh   r7, [r1, r6]\n"                                                                           \
    "6:\n\t"                                                                                          \
    "add    r3, r9\n\t"                                                                               \
    "adds   r6, r6, #2\n\t"                                                                           \
    "bne    4b\n\t"                                                                                   \
    "mov    r0, r12\n\t"                                                                              \
    "ldm    r0!, {r1, r2, r3, r7}\n\t"  /* lp lg lz rows back */                                      \
    "mov    r0, r12\n"                                                                                \
    "5:\n\t"                            /* left edge: p += step, z += dz_row, g += m, then correct */ \
    "ldr    r6, [r0, %[lstep]]\n\t"                                                                   \
    "adds   r1, r1, r6\n\t"                                                                           \
    "ldr    r6, [r0, %[ldz]]\n\t"                                                                     \
    "adds   r3, r3, r6\n\t"                                                                           \
    "ldr    r6, [r0, %[lm]]\n\t"                                                                      \
    "adds   r2, r2, r6\n\t"                                                                           \
    "bmi    7f\n\t"                     /* g < 0: no correction */                                    \
    "ldr    r6, [r0, %[la]]\n\t"                                                                      \
    "subs   r2, r2, r6\n\t"                                                                           \
    "subs   r1, r1, #2\n\t"                                                                           \
    "mov    r6, r9\n\t"                                                                               \
    "subs   r3, r3, r6\n"               /* z -= dzdx */                                               \
    "7:\n\t"                            /* right edge */                                              \
    "ldr    r6, [r0, %[rstep]]\n\t"                                                                   \
    "adds   r4, r4, r6\n\t"                                                                           \
    "ldr    r6, [r0, %[rm]]\n\t"                                                                      \
    "adds   r5, r5, r6\n\t"                                                                           \
    "bmi    8f\n\t"                                                                                   \
    "ldr    r6, [r0, %[ra]]\n\t"                                                                      \
    "subs   r5, r5, r6\n\t"                                                                           \
    "subs   r4, r4, #2\n"                                                                             \
    "8:\n\t"                                                                                          \
    "subs   r7, r7, #1\n\t"                                                                           \
    "bne    3b\n\t"                                                                                   \
    "ldr    r7, [sp, #4]\n\t"           /* rows after the switch */                                   \
    "cmp    r7, #0\n\t"                                                                               \
    "blt    90f\n\t"                    /* no switch in this call */                                  \
    "movs   r6, %[n_left]\n\t"                                                                        \
    "ldrb   r6, [r0, r6]\n\t"                                                                         \
    "cmp    r6, #0\n\t"                                                                               \
    "ldr    r6, [sp]\n\t"               /* the middle row */                                          \
    "beq    9f\n\t"                                                                                   \
    "ldr    r2, [r0, %[n_x]]\n\t"       /* the lower edge on the left */                              \
    "adds   r2, r2, r6\n\t"                                                                           \
    "subs   r1, r2, r1\n\t"                                                                           \
    "asrs   r1, r1, #1\n\t"             /* its px less the old edge's */                              \
    "mov    r6, r9\n\t"                                                                               \
    "muls   r1, r6, r1\n\t"                                                                           \
    "adds   r3, r3, r1\n\t"             /* its z (next_edge_depth()) */                               \
    "movs   r1, r2\n\t"                                                                               \
    "ldr    r2, [r0, %[n_step]]\n\t"                                                                  \
    "ldr    r6, [r0, %[lstep]]\n\t"                                                                   \
    "str    r2, [r0, %[lstep]]\n\t"                                                                   \
    "subs   r2, r2, r6\n\t"                                                                           \
    "asrs   r2, r2, #1\n\t"             /* its q less the old edge's */                               \
    "mov    r6, r9\n\t"                                                                               \
    "muls   r2, r6, r2\n\t"                                                                           \
    "ldr    r6, [r0, %[ldz]]\n\t"                                                                     \
    "adds   r2, r2, r6\n\t"                                                                           \
    "str    r2, [r0, %[ldz]]\n\t"       /* its depth step */                                          \
    "ldr    r2, [r0, %[n_a]]\n\t"                                                                     \
    "str    r2, [r0, %[la]]\n\t"                                                                      \
    "ldr    r2, [r0, %[n_m]]\n\t"                                                                     \
    "str    r2, [r0, %[lm]]\n\t"                                                                      \
    "ldr    r2, [r0, %[n_g]]\n\t"                                                                     \
    "b      10f\n"                                                                                    \
    "9:\n\t"                                                                                          \
    "ldr    r4, [r0, %[n_x]]\n\t"       /* the lower edge on the right */                             \
    "adds   r4, r4, r6\n\t"                                                                           \
    "ldr    r5, [r0, %[n_a]]\n\t"                                                                     \
    "str    r5, [r0, %[ra]]\n\t"                                                                      \
    "ldr    r5, [r0, %[n_m]]\n\t"                                                                     \
    "str    r5, [r0, %[rm]]\n\t"                                                                      \
    "ldr    r5, [r0, %[n_step]]\n\t"                                                                  \
    "str    r5, [r0, %[rstep]]\n\t"                                                                   \
    "ldr    r5, [r0, %[n_g]]\n"                                                                       \
    "10:\n\t"                                                                                         \
    "movs   r6, #0\n\t"                                                                               \
    "mvns   r6, r6\n\t"                                                                               \
    "str    r6, [sp, #4]\n\t"           /* switched */                                                \
    "cmp    r7, #0\n\t"                                                                               \
    "bne    3b\n"

/// HIDER_V6M_PHASES: the rows of a call before and after the middle row's switch, from r0 the record,
/// r2 the rows of the call (n > 0) and r4 its first row: r6 the rows before the switch, r7 those after it
/// (-1: no switch in this call), r4 the rows to the middle row. It branches to local label 2 (forward)
/// without a switch and falls through with one. Shared by run_kernel_triangle_v6m() and
/// resume_carried_v6m(); operands [mid] and [end].
#define HIDER_V6M_PHASES \
    "mov    r6, r2\n\t"                 /* rows before a switch: all */ \
    "movs   r7, #0\n\t" \
    "mvns   r7, r7\n\t"                 /* rows after it: none (-1) */ \
    "ldrh   r5, [r0, %[mid]]\n\t" \
    "sxth   r5, r5\n\t" \
    "subs   r4, r5, r4\n\t"             /* m = mid - row */ \
    "ble    2f\n\t"                     /* on or below the middle row */ \
    "ldrh   r3, [r0, %[end]]\n\t" \
    "sxth   r3, r3\n\t" \
    "cmp    r5, r3\n\t" \
    "bge    2f\n\t"                     /* no lower short edge */ \
    "cmp    r4, r2\n\t" \
    "bgt    2f\n\t"                     /* the middle row lies past this call */ \
    "mov    r6, r4\n\t" \
    "subs   r7, r2, r4\n"

/// HIDER_V6M_ROWS's operands (its callers add their own).
#define HIDER_V6M_ROWS_OPERANDS HIDER_ROW_LOOP_OPERANDS

/// Thumb-1 (Cortex-M0/M0+: eight low registers, no conditional execution). In the row loop r0 holds
/// the state, r1..r5 lp lg lz rp rg, r7 rows left in this phase, r12 the state again, r8 the colour
/// offset, r9 dz, r10 the colour; on the stack the middle row's depth pointer, the rows after the switch
/// (-1: none), the depth row after the last. Edge constants are loaded where used. A span parks lp lg lz
/// and the row count in the state with one store-multiple; its pixel loop indexes back from the span's
/// end (r4 depth, r1 colour) with r6 = lp - rp counting up to 0, r3 z, r7 colour (9 instructions a
/// written pixel, 7 a rejected one).
HIDER_NAKED inline uint16_t* run_kernel_triangle_v6m(KernelTriangle*, uint16_t*, int32_t,
                                                                          const KernelTarget*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
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
        "bgt    94f\n\t"
        "b      95f\n"                     // (past a conditional branch's reach)
        "94:\n\t"
        "strh   r6, [r0, %[row]]\n\t"       // the row after this call
        HIDER_V6M_PHASES
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
        HIDER_V6M_ROWS
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
        HIDER_V6M_RESTORE_ALL
        :
        : [row] "i"(offsetof(KernelTriangle, row)), [mid] "i"(offsetof(KernelTriangle, mid)),
          [end] "i"(offsetof(KernelTriangle, end)), [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [color] "i"(offsetof(RowKernel, color)), HIDER_V6M_ROWS_OPERANDS);
}
#endif

}  // namespace hider

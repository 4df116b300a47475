// resume_carried_v6m(): band_resume.hpp's resume_carried() in Thumb-1 for ARMv6-M. Part of
// band_resume.hpp: include that header, not this one.
#pragma once
#include <hider/raster/band_resume.hpp>

namespace hider {

#if defined(HIDER_ARMV6M)
static_assert(sizeof(KernelTriangle) < 256 && offsetof(KernelTriangle, row) < 64 && offsetof(KernelTriangle, end) < 64 &&
                  offsetof(KernelTriangle, mid) < 64,
              "resume_carried_v6m(): a slot's size in one movs, rows within ldrh's reach");

/// resume_carried() in Thumb-1 for ARMv6-M. The row loop's registers are run_kernel_triangle_v6m()'s
/// (HIDER_V6M_ROWS; r8 the colour offset, set once); the run's state lives on the stack: 0..8 the row
/// loop's three words (8: 0 when the record ends in this band, so nothing is stored back: a depth row
/// never lies at address 0), 12 `cs`, 16 cur, 20 cur_end, 24 nxt, 28 free_top, 32 pool, 36 limit, 40
/// the band's first depth row, 44 its end row, 48 the stride. Per record, the kernel's entry without the
/// call and its register saves, the slot onward or back before the rows; a record without a row to draw
/// as in resume_carried_rv32().
HIDER_NAKED inline uint32_t resume_carried_v6m(detail::CarriedSlots*, uint32_t, const detail::KernelBandTarget*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
        "sub    sp, sp, #52\n\t"            // 36 + 52: the stack stays 8-byte aligned
        "str    r0, [sp, #12]\n\t"
        "ldm    r0!, {r3-r7}\n\t"           // pool cur cur_end nxt free_top
        "str    r3, [sp, #32]\n\t"
        "str    r4, [sp, #16]\n\t"
        "str    r5, [sp, #20]\n\t"
        "str    r6, [sp, #24]\n\t"
        "str    r7, [sp, #28]\n\t"
        "str    r1, [sp, #36]\n\t"          // limit
        "ldm    r2!, {r3-r6}\n\t"           // colour offset, stride, first depth row, end row
        "mov    r8, r3\n\t"
        "str    r4, [sp, #48]\n\t"
        "str    r5, [sp, #40]\n\t"
        "str    r6, [sp, #44]\n"
        "20:\n\t"                           // a record
        "ldr    r6, [sp, #16]\n\t"
        "ldr    r7, [sp, #20]\n\t"
        "cmp    r6, r7\n\t"
        "bne    21f\n\t"
        "b      79f\n"                      // (79 and 80 lie past a conditional branch's reach)
        "21:\n\t"
        "ldrb   r5, [r6]\n\t"               // its slot
        "movs   r4, %[rec]\n\t"
        "muls   r4, r5, r4\n\t"
        "ldr    r0, [sp, #32]\n\t"
        "adds   r0, r0, r4\n\t"             // its record
        "movs   r4, %[tri]\n\t"
        "ldrh   r4, [r0, r4]\n\t"
        "ldr    r7, [sp, #36]\n\t"
        "cmp    r4, r7\n\t"
        "blo    22f\n\t"
        "b      80f\n"                      // from the limit on: pending
        "22:\n\t"
        "adds   r6, r6, #1\n\t"
        "str    r6, [sp, #16]\n\t"
        "ldrh   r4, [r0, %[row]]\n\t"
        "sxth   r4, r4\n\t"
        "ldrh   r6, [r0, %[end]]\n\t"
        "sxth   r6, r6\n\t"
        "ldr    r2, [sp, #44]\n\t"
        "mov    r7, r6\n\t"
        "cmp    r6, r2\n\t"
        "ble    1f\n\t"
        "mov    r7, r2\n"                   // stop = min(end, row_end)
        "1:\n\t"
        "subs   r2, r7, r4\n\t"             // n rows
        "bgt    23f\n\t"
        "b      62f\n"
        "23:\n\t"
        "strh   r7, [r0, %[row]]\n\t"       // the row after this call
        "cmp    r7, r6\n\t"
        "bge    5f\n\t"                     // the last rows: the slot back to the free ones
        "ldr    r3, [sp, #24]\n\t"          // onward
        "strb   r5, [r3]\n\t"
        "adds   r3, r3, #1\n\t"
        "str    r3, [sp, #24]\n\t"
        "ldr    r3, [sp, #48]\n\t"
        "muls   r3, r2, r3\n\t"
        "ldr    r1, [sp, #40]\n\t"
        "adds   r3, r3, r1\n\t"
        "str    r3, [sp, #8]\n\t"           // the depth row after the last: the state goes back there
        "b      6f\n"
        "5:\n\t"
        "ldr    r3, [sp, #28]\n\t"
        "strb   r5, [r3]\n\t"
        "adds   r3, r3, #1\n\t"
        "str    r3, [sp, #28]\n\t"
        "movs   r3, #0\n\t"
        "str    r3, [sp, #8]\n"             // no state to keep
        "6:\n\t"
        HIDER_V6M_PHASES
        "ldr    r3, [sp, #48]\n\t"
        "muls   r4, r3, r4\n\t"
        "ldr    r3, [sp, #40]\n\t"
        "adds   r4, r4, r3\n\t"
        "str    r4, [sp]\n"                 // the middle row's depth pointer
        "2:\n\t"
        "str    r7, [sp, #4]\n\t"           // rows after the switch
        "ldr    r4, [r0, %[dzdx]]\n\t"
        "mov    r9, r4\n\t"
        "ldr    r4, [r0, %[color]]\n\t"
        "mov    r10, r4\n\t"
        "mov    r12, r0\n\t"
        "mov    r7, r6\n\t"                 // rows of this phase
        "ldr    r6, [sp, #40]\n\t"
        "ldm    r0!, {r1-r5}\n\t"           // lx lg lz rx rg
        "mov    r0, r12\n\t"
        "adds   r1, r1, r6\n\t"             // lp
        "adds   r4, r4, r6\n\t"             // rp
        HIDER_V6M_ROWS
        "90:\n\t"
        "ldr    r6, [sp, #8]\n\t"           // the depth row after the last (0: the last rows)
        "cmp    r6, #0\n\t"
        "beq    91f\n\t"
        "subs   r1, r1, r6\n\t"             // back to offsets in that row
        "subs   r4, r4, r6\n\t"
        "stm    r0!, {r1-r5}\n"
        "91:\n\t"
        "b      20b\n"
        "62:\n\t"                           // no row drawn: onward while row < end (as resume_carried())
        "ldr    r3, [sp, #24]\n\t"
        "cmp    r4, r6\n\t"
        "blt    63f\n\t"
        "ldr    r3, [sp, #28]\n\t"
        "strb   r5, [r3]\n\t"
        "adds   r3, r3, #1\n\t"
        "str    r3, [sp, #28]\n\t"
        "b      20b\n"
        "63:\n\t"
        "strb   r5, [r3]\n\t"
        "adds   r3, r3, #1\n\t"
        "str    r3, [sp, #24]\n\t"
        "b      20b\n"
        "79:\n\t"
        "movs   r4, #1\n\t"
        "lsls   r4, r4, #16\n\t"
        "subs   r4, r4, #1\n"               // kNoTriangle: every record resumed
        "80:\n\t"                           // r4: the pending triangle
        "ldr    r1, [sp, #12]\n\t"
        "ldr    r2, [sp, #16]\n\t"
        "str    r2, [r1, #4]\n\t"
        "ldr    r2, [sp, #24]\n\t"
        "str    r2, [r1, #12]\n\t"
        "ldr    r2, [sp, #28]\n\t"
        "str    r2, [r1, #16]\n\t"
        "mov    r0, r4\n\t"
        "add    sp, sp, #52\n\t"
        HIDER_V6M_RESTORE_ALL
        :
        : [rec] "i"(sizeof(KernelTriangle)), [tri] "i"(offsetof(KernelTriangle, tri)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)), [color] "i"(offsetof(RowKernel, color)), HIDER_V6M_ROWS_OPERANDS);
}
#endif

}  // namespace hider

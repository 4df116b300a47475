// resume_carried_rv32(): band_resume.hpp's resume_carried() in RV32IM. Part of band_resume.hpp:
// include that header, not this one.
#pragma once
#include <hider/raster/band_resume.hpp>

namespace hider {

#if defined(HIDER_RV32_ASM)
static_assert(sizeof(KernelTriangle) < 2048, "resume_carried_rv32(): a slot's size in one li");

/// resume_carried() in RV32IM. s4..s11: cur, cur_end, nxt, free_top, pool, limit, the band's first depth
/// row, its end row; ra the stride; a3 the colour offset. Per record, run_kernel_triangle_rv32()'s
/// entry (rows, the middle row's switch, the state into registers) without the call, the slot onward or
/// back, HIDER_RV32_ROWS, then the store-back of a record sent onward. The stack: 16..24 the row loop's
/// three words (24: 0 for a record sent back, which needs no store-back: a depth row never lies at
/// address 0), 28..76 the saved registers, 0 `cs`. A record without a row to draw (KernelBands never
/// resumes one; kernelcheck's resume cases do) goes onward or back by row < end, as in resume_carried().
HIDER_NAKED inline uint32_t resume_carried_rv32(detail::CarriedSlots*, uint32_t, const detail::KernelBandTarget*) {
    __asm__ volatile(
        "addi   sp, sp, -80\n\t"
        "sw     s0, 28(sp)\n\t"
        "sw     s1, 32(sp)\n\t"
        "sw     s2, 36(sp)\n\t"
        "sw     s3, 40(sp)\n\t"
        "sw     s4, 44(sp)\n\t"
        "sw     s5, 48(sp)\n\t"
        "sw     s6, 52(sp)\n\t"
        "sw     s7, 56(sp)\n\t"
        "sw     s8, 60(sp)\n\t"
        "sw     s9, 64(sp)\n\t"
        "sw     s10, 68(sp)\n\t"
        "sw     s11, 72(sp)\n\t"
        "sw     ra, 76(sp)\n\t"
        "sw     a0, 0(sp)\n\t"
        "lw     s8, 0(a0)\n\t"              // pool
        "lw     s4, 4(a0)\n\t"              // cur
        "lw     s5, 8(a0)\n\t"              // cur_end
        "lw     s6, 12(a0)\n\t"             // nxt
        "lw     s7, 16(a0)\n\t"             // free_top
        "mv     s9, a1\n\t"                 // limit
        "lw     a3, 0(a2)\n\t"              // colour offset
        "lw     ra, 4(a2)\n\t"              // stride
        "lw     s10, 8(a2)\n\t"             // the band's first depth row
        "lw     s11, 12(a2)\n"               // its end row
        "20:\n\t"                           // a record
        "beq    s4, s5, 79f\n\t"
        "lbu    a1, 0(s4)\n\t"              // its slot
        "li     t1, %[rec]\n\t"
        "mul    t1, t1, a1\n\t"             // slot * the record's size
        "add    a0, s8, t1\n\t"
        "lhu    t2, %[tri](a0)\n\t"
        "bgeu   t2, s9, 80f\n\t"            // from the limit on: pending
        "addi   s4, s4, 1\n\t"
        "lh     t0, %[row](a0)\n\t"
        "lh     t6, %[end](a0)\n\t"
        "lh     t2, %[mid](a0)\n\t"
        "mv     t1, t6\n\t"
        "bge    s11, t1, 1f\n\t"
        "mv     t1, s11\n"                  // stop = min(end, row_end)
        "1:\n\t"
        "sub    a2, t1, t0\n\t"             // n rows
        "blez   a2, 62f\n\t"                // none: the slot by row < end
        "sh     t1, %[row](a0)\n\t"         // the row after this call
        "bge    t1, t6, 5f\n\t"             // the last rows: the slot back to the free ones
        "sb     a1, 0(s6)\n\t"              // onward
        "addi   s6, s6, 1\n\t"
        "mul    t3, a2, ra\n\t"
        "add    t3, t3, s10\n\t"
        "sw     t3, 24(sp)\n\t"             // the depth row after the last: the state goes back there
        "j      6f\n"
        "5:\n\t"
        "sb     a1, 0(s7)\n\t"
        "addi   s7, s7, 1\n\t"
        "sw     zero, 24(sp)\n"              // no state to keep
        "6:\n\t"
        "mv     t3, a2\n\t"                 // rows before a switch: all
        "li     t4, -1\n\t"                 // rows after it: none
        "sub    t5, t2, t0\n\t"             // m = mid - row
        "blez   t5, 2f\n\t"                 // on or below the middle row
        "bge    t2, t6, 2f\n\t"             // no lower short edge
        "blt    a2, t5, 2f\n\t"             // the middle row lies past this call
        "mv     t3, t5\n\t"
        "sub    t4, a2, t5\n\t"
        "mul    t5, t5, ra\n\t"
        "add    t5, t5, s10\n\t"
        "sw     t5, 20(sp)\n"               // the middle row's depth pointer
        "2:\n\t"
        "sw     t4, 16(sp)\n\t"             // rows after the switch
        "mv     a2, t3\n\t"                 // rows of this phase
        "lw     a4, 0(a0)\n\t"              // lx
        "lw     a5, 4(a0)\n\t"              // lg
        "lw     a6, 8(a0)\n\t"              // lz
        "lw     a7, 12(a0)\n\t"             // rx
        "lw     t0, 16(a0)\n\t"             // rg
        "add    a4, a4, s10\n\t"            // lp
        "add    a7, a7, s10\n\t"            // rp
        "lw     t1, %[lm](a0)\n\t"
        "lw     t2, %[lstep](a0)\n\t"
        "lw     t3, %[ldz](a0)\n\t"
        "lw     t4, %[rm](a0)\n\t"
        "lw     t5, %[rstep](a0)\n\t"
        "lw     t6, %[dzdx](a0)\n\t"
        "lw     s0, %[color](a0)\n\t"
        HIDER_RV32_ROWS
        "90:\n\t"
        "lw     a1, 24(sp)\n\t"             // the depth row after the last (0: the last rows)
        "beqz   a1, 20b\n\t"
        HIDER_RV32_STORE_STATE
        "j      20b\n"
        "62:\n\t"                           // no row drawn: onward while row < end (as resume_carried())
        "bge    t0, t6, 63f\n\t"
        "sb     a1, 0(s6)\n\t"
        "addi   s6, s6, 1\n\t"
        "j      20b\n"
        "63:\n\t"
        "sb     a1, 0(s7)\n\t"
        "addi   s7, s7, 1\n\t"
        "j      20b\n"
        "79:\n\t"
        "li     t2, 0xFFFF\n"                // kNoTriangle: every record resumed
        "80:\n\t"                           // t2: the pending triangle
        "lw     a1, 0(sp)\n\t"
        "sw     s4, 4(a1)\n\t"
        "sw     s6, 12(a1)\n\t"
        "sw     s7, 16(a1)\n\t"
        "mv     a0, t2\n\t"
        "lw     s0, 28(sp)\n\t"
        "lw     s1, 32(sp)\n\t"
        "lw     s2, 36(sp)\n\t"
        "lw     s3, 40(sp)\n\t"
        "lw     s4, 44(sp)\n\t"
        "lw     s5, 48(sp)\n\t"
        "lw     s6, 52(sp)\n\t"
        "lw     s7, 56(sp)\n\t"
        "lw     s8, 60(sp)\n\t"
        "lw     s9, 64(sp)\n\t"
        "lw     s10, 68(sp)\n\t"
        "lw     s11, 72(sp)\n\t"
        "lw     ra, 76(sp)\n\t"
        "addi   sp, sp, 80\n\t"
        "ret\n"
        :
        : [rec] "i"(sizeof(KernelTriangle)), [tri] "i"(offsetof(KernelTriangle, tri)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)), [color] "i"(offsetof(RowKernel, color)), HIDER_RV32_ROWS_OPERANDS);
}
#endif

}  // namespace hider

// The band renderer's resumes (band_carry.hpp): the set-ups carried from the band above, in slots kept in
// mesh order, each drawn on the band's rows and then moved to the next band's slots or back to the free
// ones. resume_carried() is the C++ loop; on RV32 and ARMv6-M resume_carried_rv32() and
// resume_carried_v6m() run it in assembly with the row kernel's loop inline (HIDER_RV32_ROWS,
// HIDER_V6M_ROWS), so a resume costs no call and no register saves of its own. (On ARMv7-M the band loop
// of band_loop_asm.hpp resumes inline.) firmware/kernelcheck compares them with resume_carried() on random
// runs of records and through the band renderer.
#pragma once
#include <hider/raster/band_lists.hpp>
#include <hider/raster/kernel_triangle.hpp>

namespace hider {

namespace detail {
/// The carried set-ups of KernelBands: slots in use this band (mesh order) from `cur` to
/// `cur_end`, the next band's from `nxt` (growing), and a stack of free slots below `free_top`.
/// The layout is the assembly runs' contract.
struct CarriedSlots {
    KernelTriangle* pool;
    const uint8_t* cur;
    const uint8_t* cur_end;
    uint8_t* nxt;
    uint8_t* free_top;
};

/// Where a band's kernel rows go: the target, the band's first depth row and its end row (the layout is
/// the assembly runs' contract).
struct KernelBandTarget {
    KernelTarget target;
    uint16_t* zrow;
    int32_t row_end;
};
static_assert(sizeof(void*) != 4 || (offsetof(CarriedSlots, cur) == 4 && offsetof(CarriedSlots, cur_end) == 8 &&
                                     offsetof(CarriedSlots, nxt) == 12 && offsetof(CarriedSlots, free_top) == 16 &&
                                     offsetof(KernelBandTarget, zrow) == 8 && offsetof(KernelBandTarget, row_end) == 12),
              "carried slots and band target layout");

/// The mesh triangle of the first carried set-up still to resume this band (kNoTriangle: none).
inline uint32_t pending_carried(const CarriedSlots& cs) { return cs.cur != cs.cur_end ? cs.pool[*cs.cur].tri : kNoTriangle; }

/// Resumes the carried set-ups whose triangle comes before `limit`: draws their rows of the band (each
/// is on the band's first row) and moves each to the next band's slots or back to the free ones.
/// Returns pending_carried() after them. Out of line with few live values, so GCC keeps the loop in
/// registers.
__attribute__((noinline)) inline uint32_t resume_carried(CarriedSlots& cs, uint32_t limit, const KernelBandTarget& bt) {
    KernelTriangle* const pool = cs.pool;
    const uint8_t* cur = cs.cur;
    const uint8_t* const end = cs.cur_end;
    uint8_t* nxt = cs.nxt;
    uint8_t* free_top = cs.free_top;
    uint32_t pending = kNoTriangle;
    for (; cur != end; ++cur) {
        const uint8_t s = *cur;
        KernelTriangle& kt = pool[s];
        if (kt.tri >= limit) {
            pending = kt.tri;
            break;
        }
        run_kernel_triangle(kt, bt.zrow, bt.row_end, bt.target);
        if (kt.row < kt.end) *nxt++ = s;
        else *free_top++ = s;
    }
    cs.cur = cur;
    cs.nxt = nxt;
    cs.free_top = free_top;
    return pending;
}
}  // namespace detail

#if defined(HIDER_RV32_ASM)
static_assert(sizeof(KernelTriangle) == 96, "resume_carried_rv32() indexes slots as 3 x 32 bytes");

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
        "slli   t1, a1, 1\n\t"
        "add    t1, t1, a1\n\t"
        "slli   t1, t1, 5\n\t"              // slot * 96
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
        "sub    a4, a4, a1\n\t"             // back to offsets in that row
        "sub    a7, a7, a1\n\t"
        "sw     a4, 0(a0)\n\t"
        "sw     a5, 4(a0)\n\t"
        "sw     a6, 8(a0)\n\t"
        "sw     a7, 12(a0)\n\t"
        "sw     t0, 16(a0)\n\t"
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
        : [tri] "i"(offsetof(KernelTriangle, tri)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)), [color] "i"(offsetof(RowKernel, color)), HIDER_RV32_ROWS_OPERANDS);
}
#endif

#if defined(HIDER_ARMV6M)
static_assert(sizeof(KernelTriangle) == 96 && offsetof(KernelTriangle, row) < 64 && offsetof(KernelTriangle, end) < 64 &&
                  offsetof(KernelTriangle, mid) < 64,
              "resume_carried_v6m(): slots of 96 bytes, rows within ldrh's reach");

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
        "movs   r4, #96\n\t"
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
        "subs   r7, r2, r4\n\t"
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
        : [tri] "i"(offsetof(KernelTriangle, tri)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)), [color] "i"(offsetof(RowKernel, color)), HIDER_V6M_ROWS_OPERANDS);
}
#endif

}  // namespace hider

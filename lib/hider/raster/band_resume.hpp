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

}  // namespace hider

#include <hider/raster/band_resume_rv32.hpp>  // resume_carried_rv32()
#include <hider/raster/band_resume_v6m.hpp>   // resume_carried_v6m()

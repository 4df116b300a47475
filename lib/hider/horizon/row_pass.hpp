// The two loops that project a curve of 8-bit heights (the waterfall's case): the reciprocal pass
// turns W' = w' + value hw' (W already shifted left by n0) into r = 2^45 / (W' << e) from a table (e
// normalises to [2^29, 2^30)) and stores s = s0 - e, the shift X will need, and r in each point; the
// coordinate pass then forms U and V and takes X = ((U >> 14) r) >> s, Y likewise with s + dvu. Both are
// portable C++, except on ARMv6-M (Cortex-M0/M0+), where GCC at -Os spills most of their state: there
// they are Thumb-1 loops that keep it in registers. The results are identical (firmware/horizoncheck
// compares them on random rows); project.hpp decides when the passes apply.
#pragma once
#include <hider/asm_v6m.hpp>
#include <hider/horizon/point.hpp>

namespace hider::horizon {

namespace detail {
/// round(2^24 / (256 + j)) for j = 0..256: r = 2^45 / w for w in [2^29, 2^30), by linear interpolation
/// between entries with 7 fraction bits (|error| <= 1.3 units, 2^-15.5 relative). 1 KB of flash.
struct RecipTable {
    uint32_t v[257];
    constexpr RecipTable() : v() {
        for (uint32_t j = 0; j <= 256; ++j) v[j] = ((uint32_t{1} << 24) + (256 + j) / 2) / (256 + j);
    }
};
inline constexpr RecipTable kRecip{};

/// 2^45 / wn for wn in [2^29, 2^30), from kRecip.
__attribute__((always_inline)) inline uint32_t recip45(uint32_t wn) {
    const uint32_t j = (wn >> 21) - 256, f = (wn >> 14) & 127u;
    const uint32_t t0 = kRecip.v[j], t1 = kRecip.v[j + 1];
    return t0 - (((t0 - t1) * f) >> 7);
}

/// (floor(u / 2^14) r) >> s: a screen coordinate from U (|u| < 2^29: below 2^15 after the shift) and
/// r <= 2^16, one 32-bit product. U keeps 15 significant bits, about the reciprocal's own precision.
__attribute__((always_inline)) inline int32_t scale16(int32_t u, uint32_t r, int s) {
    return ((u >> 14) * static_cast<int32_t>(r)) >> s;
}
}  // namespace detail

/// One curve for the two passes. The field order is the ARMv6-M loops' contract (static_asserts below).
struct RowPass {
    const uint8_t* values;  ///< heights, one per point
    PlotPoint* out;         ///< points, out_end - out of them
    PlotPoint* out_end;
    int32_t w, dw, hw;      ///< W << n0 at the first point for value 0, per point, per value unit
    int32_t s0;             ///< X's shift for W << n0 already in [2^29, 2^30)
    int32_t unused;
    uintptr_t table;        ///< address of kRecip.v minus 1024 (entry j at table + 4 (j + 256))
    int32_t u, du, hu;      ///< U likewise (not shifted)
    int32_t v, dv, hv;      ///< V likewise
    int32_t dvu;            ///< Y's shift minus X's
};
static_assert(sizeof(void*) != 4 ||
                  (offsetof(RowPass, w) == 12 && offsetof(RowPass, s0) == 24 && offsetof(RowPass, table) == 32 &&
                   offsetof(RowPass, u) == 36 && offsetof(RowPass, v) == 48 && offsetof(RowPass, dvu) == 60),
              "row pass layout");

/// The reciprocal pass in C++: point i gets x = its shift s, y = r. Preconditions: out < out_end; every
/// W' in [1, 2^30); s0 >= the normalisation steps of every point.
inline void reciprocal_pass_portable(const RowPass& p) {
    const uint8_t* values = p.values;
    uint32_t w = static_cast<uint32_t>(p.w);
    for (PlotPoint* o = p.out; o != p.out_end; ++o, ++values, w += static_cast<uint32_t>(p.dw)) {
        uint32_t wn = w + *values * static_cast<uint32_t>(p.hw);
        int32_t s = p.s0;
        while ((wn >> 29) == 0) {
            wn <<= 1;
            --s;
        }
        o->x = s;
        o->y = static_cast<int32_t>(detail::recip45(wn));
    }
}

/// The coordinate pass in C++ (after the reciprocal pass). Precondition: every |U|, |V| < 2^29.
inline void coordinate_pass_portable(const RowPass& p) {
    const uint8_t* values = p.values;
    int32_t u = p.u, v = p.v;
    for (PlotPoint* o = p.out; o != p.out_end; ++o, ++values, u += p.du, v += p.dv) {
        const int s = o->x;
        const uint32_t r = static_cast<uint32_t>(o->y);
        o->x = detail::scale16(u + *values * p.hu, r, s);
        o->y = detail::scale16(v + *values * p.hv, r, s + p.dvu);
    }
}

#if defined(HIDER_ARMV6M)
/// reciprocal_pass_portable() in Thumb-1. r0 values, r1 out, r2 w', r3..r6 scratch; r8 dw', r9 hw',
/// r10 table, r11 out_end, r12 s0. The two table entries come in with one load-multiple, s and r go
/// out with one store-multiple (23 instructions a point, 4 more per normalisation step).
HIDER_NAKED inline void reciprocal_pass_v6m(const RowPass*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
        "ldr    r1, [r0, #16]\n\t"        // dw'
        "mov    r8, r1\n\t"
        "ldr    r1, [r0, #20]\n\t"        // hw'
        "mov    r9, r1\n\t"
        "ldr    r1, [r0, #32]\n\t"        // table
        "mov    r10, r1\n\t"
        "ldr    r1, [r0, #8]\n\t"         // out_end
        "mov    r11, r1\n\t"
        "ldr    r1, [r0, #24]\n\t"        // s0
        "mov    r12, r1\n\t"
        "ldr    r2, [r0, #12]\n\t"        // w'
        "ldr    r1, [r0, #4]\n\t"         // out
        "ldr    r0, [r0, #0]\n"            // values
        "1:\n\t"
        "ldrb   r3, [r0]\n\t"
        "adds   r0, r0, #1\n\t"
        "mov    r4, r9\n\t"
        "muls   r3, r4, r3\n\t"           // value hw'
        "adds   r3, r3, r2\n\t"           // wn = W'
        "add    r2, r8\n\t"               // w' += dw'
        "mov    r4, r12\n\t"              // s
        "lsrs   r5, r3, #29\n\t"
        "bne    3f\n"
        "2:\n\t"                          // normalise: wn < 2^29
        "lsls   r3, r3, #1\n\t"
        "subs   r4, r4, #1\n\t"
        "lsrs   r5, r3, #29\n\t"
        "beq    2b\n"
        "3:\n\t"
        "lsrs   r5, r3, #21\n\t"
        "lsls   r5, r5, #2\n\t"
        "add    r5, r10\n\t"              // &kRecip.v[j]
        "ldm    r5, {r5, r6}\n\t"         // t0 t1
        "subs   r6, r5, r6\n\t"
        "lsls   r3, r3, #11\n\t"
        "lsrs   r3, r3, #25\n\t"          // f = (wn >> 14) & 127
        "muls   r6, r3, r6\n\t"
        "lsrs   r6, r6, #7\n\t"
        "subs   r5, r5, r6\n\t"           // r
        "stm    r1!, {r4, r5}\n\t"        // x = s, y = r
        "cmp    r1, r11\n\t"
        "bne    1b\n\t"
        HIDER_V6M_RESTORE_ALL);
}

/// coordinate_pass_portable() in Thumb-1. r0 values, r1 out, r2 u, r3 out_end, r4..r7 scratch; r8 du,
/// r9 hu, r10 v, r11 dv, r12 hv, lr dvu (24 instructions a point).
HIDER_NAKED inline void coordinate_pass_v6m(const RowPass*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
        "ldr    r1, [r0, #40]\n\t"        // du
        "mov    r8, r1\n\t"
        "ldr    r1, [r0, #44]\n\t"        // hu
        "mov    r9, r1\n\t"
        "ldr    r1, [r0, #48]\n\t"        // v
        "mov    r10, r1\n\t"
        "ldr    r1, [r0, #52]\n\t"        // dv
        "mov    r11, r1\n\t"
        "ldr    r1, [r0, #56]\n\t"        // hv
        "mov    r12, r1\n\t"
        "ldr    r1, [r0, #60]\n\t"        // dvu
        "mov    lr, r1\n\t"
        "ldr    r2, [r0, #36]\n\t"        // u
        "ldr    r3, [r0, #8]\n\t"         // out_end
        "ldr    r1, [r0, #4]\n\t"         // out
        "ldr    r0, [r0, #0]\n"            // values
        "1:\n\t"
        "ldr    r5, [r1]\n\t"             // s
        "ldr    r6, [r1, #4]\n\t"         // r
        "ldrb   r4, [r0]\n\t"
        "adds   r0, r0, #1\n\t"
        "mov    r7, r9\n\t"
        "muls   r7, r4, r7\n\t"
        "adds   r7, r7, r2\n\t"           // U
        "add    r2, r8\n\t"               // u += du
        "asrs   r7, r7, #14\n\t"
        "muls   r7, r6, r7\n\t"
        "asrs   r7, r5\n\t"               // X
        "str    r7, [r1]\n\t"
        "mov    r7, r12\n\t"
        "muls   r7, r4, r7\n\t"
        "add    r7, r10\n\t"              // V
        "add    r10, r11\n\t"             // v += dv
        "asrs   r7, r7, #14\n\t"
        "muls   r7, r6, r7\n\t"
        "add    r5, lr\n\t"               // s + dvu
        "asrs   r7, r5\n\t"               // Y
        "str    r7, [r1, #4]\n\t"
        "adds   r1, r1, #8\n\t"
        "cmp    r1, r3\n\t"
        "bne    1b\n\t"
        HIDER_V6M_RESTORE_ALL);
}
#endif

/// The portable passes over heights of any integer type T (p.values unused).
template <class T>
void row_passes_any(const T* values, const RowPass& p) {
    uint32_t w = static_cast<uint32_t>(p.w);
    PlotPoint* const out = p.out;
    const int32_t n = static_cast<int32_t>(p.out_end - p.out);
    for (int32_t i = 0; i < n; ++i, w += static_cast<uint32_t>(p.dw)) {
        uint32_t wn = w + static_cast<uint32_t>(static_cast<int32_t>(values[i]) * p.hw);
        int32_t s = p.s0;
        while ((wn >> 29) == 0) {
            wn <<= 1;
            --s;
        }
        out[i].x = s;
        out[i].y = static_cast<int32_t>(detail::recip45(wn));
    }
    int32_t u = p.u, v = p.v;
    for (int32_t i = 0; i < n; ++i, u += p.du, v += p.dv) {
        const int32_t value = static_cast<int32_t>(values[i]);
        const int s = out[i].x;
        const uint32_t r = static_cast<uint32_t>(out[i].y);
        out[i].x = detail::scale16(u + value * p.hu, r, s);
        out[i].y = detail::scale16(v + value * p.hv, r, s + p.dvu);
    }
}

/// Both passes (Thumb-1 on ARMv6-M, else the portable loops).
inline void run_row_passes(const RowPass& p) {
#if defined(HIDER_ARMV6M)
    reciprocal_pass_v6m(&p);
    coordinate_pass_v6m(&p);
#else
    reciprocal_pass_portable(p);
    coordinate_pass_portable(p);
#endif
}

}  // namespace hider::horizon

// Projection of a curve of 8-bit heights when the camera has no yaw (its view direction and up lie in
// the y-z plane, as a waterfall's camera looking along the time axis): then W and V do not change along
// a curve, so the reciprocal r = 2^45 / W and the row coordinate Y depend on the height h alone.
// project.hpp computes both exactly at the 9 knots h = 0, 32, ..., 256 of each curve and this pass
// interpolates them linearly (while W varies by less than an eighth over the heights the error stays
// below 2^-15, the reciprocal table's own), leaving per point one product for X: no table, no
// normalisation. Portable C++, and a Thumb-1 loop on ARMv6-M with identical results (firmware/horizoncheck).
#pragma once
#include <hider/asm_v6m.hpp>
#include <hider/horizon/row_pass.hpp>

namespace hider::horizon {

/// Knot j covers heights [32 j, 32 j + 32): r(h) = (ar + dr h) >> 5 and Y(h) = (ay + dy h) >> 5, with
/// ar = 32 r_j - 32 j dr (dr = r_{j+1} - r_j; the same floor as r_j + ((dr (h - 32 j)) >> 5)), ay likewise.
struct LevelKnot {
    int32_t ar, dr, ay, dy;
};
constexpr int kLevelKnots = 9;         ///< knots per curve
constexpr int kLevelKnotBits = 5;      ///< heights per knot: 32

/// One curve for the level pass. The field order is the ARMv6-M loop's contract (static_assert below).
struct LevelPass {
    const uint8_t* values;    ///< heights h, one per point
    PlotPoint* out;           ///< points, out_end - out of them
    PlotPoint* out_end;
    const LevelKnot* knots;   ///< kLevelKnots
    int32_t u, du, hu;        ///< U at the first point for h = 0, per point, per height unit
    int32_t s;                ///< X = ((U >> 14) r) >> s
};
static_assert(sizeof(void*) != 4 || (offsetof(LevelPass, knots) == 12 && offsetof(LevelPass, u) == 16 &&
                                     offsetof(LevelPass, s) == 28 && sizeof(LevelKnot) == 16),
              "level pass layout");
static_assert(kLevelKnotBits == 5 && (kLevelKnots - 1) << kLevelKnotBits == 256, "the Thumb-1 loop shifts by 5");

/// The level pass in C++. Precondition: |U| < 2^29 at every point; s in [0, 31].
inline void level_pass_portable(const LevelPass& p) {
    const uint8_t* values = p.values;
    int32_t u = p.u;
    for (PlotPoint* o = p.out; o != p.out_end; ++o, ++values, u += p.du) {
        const int32_t h = *values;
        const LevelKnot& k = p.knots[h >> kLevelKnotBits];
        const int32_t r = (k.ar + k.dr * h) >> kLevelKnotBits;
        o->x = (((u + h * p.hu) >> 14) * r) >> p.s;
        o->y = (k.ay + k.dy * h) >> kLevelKnotBits;
    }
}

#if defined(HIDER_ARMV6M)
/// level_pass_portable() in Thumb-1. r0 values, r1 out, r2 u, r3 knots, r4 h, r5..r7 scratch; r8 du,
/// r9 hu, r10 out_end, r11 s. The knot's two halves come in with two load-multiples (24 instructions a point).
HIDER_NAKED inline void level_pass_v6m(const LevelPass*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
        "ldr    r1, [r0, #20]\n\t"        // du
        "mov    r8, r1\n\t"
        "ldr    r1, [r0, #24]\n\t"        // hu
        "mov    r9, r1\n\t"
        "ldr    r1, [r0, #8]\n\t"         // out_end
        "mov    r10, r1\n\t"
        "ldr    r1, [r0, #28]\n\t"        // s
        "mov    r11, r1\n\t"
        "ldr    r2, [r0, #16]\n\t"        // u
        "ldr    r3, [r0, #12]\n\t"        // knots
        "ldr    r1, [r0, #4]\n\t"         // out
        "ldr    r0, [r0, #0]\n"            // values
        "1:\n\t"
        "ldrb   r4, [r0]\n\t"             // h
        "adds   r0, r0, #1\n\t"
        "lsrs   r7, r4, #5\n\t"
        "lsls   r7, r7, #4\n\t"
        "adds   r7, r7, r3\n\t"           // &knots[h >> 5]
        "ldm    r7!, {r5, r6}\n\t"        // ar dr
        "muls   r6, r4, r6\n\t"
        "adds   r5, r5, r6\n\t"
        "asrs   r5, r5, #5\n\t"           // r
        "mov    r6, r9\n\t"
        "muls   r6, r4, r6\n\t"           // h hu
        "adds   r6, r6, r2\n\t"           // U
        "add    r2, r8\n\t"               // u += du
        "asrs   r6, r6, #14\n\t"
        "muls   r6, r5, r6\n\t"
        "mov    r5, r11\n\t"
        "asrs   r6, r5\n\t"               // X
        "ldm    r7, {r5, r7}\n\t"         // ay dy
        "muls   r7, r4, r7\n\t"
        "adds   r7, r7, r5\n\t"
        "asrs   r7, r7, #5\n\t"           // Y
        "stm    r1!, {r6, r7}\n\t"
        "cmp    r1, r10\n\t"
        "bne    1b\n\t"
        HIDER_V6M_RESTORE_ALL);
}
#endif

/// The knots of a curve: W (shifted left by n0 fits 30 bits) and V at heights 0, 32, .., 256 start at
/// w0, v0 and step by dw, dv; X and Y shift by 31 - e - du and 31 - e - dv_shift for W normalised by e.
/// Writes knots[0..kLevelKnots) and the common e (the largest); false when a shift leaves [7, 31].
inline bool make_level_knots(int32_t w0, int32_t v0, int32_t dw, int32_t dv, int n0, int du, int dv_shift,
                             LevelKnot* knots, int& e_max) {
    constexpr int32_t kStep = 1 << kLevelKnotBits;
    for (int32_t j = 0, w = w0, v = v0; j < kLevelKnots; ++j, w += dw, v += dv) {
        uint32_t wn = static_cast<uint32_t>(w) << n0;
        int ej = n0;
        while ((wn >> 29) == 0) {
            wn <<= 1;
            ++ej;
        }
        const int sy = 31 - ej - dv_shift;
        if (31 - ej - du < 7 || sy < 7 || sy > 31) return false;
        const uint32_t r = detail::recip45(wn);
        knots[j] = {static_cast<int32_t>(r), ej, detail::scale16(v, r, sy), 0};  // Y exactly, as project() gives it
        e_max = max(e_max, ej);
    }
    // One shift for X (r <= 2^16 kept), then offsets and steps from the next knot.
    int32_t next_r = 0, next_y = 0;
    for (int32_t j = kLevelKnots - 1; j >= 0; --j) {
        LevelKnot& kn = knots[j];
        const int32_t rj = kn.ar >> (e_max - kn.dr), yj = kn.ay;
        const int32_t dr = j < kLevelKnots - 1 ? next_r - rj : 0, dy = j < kLevelKnots - 1 ? next_y - yj : 0;
        kn = {(rj - j * dr) * kStep, dr, (yj - j * dy) * kStep, dy};
        next_r = rj;
        next_y = yj;
    }
    return true;
}

/// Runs the level pass (Thumb-1 on ARMv6-M, else the portable loop).
inline void run_level_pass(const LevelPass& p) {
#if defined(HIDER_ARMV6M)
    level_pass_v6m(&p);
#else
    level_pass_portable(p);
#endif
}

}  // namespace hider::horizon

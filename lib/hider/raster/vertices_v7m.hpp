// The common vertex of project_vertices() (vertices.hpp) in Thumb-2 for ARMv7-M, so that the transform's
// constants and the quotients stay in registers. Same results as project_common() for every vertex it
// accepts; it stops at the first one it refuses, which the caller projects in C++. firmware/kernelcheck
// compares it with the C++ path on random views and points.
#pragma once
#include <hider/raster/clip.hpp>

namespace hider {

#if defined(HIDER_ARMV7M)
namespace detail {
/// Per-frame constants of the Thumb-2 vertex loop (the layout is its contract). Each row is a rotation
/// row and the 64-bit sum it starts from (lo, hi), t 2^30, so that floor((start + row . p) / 2^30) is
/// the coordinate with its translation. Row 2 is negated and starts at 2^30 - 1 - t_z 2^30:
/// -floor(s / 2^30) = floor((-s + 2^30 - 1) / 2^30), so it gives w = -z.
struct VertexPrepV7m {
    int32_t row[3][5];         ///< 0, 20, 40: three rotation entries, start lo, start hi
    int32_t near_lo;           ///< 60: max(near, kMinNearRaw): w from here ...
    uint32_t span;             ///< 64: ... to here above it, min(far, 2^30 - 1) (project_common()'s limits)
    int32_t k_q8;              ///< 68
    uint32_t c512;             ///< 72: 512
    int32_t near_raw;          ///< 76
    uint32_t z0_lo, z0_hi;     ///< 80, 84: 2 (2^31 scale + 2^30 + kDepthNear 2^31) modulo 2^64
    uint32_t zs_lo, zs_hi;     ///< 88, 92: -2 scale modulo 2^64 (scale = depth_scale_q31)
    uint32_t guard;            ///< 96: g = kGuardBand 256 - 128
};
static_assert(offsetof(VertexPrepV7m, near_lo) == 60 && offsetof(VertexPrepV7m, z0_lo) == 80 &&
                  offsetof(VertexPrepV7m, guard) == 96,
              "Thumb-2 vertex loop constants layout");
static_assert(sizeof(Vec3q16) == 12 && sizeof(ScreenVertex) == 8 && offsetof(ScreenVertex, y) == 2 &&
                  offsetof(ScreenVertex, z) == 4,
              "the Thumb-2 vertex loop's strides");

/// One row: three entries and the 64-bit start, its low word first.
inline void set_row_v7m(int32_t (&row)[5], uint32_t a, uint32_t b, uint32_t c, int64_t start) {
    row[0] = static_cast<int32_t>(a);
    row[1] = static_cast<int32_t>(b);
    row[2] = static_cast<int32_t>(c);
    row[3] = static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(start)));
    row[4] = static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(start) >> 32));
}

/// The loop's constants for view v. Where project_common() takes no w (near beyond min(far, 2^30 - 1)),
/// and for views make_view() does not give (near below 1, a negative k), every position gets
/// w = near_lo - 1, which the loop refuses.
inline VertexPrepV7m vertex_prep_v7m(const View& v) {
    VertexPrepV7m p;  // every field set below, without a loop or a clear
    const int32_t far_fast = min(v.far_raw, (int32_t{1} << 30) - 1);
    p.near_lo = max(v.near_raw, kMinNearRaw);
    const bool none = v.near_raw < 1 || v.k_q8 < 0 || far_fast < p.near_lo;
    const Q30(&m)[3][3] = v.to_view.rot.m;
    auto u = [](Q30 e) { return static_cast<uint32_t>(e.raw()); };
    constexpr int64_t kOne = int64_t{1} << 30;
    set_row_v7m(p.row[0], u(m[0][0]), u(m[0][1]), u(m[0][2]), int64_t{v.to_view.trans.x.raw()} * kOne);
    set_row_v7m(p.row[1], u(m[1][0]), u(m[1][1]), u(m[1][2]), int64_t{v.to_view.trans.y.raw()} * kOne);
    if (none)
        set_row_v7m(p.row[2], 0, 0, 0, int64_t{p.near_lo - 1} * kOne);
    else
        set_row_v7m(p.row[2], 0u - u(m[2][0]), 0u - u(m[2][1]), 0u - u(m[2][2]),
                    kOne - 1 - int64_t{v.to_view.trans.z.raw()} * kOne);
    p.span = none ? 0u : static_cast<uint32_t>(far_fast - p.near_lo);
    p.k_q8 = v.k_q8;
    p.c512 = 512;
    p.near_raw = v.near_raw;
    const uint64_t z0 = 2 * ((v.depth_scale_q31 << 31) + (uint64_t{1} << 30) + (uint64_t{kDepthNear} << 31));
    const uint64_t zs = 0 - 2 * v.depth_scale_q31;
    p.z0_lo = static_cast<uint32_t>(z0);
    p.z0_hi = static_cast<uint32_t>(z0 >> 32);
    p.zs_lo = static_cast<uint32_t>(zs);
    p.zs_hi = static_cast<uint32_t>(zs >> 32);
    p.guard = static_cast<uint32_t>(kGuardBand) * 256u - 128u;
    return p;
}
}  // namespace detail

/// project_common() (vertices.hpp) in Thumb-2 for positions [p, end) until one it refuses; returns that
/// one (end when it projected them all), having written the same vertices as project_common().
/// Per vertex, with L = clz(w) (2 <= L <= 23 for near_lo <= w < 2^30) and v = w 2^(L-1) in [2^30, 2^31):
/// - the transform: three load-multiples of a row and its start, three multiply-accumulates each;
/// - near_lo <= w <= near_lo + span as one unsigned compare;
/// - per screen coordinate c (x, and y negated): N = c k + 128 w - [c < 0], so that the rounded quotient
///   (half away from zero) is floor(N / 256 w); the guard band (|c k| <= kGuardBand 256 w) is
///   -(w g) - 1 <= N <= w (g + 256) with g = kGuardBand 256 - 128 > 2^21: it holds where both high
///   words lie in [-(w >> 11), w >> 11), and is tested exactly (64 bits) where they do not;
/// - d = floor(v / 2^14) in [2^16, 2^17) divides both quotients and n / w: e = N 2^(L-23) / d (signed
///   division of floor(N / 2^(23-L))) is floor(N / 256 w) or one more, r = floor(N / 256) - e w in
///   [-w, w) says which;
/// - u = floor(n 2^31 / w) = floor(n 2^L 2^31 / 2 v) in three signed digits of 15, 14 and 2 bits, each
///   a quotient by d that is the digit or one more, leaving a remainder in [-v, v); the last one's sign
///   corrects u (n = w gives 2^31);
/// - z = kDepthNear + (((2^31 - u) scale + 2^30) >> 31) as the high word of z0 + u zs.
/// Registers: r0 the constants (+80 during the vertex), r1 p, r2 out, r3 end.
HIDER_NAKED inline const Vec3q16* project_common_v7m(const detail::VertexPrepV7m*, const Vec3q16*,
                                                                          ScreenVertex*, const Vec3q16*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "cmp    r1, r3\n\t"
        "beq    9f\n"
        "1:\n\t"
        "ldm    r1!, {r4, r5, r6}\n\t"         // x y z
        ".irp   res, r11, r12, lr\n\t"          // X, Y, w: (start + row . p) / 2^30, low word
        "ldm    r0!, {r7, r8, r9, r10, \\res}\n\t"
        "smlal  r10, \\res, r7, r4\n\t"
        "smlal  r10, \\res, r8, r5\n\t"
        "smlal  r10, \\res, r9, r6\n\t"
        "lsl    \\res, \\res, #2\n\t"
        "orr    \\res, \\res, r10, lsr #30\n\t"
        ".endr\n\t"
        "ldm    r0!, {r4, r5, r6, r7, r8}\n\t" // near_lo, span, k, 512, n
        "sub    r9, lr, r4\n\t"
        "cmp    r9, r5\n\t"
        "bhi    8f\n\t"                        // w below near_lo or past the span
        "clz    r9, lr\n\t"                    // L
        "lsl    r7, r7, r9\n\t"                // P = 2^(9+L), 0 for L = 23
        "lsl    r8, r8, r9\n\t"                // n 2^L
        "asr    r4, r11, #31\n\t"
        "adds   r10, r4, lr, lsl #7\n\t"
        "adc    r4, r4, lr, lsr #25\n\t"
        "smlal  r10, r4, r11, r6\n\t"          // Nx = X k + 128 w - [X < 0]: r10 lo, r4 hi
        "asr    r5, r12, #31\n\t"
        "adds   r11, r5, lr, lsl #7\n\t"
        "adc    r5, r5, lr, lsr #25\n\t"
        "smlal  r11, r5, r12, r6\n\t"          // Ny = Y k + 128 w - [Y < 0]: r11 lo, r5 hi
        "eor    r6, r4, r4, asr #31\n\t"
        "eor    r12, r5, r5, asr #31\n\t"
        "orr    r6, r6, r12\n\t"
        "cmp    r6, lr, lsr #11\n\t"
        "bhs    7f\n"                          // a high word not inside w 2^-11: the exact test
        "2:\n\t"
        "rsb    r6, r9, #23\n\t"               // 23 - L
        "lsr    r12, r10, r6\n\t"
        "mla    r12, r4, r7, r12\n\t"          // floor(Nx / 2^(23-L))
        "lsr    r6, r11, r6\n\t"
        "mla    r6, r5, r7, r6\n\t"            // floor(Ny / 2^(23-L))
        "sub    r7, r9, #1\n\t"
        "lsl    r7, lr, r7\n\t"                // v
        "lsr    r9, r7, #14\n\t"               // d
        "sdiv   r12, r12, r9\n\t"              // ex
        "sdiv   r6, r6, r9\n\t"                // ey
        "lsr    r10, r10, #8\n\t"
        "orr    r10, r10, r4, lsl #24\n\t"
        "mls    r10, r12, lr, r10\n\t"         // floor(Nx / 256) - ex w
        "add    r12, r12, r10, asr #31\n\t"    // x
        "lsr    r11, r11, #8\n\t"
        "orr    r11, r11, r5, lsl #24\n\t"
        "mls    r11, r6, lr, r11\n\t"
        "rsb    r6, r6, r11, lsr #31\n\t"      // y = -floor(Ny / 256 w)
        "bfi    r12, r6, #16, #16\n\t"         // x | y << 16
        "udiv   r10, r8, r9\n\t"               // q1
        "lsl    r8, r8, #14\n\t"
        "mls    r8, r10, r7, r8\n\t"           // R1 = n 2^(L+14) - q1 v
        "sdiv   r11, r8, r9\n\t"               // q2
        "lsl    r8, r8, #14\n\t"
        "mls    r8, r11, r7, r8\n\t"           // R2
        "add    r10, r11, r10, lsl #14\n\t"
        "sdiv   r11, r8, r9\n\t"
        "asr    r11, r11, #12\n\t"             // q3
        "lsl    r8, r8, #2\n\t"
        "mls    r8, r11, r7, r8\n\t"           // R3
        "add    r10, r11, r10, lsl #2\n\t"
        "add    r10, r10, r8, asr #31\n\t"     // u
        "ldm    r0, {r4, r5, r6, r7}\n\t"      // z0, zs
        "umlal  r4, r5, r10, r6\n\t"
        "mla    r5, r10, r7, r5\n\t"           // z
        "sub    r0, r0, #80\n\t"
        "strd   r12, r5, [r2], #8\n\t"
        "cmp    r1, r3\n\t"
        "bne    1b\n"
        "9:\n\t"
        "mov    r0, r3\n\t"                    // end: all projected
        "pop    {r4-r11, pc}\n"
        "7:\n\t"                               // -(w g) - 1 <= N <= w (g + 256) for Nx and Ny
        "push   {r2, r3}\n\t"
        "ldr    r12, [r0, #16]\n\t"            // g
        "umull  r2, r3, lr, r12\n\t"
        "mvn    r2, r2\n\t"
        "mvn    r3, r3\n\t"                    // -(w g) - 1
        "subs   r6, r10, r2\n\t"
        "sbcs   r6, r4, r3\n\t"
        "blt    6f\n\t"
        "subs   r6, r11, r2\n\t"
        "sbcs   r6, r5, r3\n\t"
        "blt    6f\n\t"
        "add    r12, r12, #256\n\t"
        "umull  r2, r3, lr, r12\n\t"           // w (g + 256)
        "subs   r6, r2, r10\n\t"
        "sbcs   r6, r3, r4\n\t"
        "blt    6f\n\t"
        "subs   r6, r2, r11\n\t"
        "sbcs   r6, r3, r5\n\t"
        "blt    6f\n\t"
        "pop    {r2, r3}\n\t"
        "b      2b\n"
        "6:\n\t"
        "pop    {r2, r3}\n"
        "8:\n\t"                               // refused: the caller projects it the general way
        "sub    r0, r1, #12\n\t"
        "pop    {r4-r11, pc}\n");
}
#endif

}  // namespace hider

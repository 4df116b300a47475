// The common vertex of project_vertices() (vertices.hpp) in Thumb-2 for ARMv7-M, so that the transform's
// constants and the quotients stay in registers. Same results as project_common() for every vertex it
// accepts; it stops at the first one it refuses, which the caller projects in C++. firmware/kernelcheck
// compares it with the C++ path on random views and points.
#pragma once
#include <hider/raster/clip.hpp>

namespace hider {

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
namespace detail {
/// Per-frame constants of the Thumb-2 vertex loop (the layout is its contract).
struct VertexPrepV7m {
    int32_t row[3][4];         ///< 0, 16, 32: a rotation row and its translation; row 2 holds -t_z (w = -z)
    int32_t near_raw;          ///< 48
    int32_t far_fast;          ///< 52: min(far, 2^30 - 1), project_common()'s w limits in one
    int32_t k_q8;              ///< 56
    uint32_t guard;            ///< 60: kGuardBand 256
    uint32_t scale_lo, scale_hi;  ///< 64, 68: depth_scale_q31
};
static_assert(offsetof(VertexPrepV7m, near_raw) == 48 && offsetof(VertexPrepV7m, scale_lo) == 64,
              "Thumb-2 vertex loop constants layout");
static_assert(sizeof(Vec3q16) == 12 && sizeof(ScreenVertex) == 8 && offsetof(ScreenVertex, y) == 2 &&
                  offsetof(ScreenVertex, z) == 4,
              "the Thumb-2 vertex loop's strides");

inline VertexPrepV7m vertex_prep_v7m(const View& v) {
    VertexPrepV7m p{};
    const int32_t t[3] = {v.to_view.trans.x.raw(), v.to_view.trans.y.raw(), v.to_view.trans.z.raw()};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) p.row[i][j] = v.to_view.rot.m[i][j].raw();
        p.row[i][3] = t[i];
    }
    p.row[2][3] = static_cast<int32_t>(0u - static_cast<uint32_t>(t[2]));
    p.near_raw = v.near_raw;
    p.far_fast = min(v.far_raw, (int32_t{1} << 30) - 1);
    p.k_q8 = v.k_q8;
    p.guard = static_cast<uint32_t>(kGuardBand) * 256u;
    p.scale_lo = static_cast<uint32_t>(v.depth_scale_q31);
    p.scale_hi = static_cast<uint32_t>(v.depth_scale_q31 >> 32);
    return p;
}
}  // namespace detail

/// project_common() (vertices.hpp) in Thumb-2 for positions [p, end) until one it refuses; returns that
/// one (end when it projected them all), having written the same vertices as project_common(). In
/// assembly so that the transform's constants and the quotients stay in registers. Per vertex: the transform (three load-multiples of a row and
/// its translation, nine long multiplies), w against near and min(far, 2^30 - 1), the guard band, the
/// screen quotients with one division each, n 2^31 / w in two 16-bit digits (ratio_q31()), the depth.
/// Registers: r0 the constants (+48 after the transform); on the stack p (advanced), out and end.
HIDER_NAKED inline const Vec3q16* project_common_v7m(const detail::VertexPrepV7m*, const Vec3q16*,
                                                                          ScreenVertex*, const Vec3q16*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "push   {r1, r2, r3}\n\t"              // p, out, end
        "cmp    r1, r3\n\t"
        "beq    9f\n"
        "1:\n\t"
        "ldm    r1!, {r4, r5, r6}\n\t"         // x y z
        "str    r1, [sp]\n\t"
        ".irp   res, r1, r2, r3\n\t"            // each row: floor(sum / 2^30) (then + t)
        "ldm    r0!, {r7, r8, r9, r10}\n\t"
        "smull  r11, r12, r7, r4\n\t"
        "smlal  r11, r12, r8, r5\n\t"
        "smlal  r11, r12, r9, r6\n\t"
        "lsr    r11, r11, #30\n\t"
        "orr    r11, r11, r12, lsl #2\n\t"
        ".ifnc  \\res, r3\n\t"
        "add    \\res, r11, r10\n\t"           // x, y: + t
        ".endif\n\t"
        ".endr\n\t"
        "sub    r3, r10, r11\n\t"               // w = -t_z - floor(sum / 2^30)
        "ldm    r0, {r7, r8, r9, r10}\n\t"     // near, far_fast, k, guard
        "cmp    r3, r7\n\t"
        "blt    8f\n\t"
        "cmp    r3, r8\n\t"
        "bgt    8f\n\t"
        "smull  r4, r5, r1, r9\n\t"            // xk
        "smull  r6, r11, r2, r9\n\t"           // yk
        "asr    r1, r5, #31\n\t"               // xk < 0: -1
        "eor    r4, r4, r1\n\t"
        "eor    r5, r5, r1\n\t"
        "subs   r4, r4, r1\n\t"
        "sbc    r5, r5, r1\n\t"                // |xk|
        "asr    r2, r11, #31\n\t"
        "eor    r6, r6, r2\n\t"
        "eor    r11, r11, r2\n\t"
        "subs   r6, r6, r2\n\t"
        "sbc    r11, r11, r2\n\t"              // |yk|
        "umull  r7, r8, r3, r10\n\t"           // the guard: w kGuardBand 256
        "cmp    r7, r4\n\t"
        "sbcs   r12, r8, r5\n\t"
        "bcc    8f\n\t"                        // |xk| above it
        "cmp    r7, r6\n\t"
        "sbcs   r12, r8, r11\n\t"
        "bcc    8f\n\t"
        "clz    r7, r3\n\t"                    // leading zeros of w
        "rsbs   r8, r7, #16\n\t"
        "it     lt\n\t"
        "movlt  r8, #0\n\t"                    // s
        "sub    r9, r3, #1\n\t"
        "lsr    r9, r9, r8\n\t"
        "add    r9, r9, #1\n\t"                // W = ceil(w / 2^s)
        "add    r10, r8, #8\n\t"               // t = s + 8
        "rsb    r12, r10, #32\n\t"
        "lsl    lr, r3, #7\n\t"
        "adds   r4, r4, lr\n\t"
        "adc    r5, r5, r3, lsr #25\n\t"       // |xk| + 128 w
        "adds   r6, r6, lr\n\t"
        "adc    r11, r11, r3, lsr #25\n\t"     // |yk| + 128 w
        "lsr    lr, r4, r10\n\t"
        "lsl    r8, r5, r12\n\t"
        "orr    lr, lr, r8\n\t"
        "udiv   lr, lr, r9\n\t"                // e
        "lsr    r4, r4, #8\n\t"
        "orr    r4, r4, r5, lsl #24\n\t"       // m
        "mls    r4, lr, r3, r4\n\t"            // m - e w
        "cmp    r4, r3\n\t"
        "it     hs\n\t"
        "addhs  lr, lr, #1\n\t"                // qx
        "lsr    r4, r6, r10\n\t"
        "lsl    r8, r11, r12\n\t"
        "orr    r4, r4, r8\n\t"
        "udiv   r4, r4, r9\n\t"
        "lsr    r6, r6, #8\n\t"
        "orr    r6, r6, r11, lsl #24\n\t"
        "mls    r6, r4, r3, r6\n\t"
        "cmp    r6, r3\n\t"
        "it     hs\n\t"
        "addhs  r4, r4, #1\n\t"                // qy
        "eor    lr, lr, r1\n\t"
        "sub    lr, lr, r1\n\t"                // x: -qx when xk < 0
        "mvn    r2, r2\n\t"
        "eor    r4, r4, r2\n\t"
        "sub    r4, r4, r2\n\t"                // y: -qy unless yk < 0
        "bfi    lr, r4, #16, #16\n\t"          // x | y << 16
        "ldr    r8, [r0]\n\t"                  // near
        "mov    r5, #0x80000000\n\t"           // u = 2^31 on the near plane
        "cmp    r3, r8\n\t"
        "ble    7f\n\t"
        // u = ratio_q31(near, w, leading zeros of w): n 2^31 / w in two 16-bit digits.
        "lsl    r9, r3, r7\n\t"                // v
        "lsl    r8, r8, r7\n\t"                // nn
        "lsr    r10, r9, #16\n\t"              // vn1
        "uxth   r11, r9\n\t"                   // vn0
        "lsr    r12, r8, #1\n\t"               // un32
        "lsl    r8, r8, #31\n\t"
        "lsr    r8, r8, #16\n\t"               // un1 = (nn & 1) << 15
        "udiv   r1, r12, r10\n\t"              // q1
        "mls    r2, r1, r10, r12\n"            // rhat
        "2:\n\t"
        "cmp    r1, #0x10000\n\t"
        "bhs    3f\n\t"
        "mul    r6, r1, r11\n\t"
        "orr    r4, r8, r2, lsl #16\n\t"
        "cmp    r4, r6\n\t"
        "bhs    4f\n"                          // q1 vn0 <= rhat 2^16 + un1: q1 holds
        "3:\n\t"
        "sub    r1, r1, #1\n\t"
        "add    r2, r2, r10\n\t"
        "cmp    r2, #0x10000\n\t"
        "blo    2b\n"
        "4:\n\t"
        "add    r4, r8, r12, lsl #16\n\t"
        "mls    r4, r1, r9, r4\n\t"            // un21
        "udiv   r5, r4, r10\n\t"               // q0
        "mls    r2, r5, r10, r4\n"             // rhat
        "5:\n\t"
        "cmp    r5, #0x10000\n\t"
        "bhs    6f\n\t"
        "mul    r6, r5, r11\n\t"
        "cmp    r6, r2, lsl #16\n\t"
        "bls    61f\n"                         // q0 vn0 <= rhat 2^16: q0 holds
        "6:\n\t"
        "sub    r5, r5, #1\n\t"
        "add    r2, r2, r10\n\t"
        "cmp    r2, #0x10000\n\t"
        "blo    5b\n"
        "61:\n\t"
        "orr    r5, r5, r1, lsl #16\n"         // u
        "7:\n\t"
        "rsb    r5, r5, #0x80000000\n\t"       // 2^31 - u
        "ldrd   r8, r9, [r0, #16]\n\t"         // depth_scale_q31
        "umull  r10, r11, r5, r8\n\t"
        "mla    r11, r5, r9, r11\n\t"
        "adds   r10, r10, #0x40000000\n\t"
        "adc    r11, r11, #0\n\t"
        "lsr    r10, r10, #31\n\t"
        "orr    r10, r10, r11, lsl #1\n\t"
        "add    r10, r10, %[dnear]\n\t"        // z
        "sub    r0, r0, #48\n\t"
        "ldm    sp, {r1, r2, r12}\n\t"         // p (advanced), out, end
        "strd   lr, r10, [r2], #8\n\t"
        "str    r2, [sp, #4]\n\t"
        "cmp    r1, r12\n\t"
        "bne    1b\n"
        "9:\n\t"
        "ldr    r0, [sp, #8]\n\t"              // end: all projected
        "add    sp, sp, #12\n\t"
        "pop    {r4-r11, pc}\n"
        "8:\n\t"                               // refused: the caller projects it the general way
        "ldr    r0, [sp]\n\t"
        "sub    r0, r0, #12\n\t"
        "add    sp, sp, #12\n\t"
        "pop    {r4-r11, pc}\n"
        :
        : [dnear] "i"(kDepthNear));
}
#endif

}  // namespace hider

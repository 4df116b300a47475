// The common vertex of project_vertices() (vertices.hpp) in Thumb-1 for ARMv6-M (no long multiply, no
// divide; GCC's C++ spent most of a vertex in calls and stack traffic around 64-bit products by parts).
// Same results as outcode() and project() for every vertex it accepts; it stops at the first one it
// refuses, which the caller projects in C++. firmware/kernelcheck compares it with the C++ path on
// random views and points.
#pragma once
#include <hider/raster/clip.hpp>

namespace hider {

namespace detail {
/// Per-frame constants of the Thumb-1 vertex loop (the layout is its contract).
struct VertexPrep {
    int32_t row[3][7];          ///< per rotation row: r >> 16 per column, r & 0xFFFF per column, translation
    int32_t near_raw;           ///< 84
    int32_t far_fast;           ///< 88: min(far, 2^29 - 1): the loop refuses w above it
    uint32_t k_hi, k_lo;        ///< 92, 96: k_q8 in 16-bit halves
    uint32_t scale_lo, scale_hi;///< 100, 104: depth_scale_q31
    const uint16_t* table;      ///< 108: kReciprocalTableData
};
static_assert(sizeof(void*) != 4 || (offsetof(VertexPrep, near_raw) == 84 && offsetof(VertexPrep, table) == 108),
              "vertex loop constants layout");

inline VertexPrep vertex_prep(const View& v) {
    VertexPrep p{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            p.row[i][j] = v.to_view.rot.m[i][j].raw() >> 16;
            p.row[i][3 + j] = v.to_view.rot.m[i][j].raw() & 0xFFFF;
        }
    }
    p.row[0][6] = v.to_view.trans.x.raw();
    p.row[1][6] = v.to_view.trans.y.raw();
    p.row[2][6] = v.to_view.trans.z.raw();
    p.near_raw = v.near_raw;
    p.far_fast = min(v.far_raw, (int32_t{1} << 29) - 1);
    p.k_hi = static_cast<uint32_t>(v.k_q8) >> 16;
    p.k_lo = static_cast<uint32_t>(v.k_q8) & 0xFFFFu;
    p.scale_lo = static_cast<uint32_t>(v.depth_scale_q31);
    p.scale_hi = static_cast<uint32_t>(v.depth_scale_q31 >> 32);
    p.table = kReciprocalTableData;
    return p;
}
}  // namespace detail

#if defined(HIDER_ARMV6M)
/// Projects positions [p, end) into out while each lies inside the view volume with w < 2^29; returns
/// the first position it did not project (end when it did all). Per vertex: the transform as
/// dot3_split_floor() does it (twelve 32-bit multiplies a row), the guard band from |x| k and
/// 255 w 2^14 by 16-bit parts, then the three quotients by w from one estimate of 2^48 / (w normalised)
/// (reciprocal_word()'s table and Newton step): the screen coordinates from one estimate each, n 2^31 / w
/// in two 16-bit digits, every estimate corrected against its exact remainder. Stack: the position's
/// low halves, x y w, the guard, the shift, the normalised w and the estimate, the pointers (80 bytes).
HIDER_NAKED inline const Vec3q16* project_common_v6m(const detail::VertexPrep*, const Vec3q16*,
                                                                          ScreenVertex*, const Vec3q16*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        // One rotation row at offset \o of the constants (r7) times the position halves (ph in r4 r5 r6,
        // pl on the stack at 12..20) plus the translation, floored: 4 sum(rh ph) + floor((sum(rh pl + rl ph)
        // + floor(sum(rl pl) / 2^16)) / 2^14) + t. Result in r0; scratch r1..r3.
        ".macro hider_row o\n\t"
        "ldr    r0, [r7, #(\\o + 12)]\n\t"
        "ldr    r1, [sp, #12]\n\t"
        "muls   r0, r1, r0\n\t"                 // rl0 pl0
        "ldr    r1, [r7, #(\\o + 16)]\n\t"
        "ldr    r2, [sp, #16]\n\t"
        "muls   r1, r2, r1\n\t"                 // rl1 pl1
        "movs   r2, #0\n\t"
        "adds   r0, r0, r1\n\t"
        "adcs   r2, r2\n\t"
        "ldr    r1, [r7, #(\\o + 20)]\n\t"
        "ldr    r3, [sp, #20]\n\t"
        "muls   r1, r3, r1\n\t"                 // rl2 pl2
        "movs   r3, #0\n\t"
        "adds   r0, r0, r1\n\t"
        "adcs   r2, r3\n\t"
        "lsrs   r0, r0, #16\n\t"
        "lsls   r2, r2, #16\n\t"
        "orrs   r0, r2\n\t"                     // r1:r0 = floor(sum(rl pl) / 2^16)
        "movs   r1, #0\n\t"
        "ldr    r2, [r7, #(\\o + 0)]\n\t"
        "ldr    r3, [sp, #12]\n\t"
        "muls   r2, r3, r2\n\t"                 // rh0 pl0
        "ldr    r3, [r7, #(\\o + 12)]\n\t"
        "muls   r3, r4, r3\n\t"                 // rl0 ph0
        "adds   r2, r2, r3\n\t"
        "asrs   r3, r2, #31\n\t"
        "adds   r0, r0, r2\n\t"
        "adcs   r1, r3\n\t"
        "ldr    r2, [r7, #(\\o + 4)]\n\t"
        "ldr    r3, [sp, #16]\n\t"
        "muls   r2, r3, r2\n\t"                 // rh1 pl1
        "ldr    r3, [r7, #(\\o + 16)]\n\t"
        "muls   r3, r5, r3\n\t"                 // rl1 ph1
        "adds   r2, r2, r3\n\t"
        "asrs   r3, r2, #31\n\t"
        "adds   r0, r0, r2\n\t"
        "adcs   r1, r3\n\t"
        "ldr    r2, [r7, #(\\o + 8)]\n\t"
        "ldr    r3, [sp, #20]\n\t"
        "muls   r2, r3, r2\n\t"                 // rh2 pl2
        "ldr    r3, [r7, #(\\o + 20)]\n\t"
        "muls   r3, r6, r3\n\t"                 // rl2 ph2
        "adds   r2, r2, r3\n\t"
        "asrs   r3, r2, #31\n\t"
        "adds   r0, r0, r2\n\t"
        "adcs   r1, r3\n\t"
        "lsrs   r0, r0, #14\n\t"
        "lsls   r1, r1, #18\n\t"
        "orrs   r0, r1\n\t"                     // floor(/ 2^14)
        "ldr    r1, [r7, #(\\o + 0)]\n\t"
        "muls   r1, r4, r1\n\t"                 // rh0 ph0
        "ldr    r2, [r7, #(\\o + 4)]\n\t"
        "muls   r2, r5, r2\n\t"
        "adds   r1, r1, r2\n\t"
        "ldr    r2, [r7, #(\\o + 8)]\n\t"
        "muls   r2, r6, r2\n\t"
        "adds   r1, r1, r2\n\t"
        "lsls   r1, r1, #2\n\t"
        "adds   r0, r0, r1\n\t"
        "ldr    r1, [r7, #(\\o + 24)]\n\t"
        "adds   r0, r0, r1\n\t"
        ".endm\n\t"
        // A screen coordinate: |c| (c on the stack at \at) times k against the guard, then
        // e = floor(m / w), m = floor((|c| k + 128 w) / 256), into r4 (sign not applied).
        // Refuses (branch to 80) outside the guard band. Scratch r0..r6.
        ".macro hider_coord at\n\t"
        "ldr    r0, [sp, #\\at]\n\t"
        "asrs   r1, r0, #31\n\t"
        "eors   r0, r1\n\t"
        "subs   r0, r0, r1\n\t"                 // |c|
        "lsrs   r1, r0, #16\n\t"                // ch
        "uxth   r0, r0\n\t"                     // cl
        "ldr    r2, [r7, #96]\n\t"              // kl
        "movs   r3, r2\n\t"
        "muls   r3, r0, r3\n\t"                 // cl kl
        "muls   r2, r1, r2\n\t"                 // ch kl
        "ldr    r4, [r7, #92]\n\t"              // kh
        "movs   r5, r4\n\t"
        "muls   r5, r0, r5\n\t"                 // cl kh
        "muls   r4, r1, r4\n\t"                 // ch kh
        "adds   r2, r2, r5\n\t"                 // the middle products, carry into 2^48
        "movs   r5, #0\n\t"
        "adcs   r5, r5\n\t"
        "lsls   r5, r5, #16\n\t"
        "adds   r4, r4, r5\n\t"
        "lsls   r5, r2, #16\n\t"
        "lsrs   r2, r2, #16\n\t"
        "adds   r3, r3, r5\n\t"
        "adcs   r4, r2\n\t"                     // r4:r3 = |c| k
        "ldr    r0, [sp, #36]\n\t"
        "ldr    r1, [sp, #40]\n\t"
        "subs   r0, r0, r3\n\t"
        "sbcs   r1, r4\n\t"
        "bcs    1f\n\t"
        "b      80f\n"                          // |c| k > guard
        "1:\n\t"
        "ldr    r0, [sp, #32]\n\t"              // w
        "lsls   r1, r0, #7\n\t"
        "lsrs   r2, r0, #25\n\t"
        "adds   r3, r3, r1\n\t"
        "adcs   r4, r2\n\t"
        "lsrs   r3, r3, #8\n\t"
        "lsls   r1, r4, #24\n\t"
        "orrs   r3, r1\n\t"
        "lsrs   r4, r4, #8\n\t"                 // r4:r3 = m < w 2^15
        "ldr    r1, [sp, #44]\n\t"              // s
        "lsls   r4, r4, r1\n\t"
        "movs   r2, #32\n\t"
        "subs   r2, r2, r1\n\t"
        "movs   r1, r3\n\t"
        "lsrs   r1, r1, r2\n\t"
        "orrs   r4, r1\n\t"                     // (m << s) >> 32, below 2^15
        "ldr    r1, [sp, #52]\n\t"
        "muls   r4, r1, r4\n\t"
        "lsrs   r4, r4, #16\n\t"
        "adds   r4, r4, #1\n\t"                 // e: the quotient within a few (+1: most often exact)
        "movs   r1, r4\n\t"
        "muls   r1, r0, r1\n\t"
        "subs   r3, r3, r1\n\t"                 // m - e w (|.| < 2^31: w < 2^29)
        "bpl    3f\n"
        "2:\n\t"
        "subs   r4, r4, #1\n\t"
        "adds   r3, r3, r0\n\t"
        "bmi    2b\n\t"
        "b      5f\n"
        "3:\n\t"
        "cmp    r3, r0\n\t"
        "blo    5f\n"
        "4:\n\t"
        "adds   r4, r4, #1\n\t"
        "subs   r3, r3, r0\n\t"
        "cmp    r3, r0\n\t"
        "bhs    4b\n"
        "5:\n\t"
        ".endm\n\t"
        "push   {r4-r7, lr}\n\t"
        "sub    sp, #80\n\t"
        "mov    r7, r0\n\t"
        "str    r1, [sp, #56]\n\t"              // the current position
        "str    r2, [sp, #60]\n\t"              // its output
        "str    r3, [sp, #64]\n"                // the end
        "10:\n\t"
        "ldr    r0, [sp, #56]\n\t"
        "ldr    r1, [sp, #64]\n\t"
        "cmp    r0, r1\n\t"
        "bne    11f\n\t"
        "b      90f\n"
        "11:\n\t"
        "ldm    r0!, {r1, r2, r3}\n\t"
        "asrs   r4, r1, #16\n\t"              // ph in r4 r5 r6, pl on the stack
        "uxth   r1, r1\n\t"
        "str    r1, [sp, #12]\n\t"
        "asrs   r5, r2, #16\n\t"
        "uxth   r2, r2\n\t"
        "str    r2, [sp, #16]\n\t"
        "asrs   r6, r3, #16\n\t"
        "uxth   r3, r3\n\t"
        "str    r3, [sp, #20]\n\t"
        "hider_row 0\n\t"
        "str    r0, [sp, #24]\n\t"              // x
        "hider_row 28\n\t"
        "str    r0, [sp, #28]\n\t"              // y
        "hider_row 56\n\t"
        "negs   r0, r0\n\t"                     // w = -z
        "str    r0, [sp, #32]\n\t"
        "ldr    r1, [r7, #84]\n\t"
        "cmp    r0, r1\n\t"
        "bge    12f\n\t"
        "b      80f\n"                          // nearer than near
        "12:\n\t"
        "ldr    r1, [r7, #88]\n\t"
        "cmp    r0, r1\n\t"
        "ble    13f\n\t"
        "b      80f\n"                          // past far or 2^29
        "13:\n\t"
        "lsls   r2, r0, #8\n\t"                 // guard = (256 w - w) 2^14, 64-bit
        "lsrs   r3, r0, #24\n\t"
        "subs   r2, r2, r0\n\t"
        "movs   r4, #0\n\t"
        "sbcs   r3, r4\n\t"
        "lsls   r3, r3, #14\n\t"
        "lsrs   r4, r2, #18\n\t"
        "orrs   r3, r4\n\t"
        "lsls   r2, r2, #14\n\t"
        "str    r2, [sp, #36]\n\t"
        "str    r3, [sp, #40]\n\t"
        "movs   r1, #0\n\t"                     // s = clz(w), wn = w << s
        "movs   r2, r0\n\t"
        "lsrs   r3, r2, #16\n\t"
        "bne    14f\n\t"
        "adds   r1, r1, #16\n\t"
        "lsls   r2, r2, #16\n"
        "14:\n\t"
        "lsrs   r3, r2, #24\n\t"
        "bne    14f\n\t"
        "adds   r1, r1, #8\n\t"
        "lsls   r2, r2, #8\n"
        "14:\n\t"
        "lsrs   r3, r2, #28\n\t"
        "bne    14f\n\t"
        "adds   r1, r1, #4\n\t"
        "lsls   r2, r2, #4\n"
        "14:\n\t"
        "lsrs   r3, r2, #30\n\t"
        "bne    14f\n\t"
        "adds   r1, r1, #2\n\t"
        "lsls   r2, r2, #2\n"
        "14:\n\t"
        "lsrs   r3, r2, #31\n\t"
        "bne    14f\n\t"
        "adds   r1, r1, #1\n\t"
        "lsls   r2, r2, #1\n"
        "14:\n\t"
        "str    r1, [sp, #44]\n\t"
        "str    r2, [sp, #48]\n\t"
        // R = about 2^48 / wn: x0 = 2^16 + table[bits 30..23], x1 = x0 + x0 (2^32 - dh x0) / 2^32.
        "lsls   r3, r2, #1\n\t"
        "lsrs   r3, r3, #24\n\t"
        "lsls   r3, r3, #1\n\t"
        "ldr    r4, [r7, #108]\n\t"
        "ldrh   r3, [r4, r3]\n\t"
        "movs   r4, #1\n\t"
        "lsls   r4, r4, #16\n\t"
        "adds   r3, r3, r4\n\t"                 // x0
        "lsrs   r4, r2, #16\n\t"                // dh
        "muls   r4, r3, r4\n\t"
        "negs   r4, r4\n\t"
        "asrs   r4, r4, #8\n\t"                 // e >> 8
        "lsrs   r5, r3, #2\n\t"
        "muls   r5, r4, r5\n\t"
        "asrs   r5, r5, #22\n\t"
        "adds   r3, r3, r5\n\t"                 // R
        "str    r3, [sp, #52]\n\t"
        "hider_coord 24\n\t"
        "ldr    r1, [sp, #24]\n\t"
        "cmp    r1, #0\n\t"
        "bge    15f\n\t"
        "negs   r4, r4\n"
        "15:\n\t"
        "str    r4, [sp, #72]\n\t"              // X, stored once the vertex is accepted
        "hider_coord 28\n\t"
        "ldr    r1, [sp, #28]\n\t"
        "cmp    r1, #0\n\t"
        "blt    16f\n\t"
        "negs   r4, r4\n"                       // project() divides -y k
        "16:\n\t"
        "ldr    r0, [sp, #60]\n\t"
        "strh   r4, [r0, #2]\n\t"
        "ldr    r4, [sp, #72]\n\t"
        "strh   r4, [r0]\n\t"
        // u = n 2^31 / w (2^31 when w == n): a = n << s below wn, two 16-bit digits.
        "ldr    r0, [sp, #32]\n\t"
        "ldr    r1, [r7, #84]\n\t"
        "movs   r2, #1\n\t"
        "lsls   r2, r2, #31\n\t"
        "cmp    r0, r1\n\t"
        "ble    20f\n\t"
        "ldr    r3, [sp, #44]\n\t"
        "lsls   r1, r1, r3\n\t"                 // a
        "ldr    r5, [sp, #52]\n\t"              // R
        "ldr    r6, [sp, #48]\n\t"              // wn
        "lsrs   r2, r1, #17\n\t"
        "muls   r2, r5, r2\n\t"
        "lsrs   r2, r2, #16\n\t"
        "adds   r2, r2, #1\n\t"                 // e1 = floor(a 2^15 / wn) within a few (+1: most often exact)
        "lsrs   r3, r6, #16\n\t"
        "muls   r3, r2, r3\n\t"
        "uxth   r4, r6\n\t"
        "muls   r4, r2, r4\n\t"
        "lsls   r0, r3, #16\n\t"
        "lsrs   r3, r3, #16\n\t"
        "adds   r4, r4, r0\n\t"
        "movs   r0, #0\n\t"
        "adcs   r3, r0\n\t"                     // r3:r4 = e1 wn
        "lsrs   r0, r1, #17\n\t"
        "lsls   r1, r1, #15\n\t"
        "subs   r1, r1, r4\n\t"
        "sbcs   r0, r3\n\t"                     // r0:r1 = a 2^15 - e1 wn
        "movs   r3, #0\n\t"
        "cmp    r0, #0\n\t"
        "bge    22f\n"
        "21:\n\t"
        "subs   r2, r2, #1\n\t"
        "adds   r1, r1, r6\n\t"
        "adcs   r0, r3\n\t"
        "bmi    21b\n"
        "22:\n\t"
        "cmp    r0, #0\n\t"
        "bne    23f\n\t"
        "cmp    r1, r6\n\t"
        "blo    24f\n"
        "23:\n\t"
        "adds   r2, r2, #1\n\t"
        "subs   r1, r1, r6\n\t"
        "sbcs   r0, r3\n\t"
        "b      22b\n"
        "24:\n\t"                               // r1 = the remainder (below wn), r2 = e1
        "lsrs   r3, r1, #17\n\t"
        "muls   r3, r5, r3\n\t"
        "lsrs   r3, r3, #15\n\t"
        "adds   r3, r3, #1\n\t"                 // e2 = floor(rem 2^16 / wn) within a few
        "lsrs   r0, r3, #16\n\t"
        "beq    29f\n\t"
        "movs   r3, #1\n\t"                     // at most 2^16 - 1 (the product below stays in 32 bits)
        "lsls   r3, r3, #16\n\t"
        "subs   r3, r3, #1\n"
        "29:\n\t"
        "lsrs   r0, r6, #16\n\t"
        "muls   r0, r3, r0\n\t"
        "uxth   r4, r6\n\t"
        "muls   r4, r3, r4\n\t"
        "lsls   r5, r0, #16\n\t"
        "lsrs   r0, r0, #16\n\t"
        "adds   r4, r4, r5\n\t"
        "movs   r5, #0\n\t"
        "adcs   r0, r5\n\t"                     // r0:r4 = e2 wn
        "lsrs   r5, r1, #16\n\t"
        "lsls   r1, r1, #16\n\t"
        "subs   r1, r1, r4\n\t"
        "sbcs   r5, r0\n\t"                     // r5:r1 = rem 2^16 - e2 wn
        "movs   r0, #0\n\t"
        "cmp    r5, #0\n\t"
        "bge    26f\n"
        "25:\n\t"
        "subs   r3, r3, #1\n\t"
        "adds   r1, r1, r6\n\t"
        "adcs   r5, r0\n\t"
        "bmi    25b\n"
        "26:\n\t"
        "cmp    r5, #0\n\t"
        "bne    27f\n\t"
        "cmp    r1, r6\n\t"
        "blo    28f\n"
        "27:\n\t"
        "adds   r3, r3, #1\n\t"
        "subs   r1, r1, r6\n\t"
        "sbcs   r5, r0\n\t"
        "b      26b\n"
        "28:\n\t"
        "lsls   r2, r2, #16\n\t"
        "adds   r2, r2, r3\n"                   // u, at least n / f: w <= f
        "20:\n\t"
        // z = 4096 + ((2^31 - u) scale + 2^30) / 2^31, at most 4096 + (kDepthFar - kDepthNear): scale is
        // (kDepthFar - kDepthNear) 2^31 / (2^31 - n / f) rounded down and 2^31 - u <= 2^31 - n / f, so
        // project()'s clamps never act here.
        "movs   r0, #1\n\t"
        "lsls   r0, r0, #31\n\t"
        "subs   r0, r0, r2\n\t"                 // d
        "ldr    r1, [r7, #100]\n\t"
        "uxth   r2, r0\n\t"
        "lsrs   r3, r0, #16\n\t"
        "uxth   r4, r1\n\t"
        "lsrs   r5, r1, #16\n\t"
        "movs   r6, r2\n\t"
        "muls   r6, r4, r6\n\t"                 // dl sl
        "muls   r2, r5, r2\n\t"                 // dl sh
        "muls   r4, r3, r4\n\t"                 // dh sl
        "muls   r5, r3, r5\n\t"                 // dh sh
        "adds   r2, r2, r4\n\t"
        "movs   r4, #0\n\t"
        "adcs   r4, r4\n\t"
        "lsls   r4, r4, #16\n\t"
        "adds   r5, r5, r4\n\t"
        "lsls   r4, r2, #16\n\t"
        "lsrs   r2, r2, #16\n\t"
        "adds   r6, r6, r4\n\t"
        "adcs   r5, r2\n\t"                     // r5:r6 = d scale_lo
        "ldr    r1, [r7, #104]\n\t"
        "muls   r1, r0, r1\n\t"
        "adds   r5, r5, r1\n\t"                 // + d scale_hi 2^32
        "movs   r1, #1\n\t"
        "lsls   r1, r1, #30\n\t"
        "adds   r6, r6, r1\n\t"
        "movs   r1, #0\n\t"
        "adcs   r5, r1\n\t"
        "lsrs   r6, r6, #31\n\t"
        "lsls   r5, r5, #1\n\t"
        "orrs   r5, r6\n\t"
        "movs   r1, #1\n\t"
        "lsls   r1, r1, #12\n\t"
        "adds   r5, r5, r1\n\t"
        "ldr    r0, [sp, #60]\n\t"
        "str    r5, [r0, #4]\n\t"
        "adds   r0, r0, #8\n\t"
        "str    r0, [sp, #60]\n\t"
        "ldr    r0, [sp, #56]\n\t"
        "adds   r0, r0, #12\n\t"
        "str    r0, [sp, #56]\n\t"
        "b      10b\n"
        "80:\n"                                 // refused: the caller projects this one
        "90:\n\t"
        "ldr    r0, [sp, #56]\n\t"
        "add    sp, #80\n\t"
        "pop    {r4-r7, pc}\n\t"
        ".purgem hider_row\n\t"
        ".purgem hider_coord\n\t"
        :
        :
        : "memory");
}
#endif

}  // namespace hider

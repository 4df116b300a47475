// bin_triangles()'s loop (band_lists.hpp) in Thumb-2 for ARMv7-M and in Thumb-1 for ARMv6-M: the binning
// pass keeps its constants in registers. It links the whole triangles and hands each one with a vertex
// outside a clip plane back to C++. firmware/kernelcheck compares it with the C++ loop through the band
// renderer's output.
#pragma once
#include <hider/asm_v6m.hpp>
#include <hider/mesh.hpp>
#include <hider/screen.hpp>

namespace hider {

namespace detail {
/// Constants and in/out values of the binning loop (the layout is its contract: the first five are one
/// ldm of a binned triangle).
struct BinLoopArm {
    int32_t y_lift;             ///< 0: v = y - y_lift; row (v >> 4)
    int32_t v_last;             ///< 4: 16 height - 1: v clamped to [0, v_last], row to [0, height - 1]
    uint32_t band_scale;        ///< 8: bin_scale(band rows)
    uint16_t* head;             ///< 12
    uint16_t* next;             ///< 16
    const Tri* tris;            ///< 20
    const ScreenVertex* verts;  ///< 24
    int32_t cull_above;         ///< 28: culled when the area is above it
    uint32_t culled;            ///< 32, counted up
    uint32_t projected;         ///< 36: 1 when no vertex is outside a clip plane (all_projected()): no clip test
};
static_assert(sizeof(void*) != 4 ||
                  (offsetof(BinLoopArm, v_last) == 4 && offsetof(BinLoopArm, band_scale) == 8 &&
                   offsetof(BinLoopArm, head) == 12 && offsetof(BinLoopArm, next) == 16 && offsetof(BinLoopArm, tris) == 20 &&
                   offsetof(BinLoopArm, verts) == 24 && offsetof(BinLoopArm, cull_above) == 28 &&
                   offsetof(BinLoopArm, culled) == 32 && offsetof(BinLoopArm, projected) == 36),
              "binning loop layout: every offset the assembly uses");
static_assert(sizeof(Tri) == 6 && sizeof(ScreenVertex) == 8 && offsetof(ScreenVertex, y) == 2 &&
                  offsetof(ScreenVertex, z) == 4 && kSubpixelBits == 4,
              "the binning loop's strides and offsets, and band_scale_v()'s 2^28 = 2^32 / 16");

/// BinLoopArm's offsets as operands of the binning loops: b_lift, b_vlast, b_scale, b_head, b_next,
/// b_tris, b_verts, b_cull, b_culled, b_projected.
#define HIDER_BIN_LOOP_OPERANDS                                                                           \
    [b_lift] "i"(offsetof(detail::BinLoopArm, y_lift)), [b_vlast] "i"(offsetof(detail::BinLoopArm, v_last)), \
    [b_scale] "i"(offsetof(detail::BinLoopArm, band_scale)), [b_head] "i"(offsetof(detail::BinLoopArm, head)), \
    [b_next] "i"(offsetof(detail::BinLoopArm, next)), [b_tris] "i"(offsetof(detail::BinLoopArm, tris)),       \
    [b_verts] "i"(offsetof(detail::BinLoopArm, verts)), [b_cull] "i"(offsetof(detail::BinLoopArm, cull_above)), \
    [b_culled] "i"(offsetof(detail::BinLoopArm, culled)), [b_projected] "i"(offsetof(detail::BinLoopArm, projected))

/// ceil(2^28 / rows): floor(v * it / 2^32) is floor(v / (16 rows)) for every v < 2^32 / (16 rows), so for
/// every v of a frame of up to kMaxFrameSide rows (v < 2^14, rows <= 2^10): one umull gives the band of
/// a subpixel row, without first shifting it to a pixel row.
constexpr uint32_t band_scale_v(uint32_t rows) { return ((uint32_t{1} << 28) + rows - 1) / rows; }

}  // namespace detail

#if defined(HIDER_ARMV7M)
/// HIDER_V7M_BIN_LINK: bin_triangles_v7m()'s loop from the vertex indices r0 r1 r2 of a drawable
/// triangle on: the area, the cull, the link into its band's list, the step to the triangle below (back
/// to local label 1; to the caller's local label 7, defined after it, when none is left). Uses local
/// labels 0, 2, 4, 5 and 6.
#define HIDER_V7M_BIN_LINK \
    "2:\n\t" \
    "ldrsh  r3, [r6, r0, lsl #3]\n\t"        /* ax */ \
    "ldrsh  r12, [r7, r0, lsl #3]\n\t"       /* ay */ \
    "ldrsh  r0, [r6, r1, lsl #3]\n\t"        /* bx */ \
    "ldrsh  r1, [r7, r1, lsl #3]\n\t"        /* by */ \
    "ldrsh  lr, [r6, r2, lsl #3]\n\t"        /* cx */ \
    "ldrsh  r2, [r7, r2, lsl #3]\n\t"        /* cy */ \
    "sub    r0, r0, r3\n\t" \
    "sub    lr, lr, r3\n\t" \
    "sub    r3, r2, r12\n\t" \
    "mul    r0, r0, r3\n\t"                  /* (bx - ax) (cy - ay) */ \
    "sub    r3, r1, r12\n\t" \
    "mls    r0, lr, r3, r0\n\t"              /* - (cx - ax) (by - ay): signed_area() */ \
    "cmp    r0, r8\n\t" \
    "bgt    5f\n\t"                          /* culled (cull_above >= 0: never a zero area) */ \
    "cbz    r0, 6f\n\t"                      /* no area: not drawn */ \
    "cmp    r1, r12\n\t" \
    "it     lt\n\t" \
    "movlt  r12, r1\n\t" \
    "cmp    r2, r12\n\t" \
    "it     lt\n\t" \
    "movlt  r12, r2\n\t"                     /* the top vertex's y */ \
    "ldm    r11, {r0, r1, r2, r3, lr}\n\t"   /* y_lift, v_last, band_scale, head, next */ \
    "sub    r12, r12, r0\n\t"                /* v */ \
    "cmp    r12, r1\n\t" \
    "bhi    4f\n"                            /* v < 0 or v > v_last: clamped */ \
    "0:\n\t" \
    "umull  r0, r1, r12, r2\n\t"             /* r1: its band */ \
    "ldrh   r0, [r3, r1, lsl #1]\n\t" \
    "strh   r0, [lr, r4, lsl #1]\n\t"        /* next[t] = head[band] */ \
    "strh   r4, [r3, r1, lsl #1]\n"          /* head[band] = t */ \
    "6:\n\t" \
    "subs   r4, r4, #1\n\t" \
    "bpl    1b\n\t" \
    "b      7f\n" \
    "4:\n\t" \
    "bic    r12, r1, r12, asr #31\n\t"       /* 0 below, v_last above */ \
    "b      0b\n" \
    "5:\n\t" \
    "add    r9, r9, #1\n\t" \
    "subs   r4, r4, #1\n\t" \
    "bpl    1b\n\t"

/// bin_triangles()'s loop in Thumb-2: links triangles count - 1
/// down to 0 as bin_triangles() does and counts the culled ones into d->culled; returns t + 1 for the
/// first triangle t with a vertex outside a clip plane (bin_triangles() bins it in C++ and goes on from
/// t), 0 when done. Registers: r4 the triangle, r5 its Tri, r6 r7 r10 the vertices' x, y and z, r8
/// cull_above, r9 the culled count, r11 d.
HIDER_NAKED inline uint32_t bin_triangles_v7m(uint32_t, detail::BinLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "subs   r4, r0, #1\n\t"
        "bmi    9f\n\t"                          // no triangle left
        "mov    r11, r1\n\t"
        "ldrd   r5, r6, [r11, %[b_tris]]\n\t"    // tris, verts
        "ldrd   r8, r9, [r11, %[b_cull]]\n\t"    // cull_above, culled
        "add    r0, r0, r0, lsl #1\n\t"
        "add    r5, r5, r0, lsl #1\n\t"          // tris + 6 (t + 1): pre-decremented
        "add    r7, r6, #2\n\t"
        "add    r10, r6, #4\n\t"
        "ldr    r0, [r11, %[b_projected]]\n\t"
        "cmp    r0, #0\n\t"
        "bne    3f\n"                            // every vertex projected: the loop without the clip test
        "1:\n\t"
        "ldrh   r0, [r5, #-6]!\n\t"
        "ldrh   r1, [r5, #2]\n\t"
        "ldrh   r2, [r5, #4]\n\t"
        "ldr    r3, [r10, r0, lsl #3]\n\t"
        "cbz    r3, 8f\n\t"                      // z = 0: outside a clip plane
        "ldr    r3, [r10, r1, lsl #3]\n\t"
        "cbz    r3, 8f\n\t"
        "ldr    r3, [r10, r2, lsl #3]\n\t"
        "cbnz   r3, 2f\n"
        "8:\n\t"                                 // back to C++ with t + 1
        "str    r9, [r11, %[b_culled]]\n\t"
        "add    r0, r4, #1\n\t"
        "pop    {r4-r11, pc}\n"
        HIDER_V7M_BIN_LINK
        "b      7f\n"
        "3:\n\t"
        "1:\n\t"
        "ldrh   r0, [r5, #-6]!\n\t"
        "ldrh   r1, [r5, #2]\n\t"
        "ldrh   r2, [r5, #4]\n"
        HIDER_V7M_BIN_LINK
        "7:\n\t"
        "str    r9, [r11, %[b_culled]]\n"
        "9:\n\t"
        "mov    r0, #0\n\t"
        "pop    {r4-r11, pc}\n"
        :
        : HIDER_BIN_LOOP_OPERANDS);
}

namespace detail {
/// The chip's binning loop (bin_triangles()'s kAsm path) and its BinLoopArm::band_scale for `rows` rows a band.
inline uint32_t bin_triangles_asm(uint32_t count, BinLoopArm* d) { return bin_triangles_v7m(count, d); }
constexpr uint32_t bin_scale(uint32_t rows) { return band_scale_v(rows); }
}  // namespace detail
#endif

#if defined(HIDER_ARMV6M)
/// HIDER_V6M_BIN_FETCH: the triangle below r5 (r5 steps down to it): its vertices' byte offsets in r0 r1 r2.
#define HIDER_V6M_BIN_FETCH \
    "subs   r5, r5, #6\n\t" \
    "ldrh   r0, [r5, #0]\n\t" \
    "ldrh   r1, [r5, #2]\n\t" \
    "ldrh   r2, [r5, #4]\n\t" \
    "lsls   r0, r0, #3\n\t" \
    "lsls   r1, r1, #3\n\t" \
    "lsls   r2, r2, #3\n\t"

/// HIDER_V6M_BIN_LINK: bin_triangles_v6m()'s loop from the byte offsets r0 r1 r2 of a drawable
/// triangle's vertices on: the area, the cull, the link into its band's list, the step to the triangle
/// below (back to local label 1; to the caller's local label 7, defined after it, when none is left).
/// The top vertex's y is ay + min(0, by - ay, cy - ay), from the area's differences. Uses local labels
/// 0, 2, 4, 5 and 6, and HIDER_BIN_LOOP_OPERANDS.
#define HIDER_V6M_BIN_LINK \
    "2:\n\t" \
    "ldr    r0, [r6, r0]\n\t"           /* x | y << 16 of each */ \
    "ldr    r1, [r6, r1]\n\t" \
    "ldr    r2, [r6, r2]\n\t" \
    "sxth   r3, r0\n\t"                 /* ax */ \
    "asrs   r0, r0, #16\n\t"            /* ay */ \
    "sxth   r7, r1\n\t" \
    "subs   r7, r7, r3\n\t"             /* bx - ax */ \
    "asrs   r1, r1, #16\n\t" \
    "subs   r1, r1, r0\n\t"             /* by - ay */ \
    "mov    r12, r7\n\t" \
    "sxth   r7, r2\n\t" \
    "subs   r7, r7, r3\n\t"             /* cx - ax */ \
    "asrs   r2, r2, #16\n\t" \
    "subs   r2, r2, r0\n\t"             /* cy - ay */ \
    "muls   r7, r1, r7\n\t"             /* (cx - ax) (by - ay) */ \
    "mov    r3, r12\n\t" \
    "muls   r3, r2, r3\n\t"             /* (bx - ax) (cy - ay) */ \
    "subs   r3, r3, r7\n\t"             /* signed_area() */ \
    "beq    6f\n\t"                     /* no area: not drawn */ \
    "cmp    r3, r8\n\t" \
    "bgt    5f\n\t"                     /* culled */ \
    "cmp    r1, r2\n\t" \
    "ble    0f\n\t" \
    "movs   r1, r2\n" \
    "0:\n\t" \
    "cmp    r1, #0\n\t" \
    "bgt    0f\n\t" \
    "adds   r0, r0, r1\n" \
    "0:\n\t"                            /* r0: the top vertex's y */ \
    "mov    r7, r10\n\t"                /* d */ \
    "ldr    r3, [r7, %[b_lift]]\n\t" \
    "subs   r0, r0, r3\n\t"             /* v = y - y_lift */ \
    "ldr    r3, [r7, %[b_vlast]]\n\t" \
    "cmp    r0, r3\n\t" \
    "bhi    4f\n"                        /* v < 0 or v > v_last: clamped */ \
    "0:\n\t" \
    "lsrs   r0, r0, #4\n\t"             /* its first row */ \
    "ldr    r3, [r7, %[b_scale]]\n\t" \
    "muls   r0, r3, r0\n\t" \
    "lsrs   r0, r0, #20\n\t"            /* its band */ \
    "lsls   r0, r0, #1\n\t" \
    "ldr    r3, [r7, %[b_head]]\n\t"    /* head */ \
    "ldrh   r2, [r3, r0]\n\t" \
    "strh   r4, [r3, r0]\n\t"           /* head[band] = t */ \
    "ldr    r3, [r7, %[b_next]]\n\t"    /* next */ \
    "lsls   r1, r4, #1\n\t" \
    "strh   r2, [r3, r1]\n"              /* next[t] = the band's head before */ \
    "6:\n\t" \
    "subs   r4, r4, #1\n\t" \
    "bpl    1b\n\t" \
    "b      7f\n" \
    "4:\n\t" \
    "asrs   r0, r0, #31\n\t"            /* -1 below, 0 above */ \
    "bics   r3, r0\n\t"                 /* 0 below, v_last above */ \
    "movs   r0, r3\n\t" \
    "b      0b\n" \
    "5:\n\t" \
    "add    r9, r11\n\t"                /* culled: one more */ \
    "subs   r4, r4, #1\n\t" \
    "bpl    1b\n\t"

/// bin_triangles()'s loop in Thumb-1, as bin_triangles_v7m(): links triangles count - 1 down to 0 and
/// counts the culled ones into d->culled; returns t + 1 for the first triangle t with a vertex outside a
/// clip plane, 0 when done. Registers: r4 the triangle, r5 its Tri, r6 the vertices, r8 cull_above, r9
/// the culled count, r10 d, r11 the constant 1, r0-r3, r7 and r12 scratch.
HIDER_NAKED inline uint32_t bin_triangles_v6m(uint32_t, detail::BinLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V6M_SAVE_ALL
        "subs   r4, r0, #1\n\t"
        "bpl    11f\n\t"
        "b      9f\n"                             // no triangle left
        "11:\n\t"
        "mov    r10, r1\n\t"
        "ldr    r5, [r1, %[b_tris]]\n\t"         // tris
        "ldr    r6, [r1, %[b_verts]]\n\t"        // verts
        "ldr    r2, [r1, %[b_cull]]\n\t"
        "mov    r8, r2\n\t"                      // cull_above
        "ldr    r2, [r1, %[b_culled]]\n\t"
        "mov    r9, r2\n\t"                      // culled
        "movs   r2, #1\n\t"
        "mov    r11, r2\n\t"
        "movs   r2, #6\n\t"
        "muls   r2, r0, r2\n\t"
        "adds   r5, r5, r2\n\t"                  // tris + 6 (t + 1): pre-decremented
        "ldr    r2, [r1, %[b_projected]]\n\t"
        "cmp    r2, #0\n\t"
        "bne    3f\n"                             // every vertex projected: the loop without the clip test
        "1:\n\t"
        HIDER_V6M_BIN_FETCH
        "adds   r3, r0, #4\n\t"
        "ldr    r3, [r6, r3]\n\t"
        "cmp    r3, #0\n\t"
        "beq    8f\n\t"                          // z = 0: outside a clip plane
        "adds   r3, r1, #4\n\t"
        "ldr    r3, [r6, r3]\n\t"
        "cmp    r3, #0\n\t"
        "beq    8f\n\t"
        "adds   r3, r2, #4\n\t"
        "ldr    r3, [r6, r3]\n\t"
        "cmp    r3, #0\n\t"
        "bne    2f\n"
        "8:\n\t"                                 // back to C++ with t + 1
        "mov    r1, r10\n\t"
        "mov    r2, r9\n\t"
        "str    r2, [r1, %[b_culled]]\n\t"
        "adds   r0, r4, #1\n\t"
        "b      10f\n"
        HIDER_V6M_BIN_LINK
        "b      7f\n"
        "3:\n"
        "1:\n\t"
        HIDER_V6M_BIN_FETCH
        HIDER_V6M_BIN_LINK
        "7:\n\t"
        "mov    r1, r10\n\t"
        "mov    r2, r9\n\t"
        "str    r2, [r1, %[b_culled]]\n"
        "9:\n\t"
        "movs   r0, #0\n"
        "10:\n\t"
        HIDER_V6M_RESTORE_ALL
        :
        : HIDER_BIN_LOOP_OPERANDS);
}

namespace detail {
/// The chip's binning loop (bin_triangles()'s kAsm path) and its BinLoopArm::band_scale for `rows` rows a
/// band: ceil(2^20 / rows) (no 32 x 32 -> 64 multiply here), the band of pixel row r < 2^10 being
/// r * it >> 20, as bin_triangles() computes it in C++.
inline uint32_t bin_triangles_asm(uint32_t count, BinLoopArm* d) { return bin_triangles_v6m(count, d); }
constexpr uint32_t bin_scale(uint32_t rows) { return ((uint32_t{1} << 20) + rows - 1) / rows; }
}  // namespace detail
#endif

}  // namespace hider

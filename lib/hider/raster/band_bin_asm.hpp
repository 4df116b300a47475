// bin_triangles()'s loop (band_lists.hpp) in Thumb-2 for ARMv7-M: the binning pass keeps its constants in
// registers. It links the whole triangles and hands each one with a vertex outside a clip plane back to
// C++. firmware/kernelcheck compares it with the C++ loop through the band renderer's output.
#pragma once
#include <hider/mesh.hpp>
#include <hider/screen.hpp>

namespace hider {

namespace detail {
/// Constants and in/out values of the binning loop (the layout is its contract).
struct BinLoopArm {
    const Tri* tris;            ///< 0
    const ScreenVertex* verts;  ///< 4
    int32_t y_lift;             ///< 8: rows from (y - y_lift) >> 4
    int32_t last;               ///< 12: the frame's last row
    int32_t cull_above;         ///< 16: culled when the area is above it
    uint32_t band_scale;        ///< 20: band = row * band_scale >> 20
    uint16_t* next;             ///< 24
    uint16_t* head;             ///< 28
    uint32_t culled;            ///< 32, counted up
    uint32_t projected;         ///< 36: 1 when no vertex is outside a clip plane (all_projected()): no clip test
};
static_assert(sizeof(void*) != 4 ||
                  (offsetof(BinLoopArm, verts) == 4 && offsetof(BinLoopArm, y_lift) == 8 && offsetof(BinLoopArm, last) == 12 &&
                   offsetof(BinLoopArm, cull_above) == 16 && offsetof(BinLoopArm, band_scale) == 20 &&
                   offsetof(BinLoopArm, next) == 24 && offsetof(BinLoopArm, head) == 28 && offsetof(BinLoopArm, culled) == 32 &&
                   offsetof(BinLoopArm, projected) == 36),
              "binning loop layout: every offset the assembly uses");
static_assert(sizeof(Tri) == 6 && sizeof(ScreenVertex) == 8 && offsetof(ScreenVertex, y) == 2 &&
                  offsetof(ScreenVertex, z) == 4 && kSubpixelBits == 4,
              "the binning loop's strides and shifts");
}  // namespace detail

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// HIDER_V7M_BIN_LINK: bin_triangles_v7m()'s loop from the vertex pointers r0 r1 r2 of a drawable triangle
/// on: the area, the cull, the link into its band's list, the step to the triangle below (back to local
/// label 1). Uses local labels 2, 5 and 6.
#define HIDER_V7M_BIN_LINK \
    "2:\n\t" \
    "ldrsh  r3, [r0]\n\t"                    /* ax */ \
    "ldrsh  r12, [r0, #2]\n\t"               /* ay */ \
    "ldrsh  r0, [r1]\n\t"                    /* bx */ \
    "ldrsh  r1, [r1, #2]\n\t"                /* by */ \
    "ldrsh  lr, [r2]\n\t"                    /* cx */ \
    "ldrsh  r2, [r2, #2]\n\t"                /* cy */ \
    "sub    r0, r0, r3\n\t" \
    "sub    lr, lr, r3\n\t" \
    "sub    r3, r2, r12\n\t" \
    "mul    r0, r0, r3\n\t"                  /* (bx - ax) (cy - ay) */ \
    "sub    r3, r1, r12\n\t" \
    "mls    r0, lr, r3, r0\n\t"              /* - (cx - ax) (by - ay): signed_area() */ \
    "cmp    r0, r9\n\t" \
    "bgt    5f\n\t"                          /* culled (cull_above >= 0: never a zero area) */ \
    "cbz    r0, 6f\n\t"                      /* no area: not drawn */ \
    "cmp    r1, r12\n\t" \
    "it     lt\n\t" \
    "movlt  r12, r1\n\t" \
    "cmp    r2, r12\n\t" \
    "it     lt\n\t" \
    "movlt  r12, r2\n\t"                     /* the top vertex's y */ \
    "sub    r12, r12, r7\n\t" \
    "asr    r12, r12, #4\n\t"                /* its first row */ \
    "bic    r12, r12, r12, asr #31\n\t"      /* at least 0 */ \
    "cmp    r12, r8\n\t" \
    "it     gt\n\t" \
    "movgt  r12, r8\n\t"                     /* at most the last row */ \
    "ldrd   r0, r1, [r11, #20]\n\t"          /* band_scale, next */ \
    "mul    r12, r12, r0\n\t" \
    "lsr    r12, r12, #20\n\t"               /* its band */ \
    "ldr    r2, [r11, #28]\n\t" \
    "ldrh   r0, [r2, r12, lsl #1]\n\t" \
    "strh   r0, [r1, r4, lsl #1]\n\t"        /* next[t] = head[band] */ \
    "strh   r4, [r2, r12, lsl #1]\n\t"       /* head[band] = t */ \
    "b      6f\n" \
    "5:\n\t" \
    "add    r10, r10, #1\n" \
    "6:\n\t" \
    "sub    r5, r5, #6\n\t" \
    "subs   r4, r4, #1\n\t" \
    "bpl    1b\n\t"

/// bin_triangles()'s loop in Thumb-2: links triangles count - 1
/// down to 0 as bin_triangles() does and counts the culled ones into d->culled; returns t + 1 for the
/// first triangle t with a vertex outside a clip plane (bin_triangles() bins it in C++ and goes on from
/// t), 0 when done. Registers: r4 the triangle, r5 its Tri, r6 the vertices, r7 y_lift, r8 the last row,
/// r9 cull_above, r10 the culled count, r11 d.
HIDER_NAKED inline uint32_t bin_triangles_v7m(uint32_t, detail::BinLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "subs   r4, r0, #1\n\t"
        "bmi    9f\n\t"                          // no triangle left
        "mov    r11, r1\n\t"
        "ldm    r11, {r5-r9}\n\t"               // tris, verts, y_lift, last, cull_above
        "ldr    r10, [r11, #32]\n\t"
        "add    r0, r4, r4, lsl #1\n\t"
        "add    r5, r5, r0, lsl #1\n\t"         // tris + 6 t
        "ldr    r0, [r11, #36]\n\t"
        "cmp    r0, #0\n\t"
        "bne    3f\n"                            // every vertex projected: the loop without the clip test
        "1:\n\t"
        "ldrh   r0, [r5]\n\t"
        "ldrh   r1, [r5, #2]\n\t"
        "ldrh   r2, [r5, #4]\n\t"
        "add    r0, r6, r0, lsl #3\n\t"
        "add    r1, r6, r1, lsl #3\n\t"
        "add    r2, r6, r2, lsl #3\n\t"
        "ldr    r3, [r0, #4]\n\t"
        "cbz    r3, 8f\n\t"                      // z = 0: outside a clip plane
        "ldr    r3, [r1, #4]\n\t"
        "cbz    r3, 8f\n\t"
        "ldr    r3, [r2, #4]\n\t"
        "cbnz   r3, 2f\n"
        "8:\n\t"                                 // back to C++ with t + 1
        "str    r10, [r11, #32]\n\t"
        "add    r0, r4, #1\n\t"
        "pop    {r4-r11, pc}\n"
        HIDER_V7M_BIN_LINK
        "b      7f\n"
        "3:\n\t"
        "1:\n\t"
        "ldrh   r0, [r5]\n\t"
        "ldrh   r1, [r5, #2]\n\t"
        "ldrh   r2, [r5, #4]\n\t"
        "add    r0, r6, r0, lsl #3\n\t"
        "add    r1, r6, r1, lsl #3\n\t"
        "add    r2, r6, r2, lsl #3\n"
        HIDER_V7M_BIN_LINK
        "7:\n\t"
        "str    r10, [r11, #32]\n"
        "9:\n\t"
        "mov    r0, #0\n\t"
        "pop    {r4-r11, pc}\n");
}
#endif

}  // namespace hider

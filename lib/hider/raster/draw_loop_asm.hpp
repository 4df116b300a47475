// The z-buffer's triangle loop for the row kernel on Cortex-M (Thumb-1 on ARMv6-M, Thumb-2 on ARMv7-M):
// per mesh triangle the drawable test, the snapped area and the cull, then for the drawn ones the chip's
// kernel set-up, the headlight colour (FaceShading::color565()) and its run_kernel_triangle (on ARMv7-M
// the colour first, then kernel_draw_v7m(), which sets up and draws in one call). GCC kept
// the loop's state on the stack (loads and stores around every face and call on the M0+); here the
// triangle, the context and the vertex array stay in registers. Triangles
// with a vertex outside a clip plane and those the set-up calls generic go back to the C++ loop
// (zbuffer.hpp), which does exactly what it did before.
// firmware/kernelcheck draws random meshes both ways and compares the frames and statistics.
#pragma once
#include <hider/raster/kernel_triangle.hpp>
#include <hider/shade.hpp>

namespace hider {

namespace detail {
/// The Cortex-M draw loops' constants and counters (the layout is their contract).
struct DrawLoopArm {
    const Tri* end;              ///< 0
    const ScreenVertex* verts;   ///< 4
    uint32_t cull;               ///< 8
    uint32_t culled;             ///< 12, counted up
    uint32_t drawn;              ///< 16, counted up (kernel set-ups only: whole frames)
    KernelSetupIo* io;           ///< 20 (io->out is the triangle record)
    intptr_t normals_offset;     ///< 24: bytes from a Tri to its Normal14 (both 6 bytes)
    uint32_t projected;          ///< 28: 1 when no vertex is outside a clip plane (all_projected(); ARMv7-M only)
    int32_t view_z[3];           ///< 32, 36, 40
    uint32_t base_r, base_g, base_b;  ///< 44, 48, 52
    uint16_t* depth;             ///< 56
    int32_t y0;                  ///< 60
    int32_t stride_bytes;        ///< 64
    int32_t y1;                  ///< 68
    const KernelTarget* target;  ///< 72
};
static_assert(sizeof(void*) != 4 || (offsetof(DrawLoopArm, view_z) == 32 && offsetof(DrawLoopArm, target) == 72),
              "draw loop layout");
static_assert(sizeof(Tri) == 6 && sizeof(Normal14) == 6, "a triangle's normal sits a fixed offset from it");

/// The draw loops' operands: DrawLoopArm's fields (d_*, view_z0..2, base_*), KernelSetupIo's area and
/// out, the record's row, end and colour, and a vertex's z.
#define HIDER_DRAW_LOOP_OPERANDS \
    [d_end] "i"(offsetof(detail::DrawLoopArm, end)), [d_verts] "i"(offsetof(detail::DrawLoopArm, verts)), \
    [d_cull] "i"(offsetof(detail::DrawLoopArm, cull)), [d_culled] "i"(offsetof(detail::DrawLoopArm, culled)), \
    [d_drawn] "i"(offsetof(detail::DrawLoopArm, drawn)), [d_io] "i"(offsetof(detail::DrawLoopArm, io)), \
    [d_normals] "i"(offsetof(detail::DrawLoopArm, normals_offset)), \
    [d_projected] "i"(offsetof(detail::DrawLoopArm, projected)), \
    [view_z0] "i"(offsetof(detail::DrawLoopArm, view_z)), [view_z1] "i"(offsetof(detail::DrawLoopArm, view_z) + 4), \
    [view_z2] "i"(offsetof(detail::DrawLoopArm, view_z) + 8), [base_r] "i"(offsetof(detail::DrawLoopArm, base_r)), \
    [base_g] "i"(offsetof(detail::DrawLoopArm, base_g)), [base_b] "i"(offsetof(detail::DrawLoopArm, base_b)), \
    [d_depth] "i"(offsetof(detail::DrawLoopArm, depth)), [d_y0] "i"(offsetof(detail::DrawLoopArm, y0)), \
    [d_stride] "i"(offsetof(detail::DrawLoopArm, stride_bytes)), [d_y1] "i"(offsetof(detail::DrawLoopArm, y1)), \
    [d_target] "i"(offsetof(detail::DrawLoopArm, target)), [io_area] "i"(offsetof(KernelSetupIo, area)), \
    [io_out] "i"(offsetof(KernelSetupIo, out)), [k_row] "i"(offsetof(KernelTriangle, row)), \
    [k_end] "i"(offsetof(KernelTriangle, end)), \
    [k_color] "i"(offsetof(KernelTriangle, k) + offsetof(RowKernel, color)), \
    [v_z] "i"(offsetof(ScreenVertex, z))

inline DrawLoopArm draw_loop_arm(const Tri* tris, const Mesh& mesh, Span<const ScreenVertex> verts,
                                 const FaceShading& shading, bool cull, KernelSetupIo& io, uint16_t* depth, int32_t y0,
                                 int32_t stride, int32_t y1, const KernelTarget& target) {
    DrawLoopArm d{};
    d.end = tris + mesh.tris.size();
    d.verts = verts.data();
    d.cull = cull ? 1u : 0u;
    d.io = &io;
    d.normals_offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(mesh.normals.data()) -
                                             reinterpret_cast<uintptr_t>(tris));
    for (int j = 0; j < 3; ++j) d.view_z[j] = shading.view_z(j);
    d.base_r = shading.options().base.r;
    d.base_g = shading.options().base.g;
    d.base_b = shading.options().base.b;
    d.depth = depth;
    d.y0 = y0;
    d.stride_bytes = stride * static_cast<int32_t>(sizeof(uint16_t));
    d.y1 = y1;
    d.target = &target;
    return d;
}
}  // namespace detail

#if defined(HIDER_ARMV6M)
/// Draws triangles from p on until one it hands back (a vertex outside a clip plane, or a generic
/// set-up) or the end; returns that triangle (d->end when none). Culled faces and kernel set-ups are
/// counted into d. Registers: r4 the triangle, r6 d, r8 the end, r9 the vertices; on the stack the three
/// vertex pointers and the area.
HIDER_NAKED inline const Tri* draw_flat_v6m(const Tri*, detail::DrawLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r7, lr}\n\t"
        "mov    r4, r8\n\t"
        "mov    r5, r9\n\t"
        "push   {r4, r5}\n\t"
        "sub    sp, #16\n\t"
        "movs   r4, r0\n\t"
        "movs   r6, r1\n\t"
        "ldr    r0, [r6, %[d_end]]\n\t"
        "mov    r8, r0\n\t"
        "ldr    r0, [r6, %[d_verts]]\n\t"
        "mov    r9, r0\n"
        "1:\n\t"
        "cmp    r4, r8\n\t"
        "beq    89f\n\t"
        "ldrh   r0, [r4]\n\t"
        "ldrh   r1, [r4, #2]\n\t"
        "ldrh   r2, [r4, #4]\n\t"
        "mov    r3, r9\n\t"
        "lsls   r0, r0, #3\n\t"
        "adds   r0, r0, r3\n\t"
        "lsls   r1, r1, #3\n\t"
        "adds   r1, r1, r3\n\t"
        "lsls   r2, r2, #3\n\t"
        "adds   r2, r2, r3\n\t"
        "ldr    r3, [r0, %[v_z]]\n\t"
        "cmp    r3, #0\n\t"
        "beq    89f\n\t"                        // a vertex outside a clip plane: back to C++
        "ldr    r3, [r1, %[v_z]]\n\t"
        "cmp    r3, #0\n\t"
        "beq    89f\n\t"
        "ldr    r3, [r2, %[v_z]]\n\t"
        "cmp    r3, #0\n\t"
        "beq    89f\n\t"
        "str    r0, [sp, #0]\n\t"
        "str    r1, [sp, #4]\n\t"
        "str    r2, [sp, #8]\n\t"
        "ldr    r0, [r0]\n\t"                   // x | y << 16 of each
        "ldr    r1, [r1]\n\t"
        "ldr    r2, [r2]\n\t"
        "sxth   r3, r0\n\t"                     // ax
        "sxth   r7, r1\n\t"
        "subs   r7, r7, r3\n\t"                 // bx - ax
        "asrs   r1, r1, #16\n\t"
        "asrs   r0, r0, #16\n\t"                // ay
        "subs   r1, r1, r0\n\t"                 // by - ay
        "asrs   r5, r2, #16\n\t"
        "subs   r5, r5, r0\n\t"                 // cy - ay
        "sxth   r2, r2\n\t"
        "subs   r2, r2, r3\n\t"                 // cx - ax
        "muls   r7, r5, r7\n\t"
        "muls   r2, r1, r2\n\t"
        "subs   r7, r7, r2\n\t"                 // signed_area(a, b, c)
        "beq    8f\n\t"                         // zero: nothing
        "bmi    2f\n\t"                         // counter-clockwise: drawn
        "ldr    r0, [r6, %[d_cull]]\n\t"
        "cmp    r0, #0\n\t"
        "beq    2f\n\t"                         // not culling: drawn
        "ldr    r0, [r6, %[d_culled]]\n\t"
        "adds   r0, r0, #1\n\t"
        "str    r0, [r6, %[d_culled]]\n"        // culled
        "8:\n\t"
        "adds   r4, r4, #6\n\t"
        "b      1b\n"
        "89:\n\t"
        "b      90f\n"
        "2:\n\t"
        "str    r7, [sp, #12]\n\t"
        "ldr    r3, [r6, %[d_io]]\n\t"          // io
        "str    r7, [r3, %[io_area]]\n\t"       // io->area
        "ldr    r0, [sp, #0]\n\t"
        "ldr    r1, [sp, #4]\n\t"
        "ldr    r2, [sp, #8]\n\t"
        "bl     %c[setup]\n\t"
        "cmp    r0, #1\n\t"
        "beq    3f\n\t"
        "cmp    r0, #0\n\t"
        "beq    8b\n\t"                         // none
        "b      90f\n"                          // generic: back to C++
        "3:\n\t"
        "ldr    r0, [r6, %[d_drawn]]\n\t"
        "adds   r0, r0, #1\n\t"
        "str    r0, [r6, %[d_drawn]]\n\t"       // drawn
        "ldr    r3, [r6, %[d_io]]\n\t"
        "ldr    r5, [r3, %[io_out]]\n\t"        // the triangle record
        "ldrh   r0, [r5, %[k_row]]\n\t"
        "sxth   r0, r0\n\t"                     // row
        "ldrh   r1, [r5, %[k_end]]\n\t"
        "sxth   r1, r1\n\t"                     // end
        "cmp    r0, r1\n\t"
        "bge    8b\n\t"                         // no row
        // FaceShading::color565(): b = N.z (Q16) from the view rotation's third row, -N.z for a back
        // face (area > 0), clamped to [0, 2^16]; channel (base b + 2^15) >> 16, packed RGB565.
        "ldr    r1, [r6, %[d_normals]]\n\t"
        "adds   r1, r1, r4\n\t"                 // the triangle's normal
        "ldrh   r2, [r1]\n\t"
        "sxth   r2, r2\n\t"
        "ldr    r3, [r6, %[view_z0]]\n\t"
        "muls   r2, r3, r2\n\t"
        "ldrh   r7, [r1, #2]\n\t"
        "sxth   r7, r7\n\t"
        "ldr    r3, [r6, %[view_z1]]\n\t"
        "muls   r7, r3, r7\n\t"
        "adds   r2, r2, r7\n\t"
        "ldrh   r7, [r1, #4]\n\t"
        "sxth   r7, r7\n\t"
        "ldr    r3, [r6, %[view_z2]]\n\t"
        "muls   r7, r3, r7\n\t"
        "adds   r2, r2, r7\n\t"
        "asrs   r2, r2, #12\n\t"
        "ldr    r3, [sp, #12]\n\t"
        "cmp    r3, #0\n\t"
        "blt    4f\n\t"
        "negs   r2, r2\n"
        "4:\n\t"
        "cmp    r2, #0\n\t"
        "bge    5f\n\t"
        "movs   r2, #0\n"
        "5:\n\t"
        "movs   r3, #1\n\t"
        "lsls   r3, r3, #16\n\t"
        "cmp    r2, r3\n\t"
        "ble    6f\n\t"
        "movs   r2, r3\n"
        "6:\n\t"
        "movs   r3, #1\n\t"
        "lsls   r3, r3, #15\n\t"
        "ldr    r1, [r6, %[base_r]]\n\t"
        "muls   r1, r2, r1\n\t"
        "adds   r1, r1, r3\n\t"
        "lsrs   r1, r1, #19\n\t"
        "lsls   r1, r1, #11\n\t"                // red
        "ldr    r7, [r6, %[base_g]]\n\t"
        "muls   r7, r2, r7\n\t"
        "adds   r7, r7, r3\n\t"
        "lsrs   r7, r7, #18\n\t"
        "lsls   r7, r7, #5\n\t"
        "orrs   r1, r7\n\t"                     // green
        "ldr    r7, [r6, %[base_b]]\n\t"
        "muls   r7, r2, r7\n\t"
        "adds   r7, r7, r3\n\t"
        "lsrs   r7, r7, #19\n\t"
        "orrs   r1, r7\n\t"                     // blue
        "str    r1, [r5, %[k_color]]\n\t"       // k.color
        "ldr    r1, [r6, %[d_y0]]\n\t"
        "subs   r0, r0, r1\n\t"
        "ldr    r1, [r6, %[d_stride]]\n\t"
        "muls   r0, r1, r0\n\t"
        "ldr    r1, [r6, %[d_depth]]\n\t"
        "adds   r1, r1, r0\n\t"                 // the depth row of `row`
        "movs   r0, r5\n\t"
        "ldr    r2, [r6, %[d_y1]]\n\t"
        "ldr    r3, [r6, %[d_target]]\n\t"
        "bl     %c[kernel]\n\t"
        "b      8b\n"
        "90:\n\t"
        "movs   r0, r4\n\t"
        "add    sp, #16\n\t"
        "pop    {r4, r5}\n\t"
        "mov    r8, r4\n\t"
        "mov    r9, r5\n\t"
        "pop    {r4-r7, pc}\n"
        :
        : [setup] "i"(kernel_setup_v6m), [kernel] "i"(run_kernel_triangle_v6m), HIDER_DRAW_LOOP_OPERANDS);
}
#endif

#if defined(HIDER_ARMV7M)
/// Thumb-2 text of draw_flat_v7m()'s general loop (the projected one and draw_band_v7m() compute the area
/// in other registers, keeping the vertex indices or pointers). HIDER_V7M_AREA:
/// stores the vertex pointers r0 r1 r2 at sp and leaves signed_area() of their vertices in r10 (r0-r3,
/// r12 and lr clobbered).
#define HIDER_V7M_AREA \
    "stm    sp, {r0, r1, r2}\n\t" \
    "ldr    r0, [r0]\n\t"             /* x | y << 16 of each */ \
    "ldr    r1, [r1]\n\t" \
    "ldr    r2, [r2]\n\t" \
    "sxth   r3, r0\n\t"               /* ax */ \
    "sxth   r12, r1\n\t" \
    "sub    r12, r12, r3\n\t"         /* bx - ax */ \
    "sxth   lr, r2\n\t" \
    "sub    lr, lr, r3\n\t"           /* cx - ax */ \
    "asr    r0, r0, #16\n\t"          /* ay */ \
    "rsb    r1, r0, r1, asr #16\n\t"  /* by - ay */ \
    "rsb    r2, r0, r2, asr #16\n\t"  /* cy - ay */ \
    "mul    r10, r12, r2\n\t" \
    "mls    r10, lr, r1, r10\n\t"     /* signed_area(a, b, c) */

/// HIDER_V7M_COLOR565_IN(n, b, t, u): FaceShading::color565() of the face whose Normal14 register n points
/// to, back facing when r10 >= 0, into n (registers b, t and u clobbered); the asm statement gives the
/// offsets of the view's z row and the base colour from r5 as operands view_z0..2 and base_r, base_g,
/// base_b. Uses local label 117. HIDER_V7M_COLOR565 is it in r1 (r2, r3 and lr clobbered).
#define HIDER_V7M_COLOR565_IN(n, b, t, u) \
    "ldrsh  " #b ", [" #n "]\n\t" \
    "ldr    " #t ", [r5, %[view_z0]]\n\t" \
    "mul    " #b ", " #t ", " #b "\n\t" \
    "ldrsh  " #u ", [" #n ", #2]\n\t" \
    "ldr    " #t ", [r5, %[view_z1]]\n\t" \
    "mla    " #b ", " #t ", " #u ", " #b "\n\t" \
    "ldrsh  " #u ", [" #n ", #4]\n\t" \
    "ldr    " #t ", [r5, %[view_z2]]\n\t" \
    "mla    " #b ", " #t ", " #u ", " #b "\n\t" \
    "cmp    r10, #0\n\t" \
    "blt    117f\n\t"                   /* a front face */ \
    "bfc    " #b ", #0, #12\n\t"        /* a back face: -(s >> 12) = -(s with bits 0..11 cleared) >> 12 */ \
    "neg    " #b ", " #b "\n" \
    "117:\n\t" \
    "usat   " #b ", #16, " #b ", asr #12\n\t"  /* clamped to [0, 2^16 - 1]: 2^16 gives the same 8-bit channels */ \
    "mov    " #t ", #32768\n\t" \
    "ldr    " #n ", [r5, %[base_r]]\n\t" \
    "mla    " #n ", " #b ", " #n ", " #t "\n\t" \
    "lsr    " #n ", " #n ", #19\n\t" \
    "lsl    " #n ", " #n ", #11\n\t"    /* red */ \
    "ldr    " #u ", [r5, %[base_g]]\n\t" \
    "mla    " #u ", " #b ", " #u ", " #t "\n\t" \
    "lsr    " #u ", " #u ", #18\n\t" \
    "orr    " #n ", " #n ", " #u ", lsl #5\n\t"  /* green */ \
    "ldr    " #u ", [r5, %[base_b]]\n\t" \
    "mla    " #u ", " #b ", " #u ", " #t "\n\t" \
    "orr    " #n ", " #n ", " #u ", lsr #19\n\t"  /* blue */
#define HIDER_V7M_COLOR565 HIDER_V7M_COLOR565_IN(r1, r2, r3, lr)

/// The same loop in Thumb-2 around kernel_draw_v7m(), in two copies: with culling on and every vertex
/// projected (d->projected), a loop without the clip-plane and cull-flag tests that loads each vertex's
/// x | y by its index (its pointer is made only for a drawn face); else the general one. Each copy has
/// its own drawn path: the colour, then one call that sets up and draws. Registers: r4 the triangle, r5
/// d, r6 the end, r7 the vertices, r9 d->io, r10 the area, r11 the faces culled in this call; in the
/// projected loop r0..r2 the vertex indices and r8 scratch; in the general one the three vertex
/// pointers on the stack.
HIDER_NAKED inline const Tri* draw_flat_v7m(const Tri*, detail::DrawLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "sub    sp, #12\n\t"
        "mov    r4, r0\n\t"
        "mov    r5, r1\n\t"
        "ldr    r6, [r5, %[d_end]]\n\t"
        "ldr    r7, [r5, %[d_verts]]\n\t"
        "ldr    r9, [r5, %[d_io]]\n\t"
        "movs   r11, #0\n\t"
        "cmp    r4, r6\n\t"
        "beq    90f\n\t"
        "ldr    r0, [r5, %[d_cull]]\n\t"
        "ldr    r1, [r5, %[d_projected]]\n\t"
        "ands   r0, r0, r1\n\t"
        "beq    1f\n"                        // not culling, or a vertex outside a clip plane
        "20:\n\t"                              // culling, every vertex projected
        "ldrh   r0, [r4]\n\t"
        "ldrh   r1, [r4, #2]\n\t"
        "ldrh   r2, [r4, #4]\n\t"
        "ldr    r3, [r7, r0, lsl #3]\n\t"     // x | y << 16 of each
        "ldr    r12, [r7, r1, lsl #3]\n\t"
        "ldr    lr, [r7, r2, lsl #3]\n\t"
        "sxth   r8, r3\n\t"                    // ax
        "asr    r3, r3, #16\n\t"               // ay
        "sxth   r10, r12\n\t"
        "sub    r10, r10, r8\n\t"              // bx - ax
        "rsb    r12, r3, r12, asr #16\n\t"     // by - ay
        "rsb    r3, r3, lr, asr #16\n\t"       // cy - ay
        "mul    r10, r10, r3\n\t"
        "sxth   lr, lr\n\t"
        "sub    lr, lr, r8\n\t"                // cx - ax
        "mls    r10, lr, r12, r10\n\t"         // signed_area(a, b, c), as HIDER_V7M_AREA
        "cmp    r10, #0\n\t"
        "bmi    21f\n\t"                       // counter-clockwise: drawn
        "it     ne\n\t"
        "addne  r11, r11, #1\n"                 // culled (zero: nothing)
        "28:\n\t"
        "adds   r4, r4, #6\n\t"
        "cmp    r4, r6\n\t"
        "bne    20b\n\t"
        "b      90f\n"
        "21:\n\t"                              // FaceShading::color565(), as in draw_flat_v6m
        "ldr    r12, [r5, %[d_normals]]\n\t"
        "add    r12, r12, r4\n\t"              // the triangle's normal
        HIDER_V7M_COLOR565_IN(r12, r8, r3, lr)
        "ldr    r3, [r9, %[io_out]]\n\t"       // the triangle record
        "str    r12, [r3, %[k_color]]\n\t"     // k.color
        "str    r10, [r9, %[io_area]]\n\t"     // io->area
        "add    r0, r7, r0, lsl #3\n\t"
        "add    r1, r7, r1, lsl #3\n\t"
        "add    r2, r7, r2, lsl #3\n\t"
        "mov    r3, r9\n\t"
        "bl     %c[draw]\n\t"                  // set up and drawn
        "cmp    r0, #1\n\t"
        "bne    22f\n\t"
        "ldr    r0, [r5, %[d_drawn]]\n\t"
        "adds   r0, r0, #1\n\t"
        "str    r0, [r5, %[d_drawn]]\n\t"      // drawn
        "b      28b\n"
        "22:\n\t"
        "cmp    r0, #0\n\t"
        "beq    28b\n\t"                       // none
        "b      90f\n"                          // generic: back to C++
        "1:\n\t"
        "cmp    r4, r6\n\t"
        "beq    90f\n\t"
        "ldrh   r0, [r4]\n\t"
        "ldrh   r1, [r4, #2]\n\t"
        "ldrh   r2, [r4, #4]\n\t"
        "add    r0, r7, r0, lsl #3\n\t"
        "add    r1, r7, r1, lsl #3\n\t"
        "add    r2, r7, r2, lsl #3\n\t"
        "ldr    r3, [r0, %[v_z]]\n\t"
        "ldr    r12, [r1, %[v_z]]\n\t"
        "ldr    lr, [r2, %[v_z]]\n\t"
        "cmp    r3, #0\n\t"
        "it     ne\n\t"
        "cmpne  r12, #0\n\t"
        "it     ne\n\t"
        "cmpne  lr, #0\n\t"
        "beq    90f\n\t"                        // a vertex outside a clip plane: back to C++
        HIDER_V7M_AREA
        "cmp    r10, #0\n\t"
        "beq    8f\n\t"                         // zero: nothing
        "bmi    2f\n\t"                         // counter-clockwise: drawn
        "ldr    r0, [r5, %[d_cull]]\n\t"
        "cbz    r0, 2f\n\t"                     // not culling: drawn
        "adds   r11, r11, #1\n"                  // culled
        "8:\n\t"
        "adds   r4, r4, #6\n\t"
        "b      1b\n"
        "2:\n\t"                               // FaceShading::color565(), as in draw_flat_v6m
        "ldr    r1, [r5, %[d_normals]]\n\t"
        "add    r1, r1, r4\n\t"                 // the triangle's normal
        HIDER_V7M_COLOR565
        "ldr    r12, [r9, %[io_out]]\n\t"      // the triangle record
        "str    r1, [r12, %[k_color]]\n\t"     // k.color
        "str    r10, [r9, %[io_area]]\n\t"     // io->area
        "ldm    sp, {r0, r1, r2}\n\t"
        "mov    r3, r9\n\t"
        "bl     %c[draw]\n\t"                   // set up and drawn
        "cmp    r0, #1\n\t"
        "bne    3f\n\t"
        "ldr    r0, [r5, %[d_drawn]]\n\t"
        "adds   r0, r0, #1\n\t"
        "str    r0, [r5, %[d_drawn]]\n\t"      // drawn
        "b      8b\n"
        "3:\n\t"
        "cmp    r0, #0\n\t"
        "beq    8b\n"                           // none
        "90:\n\t"
        "ldr    r0, [r5, %[d_culled]]\n\t"
        "add    r0, r0, r11\n\t"
        "str    r0, [r5, %[d_culled]]\n\t"     // culled
        "mov    r0, r4\n\t"
        "add    sp, #12\n\t"
        "pop    {r4-r11, pc}\n"
        :
        : [draw] "i"(kernel_draw_v7m), HIDER_DRAW_LOOP_OPERANDS);
}
#endif

}  // namespace hider

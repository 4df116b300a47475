// The band renderer's loop over one band (binned.hpp) in Thumb-2 for ARMv7-M: merges in mesh order the
// set-ups carried from the band above (a run of them resumed with the row kernel's loop inline, each
// slot then onward or back) with the band's list (set-up into a free slot, headlight colour, rows). In
// assembly so that the list, the vertices and the slot stay in registers. Clipped triangles, those
// without a free slot and generic set-ups (flagged) go back to the C++ loop. firmware/kernelcheck
// compares both loops.
#pragma once
#include <hider/mesh.hpp>
#include <hider/raster/draw_loop_asm.hpp>

namespace hider {

namespace detail {
/// Constants and in/out values of the band list loop (the layout is its contract).
struct BandLoopArm {
    const Tri* tris;                  ///< 0
    const ScreenVertex* verts;        ///< 4
    const uint16_t* next;             ///< 8: the band lists (binned.hpp)
    KernelSetupIo* io;                ///< 12 (io->out is set to the slot's record per triangle)
    intptr_t normals_offset;          ///< 16: bytes from a Tri to its Normal14 (both 6 bytes)
    int32_t view_z[3];                ///< 20, 24, 28
    uint32_t base_r, base_g, base_b;  ///< 32, 36, 40
    uint16_t* depth;                  ///< 44: the band's first depth row
    int32_t y0;                       ///< 48: the band's first row
    int32_t y1;                       ///< 52: the row after the band
    KernelTarget target;              ///< 56: colour offset, 60: stride
    KernelTriangle* pool;             ///< 64: the carried slots
    const uint8_t* free_base;         ///< 68: the free-slot stack's bottom
    uint8_t* free_top;                ///< 72, in and out
    uint8_t* nxt;                     ///< 76, in and out: the next band's slots
    int32_t count_from;               ///< 80: a set-up counts as drawn from this top row on
    uint32_t drawn;                   ///< 84, counted up
    const uint8_t* cur;               ///< 88, in and out: this band's carried slots still to resume
    const uint8_t* cur_end;           ///< 92
    uint32_t projected;               ///< 96: 1 when no vertex is outside a clip plane (all_projected())
    uintptr_t head;                   ///< 100: set by draw_band_v7m(): its loop head for `projected`
    intptr_t color_less_2;            ///< 104: target.color_offset - 2 (the row loop's post-increment)
    int32_t stride_bytes;             ///< 108: target.stride_bytes, next to it for one load
};
static_assert(sizeof(void*) != 4 ||
                  (offsetof(BandLoopArm, verts) == 4 && offsetof(BandLoopArm, next) == 8 && offsetof(BandLoopArm, io) == 12 &&
                   offsetof(BandLoopArm, normals_offset) == 16 && offsetof(BandLoopArm, view_z) == 20 &&
                   offsetof(BandLoopArm, base_r) == 32 && offsetof(BandLoopArm, depth) == 44 &&
                   offsetof(BandLoopArm, y0) == 48 && offsetof(BandLoopArm, y1) == 52 &&
                   offsetof(BandLoopArm, target) == 56 && offsetof(BandLoopArm, pool) == 64 &&
                   offsetof(BandLoopArm, free_base) == 68 && offsetof(BandLoopArm, free_top) == 72 &&
                   offsetof(BandLoopArm, nxt) == 76 && offsetof(BandLoopArm, count_from) == 80 &&
                   offsetof(BandLoopArm, drawn) == 84 && offsetof(BandLoopArm, cur) == 88 &&
                   offsetof(BandLoopArm, cur_end) == 92 && offsetof(BandLoopArm, projected) == 96 &&
                   offsetof(BandLoopArm, head) == 100 && offsetof(BandLoopArm, color_less_2) == 104 &&
                   offsetof(BandLoopArm, stride_bytes) == 108),
              "band loop layout: every offset the assembly uses");
static_assert(sizeof(void*) != 4 || sizeof(KernelTriangle) == 96, "slot records are 96 bytes");
/// draw_band_v7m() hands a listed triangle back with this bit set when its set-up said generic.
constexpr uint32_t kGenericHandBack = 0x10000;
static_assert(sizeof(void*) != 4 || offsetof(KernelSetupIo, out) == offsetof(KernelSetupIo, area) + sizeof(int32_t), "io area and out: one strd");
}  // namespace detail

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// Draws the band from listed triangle t on (following d->next), resuming every carried set-up from
/// d->cur whose triangle comes before the next listed one; returns kNoTriangle when the list and the
/// carried set-ups are done, else a listed triangle it hands back (a vertex outside a clip plane, no free
/// slot, a generic set-up: with kGenericHandBack set), the carried ones before it resumed. Every listed triangle has a non-zero
/// area and is not culled (bin_triangles()). Registers: r4 the listed triangle, r5 d, r6 the next carried
/// triangle (0xFFFF: none), r7 the vertices, r8 the triangles, r9 d->next, r10 the area, r11 the slot's
/// record; on the stack three words for the resumes' row loop, then d and the listed triangle. The loop
/// comes back to its head through d->head: without the clip test when d->projected. A run of resumes
/// keeps its state on the stack and in d (the slot order pointer at sp + 12, and at sp + 24 where the
/// record's slot goes after it: d->nxt or d->free_top) and draws each record's
/// rows with run_kernel_triangle_v7m()'s row loop (HIDER_V7M_ROWS) inline: every one is on the band's
/// first row.
HIDER_NAKED inline uint32_t draw_band_v7m(uint32_t, detail::BandLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "sub    sp, #28\n\t"                         // 36 + 28: the calls see an 8-byte aligned stack
        "mov    r4, r0\n\t"
        "mov    r5, r1\n\t"
        "str    r5, [sp, #16]\n\t"
        "ldr    r8, [r5, #0]\n\t"
        "ldr    r7, [r5, #4]\n\t"
        "ldr    r9, [r5, #8]\n\t"              // d->next
        "movw   r6, #0xFFFF\n\t"
        "ldr    r0, [r5, #88]\n\t"
        "ldr    r1, [r5, #92]\n\t"
        "cmp    r0, r1\n\t"
        "beq    1f\n\t"                         // nothing carried
        "ldrb   r0, [r0]\n\t"
        "ldr    r1, [r5, #64]\n\t"
        "add    r0, r0, r0, lsl #1\n\t"
        "add    r0, r1, r0, lsl #5\n\t"
        "ldrh   r6, [r0, %[tri]]\n"              // the next carried triangle
        "1:\n\t"
        "ldr    r0, [r5, #96]\n\t"              // the loop head: with the clip test unless every vertex
        "cbnz   r0, 25f\n\t"                    // is projected (a Thumb address: the loop comes back
        "movw   r0, #:lower16:(21f + 1)\n\t"    // through it with a load into pc)
        "movt   r0, #:upper16:(21f + 1)\n\t"
        "b      26f\n"
        "25:\n\t"
        "movw   r0, #:lower16:(24f + 1)\n\t"
        "movt   r0, #:upper16:(24f + 1)\n"
        "26:\n\t"
        "str    r0, [r5, #100]\n\t"
        "ldr    pc, [r5, #100]\n"
        "21:\n\t"
        "cmp    r4, r6\n\t"
        "bhs    50f\n\t"                        // the carried triangle first, or the list's end
        "add    r0, r4, r4, lsl #1\n\t"
        "add    r12, r8, r0, lsl #1\n\t"        // the triangle: tris + 6 t
        "ldrh   r0, [r12]\n\t"
        "ldrh   r1, [r12, #2]\n\t"
        "ldrh   r2, [r12, #4]\n\t"
        "add    r0, r7, r0, lsl #3\n\t"
        "add    r1, r7, r1, lsl #3\n\t"
        "add    r2, r7, r2, lsl #3\n\t"
        "ldr    r3, [r0, #4]\n\t"
        "cbz    r3, 91f\n\t"                    // a vertex outside a clip plane: back to C++
        "ldr    r3, [r1, #4]\n\t"
        "cbz    r3, 91f\n\t"
        "ldr    r3, [r2, #4]\n\t"
        "cbz    r3, 91f\n\t"
        "b      4f\n"
        "91:\n\t"
        "b      90f\n"                           // within the reach of cbz
        "24:\n\t"                               // every vertex projected: no clip test
        "cmp    r4, r6\n\t"
        "bhs    50f\n\t"
        "add    r0, r4, r4, lsl #1\n\t"
        "add    r12, r8, r0, lsl #1\n\t"
        "ldrh   r0, [r12]\n\t"
        "ldrh   r1, [r12, #2]\n\t"
        "ldrh   r2, [r12, #4]\n\t"
        "add    r0, r7, r0, lsl #3\n\t"
        "add    r1, r7, r1, lsl #3\n\t"
        "add    r2, r7, r2, lsl #3\n"
        "4:\n\t"                                // signed_area() as HIDER_V7M_AREA, the pointers kept
        "ldr    r3, [r0]\n\t"                   // x | y << 16 of each
        "ldr    r12, [r1]\n\t"
        "ldr    r11, [r2]\n\t"
        "sxth   lr, r3\n\t"                     // ax
        "asr    r3, r3, #16\n\t"                // ay
        "sxth   r10, r12\n\t"
        "sub    r10, r10, lr\n\t"               // bx - ax
        "rsb    r12, r3, r12, asr #16\n\t"      // by - ay
        "rsb    r3, r3, r11, asr #16\n\t"       // cy - ay
        "mul    r10, r10, r3\n\t"
        "sxth   r11, r11\n\t"
        "sub    r11, r11, lr\n\t"               // cx - ax
        "mls    r10, r11, r12, r10\n\t"         // signed_area(a, b, c)
        "ldrd   r12, r3, [r5, #68]\n\t"         // free_base, free_top
        "cmp    r3, r12\n\t"
        "beq    90f\n\t"                        // no free slot: back to C++ (the spare)
        "ldrb   r3, [r3, #-1]\n\t"              // the slot on top
        "ldr    r12, [r5, #64]\n\t"
        "add    r3, r3, r3, lsl #1\n\t"
        "add    r11, r12, r3, lsl #5\n\t"       // its record: pool + 96 s
        // FaceShading::color565(), as in draw_flat_v7m: first, so that the set-up draws at once; the
        // vertices stay in r0 r1 r2, r9 lends itself and comes back from d.
        "add    r12, r4, r4, lsl #1\n\t"
        "add    r12, r8, r12, lsl #1\n\t"
        "ldr    r3, [r5, #16]\n\t"
        "add    r12, r12, r3\n\t"               // the triangle's normal
        HIDER_V7M_COLOR565_IN(r12, r9, r3, lr)
        "ldr    r9, [r5, #8]\n\t"               // d->next
        "str    r12, [r11, %[color]]\n\t"       // k.color
        "strh   r4, [r11, %[tri]]\n\t"          // the mesh triangle
        "ldr    r3, [r5, #12]\n\t"              // d->io
        "strd   r10, r11, [r3, %[io_area]]\n\t" // io->area, io->out
        "bl     %c[draw]\n\t"                   // set up, and the rows in this band drawn
        "cmp    r0, #1\n\t"
        "beq    3f\n\t"
        "cmp    r0, #0\n\t"
        "bne    92f\n"                          // generic: back to C++, flagged
        "8:\n\t"                                // the next listed triangle
        "ldrh   r4, [r9, r4, lsl #1]\n\t"
        "ldr    pc, [r5, #100]\n"                // the loop head
        "3:\n\t"
        "ldrsh  r0, [r11, %[top]]\n\t"
        "ldrd   r1, r2, [r5, #80]\n\t"          // count_from, drawn
        "cmp    r0, r1\n\t"
        "itt    ge\n\t"
        "addge  r2, r2, #1\n\t"
        "strge  r2, [r5, #84]\n\t"              // drawn: its first row is in this band
        // A set-up without a row in the band is rare: it returns at once and the test below keeps the
        // slot free.
        "ldrsh  r0, [r11, %[row]]\n\t"
        "ldrsh  r1, [r11, %[end]]\n\t"
        "cmp    r0, r1\n\t"
        "bge    8b\n\t"                         // done in this band: the slot stays free
        "ldr    r0, [r5, #72]\n\t"
        "ldrb   r1, [r0, #-1]!\n\t"             // the slot leaves the free stack
        "str    r0, [r5, #72]\n\t"
        "ldr    r2, [r5, #76]\n\t"
        "strb   r1, [r2], #1\n\t"               // for the next band
        "str    r2, [r5, #76]\n\t"
        "b      8b\n"
        "92:\n\t"
        "orr    r4, r4, #0x10000\n"             // kGenericHandBack: C++ draws it without another set-up
        "90:\n\t"
        "mov    r0, r4\n\t"
        "add    sp, #28\n\t"
        "pop    {r4-r11, pc}\n"

        "50:\n\t"                               // resume the carried set-ups before r4
        "movw   r0, #0xFFFF\n\t"
        "cmp    r6, r0\n\t"
        "beq    90b\n\t"                        // none left: r4 is the list's end
        "str    r4, [sp, #20]\n\t"
        "mov    r12, r5\n\t"
        "ldr    r10, [r5, #88]\n"
        "61:\n\t"                               // r10 the slot order, r12 d, r4 the listed triangle
        "ldrb   r11, [r10], #1\n\t"             // its slot
        "ldr    r0, [r12, #64]\n\t"
        "add    r9, r11, r11, lsl #1\n\t"
        "add    r0, r0, r9, lsl #5\n\t"         // its record
        "ldrh   r9, [r0, %[tri]]\n\t"
        "cmp    r9, r4\n\t"
        "bhs    65f\n\t"                        // after the listed triangle: stop
        "str    r10, [sp, #12]\n\t"
        // run_kernel_triangle_v7m()'s entry for a record on the band's first row, to the band's end.
        "ldrsh  r6, [r0, %[end]]\n\t"
        "ldrsh  r5, [r0, %[mid]]\n\t"
        "ldrd   r4, r2, [r12, #48]\n\t"         // y0, y1
        "ldr    r9, [r12, #44]\n\t"             // the depth row of y0
        "ldrd   r7, r3, [r12, #104]\n\t"        // colour offset less HIDER_V7M_ROWS's post-increment, stride
        "cmp    r6, r2\n\t"
        "itte   gt\n\t"
        "movgt  r6, r2\n\t"                     // stop = min(end, y1)
        "addgt  r8, r12, #76\n\t"               // rows remain: the slot goes to the next band's
        "addle  r8, r12, #72\n\t"               // done: back to the free slots
        "str    r8, [sp, #24]\n\t"
        "strh   r6, [r0, %[row]]\n\t"           // the row after this band
        "sub    r6, r6, r4\n\t"                 // n rows (a carried set-up has some left)
        "mla    r11, r6, r3, r9\n\t"            // the depth row after the last
        "mov    r8, #-1\n\t"                    // rows after a switch: none
        "subs   r1, r5, r4\n\t"                 // m = mid - y0
        "ble    62f\n\t"                        // on or below the middle row
        "ldrsh  r2, [r0, %[end]]\n\t"
        "cmp    r5, r2\n\t"
        "bge    62f\n\t"                        // no lower short edge
        "cmp    r1, r6\n\t"
        "bgt    62f\n\t"                        // the middle row lies past this band
        "sub    r8, r6, r1\n\t"
        "mov    r6, r1\n\t"
        "mla    r1, r1, r3, r9\n\t"
        "str    r1, [sp]\n"                     // the middle row's depth row
        "62:\n\t"
        "strd   r8, r11, [sp, #4]\n\t"
        "ldrd   r8, r10, [r0, %[dzdx]]\n\t"     // dzdx, colour
        "ldm    r0, {r1-r5}\n\t"                // lx lg lz rx rg
        "add    r1, r1, r9\n\t"                 // lp
        "add    r4, r4, r9\n\t"                 // rp
        "add    r0, r0, %[ra]\n"
        HIDER_V7M_ROWS
        "ldrd   r10, r12, [sp, #12]\n\t"        // the slot order, d
        "ldrb   r11, [r10, #-1]\n\t"            // the record's slot
        "ldr    r3, [sp, #24]\n\t"              // where it goes
        "ldr    r2, [r3]\n\t"
        "strb   r11, [r2], #1\n\t"
        "str    r2, [r3]\n\t"
        "ldr    r4, [sp, #20]\n\t"
        "ldr    r11, [r12, #92]\n\t"
        "cmp    r10, r11\n\t"
        "bne    61b\n\t"
        "movw   r6, #0xFFFF\n\t"                // all resumed
        "b      66f\n"
        "65:\n\t"
        "mov    r6, r9\n\t"                     // the next carried triangle
        "sub    r10, r10, #1\n"                 // its slot stays in the order
        "66:\n\t"
        "str    r10, [r12, #88]\n\t"
        "mov    r5, r12\n\t"
        "ldr    r8, [r5, #0]\n\t"
        "ldr    r7, [r5, #4]\n\t"
        "ldr    r9, [r5, #8]\n\t"              // d->next
        "ldr    pc, [r5, #100]\n"
        :
        : [draw] "i"(kernel_draw_v7m),
          [top] "i"(offsetof(KernelTriangle, top)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [color] "i"(offsetof(KernelTriangle, k) + offsetof(RowKernel, color)),
          [dzdx] "i"(offsetof(KernelTriangle, k) + offsetof(RowKernel, dzdx)), [ra] "i"(offsetof(RowKernel, ra)),
          [n_left] "i"(offsetof(KernelTriangle, next_left) - offsetof(RowKernel, ra)),
          [n_x] "i"(offsetof(KernelTriangle, next_x) - offsetof(RowKernel, ra)),
          [n_g] "i"(offsetof(KernelTriangle, next_g) - offsetof(RowKernel, ra)),
          [n_a] "i"(offsetof(KernelTriangle, next_a) - offsetof(RowKernel, ra)),
          [n_z] "i"(offsetof(KernelTriangle, next_z) - offsetof(RowKernel, ra)),
          [n_dz] "i"(offsetof(KernelTriangle, next_dz) - offsetof(RowKernel, ra)),
          [tri] "i"(offsetof(KernelTriangle, tri)), [io_area] "i"(offsetof(KernelSetupIo, area)),
          [view_z0] "i"(offsetof(detail::BandLoopArm, view_z)),
          [view_z1] "i"(offsetof(detail::BandLoopArm, view_z) + 4), [view_z2] "i"(offsetof(detail::BandLoopArm, view_z) + 8),
          [base_r] "i"(offsetof(detail::BandLoopArm, base_r)), [base_g] "i"(offsetof(detail::BandLoopArm, base_g)),
          [base_b] "i"(offsetof(detail::BandLoopArm, base_b)));
}
#endif

}  // namespace hider

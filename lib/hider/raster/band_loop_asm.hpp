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
/// Constants and in/out values of the band list loop (the layout is its contract). The first twelve
/// words are one ldm of a resume (draw_band_v7m()), in the order of the registers they load: r0..r10
/// and lr.
struct BandLoopArm {
    KernelTriangle* pool;             ///< 0: the carried slots (r0)
    int32_t y0;                       ///< 4: the band's first row (r1)
    int32_t y1;                       ///< 8: the row after the band (r2)
    int32_t stride_bytes;             ///< 12: target.stride_bytes (r3)
    uint32_t limit;                   ///< 16: set by draw_band_v7m(): where a run of resumes stops (r4)
    const uint8_t* cur;               ///< 20, in and out: this band's carried slots still to resume (r5)
    const uint8_t* cur_end;           ///< 24 (r6)
    intptr_t color_less_2;            ///< 28: target.color_offset - 2 (the row loop's post-increment) (r7)
    uint8_t* nxt;                     ///< 32, in and out: the next band's slots (r8)
    uint8_t* free_top;                ///< 36, in and out (r9)
    const uint8_t* free_base;         ///< 40: the free-slot stack's bottom (r10)
    uint16_t* depth;                  ///< 44: the band's first depth row (lr)
    const Tri* tris;                  ///< 48
    const ScreenVertex* verts;        ///< 52
    const uint16_t* next;             ///< 56: the band lists (binned.hpp)
    KernelSetupIo* io;                ///< 60 (io->out is set to the slot's record per triangle)
    intptr_t normals_offset;          ///< 64: bytes from a Tri to its Normal14 (both 6 bytes)
    int32_t view_z[3];                ///< 68, 72, 76
    uint32_t base_r, base_g, base_b;  ///< 80, 84, 88
    int32_t count_from;               ///< 92: a set-up counts as drawn from this top row on
    uint32_t drawn;                   ///< 96, counted up
    uint32_t projected;               ///< 100: 1 when no vertex is outside a clip plane (all_projected())
    uintptr_t head;                   ///< 104: set by draw_band_v7m(): its loop head for `projected`
};
static_assert(sizeof(void*) != 4 ||
                  (offsetof(BandLoopArm, y0) == 4 && offsetof(BandLoopArm, y1) == 8 &&
                   offsetof(BandLoopArm, stride_bytes) == 12 && offsetof(BandLoopArm, limit) == 16 &&
                   offsetof(BandLoopArm, cur) == 20 && offsetof(BandLoopArm, cur_end) == 24 &&
                   offsetof(BandLoopArm, color_less_2) == 28 && offsetof(BandLoopArm, nxt) == 32 &&
                   offsetof(BandLoopArm, free_top) == 36 && offsetof(BandLoopArm, free_base) == 40 &&
                   offsetof(BandLoopArm, depth) == 44 && offsetof(BandLoopArm, tris) == 48 &&
                   offsetof(BandLoopArm, verts) == 52 && offsetof(BandLoopArm, next) == 56 &&
                   offsetof(BandLoopArm, io) == 60 && offsetof(BandLoopArm, normals_offset) == 64 &&
                   offsetof(BandLoopArm, view_z) == 68 && offsetof(BandLoopArm, base_r) == 80 &&
                   offsetof(BandLoopArm, count_from) == 92 && offsetof(BandLoopArm, drawn) == 96 &&
                   offsetof(BandLoopArm, projected) == 100 && offsetof(BandLoopArm, head) == 104),
              "band loop layout: every offset the assembly uses");
static_assert(sizeof(void*) != 4 || sizeof(KernelTriangle) < 256, "slot records: one mov of their size");
/// draw_band_v7m() hands a listed triangle back with this bit set when its set-up said generic.
constexpr uint32_t kGenericHandBack = 0x10000;
static_assert(sizeof(void*) != 4 || offsetof(KernelSetupIo, out) == offsetof(KernelSetupIo, area) + sizeof(int32_t), "io area and out: one strd");
}  // namespace detail

#if defined(HIDER_ARMV7M)
/// Draws the band from listed triangle t on (following d->next), resuming every carried set-up from
/// d->cur whose triangle comes before the next listed one; returns kNoTriangle when the list and the
/// carried set-ups are done, else a listed triangle it hands back (a vertex outside a clip plane, no free
/// slot, a generic set-up: with kGenericHandBack set), the carried ones before it resumed. Every listed triangle has a non-zero
/// area and is not culled (bin_triangles()). Registers: r4 the listed triangle, r5 d, r6 the next carried
/// triangle (0xFFFF: none), r7 the vertices, r8 the triangles, r9 d->next, r10 the area, r11 the slot's
/// record; on the stack three words for the resumes' row loop, then d (sp + 16). The loop comes back to
/// its head through d->head: without the clip test when d->projected. A run of resumes keeps its state
/// in d (the listed triangle in d->limit, d->cur stored per record, the record's slot pushed onto d->nxt
/// or d->free_top before its rows), reloads it with one ldm of d's first twelve words after each record
/// and draws each record's rows with run_kernel_triangle_v7m()'s row loop (HIDER_V7M_ROWS) inline: every
/// one is on the band's first row.
HIDER_NAKED inline uint32_t draw_band_v7m(uint32_t, detail::BandLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "sub    sp, #28\n\t"                         // 36 + 28: the calls see an 8-byte aligned stack
        "mov    r4, r0\n\t"
        "mov    r5, r1\n\t"
        "str    r5, [sp, #16]\n\t"
        "ldr    r8, [r5, #48]\n\t"
        "ldr    r7, [r5, #52]\n\t"
        "ldr    r9, [r5, #56]\n\t"              // d->next
        "movw   r6, #0xFFFF\n\t"
        "ldrd   r0, r1, [r5, #20]\n\t"          // cur, cur_end
        "cmp    r0, r1\n\t"
        "beq    1f\n\t"                         // nothing carried
        "ldrb   r0, [r0]\n\t"
        "ldr    r1, [r5, #0]\n\t"
        "mov    r2, %[rec]\n\t"
        "mla    r0, r0, r2, r1\n\t"
        "ldrh   r6, [r0, %[tri]]\n"              // the next carried triangle
        "1:\n\t"
        "ldr    r0, [r5, #100]\n\t"             // the loop head: with the clip test unless every vertex
        "cbnz   r0, 25f\n\t"                    // is projected (a Thumb address: the loop comes back
        "movw   r0, #:lower16:(21f + 1)\n\t"    // through it with a load into pc)
        "movt   r0, #:upper16:(21f + 1)\n\t"
        "b      26f\n"
        "25:\n\t"
        "movw   r0, #:lower16:(24f + 1)\n\t"
        "movt   r0, #:upper16:(24f + 1)\n"
        "26:\n\t"
        "str    r0, [r5, #104]\n\t"
        "ldr    pc, [r5, #104]\n"
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
        "ldrd   r3, r12, [r5, #36]\n\t"         // free_top, free_base
        "cmp    r3, r12\n\t"
        "beq    90f\n\t"                        // no free slot: back to C++ (the spare)
        "ldrb   r3, [r3, #-1]\n\t"              // the slot on top
        "ldr    r12, [r5, #0]\n\t"
        "mov    r11, %[rec]\n\t"
        "mla    r11, r3, r11, r12\n\t"         // its record: pool + s records
        // FaceShading::color565(), as in draw_flat_v7m: first, so that the set-up draws at once; the
        // vertices stay in r0 r1 r2, r9 lends itself and comes back from d.
        "add    r12, r4, r4, lsl #1\n\t"
        "add    r12, r8, r12, lsl #1\n\t"
        "ldr    r3, [r5, #64]\n\t"
        "add    r12, r12, r3\n\t"               // the triangle's normal
        HIDER_V7M_COLOR565_IN(r12, r9, r3, lr)
        "ldrd   r9, r3, [r5, #56]\n\t"          // d->next, d->io
        "str    r12, [r11, %[color]]\n\t"       // k.color
        "strh   r4, [r11, %[tri]]\n\t"          // the mesh triangle
        "strd   r10, r11, [r3, %[io_area]]\n\t" // io->area, io->out
        "bl     %c[draw]\n\t"                   // set up, and the rows in this band drawn
        "cmp    r0, #1\n\t"
        "beq    3f\n\t"
        "cmp    r0, #0\n\t"
        "bne    92f\n"                          // generic: back to C++, flagged
        "8:\n\t"                                // the next listed triangle
        "ldrh   r4, [r9, r4, lsl #1]\n\t"
        "ldr    pc, [r5, #104]\n"                // the loop head
        "3:\n\t"
        "ldrsh  r0, [r11, %[top]]\n\t"
        "ldrd   r1, r2, [r5, #92]\n\t"          // count_from, drawn
        "cmp    r0, r1\n\t"
        "itt    ge\n\t"
        "addge  r2, r2, #1\n\t"
        "strge  r2, [r5, #96]\n\t"              // drawn: its first row is in this band
        // A set-up without a row in the band is rare: it returns at once and the test below keeps the
        // slot free.
        "ldrsh  r0, [r11, %[row]]\n\t"
        "ldrsh  r1, [r11, %[end]]\n\t"
        "cmp    r0, r1\n\t"
        "bge    8b\n\t"                         // done in this band: the slot stays free
        "ldrd   r2, r0, [r5, #32]\n\t"          // nxt, free_top
        "ldrb   r1, [r0, #-1]!\n\t"             // the slot leaves the free stack
        "strb   r1, [r2], #1\n\t"               // for the next band
        "strd   r2, r0, [r5, #32]\n\t"
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
        "mov    r12, r5\n\t"
        "str    r4, [r12, #16]\n\t"             // d->limit
        "ldm    r12, {r0-r10, lr}\n"            // as at the end of a resume
        "61:\n\t"                               // r12 d, r0..r10 and lr its first twelve words (BandLoopArm)
        "ldrb   r11, [r5], #1\n\t"              // the slot
        "mov    r6, %[rec]\n\t"
        "mla    r0, r11, r6, r0\n\t"           // its record: pool + s records
        "ldrh   r6, [r0, %[tri]]\n\t"
        "cmp    r6, r4\n\t"
        "bhs    65f\n\t"                        // after the listed triangle: stop
        "str    r5, [r12, #20]\n\t"             // d->cur
        // run_kernel_triangle_v7m()'s entry for a record on the band's first row, to the band's end.
        "ldrsh  r6, [r0, %[end]]\n\t"
        "ldrsh  r5, [r0, %[mid]]\n\t"
        "cmp    r6, r2\n\t"
        "itte   gt\n\t"
        "movgt  r6, r2\n\t"                     // stop = min(end, y1)
        "strbgt r11, [r8], #1\n\t"              // rows remain: the slot goes to the next band's
        "strble r11, [r9], #1\n\t"              // done: back to the free slots
        "strd   r8, r9, [r12, #32]\n\t"         // d->nxt, d->free_top
        "strh   r6, [r0, %[row]]\n\t"           // the row after this band
        "sub    r6, r6, r1\n\t"                 // n rows (a carried set-up has some left)
        "mla    r11, r6, r3, lr\n\t"            // the depth row after the last
        "mov    r8, #-1\n\t"                    // rows after a switch: none
        "subs   r1, r5, r1\n\t"                 // m = mid - y0
        "ble    62f\n\t"                        // on or below the middle row
        "ldrsh  r2, [r0, %[end]]\n\t"
        "cmp    r5, r2\n\t"
        "bge    62f\n\t"                        // no lower short edge
        "cmp    r1, r6\n\t"
        "bgt    62f\n\t"                        // the middle row lies past this band
        "sub    r8, r6, r1\n\t"
        "mov    r6, r1\n\t"
        "mla    r1, r1, r3, lr\n\t"
        "str    r1, [sp]\n"                     // the middle row's depth row
        "62:\n\t"
        "strd   r8, r11, [sp, #4]\n\t"
        "ldrd   r8, r10, [r0, %[dzdx]]\n\t"     // dzdx, colour
        "ldm    r0, {r1-r5}\n\t"                // lx lg lz rx rg
        "add    r1, r1, lr\n\t"                 // lp
        "add    r4, r4, lr\n\t"                 // rp
        "add    r0, r0, %[ra]\n"
        HIDER_V7M_ROWS
        "ldr    r12, [sp, #16]\n\t"             // d
        "ldm    r12, {r0-r10, lr}\n\t"
        "cmp    r5, r6\n\t"                     // cur, cur_end
        "bne    61b\n\t"
        "movw   r6, #0xFFFF\n\t"                // all resumed
        "b      66f\n"
        "65:\n\t"                               // r6 the next carried triangle
        "sub    r5, r5, #1\n\t"                 // its slot stays in the order
        "str    r5, [r12, #20]\n"
        "66:\n\t"
        "mov    r5, r12\n\t"
        "ldr    r8, [r5, #48]\n\t"
        "ldr    r7, [r5, #52]\n\t"
        "ldr    r9, [r5, #56]\n\t"              // d->next
        "ldr    pc, [r5, #104]\n"
        :
        : [draw] "i"(kernel_draw_v7m), [rec] "i"(sizeof(KernelTriangle)),
          [top] "i"(offsetof(KernelTriangle, top)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [color] "i"(offsetof(KernelTriangle, k) + offsetof(RowKernel, color)),
          [dzdx] "i"(offsetof(KernelTriangle, k) + offsetof(RowKernel, dzdx)), [ra] "i"(offsetof(RowKernel, ra)),
          HIDER_V7M_ROWS_OPERANDS,
          [tri] "i"(offsetof(KernelTriangle, tri)), [io_area] "i"(offsetof(KernelSetupIo, area)),
          [view_z0] "i"(offsetof(detail::BandLoopArm, view_z)),
          [view_z1] "i"(offsetof(detail::BandLoopArm, view_z) + 4), [view_z2] "i"(offsetof(detail::BandLoopArm, view_z) + 8),
          [base_r] "i"(offsetof(detail::BandLoopArm, base_r)), [base_g] "i"(offsetof(detail::BandLoopArm, base_g)),
          [base_b] "i"(offsetof(detail::BandLoopArm, base_b)));
}
#endif

}  // namespace hider

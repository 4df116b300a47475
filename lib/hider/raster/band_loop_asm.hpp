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
/// Constants and in/out values of the band list loop (the layout is its contract). draw_band_v7m() copies
/// the first twelve words onto its stack per call (and cur, nxt, free_top back to them on its return);
/// one ldm of that copy gives a resume r0..r10 and lr in the order of the words.
struct BandLoopArm {
    const uint8_t* cur;               ///< 0, in and out: this band's carried slots still to resume (r0)
    uint8_t* nxt;                     ///< 4, in and out: the next band's slots (r1)
    uint8_t* free_top;                ///< 8, in and out (r2)
    const uint8_t* free_base;         ///< 12: the free-slot stack's bottom (r3)
    uint32_t limit;                   ///< 16: where a run of resumes stops (r4; set in the stack's copy only)
    int32_t y0;                       ///< 20: the band's first row (r5)
    const uint8_t* cur_end;           ///< 24 (r6)
    intptr_t color_less_2;            ///< 28: target.color_offset - 2 (the row loop's post-increment) (r7)
    uint32_t record_size;             ///< 32: sizeof(KernelTriangle) (r8)
    KernelTriangle* pool;             ///< 36: the carried slots (r9)
    int32_t y1;                       ///< 40: the row after the band (r10)
    uint16_t* depth;                  ///< 44: the band's first depth row (lr)
    int32_t stride_bytes;             ///< 48: target.stride_bytes
    const Tri* tris;                  ///< 52
    const ScreenVertex* verts;        ///< 56
    const uint16_t* next;             ///< 60: the band lists (binned.hpp)
    KernelSetupIo* io;                ///< 64 (io->out is set to the slot's record per triangle)
    intptr_t normals_offset;          ///< 68: bytes from a Tri to its Normal14 (both 6 bytes)
    int32_t view_z[3];                ///< 72, 76, 80
    uint32_t base_r, base_g, base_b;  ///< 84, 88, 92
    int32_t count_from;               ///< 96: a set-up counts as drawn from this top row on
    uint32_t drawn;                   ///< 100, counted up
    uint32_t projected;               ///< 104: 1 when no vertex is outside a clip plane (all_projected())
    uintptr_t head;                   ///< 108: set by draw_band_v7m(): its loop head for `projected`
};
/// draw_band_v7m()'s stack frame below its nine saved registers: the copy of BandLoopArm's first twelve
/// words, HIDER_V7M_ROWS's three words (the middle row's depth row, the rows after a switch, kept at -1
/// between resumes, and the depth row after the band's last), the stride and d.
constexpr int kBandLoopRows = 48, kBandLoopStride = 60, kBandLoopD = 64, kBandLoopFrame = 68;
static_assert((36 + kBandLoopFrame) % 8 == 0, "draw_band_v7m(): its calls see an 8-byte aligned stack");
static_assert(sizeof(void*) != 4 ||
                  (offsetof(BandLoopArm, nxt) == 4 && offsetof(BandLoopArm, free_top) == 8 &&
                   offsetof(BandLoopArm, free_base) == 12 && offsetof(BandLoopArm, limit) == 16 &&
                   offsetof(BandLoopArm, y0) == 20 && offsetof(BandLoopArm, cur_end) == 24 &&
                   offsetof(BandLoopArm, color_less_2) == 28 && offsetof(BandLoopArm, record_size) == 32 &&
                   offsetof(BandLoopArm, pool) == 36 && offsetof(BandLoopArm, y1) == 40 &&
                   offsetof(BandLoopArm, depth) == 44 && offsetof(BandLoopArm, stride_bytes) == 48 &&
                   offsetof(BandLoopArm, tris) == 52 && offsetof(BandLoopArm, verts) == 56 &&
                   offsetof(BandLoopArm, next) == 60 && offsetof(BandLoopArm, io) == 64 &&
                   offsetof(BandLoopArm, normals_offset) == 68 && offsetof(BandLoopArm, view_z) == 72 &&
                   offsetof(BandLoopArm, base_r) == 84 && offsetof(BandLoopArm, count_from) == 96 &&
                   offsetof(BandLoopArm, drawn) == 100 && offsetof(BandLoopArm, projected) == 104 &&
                   offsetof(BandLoopArm, head) == 108),
              "band loop layout: every offset the assembly uses (the first twelve words in register order)");
/// draw_band_v7m() hands a listed triangle back with this bit set when its set-up said generic.
constexpr uint32_t kGenericHandBack = 0x10000;
static_assert(sizeof(void*) != 4 || offsetof(KernelSetupIo, out) == offsetof(KernelSetupIo, area) + sizeof(int32_t), "io area and out: one strd");
}  // namespace detail

#if defined(HIDER_ARMV7M)
/// Draws the band from listed triangle t on (following d->next), resuming every carried set-up from d->cur
/// whose triangle comes before the next listed one; returns kNoTriangle when the list and the carried set-ups
/// are done, else a listed triangle it hands back (a vertex outside a clip plane, no free slot, a generic
/// set-up: with kGenericHandBack set), the carried ones before it resumed. Every listed triangle has a
/// non-zero area and is not culled (bin_triangles()). Registers: r4 the listed triangle, r5 d, r6 the next
/// carried triangle (0xFFFF: none), r7 the vertices, r8 the triangles, r9 d->next (the listed triangle's Tri
/// until its colour), r10 the area, r11 the slot's record; the slot words (cur, nxt, free_top, free_base, the
/// record size and pool) in the stack's copy of d's first twelve words (kBandLoopFrame: the copy, the row
/// loop's words, the stride, d). The loop comes back to its head through d->head: without the clip test when
/// d->projected. A run of resumes keeps its state in that copy (the listed triangle as the limit, cur, nxt
/// and free_top stored with one stm per record, each record's slot pushed onto nxt or free_top before its
/// rows), reloads it with one ldm after each record and draws each record's rows with
/// run_kernel_triangle_v7m()'s row loop (HIDER_V7M_ROWS) inline: every one is on the band's first row, and
/// one that continues ends on the band's last, so the depth row after it is the band's (the row loop's words
/// set once a call). A resume leaves the record's `row` as it was: nothing reads it again in this loop.
HIDER_NAKED inline uint32_t draw_band_v7m(uint32_t, detail::BandLoopArm*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "sub    sp, %[frame]\n\t"
        "mov    r4, r0\n\t"
        "mov    r5, r1\n\t"
        "str    r5, [sp, %[d_sp]]\n\t"
        "ldm    r5, {r0-r3, r6-r12, lr}\n\t"    // d's first twelve words, onto the stack
        "stm    sp, {r0-r3, r6-r12, lr}\n\t"    // (r7 y0, r8 cur_end, r10 record size, r11 pool, r12 y1)
        "ldr    r3, [r5, #48]\n\t"
        "sub    r12, r12, r7\n\t"               // the band's rows
        "mla    r12, r12, r3, lr\n\t"           // the depth row after its last
        "mov    r6, #-1\n\t"                    // no switch pending
        "strd   r6, r12, [sp, %[rows_sp4]]\n\t"
        "str    r3, [sp, %[stride_sp]]\n\t"
        "movw   r6, #0xFFFF\n\t"
        "cmp    r0, r8\n\t"                     // cur, cur_end
        "beq    1f\n\t"                         // nothing carried
        "ldrb   r0, [r0]\n\t"
        "mla    r0, r0, r10, r11\n\t"
        "ldrh   r6, [r0, %[tri]]\n"             // the next carried triangle
        "1:\n\t"
        "ldr    r8, [r5, #52]\n\t"
        "ldr    r7, [r5, #56]\n\t"
        "ldr    r9, [r5, #60]\n\t"
        "ldr    r0, [r5, #104]\n\t"             // the loop head: with the clip test unless every vertex
        "cbnz   r0, 25f\n\t"                    // is projected (a Thumb address: the loop comes back
        "movw   r0, #:lower16:(21f + 1)\n\t"    // through it with a load into pc)
        "movt   r0, #:upper16:(21f + 1)\n\t"
        "b      26f\n"
        "25:\n\t"
        "movw   r0, #:lower16:(24f + 1)\n\t"
        "movt   r0, #:upper16:(24f + 1)\n"
        "26:\n\t"
        "str    r0, [r5, #108]\n\t"
        "ldr    pc, [r5, #108]\n"
        "21:\n\t"
        "cmp    r4, r6\n\t"
        "bhs    50f\n\t"                        // the carried triangle first, or the list's end
        "add    r0, r4, r4, lsl #1\n\t"
        "add    r9, r8, r0, lsl #1\n\t"         // the triangle: tris + 6 t (r9 comes back from d)
        "ldrh   r0, [r9]\n\t"
        "ldrh   r1, [r9, #2]\n\t"
        "ldrh   r2, [r9, #4]\n\t"
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
        "b      90f\n"                          // within the reach of cbz
        "24:\n\t"                               // every vertex projected: no clip test
        "cmp    r4, r6\n\t"
        "bhs    50f\n\t"
        "add    r0, r4, r4, lsl #1\n\t"
        "add    r9, r8, r0, lsl #1\n\t"
        "ldrh   r0, [r9]\n\t"
        "ldrh   r1, [r9, #2]\n\t"
        "ldrh   r2, [r9, #4]\n\t"
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
        "ldrd   r3, r12, [sp, #8]\n\t"          // free_top, free_base
        "cmp    r3, r12\n\t"
        "beq    90f\n\t"                        // no free slot: back to C++ (the spare)
        "ldrb   r3, [r3, #-1]\n\t"              // the slot on top
        "ldrd   r11, r12, [sp, #32]\n\t"        // record size, pool
        "mla    r11, r3, r11, r12\n\t"          // its record: pool + s records
        // FaceShading::color565(), as in draw_flat_v7m: first, so that the set-up draws at once; the
        // vertices stay in r0 r1 r2, r9 (the triangle) lends itself and comes back from d.
        "ldr    r3, [r5, #68]\n\t"
        "add    r12, r9, r3\n\t"                // the triangle's normal
        HIDER_V7M_COLOR565_IN(r12, r9, r3, lr)
        "ldrd   r9, r3, [r5, #60]\n\t"          // d->next, d->io
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
        "ldr    pc, [r5, #108]\n"               // the loop head
        "3:\n\t"
        "ldrsh  r0, [r11, %[top]]\n\t"
        "ldrd   r1, r2, [r5, #96]\n\t"          // count_from, drawn
        "cmp    r0, r1\n\t"
        "itt    ge\n\t"
        "addge  r2, r2, #1\n\t"
        "strge  r2, [r5, #100]\n\t"             // drawn: its first row is in this band
        // A set-up without a row in the band is rare: it returns at once and the test below keeps the
        // slot free.
        "ldrsh  r0, [r11, %[row]]\n\t"
        "ldrsh  r1, [r11, %[end]]\n\t"
        "cmp    r0, r1\n\t"
        "bge    8b\n\t"                         // done in this band: the slot stays free
        "ldrd   r2, r0, [sp, #4]\n\t"           // nxt, free_top
        "ldrb   r1, [r0, #-1]!\n\t"             // the slot leaves the free stack
        "strb   r1, [r2], #1\n\t"               // for the next band
        "strd   r2, r0, [sp, #4]\n\t"
        "b      8b\n"
        "92:\n\t"
        "orr    r4, r4, #0x10000\n"             // kGenericHandBack: C++ draws it without another set-up
        "90:\n\t"
        "ldm    sp, {r0, r1, r2}\n\t"           // cur, nxt, free_top: back to d
        "stm    r5, {r0, r1, r2}\n\t"
        "mov    r0, r4\n\t"
        "add    sp, %[frame]\n\t"
        "pop    {r4-r11, pc}\n"

        "50:\n\t"                               // resume the carried set-ups before r4
        "movw   r0, #0xFFFF\n\t"
        "cmp    r6, r0\n\t"
        "beq    90b\n\t"                        // none left: r4 is the list's end
        "str    r4, [sp, #16]\n\t"
        "ldm    sp, {r0-r10, lr}\n"             // as at the end of a resume
        "61:\n\t"                               // r0..r10 and lr the copy's words (BandLoopArm)
        "ldrb   r11, [r0], #1\n\t"              // the slot
        "mla    r12, r11, r8, r9\n\t"           // its record: pool + s records
        "ldrh   r6, [r12, %[tri]]\n\t"
        "cmp    r6, r4\n\t"
        "bhs    66f\n\t"                        // after the listed triangle: stop (the copy's cur is its slot)
        "ldrsh  r3, [r12, %[end]]\n\t"
        "ldrsh  r8, [r12, %[mid]]\n\t"
        "cmp    r3, r10\n\t"
        "itte   gt\n\t"
        "movgt  r3, r10\n\t"                    // stop = min(end, y1)
        "strbgt r11, [r1], #1\n\t"              // rows remain: the slot goes to the next band's
        "strble r11, [r2], #1\n\t"              // done: back to the free slots
        "stm    sp, {r0, r1, r2}\n\t"           // cur, nxt, free_top
        "sub    r6, r3, r5\n\t"                 // n rows (a carried set-up has some left)
        "subs   r1, r8, r5\n\t"                 // m = mid - y0
        "ble    62f\n\t"                        // on or below the middle row
        "ldrsh  r2, [r12, %[end]]\n\t"
        "cmp    r8, r2\n\t"
        "bge    62f\n\t"                        // no lower short edge
        "cmp    r1, r6\n\t"
        "bgt    62f\n\t"                        // the middle row lies past this band
        "sub    r2, r6, r1\n\t"                 // rows after the switch
        "mov    r6, r1\n\t"
        "ldr    r3, [sp, %[stride_sp]]\n\t"
        "mla    r1, r1, r3, lr\n\t"             // the middle row's depth row
        "strd   r1, r2, [sp, %[rows_sp]]\n"
        "62:\n\t"
        "add    r0, r12, %[ra]\n\t"
        "ldm    r12, {r1-r5}\n\t"               // lx lg lz rx rg
        "ldrd   r8, r10, [r12, %[dzdx]]\n\t"    // dzdx, colour
        "add    r1, r1, lr\n\t"                 // lp
        "add    r4, r4, lr\n"                   // rp
        HIDER_V7M_ROWS
        "ldm    sp, {r0-r10, lr}\n\t"
        "cmp    r0, r6\n\t"                     // cur, cur_end
        "bne    61b\n\t"
        "movw   r6, #0xFFFF\n"                  // all resumed
        "66:\n\t"                               // r6 the next carried triangle, r4 the listed one
        "ldr    r5, [sp, %[d_sp]]\n\t"
        "ldr    r8, [r5, #52]\n\t"
        "ldr    r7, [r5, #56]\n\t"
        "ldr    r9, [r5, #60]\n\t"
        "ldr    pc, [r5, #108]\n"
        :
        : [draw] "i"(kernel_draw_v7m), HIDER_V7M_ROWS_STACK(detail::kBandLoopRows), [frame] "i"(detail::kBandLoopFrame),
          [d_sp] "i"(detail::kBandLoopD), [stride_sp] "i"(detail::kBandLoopStride),
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

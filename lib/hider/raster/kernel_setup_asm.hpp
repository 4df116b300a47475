// kernel_setup_portable() (kernel_triangle.hpp) in Thumb-2 for ARMv7-M. At -Os GCC keeps about a
// hundred bytes of the set-up on the stack (three vertices, the sorted ones, the plane, three walkers);
// here the sorted vertices, the plane and the walkers each live in registers while they are used, and
// move between phases with one load- or store-multiple. Same results as the portable set-up, field for
// field: firmware/kernelcheck compares them on random triangles. Also defines kernel_setup(), which picks
// the set-up for the target; kernel_triangle.hpp includes this header at its end.
#pragma once
#include <hider/raster/kernel_triangle.hpp>

namespace hider {

namespace detail {
/// floor(hi:lo / d) for a quotient below 2^32: the set-up's slow path for areas above 0xFFFF.
extern "C" __attribute__((used, noinline)) inline uint32_t hider_kernel_udiv64(uint32_t lo, uint32_t hi, uint32_t d) {
    uint32_t rem = 0;
    return udiv64_32((uint64_t{hi} << 32) | lo, d, rem);
}
}  // namespace detail

// The kernel record's offsets the Thumb-1 and RV32 set-ups write as numbers (an asm statement takes
// at most 30 operands).
static_assert(sizeof(void*) != 4 || (offsetof(KernelTriangle, top) == 56 && offsetof(KernelTriangle, row) == 58 &&
                  offsetof(KernelTriangle, mid) == 60 && offsetof(KernelTriangle, end) == 62 &&
                  offsetof(RowKernel, lx) == 0 && offsetof(RowKernel, lg) == 4 && offsetof(RowKernel, lz) == 8 &&
                  offsetof(RowKernel, rx) == 12 && offsetof(RowKernel, rg) == 16 && offsetof(RowKernel, la) == 20 &&
                  offsetof(RowKernel, lm) == 24 && offsetof(RowKernel, lstep) == 28 && offsetof(RowKernel, ldz) == 32 &&
                  offsetof(RowKernel, ra) == 36 && offsetof(RowKernel, rm) == 40 && offsetof(RowKernel, rstep) == 44 &&
                  offsetof(RowKernel, dzdx) == 48 && offsetof(KernelTriangle, next_x) == 64 &&
                  offsetof(KernelTriangle, next_g) == 68 && offsetof(KernelTriangle, next_a) == 72 &&
                  offsetof(KernelTriangle, next_m) == 76 && offsetof(KernelTriangle, next_step) == 80 &&
                  offsetof(KernelTriangle, next_z) == 84 && offsetof(KernelTriangle, next_dz) == 88 &&
                  offsetof(KernelTriangle, next_left) == 94),
              "kernel record layout (the Thumb-1 and RV32 set-ups)");

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
/// Returns the KernelSetup value. Stack while the plane is computed: sorted vertices and rows (10 words)
/// above v0 v1 v2 |area| (4 words); during the walkers the plane (5 words) below them. The walker is a
/// local subroutine (label 80): in r5 xu, r7 yu, r8 xl, r9 yl, r3 row, r10 x_origin, r11 y_origin;
/// out r0 px, r1 g - a, r2 a, r3 m, r12 q; the edge stores (84 left, 86 right) turn px and q into the
/// kernel's bytes (2 px, 2 q + stride).
__attribute__((naked, noinline)) inline uint32_t kernel_setup_v7m(const ScreenVertex*, const ScreenVertex*,
                                                                  const ScreenVertex*, KernelSetupIo*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        // Rounded quotient of the signed 64-bit \hi:\lo by d = r9 into \lo (|q| < 2^31, else generic);
        // scratch r1 r2 r11 r12. Small divisors: two 16-bit digits, one udiv each.
        ".macro hider_divr lo, hi\n\t"
        "asr    r11, \\hi, #31\n\t"
        "eor    \\lo, \\lo, r11\n\t"
        "eor    \\hi, \\hi, r11\n\t"
        "subs   \\lo, \\lo, r11\n\t"
        "sbc    \\hi, \\hi, r11\n\t"          // |n|
        "adds   \\lo, \\lo, r9, lsr #1\n\t"
        "adc    \\hi, \\hi, #0\n\t"           // m = |n| + d / 2
        "lsl    r1, \\hi, #1\n\t"
        "orr    r1, r1, \\lo, lsr #31\n\t"
        "cmp    r1, r9\n\t"
        "bhs    93f\n\t"                      // m / d >= 2^31
        "cmp    r9, #0x10000\n\t"
        "bhs    7f\n\t"
        "lsl    r1, \\hi, #16\n\t"
        "orr    r1, r1, \\lo, lsr #16\n\t"    // m >> 16, below d 2^16
        "udiv   r2, r1, r9\n\t"
        "mls    r1, r2, r9, r1\n\t"
        "lsl    r1, r1, #16\n\t"
        "bfi    r1, \\lo, #0, #16\n\t"
        "udiv   r1, r1, r9\n\t"
        "add    r2, r1, r2, lsl #16\n\t"
        "b      8f\n"
        "7:\n\t"
        "push   {r0, r3, lr}\n\t"
        "mov    r0, \\lo\n\t"
        "mov    r1, \\hi\n\t"
        "mov    r2, r9\n\t"
        "bl     hider_kernel_udiv64\n\t"
        "mov    r2, r0\n\t"
        "pop    {r0, r3, lr}\n"
        "8:\n\t"
        "eor    \\lo, r2, r11\n\t"
        "sub    \\lo, \\lo, r11\n\t"
        ".endm\n\t"
        "push   {r4-r11, lr}\n\t"
        "ldm    r3, {r4, r5, r6}\n\t"         // band, area, out
        "cmp    r5, #0\n\t"
        "itttt  lt\n\t"                       // clockwise on the image: a, c, b
        "movlt  r7, r1\n\t"
        "movlt  r1, r2\n\t"
        "movlt  r2, r7\n\t"
        "neglt  r5, r5\n\t"
        "push   {r0, r1, r2, r5}\n\t"
        "ldrsh  r7, [r0]\n\t"                 // r7 r8: top, r9 r10: mid, r11 r12: bottom
        "ldrsh  r8, [r0, #2]\n\t"
        "ldrsh  r9, [r1]\n\t"
        "ldrsh  r10, [r1, #2]\n\t"
        "ldrsh  r11, [r2]\n\t"
        "ldrsh  r12, [r2, #2]\n\t"
        "movs   r3, #0\n\t"                   // 1: odd permutation, the long edge on the right
        "cmp    r10, r8\n\t"
        "bge    1f\n\t"
        "mov    r0, r7\n\t" "mov r7, r9\n\t" "mov r9, r0\n\t"
        "mov    r0, r8\n\t" "mov r8, r10\n\t" "mov r10, r0\n\t"
        "eor    r3, r3, #1\n"
        "1:\n\t"
        "cmp    r12, r10\n\t"
        "bge    2f\n\t"
        "mov    r0, r9\n\t" "mov r9, r11\n\t" "mov r11, r0\n\t"
        "mov    r0, r10\n\t" "mov r10, r12\n\t" "mov r12, r0\n\t"
        "eor    r3, r3, #1\n"
        "2:\n\t"
        "cmp    r10, r8\n\t"
        "bge    3f\n\t"
        "mov    r0, r7\n\t" "mov r7, r9\n\t" "mov r9, r0\n\t"
        "mov    r0, r8\n\t" "mov r8, r10\n\t" "mov r10, r0\n\t"
        "eor    r3, r3, #1\n"
        "3:\n\t"
        "cmp    r7, r9\n\t"                   // r0 = x_min, r1 = x_max
        "ite    lt\n\t"
        "movlt  r0, r7\n\t"
        "movge  r0, r9\n\t"
        "cmp    r11, r0\n\t"
        "it     lt\n\t"
        "movlt  r0, r11\n\t"
        "cmp    r7, r9\n\t"
        "ite    gt\n\t"
        "movgt  r1, r7\n\t"
        "movle  r1, r9\n\t"
        "cmp    r11, r1\n\t"
        "it     gt\n\t"
        "movgt  r1, r11\n\t"
        "ldrd   r2, r5, [r4, %[y_first]]\n\t"
        "cmp    r12, r2\n\t"
        "blt    90f\n\t"                      // below the band's first centre: none
        "cmp    r8, r5\n\t"
        "bgt    90f\n\t"                      // above its last: none
        "ldrd   r2, r5, [r4]\n\t"             // x_origin, y_origin
        "ldr    lr, [r4, %[x_last]]\n\t"
        "cmp    r0, r2\n\t"
        "blt    92f\n\t"                      // past the columns: generic
        "cmp    r1, lr\n\t"
        "bgt    92f\n\t"
        "sub    r0, r0, r2\n\t"
        "add    r0, r0, #15\n\t"
        "bic    r0, r0, #15\n\t"
        "add    r0, r0, r2\n\t"
        "cmp    r0, r1\n\t"
        "bgt    90f\n\t"                      // no column centre in the box: none
        "sub    r0, r8, r5\n\t"
        "add    r0, r0, #15\n\t"
        "bic    r1, r0, #15\n\t"
        "add    r1, r1, r5\n\t"
        "cmp    r1, r12\n\t"
        "bgt    90f\n\t"                      // no row centre in the box: none
        "asr    r0, r0, #4\n\t"               // top row
        "sub    r1, r10, r5\n\t"
        "add    r1, r1, #15\n\t"
        "asr    r1, r1, #4\n\t"               // middle row
        "sub    r2, r12, r5\n\t"
        "add    r2, r2, #15\n\t"
        "asr    r2, r2, #4\n\t"               // bottom row
        "ldrd   r5, lr, [r4, %[row_from]]\n\t"
        "cmp    r0, r5\n\t"
        "it     gt\n\t"
        "movgt  r5, r0\n\t"                   // y0 = max(top, row_from)
        "cmp    r2, lr\n\t"
        "it     lt\n\t"
        "movlt  lr, r2\n\t"                   // y1 = min(bottom, row_end)
        "strh   r0, [r6, %[top]]\n\t"
        "strh   r5, [r6, %[row]]\n\t"
        "strh   r1, [r6, %[mid]]\n\t"
        "strh   lr, [r6, %[end]]\n\t"
        "cmp    r5, lr\n\t"
        "bge    91f\n\t"                      // no row: set up, nothing to draw
        "push   {r1, r3, r5, r7-r12, lr}\n\t" // mid odd y0 xt yt xm ym xb yb y1
        // The plane (plane.hpp): numerators from three long multiplies each, then two rounded quotients.
        "add    r0, sp, #40\n\t"
        "ldm    r0, {r0, r1, r2, r9}\n\t"     // v0 v1 v2 area
        "ldr    r8, [r0, #4]\n\t"
        "ldrsh  r5, [r0]\n\t"                 // x0
        "ldrsh  r7, [r0, #2]\n\t"             // y0
        "ldrsh  r10, [r1, #2]\n\t"
        "ldr    r11, [r1, #4]\n\t"
        "ldrsh  r1, [r1]\n\t"
        "ldrsh  r12, [r2]\n\t"
        "ldrsh  lr, [r2, #2]\n\t"
        "ldr    r2, [r2, #4]\n\t"
        "sub    r1, r1, r5\n\t"               // dx1
        "sub    r10, r10, r7\n\t"             // dy1
        "sub    r12, r12, r5\n\t"             // dx2
        "sub    lr, lr, r7\n\t"               // dy2
        "eor    r8, r8, #0x80000000\n\t"      // s = z - 2^31
        "eor    r11, r11, #0x80000000\n\t"
        "eor    r2, r2, #0x80000000\n\t"
        "sub    r3, r10, lr\n\t"              // npx / 16 = s0 (dy1 - dy2) + s1 dy2 - s2 dy1
        "smull  r0, r3, r8, r3\n\t"
        "smlal  r0, r3, r11, lr\n\t"
        "neg    r10, r10\n\t"
        "smlal  r0, r3, r2, r10\n\t"
        "sub    lr, r12, r1\n\t"              // nqy / 16 = s0 (dx2 - dx1) + s2 dx1 - s1 dx2
        "smull  r10, lr, r8, lr\n\t"
        "smlal  r10, lr, r2, r1\n\t"
        "neg    r12, r12\n\t"
        "smlal  r10, lr, r11, r12\n\t"
        "lsl    r3, r3, #4\n\t"
        "orr    r3, r3, r0, lsr #28\n\t"
        "lsl    r0, r0, #4\n\t"
        "lsl    lr, lr, #4\n\t"
        "orr    lr, lr, r10, lsr #28\n\t"
        "lsl    r10, r10, #4\n\t"
        "hider_divr r0, r3\n\t"               // dzdx
        "hider_divr r10, lr\n\t"              // dzdy
        "ldrd   r1, r2, [r4]\n\t"             // reference pixel: the cell holding v0
        "sub    r5, r5, r1\n\t"
        "add    r3, r5, #8\n\t"
        "bic    r3, r3, #15\n\t"
        "sub    r5, r3, r5\n\t"               // ox
        "asr    r3, r3, #4\n\t"               // ref_px
        "sub    r7, r7, r2\n\t"
        "add    r12, r7, #8\n\t"
        "bic    r12, r12, #15\n\t"
        "sub    r7, r12, r7\n\t"              // oy
        "asr    r12, r12, #4\n\t"             // ref_py
        "smull  r1, r2, r0, r5\n\t"           // z_ref = z0 + round((dzdx ox + dzdy oy) / 16)
        "smlal  r1, r2, r10, r7\n\t"
        "asr    r11, r2, #31\n\t"
        "adds   r1, r1, #8\n\t"
        "adc    r2, r2, #0\n\t"
        "adds   r1, r1, r11\n\t"
        "adc    r2, r2, r11\n\t"
        "lsr    r1, r1, #4\n\t"
        "orr    r1, r1, r2, lsl #28\n\t"
        "eor    r8, r8, #0x80000000\n\t"
        "add    r8, r8, r1\n\t"
        "str    r0, [r6, %[dzdx]]\n\t"
        "push   {r0, r3, r8, r10, r12}\n\t"   // dzdx ref_px z_ref dzdy ref_py; the rows at sp + 20
        "ldrd   r10, r11, [r4]\n\t"           // x_origin, y_origin for the walkers
        // The long edge (top -> bottom) on row y0: the left edge for an even permutation.
        "ldrd   r5, r7, [sp, #32]\n\t"        // xt yt
        "ldrd   r8, r9, [sp, #48]\n\t"        // xb yb
        "ldr    r3, [sp, #28]\n\t"            // y0
        "bl     80f\n\t"
        "ldr    lr, [sp, #24]\n\t"
        "cmp    lr, #0\n\t"
        "bne    10f\n\t"
        "ldr    r9, [sp, #28]\n\t"
        "bl     84f\n\t"                      // left, with its depth
        "b      11f\n"
        "10:\n\t"
        "bl     86f\n"                        // right
        "11:\n\t"
        // The short edge on row y0: top -> mid above the middle row, mid -> bottom from it on.
        "ldrd   r3, r1, [sp, #20]\n\t"        // mid, odd
        "ldr    r2, [sp, #28]\n\t"            // y0
        "cmp    r2, r3\n\t"
        "bge    12f\n\t"
        "ldrd   r5, r7, [sp, #32]\n\t"        // xt yt
        "ldrd   r8, r9, [sp, #40]\n\t"        // xm ym
        "b      13f\n"
        "12:\n\t"
        "ldrd   r5, r7, [sp, #40]\n\t"        // xm ym
        "ldrd   r8, r9, [sp, #48]\n\t"        // xb yb
        "13:\n\t"
        "mov    r3, r2\n\t"
        "bl     80f\n\t"
        "ldr    lr, [sp, #24]\n\t"
        "cmp    lr, #0\n\t"
        "beq    14f\n\t"
        "ldr    r9, [sp, #28]\n\t"
        "bl     84f\n\t"                      // left
        "b      15f\n"
        "14:\n\t"
        "bl     86f\n"                        // right
        "15:\n\t"
        // The lower short edge from the middle row, when it starts inside [y0, y1).
        "ldr    r1, [sp, #24]\n\t"
        "strb   r1, [r6, %[next_left]]\n\t"
        "ldrd   r3, r1, [sp, #20]\n\t"        // mid (odd unused)
        "ldr    r2, [sp, #28]\n\t"            // y0
        "cmp    r2, r3\n\t"
        "bge    16f\n\t"                      // y0 >= mid: no upper part
        "ldr    r2, [sp, #56]\n\t"            // y1
        "cmp    r3, r2\n\t"
        "bge    16f\n\t"                      // mid >= y1: the lower edge never runs
        "ldrd   r5, r7, [sp, #40]\n\t"        // xm ym
        "ldrd   r8, r9, [sp, #48]\n\t"        // xb yb
        "bl     80f\n\t"
        "lsl    r8, r0, #1\n\t"
        "strd   r8, r1, [r6, %[next_x]]\n\t"
        "ldr    r8, [r4, %[stride]]\n\t"
        "add    r8, r8, r12, lsl #1\n\t"      // step = 2 q + stride
        "add    lr, r6, %[next_a]\n\t"
        "stm    lr, {r2, r3, r8}\n\t"
        "ldr    lr, [sp, #24]\n\t"
        "cmp    lr, #0\n\t"
        "beq    16f\n\t"
        "ldm    sp, {r1, r2, r3, r5, r7}\n\t" // the next left edge's depth and depth step
        "sub    r0, r0, r2\n\t"
        "mla    r3, r1, r0, r3\n\t"
        "ldr    r2, [sp, #20]\n\t"            // mid
        "sub    r2, r2, r7\n\t"
        "mla    r3, r5, r2, r3\n\t"
        "mla    r5, r1, r12, r5\n\t"
        "strd   r3, r5, [r6, %[next_z]]\n"
        "16:\n\t"
        "movs   r0, #1\n\t"                   // kernel
        "add    sp, sp, #76\n\t"
        "pop    {r4-r11, pc}\n"
        "90:\n\t"
        "movs   r0, #0\n\t"                   // none
        "add    sp, sp, #16\n\t"
        "pop    {r4-r11, pc}\n"
        "91:\n\t"
        "movs   r0, #1\n\t"                   // kernel, no rows
        "add    sp, sp, #16\n\t"
        "pop    {r4-r11, pc}\n"
        "92:\n\t"
        "movs   r0, #2\n\t"                   // generic
        "add    sp, sp, #16\n\t"
        "pop    {r4-r11, pc}\n"
        "93:\n\t"
        "movs   r0, #2\n\t"                   // generic: a depth step of 2^31 or more
        "add    sp, sp, #56\n\t"
        "pop    {r4-r11, pc}\n"
        // Walker (edge.hpp): in r5 xu, r7 yu, r8 xl, r9 yl, r3 row; out r0 px, r1 g - a, r2 a, r3 m, r12 q.
        "80:\n\t"
        "sub    r8, r8, r5\n\t"               // dx
        "sub    r9, r9, r7\n\t"               // dy
        "lsl    r2, r9, #4\n\t"               // a = 16 dy
        "add    r12, r11, r3, lsl #4\n\t"     // row centre
        "sub    r12, r12, r7\n\t"
        "sub    r0, r10, r5\n\t"
        "mul    r0, r9, r0\n\t"
        "mls    r3, r8, r12, r0\n\t"          // g0 = dy (x_origin - xu) - dx (yc - yu)
        "cmp    r3, #0\n\t"
        "blt    81f\n\t"
        "udiv   r0, r3, r2\n\t"               // px = -floor(g0 / a)
        "neg    r0, r0\n\t"
        "b      82f\n"
        "81:\n\t"
        "mvn    r0, r3\n\t"
        "udiv   r0, r0, r2\n\t"
        "add    r0, r0, #1\n"
        "82:\n\t"
        "mla    r1, r0, r2, r3\n\t"           // g = g0 + px a
        "sub    r1, r1, r2\n\t"               // biased by -a
        "lsl    r3, r8, #4\n\t"
        "neg    r3, r3\n\t"                   // dg = -16 dx
        "cmp    r3, #0\n\t"
        "blt    83f\n\t"
        "cmp    r3, r2\n\t"
        "bge    88f\n\t"
        "movs   r12, #0\n\t"                  // 0 <= dg < a: q = 0, m = dg
        "bx     lr\n"
        "83:\n\t"
        "cmn    r3, r2\n\t"
        "blt    89f\n\t"
        "movs   r12, #1\n\t"                  // -a <= dg < 0: q = 1, m = dg + a
        "add    r3, r3, r2\n\t"
        "bx     lr\n"
        "88:\n\t"
        "udiv   r12, r3, r2\n\t"              // dg >= a: q = -floor(dg / a)
        "neg    r12, r12\n\t"
        "mla    r3, r12, r2, r3\n\t"
        "bx     lr\n"
        "89:\n\t"
        "mvn    r12, r3\n\t"                  // dg < -a
        "udiv   r12, r12, r2\n\t"
        "add    r12, r12, #1\n\t"
        "mla    r3, r12, r2, r3\n\t"
        "bx     lr\n"
        // Left edge store: r0 px, r1 g - a, r2 a, r3 m, r12 q, r9 its row; depth from the plane at sp.
        "84:\n\t"
        "lsl    r8, r0, #1\n\t"
        "strd   r8, r1, [r6, %[lx]]\n\t"
        "ldr    r8, [r4, %[stride]]\n\t"
        "add    r8, r8, r12, lsl #1\n\t"
        "add    r1, r6, %[la]\n\t"
        "stm    r1, {r2, r3, r8}\n\t"
        "ldm    sp, {r1, r2, r3, r5, r7}\n\t"  // dzdx ref_px z_ref dzdy ref_py
        "sub    r0, r0, r2\n\t"
        "mla    r3, r1, r0, r3\n\t"
        "sub    r9, r9, r7\n\t"
        "mla    r3, r5, r9, r3\n\t"
        "mla    r5, r1, r12, r5\n\t"
        "str    r3, [r6, %[lz]]\n\t"
        "str    r5, [r6, %[ldz]]\n\t"
        "bx     lr\n"
        // Right edge store.
        "86:\n\t"
        "lsl    r8, r0, #1\n\t"
        "strd   r8, r1, [r6, %[rx]]\n\t"
        "ldr    r8, [r4, %[stride]]\n\t"
        "add    r8, r8, r12, lsl #1\n\t"
        "add    r1, r6, %[ra]\n\t"
        "stm    r1, {r2, r3, r8}\n\t"
        "bx     lr\n"
        ".purgem hider_divr\n"
        :
        : [y_first] "i"(offsetof(KernelBand, y_first)), [x_last] "i"(offsetof(KernelBand, x_last)),
          [row_from] "i"(offsetof(KernelBand, row_from)), [stride] "i"(offsetof(KernelBand, stride_bytes)),
          [top] "i"(offsetof(KernelTriangle, top)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)),
          [lx] "i"(offsetof(RowKernel, lx)), [lz] "i"(offsetof(RowKernel, lz)), [la] "i"(offsetof(RowKernel, la)),
          [ldz] "i"(offsetof(RowKernel, ldz)), [rx] "i"(offsetof(RowKernel, rx)), [ra] "i"(offsetof(RowKernel, ra)),
          [next_x] "i"(offsetof(KernelTriangle, next_x)), [next_a] "i"(offsetof(KernelTriangle, next_a)),
          [next_z] "i"(offsetof(KernelTriangle, next_z)), [next_left] "i"(offsetof(KernelTriangle, next_left)));
}
#elif defined(__ARM_ARCH_6M__)
/// Thumb-1 (no long multiply, no divide, eight low registers): the same set-up with its state in a
/// 184-byte frame. Depth products by balanced 16-bit halves of s = z - 2^31 (the three differences sum
/// to zero, so each half's sum stays in 32 bits); the two plane quotients by one estimate of
/// 2^48 / (area normalised) (reciprocal_word()'s table and Newton step) in two 16-bit digits, each
/// corrected against its exact remainder; the walkers' floor divisions through __aeabi_uidivmod.
/// Subroutines: 40 walker (r0, r1 the upper and lower vertex as packed x | y << 16, r2 the row; results
/// in the frame), 44/46/48 the left, right and next edge stores (r2 the row), 50 floor division
/// (r0 n, r1 a > 0 -> r0 floor(n / a), r1 the remainder), 59 the area's shift, normalised value and
/// estimate, 60 the rounded plane quotient (r1:r0 -> r0, or the generic exit).
__attribute__((naked, noinline)) inline uint32_t kernel_setup_v6m(const ScreenVertex*, const ScreenVertex*,
                                                                  const ScreenVertex*, KernelSetupIo*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        ".equ hks_v0, 0\n\t" ".equ hks_v1, 4\n\t" ".equ hks_v2, 8\n\t" ".equ hks_area, 12\n\t"
        ".equ hks_band, 16\n\t" ".equ hks_out, 20\n\t" ".equ hks_t, 24\n\t" ".equ hks_m, 28\n\t"
        ".equ hks_b, 32\n\t" ".equ hks_odd, 36\n\t" ".equ hks_mid, 40\n\t" ".equ hks_y0, 44\n\t"
        ".equ hks_y1, 48\n\t" ".equ hks_dzdx, 52\n\t" ".equ hks_refpx, 56\n\t" ".equ hks_zref, 60\n\t"
        ".equ hks_dzdy, 64\n\t" ".equ hks_refpy, 68\n\t" ".equ hks_s, 72\n\t" ".equ hks_dn, 76\n\t"
        ".equ hks_r, 80\n\t" ".equ hks_px, 84\n\t" ".equ hks_g, 88\n\t" ".equ hks_a, 92\n\t"
        ".equ hks_mm, 96\n\t" ".equ hks_q, 100\n\t" ".equ hks_x0, 104\n\t" ".equ hks_yv0, 108\n\t"
        ".equ hks_z0, 112\n\t" ".equ hks_d, 116\n\t" ".equ hks_e, 128\n\t" ".equ hks_sh, 140\n\t"
        ".equ hks_sign, 164\n\t" ".equ hks_dx, 168\n\t" ".equ hks_wlr, 172\n\t"
        ".equ hks_flr, 176\n\t" ".equ hks_fa, 180\n\t"
        "push   {r4-r7, lr}\n\t"
        "sub    sp, #184\n\t"
        "ldm    r3!, {r4, r5, r6}\n\t"        // band, area, out
        "cmp    r5, #0\n\t"
        "bge    1f\n\t"
        "movs   r7, r1\n\t"                   // clockwise on the image: a, c, b
        "movs   r1, r2\n\t"
        "movs   r2, r7\n\t"
        "negs   r5, r5\n"
        "1:\n\t"
        "str    r0, [sp, #hks_v0]\n\t"
        "str    r1, [sp, #hks_v1]\n\t"
        "str    r2, [sp, #hks_v2]\n\t"
        "str    r5, [sp, #hks_area]\n\t"
        "str    r4, [sp, #hks_band]\n\t"
        "str    r6, [sp, #hks_out]\n\t"
        "ldr    r0, [r0]\n\t"                 // x | y << 16 of each
        "ldr    r1, [r1]\n\t"
        "ldr    r2, [r2]\n\t"
        "movs   r3, #0\n\t"                   // 1: odd permutation, the long edge on the right
        "movs   r6, #1\n\t"
        "asrs   r4, r1, #16\n\t"
        "asrs   r5, r0, #16\n\t"
        "cmp    r4, r5\n\t"
        "bge    1f\n\t"
        "movs   r7, r0\n\t" "movs r0, r1\n\t" "movs r1, r7\n\t" "eors r3, r6\n"
        "1:\n\t"
        "asrs   r4, r2, #16\n\t"
        "asrs   r5, r1, #16\n\t"
        "cmp    r4, r5\n\t"
        "bge    1f\n\t"
        "movs   r7, r1\n\t" "movs r1, r2\n\t" "movs r2, r7\n\t" "eors r3, r6\n"
        "1:\n\t"
        "asrs   r4, r1, #16\n\t"
        "asrs   r5, r0, #16\n\t"
        "cmp    r4, r5\n\t"
        "bge    1f\n\t"
        "movs   r7, r0\n\t" "movs r0, r1\n\t" "movs r1, r7\n\t" "eors r3, r6\n"
        "1:\n\t"
        "str    r3, [sp, #hks_odd]\n\t"
        "str    r0, [sp, #hks_t]\n\t"         // top, middle, bottom
        "str    r1, [sp, #hks_m]\n\t"
        "str    r2, [sp, #hks_b]\n\t"
        "ldr    r4, [sp, #hks_band]\n\t"
        "asrs   r5, r2, #16\n\t"
        "ldr    r7, [r4, %[y_first]]\n\t"
        "cmp    r5, r7\n\t"
        "bge    1f\n\t"
        "b      90f\n"                        // below the band's first centre: none
        "1:\n\t"
        "asrs   r5, r0, #16\n\t"
        "ldr    r7, [r4, %[y_last]]\n\t"
        "cmp    r5, r7\n\t"
        "ble    1f\n\t"
        "b      90f\n"                        // above its last: none
        "1:\n\t"
        "sxth   r0, r0\n\t"
        "sxth   r1, r1\n\t"
        "sxth   r2, r2\n\t"
        "movs   r3, r0\n\t"                   // r3 = x_min, r5 = x_max
        "movs   r5, r0\n\t"
        "cmp    r1, r3\n\t" "bge 1f\n\t" "movs r3, r1\n" "1:\n\t"
        "cmp    r1, r5\n\t" "ble 1f\n\t" "movs r5, r1\n" "1:\n\t"
        "cmp    r2, r3\n\t" "bge 1f\n\t" "movs r3, r2\n" "1:\n\t"
        "cmp    r2, r5\n\t" "ble 1f\n\t" "movs r5, r2\n" "1:\n\t"
        "ldr    r7, [r4, #0]\n\t"             // x_origin
        "cmp    r3, r7\n\t"
        "bge    1f\n\t"
        "b      92f\n"                        // past the columns: generic
        "1:\n\t"
        "ldr    r6, [r4, %[x_last]]\n\t"
        "cmp    r5, r6\n\t"
        "ble    1f\n\t"
        "b      92f\n"
        "1:\n\t"
        "subs   r3, r3, r7\n\t"
        "adds   r3, #15\n\t"
        "asrs   r3, r3, #4\n\t"
        "lsls   r3, r3, #4\n\t"
        "adds   r3, r3, r7\n\t"
        "cmp    r3, r5\n\t"
        "ble    1f\n\t"
        "b      90f\n"                        // no column centre in the box: none
        "1:\n\t"
        "ldr    r7, [r4, #4]\n\t"             // y_origin
        "ldr    r0, [sp, #hks_t]\n\t"
        "asrs   r0, r0, #16\n\t"
        "subs   r0, r0, r7\n\t"
        "adds   r0, #15\n\t"
        "asrs   r0, r0, #4\n\t"               // top row
        "lsls   r3, r0, #4\n\t"
        "adds   r3, r3, r7\n\t"
        "ldr    r2, [sp, #hks_b]\n\t"
        "asrs   r2, r2, #16\n\t"
        "cmp    r3, r2\n\t"
        "ble    1f\n\t"
        "b      90f\n"                        // no row centre in the box: none
        "1:\n\t"
        "subs   r2, r2, r7\n\t"
        "adds   r2, #15\n\t"
        "asrs   r2, r2, #4\n\t"               // bottom row
        "ldr    r1, [sp, #hks_m]\n\t"
        "asrs   r1, r1, #16\n\t"
        "subs   r1, r1, r7\n\t"
        "adds   r1, #15\n\t"
        "asrs   r1, r1, #4\n\t"               // middle row
        "ldr    r5, [r4, %[row_from]]\n\t"
        "cmp    r0, r5\n\t" "ble 1f\n\t" "movs r5, r0\n" "1:\n\t"   // y0 = max(top, row_from)
        "ldr    r3, [r4, %[row_end]]\n\t"
        "cmp    r2, r3\n\t" "bge 1f\n\t" "movs r3, r2\n" "1:\n\t"   // y1 = min(bottom, row_end)
        "ldr    r6, [sp, #hks_out]\n\t"
        "strh   r0, [r6, #56]\n\t"
        "strh   r5, [r6, #58]\n\t"
        "strh   r1, [r6, #60]\n\t"
        "strh   r3, [r6, #62]\n\t"
        "str    r1, [sp, #hks_mid]\n\t"
        "str    r5, [sp, #hks_y0]\n\t"
        "str    r3, [sp, #hks_y1]\n\t"
        "cmp    r5, r3\n\t"
        "blt    1f\n\t"
        "b      91f\n"                        // no row: set up, nothing to draw
        "1:\n\t"
        // The plane (plane.hpp) of (v0, v1, v2): npx / 16 = sum s_i (y_i+1 - y_i+2) and
        // nqy / 16 = sum s_i (x_i+2 - x_i+1) with s = z - 2^31 split into balanced halves.
        "bl     59f\n\t"
        "ldr    r0, [sp, #hks_v0]\n\t"
        "ldr    r1, [sp, #hks_v1]\n\t"
        "ldr    r2, [sp, #hks_v2]\n\t"
        "ldr    r3, [r0]\n\t"
        "ldr    r4, [r1]\n\t"
        "ldr    r5, [r2]\n\t"
        "asrs   r6, r4, #16\n\t" "asrs r7, r5, #16\n\t" "subs r6, r6, r7\n\t" "str r6, [sp, #(hks_d + 0)]\n\t"
        "asrs   r6, r5, #16\n\t" "asrs r7, r3, #16\n\t" "subs r6, r6, r7\n\t" "str r6, [sp, #(hks_d + 4)]\n\t"
        "asrs   r6, r3, #16\n\t" "asrs r7, r4, #16\n\t" "subs r6, r6, r7\n\t" "str r6, [sp, #(hks_d + 8)]\n\t"
        "sxth   r6, r5\n\t" "sxth r7, r4\n\t" "subs r6, r6, r7\n\t" "str r6, [sp, #(hks_e + 0)]\n\t"
        "sxth   r6, r3\n\t" "sxth r7, r5\n\t" "subs r6, r6, r7\n\t" "str r6, [sp, #(hks_e + 4)]\n\t"
        "sxth   r6, r4\n\t" "sxth r7, r3\n\t" "subs r6, r6, r7\n\t" "str r6, [sp, #(hks_e + 8)]\n\t"
        "sxth   r6, r3\n\t"
        "str    r6, [sp, #hks_x0]\n\t"
        "asrs   r6, r3, #16\n\t"
        "str    r6, [sp, #hks_yv0]\n\t"
        "ldr    r3, [r0, #4]\n\t"
        "str    r3, [sp, #hks_z0]\n\t"
        "ldr    r4, [r1, #4]\n\t"
        "ldr    r5, [r2, #4]\n\t"
        "movs   r7, #1\n\t"
        "lsls   r7, r7, #31\n\t"
        // s = z ^ 2^31; sh = round(s / 2^16) = ((s >> 15) + 1) >> 1, sl = s - sh 2^16 in [-2^15, 2^15)
        ".irp   reg, r3, r4, r5\n\t"
        "eors   \\reg, r7\n\t"
        ".endr\n\t"
        "asrs   r6, r3, #15\n\t" "adds r6, #1\n\t" "asrs r6, r6, #1\n\t" "lsls r0, r6, #16\n\t" "subs r3, r3, r0\n\t"
        "str    r6, [sp, #(hks_sh + 0)]\n\t" "str r3, [sp, #(hks_sh + 4)]\n\t"
        "asrs   r6, r4, #15\n\t" "adds r6, #1\n\t" "asrs r6, r6, #1\n\t" "lsls r0, r6, #16\n\t" "subs r4, r4, r0\n\t"
        "str    r6, [sp, #(hks_sh + 8)]\n\t" "str r4, [sp, #(hks_sh + 12)]\n\t"
        "asrs   r6, r5, #15\n\t" "adds r6, #1\n\t" "asrs r6, r6, #1\n\t" "lsls r0, r6, #16\n\t" "subs r5, r5, r0\n\t"
        "str    r6, [sp, #(hks_sh + 16)]\n\t" "str r5, [sp, #(hks_sh + 20)]\n\t"
        // One numerator: H = sum sh d, L = sum sl d (each within 32 bits), n = H 2^20 + 16 L in r1:r0.
        ".macro hks_numerator at\n\t"
        "ldr    r2, [sp, #(\\at + 0)]\n\t"
        "ldr    r0, [sp, #(hks_sh + 0)]\n\t" "muls r0, r2, r0\n\t"
        "ldr    r1, [sp, #(hks_sh + 4)]\n\t" "muls r1, r2, r1\n\t"
        "ldr    r2, [sp, #(\\at + 4)]\n\t"
        "ldr    r3, [sp, #(hks_sh + 8)]\n\t" "muls r3, r2, r3\n\t" "adds r0, r0, r3\n\t"
        "ldr    r3, [sp, #(hks_sh + 12)]\n\t" "muls r3, r2, r3\n\t" "adds r1, r1, r3\n\t"
        "ldr    r2, [sp, #(\\at + 8)]\n\t"
        "ldr    r3, [sp, #(hks_sh + 16)]\n\t" "muls r3, r2, r3\n\t" "adds r0, r0, r3\n\t"
        "ldr    r3, [sp, #(hks_sh + 20)]\n\t" "muls r3, r2, r3\n\t" "adds r1, r1, r3\n\t"
        "lsls   r2, r0, #20\n\t"
        "asrs   r3, r0, #12\n\t"
        "lsls   r0, r1, #4\n\t"
        "asrs   r1, r1, #28\n\t"
        "adds   r0, r0, r2\n\t"
        "adcs   r1, r3\n\t"
        ".endm\n\t"
        "hks_numerator hks_d\n\t"
        "bl     60f\n\t"                      // dzdx
        "str    r0, [sp, #hks_dzdx]\n\t"
        "ldr    r6, [sp, #hks_out]\n\t"
        "str    r0, [r6, #48]\n\t"
        "hks_numerator hks_e\n\t"
        "bl     60f\n\t"                      // dzdy
        "str    r0, [sp, #hks_dzdy]\n\t"
        ".purgem hks_numerator\n\t"
        // Reference pixel (the cell holding v0) and z_ref = z0 + round((dzdx ox + dzdy oy) / 16).
        "ldr    r4, [sp, #hks_band]\n\t"
        "ldr    r1, [r4, #0]\n\t"
        "ldr    r2, [sp, #hks_x0]\n\t"
        "subs   r3, r2, r1\n\t"
        "adds   r3, #8\n\t"
        "asrs   r3, r3, #4\n\t"
        "str    r3, [sp, #hks_refpx]\n\t"
        "lsls   r3, r3, #4\n\t"
        "adds   r3, r3, r1\n\t"
        "subs   r3, r3, r2\n\t"               // ox
        "ldr    r1, [r4, #4]\n\t"
        "ldr    r2, [sp, #hks_yv0]\n\t"
        "subs   r5, r2, r1\n\t"
        "adds   r5, #8\n\t"
        "asrs   r5, r5, #4\n\t"
        "str    r5, [sp, #hks_refpy]\n\t"
        "lsls   r5, r5, #4\n\t"
        "adds   r5, r5, r1\n\t"
        "subs   r5, r5, r2\n\t"               // oy
        "ldr    r0, [sp, #hks_dzdx]\n\t"
        "ldr    r1, [sp, #hks_dzdy]\n\t"
        "asrs   r2, r0, #16\n\t" "muls r2, r3, r2\n\t"
        "uxth   r0, r0\n\t" "muls r0, r3, r0\n\t"
        "asrs   r4, r1, #16\n\t" "muls r4, r5, r4\n\t"
        "uxth   r1, r1\n\t" "muls r1, r5, r1\n\t"
        "adds   r2, r2, r4\n\t"               // high halves' sum
        "adds   r0, r0, r1\n\t"               // low halves' sum
        "asrs   r1, r2, #16\n\t"
        "lsls   r2, r2, #16\n\t"
        "asrs   r4, r0, #31\n\t"
        "adds   r2, r2, r0\n\t"
        "adcs   r1, r4\n\t"                   // r1:r2 = S
        "asrs   r4, r1, #31\n\t"
        "eors   r2, r4\n\t"
        "eors   r1, r4\n\t"
        "subs   r2, r2, r4\n\t"
        "sbcs   r1, r4\n\t"                   // |S|
        "adds   r2, #8\n\t"
        "movs   r3, #0\n\t"
        "adcs   r1, r3\n\t"
        "lsrs   r2, r2, #4\n\t"
        "lsls   r1, r1, #28\n\t"
        "orrs   r2, r1\n\t"
        "eors   r2, r4\n\t"
        "subs   r2, r2, r4\n\t"               // div_round_pow2(S, 4), low word
        "ldr    r0, [sp, #hks_z0]\n\t"
        "adds   r0, r0, r2\n\t"
        "str    r0, [sp, #hks_zref]\n\t"
        // The long edge (top -> bottom) on row y0: the left edge for an even permutation.
        "ldr    r0, [sp, #hks_t]\n\t"
        "ldr    r1, [sp, #hks_b]\n\t"
        "ldr    r2, [sp, #hks_y0]\n\t"
        "bl     40f\n\t"
        "ldr    r2, [sp, #hks_y0]\n\t"
        "ldr    r0, [sp, #hks_odd]\n\t"
        "cmp    r0, #0\n\t"
        "bne    1f\n\t"
        "bl     44f\n\t"
        "b      2f\n"
        "1:\n\t"
        "bl     46f\n"
        "2:\n\t"
        // The short edge on row y0: top -> mid above the middle row, mid -> bottom from it on.
        "ldr    r2, [sp, #hks_y0]\n\t"
        "ldr    r3, [sp, #hks_mid]\n\t"
        "cmp    r2, r3\n\t"
        "bge    1f\n\t"
        "ldr    r0, [sp, #hks_t]\n\t"
        "ldr    r1, [sp, #hks_m]\n\t"
        "b      2f\n"
        "1:\n\t"
        "ldr    r0, [sp, #hks_m]\n\t"
        "ldr    r1, [sp, #hks_b]\n"
        "2:\n\t"
        "bl     40f\n\t"
        "ldr    r2, [sp, #hks_y0]\n\t"
        "ldr    r0, [sp, #hks_odd]\n\t"
        "cmp    r0, #0\n\t"
        "beq    1f\n\t"
        "bl     44f\n\t"
        "b      2f\n"
        "1:\n\t"
        "bl     46f\n"
        "2:\n\t"
        "ldr    r6, [sp, #hks_out]\n\t"
        "ldr    r0, [sp, #hks_odd]\n\t"
        "movs   r1, #94\n\t"
        "strb   r0, [r6, r1]\n\t"             // next_left: the short edges are on the left when odd
        // The lower short edge from the middle row, when it starts inside [y0, y1).
        "ldr    r2, [sp, #hks_y0]\n\t"
        "ldr    r3, [sp, #hks_mid]\n\t"
        "cmp    r2, r3\n\t"
        "bge    1f\n\t"
        "ldr    r2, [sp, #hks_y1]\n\t"
        "cmp    r3, r2\n\t"
        "bge    1f\n\t"
        "ldr    r0, [sp, #hks_m]\n\t"
        "ldr    r1, [sp, #hks_b]\n\t"
        "movs   r2, r3\n\t"
        "bl     40f\n\t"
        "ldr    r2, [sp, #hks_mid]\n\t"
        "bl     48f\n"
        "1:\n\t"
        "movs   r0, #1\n\t"                   // kernel
        "b      95f\n"
        "90:\n\t"
        "movs   r0, #0\n\t"                   // none
        "b      95f\n"
        "91:\n\t"
        "movs   r0, #1\n\t"                   // kernel, no rows
        "b      95f\n"
        "92:\n"                               // generic
        "93:\n\t"                             // generic: a depth step of 2^31 or more (from 60)
        "movs   r0, #2\n"
        "95:\n\t"
        "add    sp, #184\n\t"
        "pop    {r4-r7, pc}\n"
        // Walker (edge.hpp): r0 (xu, yu), r1 (xl, yl) packed, r2 row -> px g-a a m q in the frame.
        "40:\n\t"
        "mov    r3, lr\n\t"
        "str    r3, [sp, #hks_wlr]\n\t"
        "sxth   r4, r0\n\t"                   // xu
        "asrs   r5, r0, #16\n\t"              // yu
        "sxth   r6, r1\n\t"
        "asrs   r7, r1, #16\n\t"
        "subs   r6, r6, r4\n\t"               // dx
        "subs   r7, r7, r5\n\t"               // dy
        "lsls   r1, r7, #4\n\t"
        "str    r1, [sp, #hks_a]\n\t"         // a = 16 dy
        "ldr    r3, [sp, #hks_band]\n\t"
        "ldr    r0, [r3, #4]\n\t"
        "lsls   r2, r2, #4\n\t"
        "adds   r2, r2, r0\n\t"
        "subs   r2, r2, r5\n\t"               // yc - yu
        "ldr    r0, [r3, #0]\n\t"
        "subs   r0, r0, r4\n\t"
        "muls   r0, r7, r0\n\t"
        "muls   r2, r6, r2\n\t"
        "subs   r0, r0, r2\n\t"               // g0 = dy (x_origin - xu) - dx (yc - yu)
        "str    r6, [sp, #hks_dx]\n\t"
        "bl     50f\n\t"
        "negs   r0, r0\n\t"
        "str    r0, [sp, #hks_px]\n\t"        // px = -floor(g0 / a)
        "ldr    r2, [sp, #hks_a]\n\t"
        "subs   r1, r1, r2\n\t"
        "str    r1, [sp, #hks_g]\n\t"         // g = g0 + px a, biased by -a
        "ldr    r0, [sp, #hks_dx]\n\t"
        "lsls   r0, r0, #4\n\t"
        "negs   r0, r0\n\t"                   // dg = -16 dx
        "movs   r1, r2\n\t"
        "bl     50f\n\t"
        "negs   r0, r0\n\t"
        "str    r0, [sp, #hks_q]\n\t"         // q = -floor(dg / a)
        "str    r1, [sp, #hks_mm]\n\t"        // m = dg mod a
        "ldr    r3, [sp, #hks_wlr]\n\t"
        "bx     r3\n"
        // Left edge store (with its depth), r2 the edge's row.
        "44:\n\t"
        "ldr    r6, [sp, #hks_out]\n\t"
        "ldr    r4, [sp, #hks_band]\n\t"
        "ldr    r0, [sp, #hks_px]\n\t"
        "lsls   r1, r0, #1\n\t"
        "str    r1, [r6, #0]\n\t"
        "ldr    r1, [sp, #hks_g]\n\t"
        "str    r1, [r6, #4]\n\t"
        "ldr    r1, [sp, #hks_a]\n\t"
        "str    r1, [r6, #20]\n\t"
        "ldr    r1, [sp, #hks_mm]\n\t"
        "str    r1, [r6, #24]\n\t"
        "ldr    r3, [sp, #hks_q]\n\t"
        "lsls   r1, r3, #1\n\t"
        "ldr    r5, [r4, %[stride]]\n\t"
        "adds   r1, r1, r5\n\t"
        "str    r1, [r6, #28]\n\t"       // 2 q + stride
        "ldr    r5, [sp, #hks_refpx]\n\t"
        "subs   r0, r0, r5\n\t"
        "ldr    r5, [sp, #hks_dzdx]\n\t"
        "muls   r0, r5, r0\n\t"
        "ldr    r7, [sp, #hks_refpy]\n\t"
        "subs   r2, r2, r7\n\t"
        "ldr    r7, [sp, #hks_dzdy]\n\t"
        "muls   r2, r7, r2\n\t"
        "adds   r0, r0, r2\n\t"
        "ldr    r1, [sp, #hks_zref]\n\t"
        "adds   r0, r0, r1\n\t"
        "str    r0, [r6, #8]\n\t"          // plane.at(px, row)
        "muls   r3, r5, r3\n\t"
        "adds   r3, r3, r7\n\t"
        "str    r3, [r6, #32]\n\t"         // dzdy + dzdx q
        "bx     lr\n"
        // Right edge store.
        "46:\n\t"
        "ldr    r6, [sp, #hks_out]\n\t"
        "ldr    r4, [sp, #hks_band]\n\t"
        "ldr    r0, [sp, #hks_px]\n\t"
        "lsls   r1, r0, #1\n\t"
        "str    r1, [r6, #12]\n\t"
        "ldr    r1, [sp, #hks_g]\n\t"
        "str    r1, [r6, #16]\n\t"
        "ldr    r1, [sp, #hks_a]\n\t"
        "str    r1, [r6, #36]\n\t"
        "ldr    r1, [sp, #hks_mm]\n\t"
        "str    r1, [r6, #40]\n\t"
        "ldr    r3, [sp, #hks_q]\n\t"
        "lsls   r1, r3, #1\n\t"
        "ldr    r5, [r4, %[stride]]\n\t"
        "adds   r1, r1, r5\n\t"
        "str    r1, [r6, #44]\n\t"
        "bx     lr\n"
        // The next (lower short) edge store, r2 = the middle row; its depth when it is a left edge.
        "48:\n\t"
        "ldr    r6, [sp, #hks_out]\n\t"
        "ldr    r4, [sp, #hks_band]\n\t"
        "ldr    r0, [sp, #hks_px]\n\t"
        "lsls   r1, r0, #1\n\t"
        "str    r1, [r6, #64]\n\t"
        "ldr    r1, [sp, #hks_g]\n\t"
        "str    r1, [r6, #68]\n\t"
        "ldr    r1, [sp, #hks_a]\n\t"
        "str    r1, [r6, #72]\n\t"
        "ldr    r1, [sp, #hks_mm]\n\t"
        "str    r1, [r6, #76]\n\t"
        "ldr    r3, [sp, #hks_q]\n\t"
        "lsls   r1, r3, #1\n\t"
        "ldr    r5, [r4, %[stride]]\n\t"
        "adds   r1, r1, r5\n\t"
        "str    r1, [r6, #80]\n\t"
        "ldr    r1, [sp, #hks_odd]\n\t"
        "cmp    r1, #0\n\t"
        "beq    1f\n\t"
        "ldr    r5, [sp, #hks_refpx]\n\t"
        "subs   r0, r0, r5\n\t"
        "ldr    r5, [sp, #hks_dzdx]\n\t"
        "muls   r0, r5, r0\n\t"
        "ldr    r7, [sp, #hks_refpy]\n\t"
        "subs   r2, r2, r7\n\t"
        "ldr    r7, [sp, #hks_dzdy]\n\t"
        "muls   r2, r7, r2\n\t"
        "adds   r0, r0, r2\n\t"
        "ldr    r1, [sp, #hks_zref]\n\t"
        "adds   r0, r0, r1\n\t"
        "str    r0, [r6, #84]\n\t"
        "muls   r3, r5, r3\n\t"
        "adds   r3, r3, r7\n\t"
        "str    r3, [r6, #88]\n"
        "1:\n\t"
        "bx     lr\n"
        // floor(n / a) and n - floor(n / a) a for a > 0: r0 n, r1 a -> r0, r1. __aeabi_uidivmod (its
        // quotients here are small, where the library's shift-subtract exits early: a reciprocal of
        // dy per walker cost more).
        "50:\n\t"
        "cmp    r0, #0\n\t"
        "blt    52f\n\t"
        "cmp    r0, r1\n\t"
        "bhs    51f\n\t"
        "movs   r1, r0\n\t"                   // 0 <= n < a
        "movs   r0, #0\n\t"
        "bx     lr\n"
        "51:\n\t"
        "mov    r3, lr\n\t"
        "str    r3, [sp, #hks_flr]\n\t"
        "bl     __aeabi_uidivmod\n\t"
        "ldr    r3, [sp, #hks_flr]\n\t"
        "bx     r3\n"
        "52:\n\t"
        "adds   r2, r0, r1\n\t"
        "blt    53f\n\t"
        "movs   r1, r2\n\t"                   // -a <= n < 0: -1, n + a
        "movs   r0, #1\n\t"
        "negs   r0, r0\n\t"
        "bx     lr\n"
        "53:\n\t"
        "mov    r3, lr\n\t"
        "str    r3, [sp, #hks_flr]\n\t"
        "str    r1, [sp, #hks_fa]\n\t"
        "mvns   r0, r0\n\t"                   // -n - 1 = q' a + r'
        "bl     __aeabi_uidivmod\n\t"
        "mvns   r0, r0\n\t"                   // floor = -q' - 1
        "ldr    r2, [sp, #hks_fa]\n\t"
        "subs   r2, r2, #1\n\t"
        "subs   r1, r2, r1\n\t"               // remainder a - 1 - r'
        "ldr    r3, [sp, #hks_flr]\n\t"
        "bx     r3\n"
        // Rounded plane quotient: r1:r0 = n (signed) -> r0 = round(n / area), ties away from zero;
        // the generic exit when it is 2^31 or more. M = (|n| + area / 2) << s over dn in two digits.
        "60:\n\t"
        "asrs   r7, r1, #31\n\t"
        "str    r7, [sp, #hks_sign]\n\t"
        "eors   r0, r7\n\t"
        "eors   r1, r7\n\t"
        "subs   r0, r0, r7\n\t"
        "sbcs   r1, r7\n\t"                   // |n|
        "ldr    r6, [sp, #hks_area]\n\t"
        "lsrs   r5, r6, #1\n\t"
        "adds   r0, r0, r5\n\t"
        "movs   r5, #0\n\t"
        "adcs   r1, r5\n\t"                   // m
        "lsls   r5, r1, #1\n\t"
        "lsrs   r4, r0, #31\n\t"
        "orrs   r5, r4\n\t"
        "cmp    r5, r6\n\t"
        "blo    61f\n\t"
        "b      93b\n"                        // m / area >= 2^31
        "61:\n\t"
        "ldr    r5, [sp, #hks_s]\n\t"
        "lsls   r1, r1, r5\n\t"
        "movs   r4, #32\n\t"
        "subs   r4, r4, r5\n\t"
        "movs   r3, r0\n\t"
        "lsrs   r3, r3, r4\n\t"
        "orrs   r1, r3\n\t"
        "lsls   r0, r0, r5\n\t"               // r1:r0 = M < dn 2^31
        "ldr    r6, [sp, #hks_r]\n\t"
        "lsrs   r2, r1, #16\n\t"
        "muls   r2, r6, r2\n\t"
        "lsrs   r2, r2, #16\n\t"
        "adds   r2, #1\n\t"                   // e1: floor(M / (dn 2^16)) within a few
        "lsrs   r3, r1, #16\n\t"
        "lsls   r1, r1, #16\n\t"
        "lsrs   r4, r0, #16\n\t"
        "orrs   r1, r4\n\t"                   // r3:r1 = M >> 16
        "ldr    r5, [sp, #hks_dn]\n\t"
        "lsrs   r4, r5, #16\n\t"
        "muls   r4, r2, r4\n\t"
        "uxth   r7, r5\n\t"
        "muls   r7, r2, r7\n\t"
        "lsls   r6, r4, #16\n\t"
        "lsrs   r4, r4, #16\n\t"
        "adds   r7, r7, r6\n\t"
        "movs   r6, #0\n\t"
        "adcs   r4, r6\n\t"                   // r4:r7 = e1 dn
        "subs   r1, r1, r7\n\t"
        "sbcs   r3, r4\n\t"
        "cmp    r3, #0\n\t"
        "bge    63f\n"
        "62:\n\t"
        "subs   r2, #1\n\t"
        "adds   r1, r1, r5\n\t"
        "adcs   r3, r6\n\t"
        "bmi    62b\n"
        "63:\n\t"
        "cmp    r3, #0\n\t"
        "bne    64f\n\t"
        "cmp    r1, r5\n\t"
        "blo    65f\n"
        "64:\n\t"
        "adds   r2, #1\n\t"
        "subs   r1, r1, r5\n\t"
        "sbcs   r3, r6\n\t"
        "b      63b\n"
        "65:\n\t"                             // r1 = the remainder below dn, r2 = the high digit
        "ldr    r6, [sp, #hks_r]\n\t"
        "lsrs   r3, r1, #17\n\t"
        "muls   r3, r6, r3\n\t"
        "lsrs   r3, r3, #15\n\t"
        "adds   r3, #1\n\t"                   // e2 within a few, at most 2^16 - 1
        "lsrs   r4, r3, #16\n\t"
        "beq    66f\n\t"
        "movs   r3, #1\n\t"
        "lsls   r3, r3, #16\n\t"
        "subs   r3, #1\n"
        "66:\n\t"
        "uxth   r0, r0\n\t"
        "lsrs   r4, r1, #16\n\t"
        "lsls   r1, r1, #16\n\t"
        "orrs   r1, r0\n\t"                   // r4:r1 = remainder 2^16 + the low 16 bits of M
        "lsrs   r6, r5, #16\n\t"
        "muls   r6, r3, r6\n\t"
        "uxth   r7, r5\n\t"
        "muls   r7, r3, r7\n\t"
        "lsls   r0, r6, #16\n\t"
        "lsrs   r6, r6, #16\n\t"
        "adds   r7, r7, r0\n\t"
        "movs   r0, #0\n\t"
        "adcs   r6, r0\n\t"                   // r6:r7 = e2 dn
        "subs   r1, r1, r7\n\t"
        "sbcs   r4, r6\n\t"
        "cmp    r4, #0\n\t"
        "bge    68f\n"
        "67:\n\t"
        "subs   r3, #1\n\t"
        "adds   r1, r1, r5\n\t"
        "adcs   r4, r0\n\t"
        "bmi    67b\n"
        "68:\n\t"
        "cmp    r4, #0\n\t"
        "bne    69f\n\t"
        "cmp    r1, r5\n\t"
        "blo    70f\n"
        "69:\n\t"
        "adds   r3, #1\n\t"
        "subs   r1, r1, r5\n\t"
        "sbcs   r4, r0\n\t"
        "b      68b\n"
        "70:\n\t"
        "lsls   r2, r2, #16\n\t"
        "adds   r0, r2, r3\n\t"
        "ldr    r7, [sp, #hks_sign]\n\t"
        "eors   r0, r7\n\t"
        "subs   r0, r0, r7\n\t"
        "bx     lr\n"
        // The area's shift s = clz(area), dn = area << s and R = about 2^48 / dn.
        "59:\n\t"
        "ldr    r0, [sp, #hks_area]\n\t"
        "movs   r1, #0\n\t"
        "lsrs   r2, r0, #16\n\t" "bne 1f\n\t" "adds r1, #16\n\t" "lsls r0, r0, #16\n" "1:\n\t"
        "lsrs   r2, r0, #24\n\t" "bne 1f\n\t" "adds r1, #8\n\t" "lsls r0, r0, #8\n" "1:\n\t"
        "lsrs   r2, r0, #28\n\t" "bne 1f\n\t" "adds r1, #4\n\t" "lsls r0, r0, #4\n" "1:\n\t"
        "lsrs   r2, r0, #30\n\t" "bne 1f\n\t" "adds r1, #2\n\t" "lsls r0, r0, #2\n" "1:\n\t"
        "lsrs   r2, r0, #31\n\t" "bne 1f\n\t" "adds r1, #1\n\t" "lsls r0, r0, #1\n" "1:\n\t"
        "str    r1, [sp, #hks_s]\n\t"
        "str    r0, [sp, #hks_dn]\n\t"
        "lsls   r3, r0, #1\n\t"
        "lsrs   r3, r3, #24\n\t"
        "lsls   r3, r3, #1\n\t"
        "ldr    r4, 99f\n\t"
        "ldrh   r3, [r4, r3]\n\t"
        "movs   r4, #1\n\t"
        "lsls   r4, r4, #16\n\t"
        "adds   r3, r3, r4\n\t"               // x0
        "lsrs   r4, r0, #16\n\t"
        "muls   r4, r3, r4\n\t"
        "negs   r4, r4\n\t"
        "asrs   r4, r4, #8\n\t"
        "lsrs   r5, r3, #2\n\t"
        "muls   r5, r4, r5\n\t"
        "asrs   r5, r5, #22\n\t"
        "adds   r3, r3, r5\n\t"
        "str    r3, [sp, #hks_r]\n\t"
        "bx     lr\n\t"
        ".balign 4\n"
        "99:\n\t"
        ".word  %c[table]\n"
        :
        : [y_first] "i"(offsetof(KernelBand, y_first)), [y_last] "i"(offsetof(KernelBand, y_last)),
          [x_last] "i"(offsetof(KernelBand, x_last)), [row_from] "i"(offsetof(KernelBand, row_from)),
          [row_end] "i"(offsetof(KernelBand, row_end)), [stride] "i"(offsetof(KernelBand, stride_bytes)),
          [table] "i"(kReciprocalTableData));
}
#elif defined(__riscv) && __riscv_xlen == 32
/// RV32IM: the same set-up in registers (s0 band, s1 out, s2 odd, s3 y0, s4 mid, s5 y1; after the
/// plane t3 dzdx, t4 dzdy, t5 the plane's value at pixel (0, 0) of the frame, t6 the stride), the sorted
/// vertices in the frame. Plane quotients with the 32-bit divide in two 16-bit digits (areas below
/// 2^16; larger ones call hider_kernel_udiv64); walker divisions with divu/remu. Local subroutines
/// (link register t2 or t3): 80 walker (a0 xu, a1 yu, a2 xl, a3 yl, a4 row -> a0 px, a1 g - a,
/// a2 a, a3 m, a4 q), 84/86/88 left, right and next edge stores (a5 the row), 70 the rounded
/// plane quotient (a1:a0 -> a0, area in t0; link t3).
__attribute__((naked, noinline)) inline uint32_t kernel_setup_rv32(const ScreenVertex*, const ScreenVertex*,
                                                                   const ScreenVertex*, KernelSetupIo*) {
    __asm__ volatile(
        "addi   sp, sp, -112\n\t"
        "sw     s0, 24(sp)\n\t"
        "sw     s1, 28(sp)\n\t"
        "sw     s2, 32(sp)\n\t"
        "sw     s3, 36(sp)\n\t"
        "sw     s4, 40(sp)\n\t"
        "sw     s5, 44(sp)\n\t"
        "lw     s0, 0(a3)\n\t"                // band
        "lw     t0, 4(a3)\n\t"                // area
        "lw     s1, 8(a3)\n\t"                // out
        "bgez   t0, 1f\n\t"
        "mv     t1, a1\n\t"                   // clockwise on the image: a, c, b
        "mv     a1, a2\n\t"
        "mv     a2, t1\n\t"
        "neg    t0, t0\n"
        "1:\n\t"
        "lh     a4, 0(a0)\n\t"                // (a4, a5) top, (a6, a7) middle, (t1, t2) bottom
        "lh     a5, 2(a0)\n\t"
        "lh     a6, 0(a1)\n\t"
        "lh     a7, 2(a1)\n\t"
        "lh     t1, 0(a2)\n\t"
        "lh     t2, 2(a2)\n\t"
        "li     s2, 0\n\t"                    // 1: odd permutation, the long edge on the right
        "bge    a7, a5, 2f\n\t"
        "mv     t3, a4\n\t" "mv a4, a6\n\t" "mv a6, t3\n\t"
        "mv     t3, a5\n\t" "mv a5, a7\n\t" "mv a7, t3\n\t"
        "xori   s2, s2, 1\n"
        "2:\n\t"
        "bge    t2, a7, 3f\n\t"
        "mv     t3, a6\n\t" "mv a6, t1\n\t" "mv t1, t3\n\t"
        "mv     t3, a7\n\t" "mv a7, t2\n\t" "mv t2, t3\n\t"
        "xori   s2, s2, 1\n"
        "3:\n\t"
        "bge    a7, a5, 4f\n\t"
        "mv     t3, a4\n\t" "mv a4, a6\n\t" "mv a6, t3\n\t"
        "mv     t3, a5\n\t" "mv a5, a7\n\t" "mv a7, t3\n\t"
        "xori   s2, s2, 1\n"
        "4:\n\t"
        "sw     a4, 0(sp)\n\t"
        "sw     a5, 4(sp)\n\t"
        "sw     a6, 8(sp)\n\t"
        "sw     a7, 12(sp)\n\t"
        "sw     t1, 16(sp)\n\t"
        "sw     t2, 20(sp)\n\t"
        "lw     t3, %[y_first](s0)\n\t"
        "blt    t2, t3, 90f\n\t"              // below the band's first centre: none
        "lw     t3, %[y_last](s0)\n\t"
        "bgt    a5, t3, 90f\n\t"              // above its last: none
        "mv     t3, a4\n\t"                   // t3 = x_min, t4 = x_max
        "mv     t4, a4\n\t"
        "bge    a6, t3, 5f\n\t" "mv t3, a6\n" "5:\n\t"
        "ble    a6, t4, 5f\n\t" "mv t4, a6\n" "5:\n\t"
        "bge    t1, t3, 5f\n\t" "mv t3, t1\n" "5:\n\t"
        "ble    t1, t4, 5f\n\t" "mv t4, t1\n" "5:\n\t"
        "lw     t5, 0(s0)\n\t"                // x_origin
        "blt    t3, t5, 92f\n\t"              // past the columns: generic
        "lw     t6, %[x_last](s0)\n\t"
        "bgt    t4, t6, 92f\n\t"
        "sub    t3, t3, t5\n\t"
        "addi   t3, t3, 15\n\t"
        "andi   t3, t3, -16\n\t"
        "add    t3, t3, t5\n\t"
        "bgt    t3, t4, 90f\n\t"              // no column centre in the box: none
        "lw     t5, 4(s0)\n\t"                // y_origin
        "sub    t3, a5, t5\n\t"
        "addi   t3, t3, 15\n\t"
        "srai   t3, t3, 4\n\t"                // top row
        "slli   t4, t3, 4\n\t"
        "add    t4, t4, t5\n\t"
        "bgt    t4, t2, 90f\n\t"              // no row centre in the box: none
        "sub    t4, t2, t5\n\t"
        "addi   t4, t4, 15\n\t"
        "srai   t4, t4, 4\n\t"                // bottom row
        "sub    s4, a7, t5\n\t"
        "addi   s4, s4, 15\n\t"
        "srai   s4, s4, 4\n\t"                // middle row
        "lw     s3, %[row_from](s0)\n\t"
        "bge    s3, t3, 6f\n\t" "mv s3, t3\n" "6:\n\t"   // y0 = max(top, row_from)
        "lw     s5, %[row_end](s0)\n\t"
        "ble    s5, t4, 6f\n\t" "mv s5, t4\n" "6:\n\t"   // y1 = min(bottom, row_end)
        "sh     t3, %[top](s1)\n\t"
        "sh     s3, %[row](s1)\n\t"
        "sh     s4, %[mid](s1)\n\t"
        "sh     s5, %[end](s1)\n\t"
        "bge    s3, s5, 91f\n\t"              // no row: set up, nothing to draw
        // The plane (plane.hpp): npx / 16 = s0 (y1 - y2) + s1 (y2 - y0) + s2 (y0 - y1) and nqy / 16 =
        // s0 (x2 - x1) + s1 (x0 - x2) + s2 (x1 - x0), s = z - 2^31, then two rounded quotients.
        "lh     a3, 0(a0)\n\t"                // x0
        "lh     a4, 2(a0)\n\t"                // y0
        "lw     a5, 4(a0)\n\t"
        "lh     a6, 0(a1)\n\t"                // x1
        "lh     a7, 2(a1)\n\t"                // y1
        "lw     t1, 4(a1)\n\t"
        "lh     t2, 0(a2)\n\t"                // x2
        "lh     t3, 2(a2)\n\t"                // y2
        "lw     t4, 4(a2)\n\t"
        "lui    t5, 0x80000\n\t"
        "xor    a5, a5, t5\n\t"               // s0
        "xor    t1, t1, t5\n\t"               // s1
        "xor    t4, t4, t5\n\t"               // s2
        ".macro hks_cross d0, d1, d2\n\t"     // a1:a0 = 16 (s0 d0 + s1 d1 + s2 d2); scratch a2 t5 t6
        "mul    a0, a5, \\d0\n\t"
        "mulh   a1, a5, \\d0\n\t"
        "mul    a2, t1, \\d1\n\t"
        "mulh   t6, t1, \\d1\n\t"
        "add    a0, a0, a2\n\t"
        "sltu   a2, a0, a2\n\t"
        "add    a1, a1, t6\n\t"
        "add    a1, a1, a2\n\t"
        "mul    a2, t4, \\d2\n\t"
        "mulh   t6, t4, \\d2\n\t"
        "add    a0, a0, a2\n\t"
        "sltu   a2, a0, a2\n\t"
        "add    a1, a1, t6\n\t"
        "add    a1, a1, a2\n\t"
        "slli   a1, a1, 4\n\t"
        "srli   a2, a0, 28\n\t"
        "or     a1, a1, a2\n\t"
        "slli   a0, a0, 4\n\t"
        ".endm\n\t"
        "sub    t5, a7, t3\n\t"               // d0 = y1 - y2
        "sub    t3, t3, a4\n\t"               // d1 = y2 - y0
        "sub    a7, a4, a7\n\t"               // d2 = y0 - y1
        "hks_cross t5, t3, a7\n\t"
        "jal    t3, 70f\n\t"
        "sw     a0, %[dzdx](s1)\n\t"
        "sub    t5, t2, a6\n\t"               // x2 - x1
        "sub    t3, a3, t2\n\t"               // x0 - x2
        "sub    a7, a6, a3\n\t"               // x1 - x0
        "hks_cross t5, t3, a7\n\t"
        "jal    t3, 70f\n\t"
        "mv     t4, a0\n\t"                   // dzdy
        "lw     t3, %[dzdx](s1)\n\t"          // dzdx
        ".purgem hks_cross\n\t"
        // Reference pixel (the cell holding v0), z_ref = z0 + round((dzdx ox + dzdy oy) / 16), and
        // t5 = z_ref - dzdx ref_px - dzdy ref_py (plane.at(px, py) = t5 + dzdx px + dzdy py, mod 2^32).
        "lw     a0, 0(s0)\n\t"
        "sub    a1, a3, a0\n\t"
        "addi   a1, a1, 8\n\t"
        "srai   a1, a1, 4\n\t"                // ref_px
        "slli   a2, a1, 4\n\t"
        "add    a2, a2, a0\n\t"
        "sub    a2, a2, a3\n\t"               // ox
        "lw     a0, 4(s0)\n\t"
        "sub    a6, a4, a0\n\t"
        "addi   a6, a6, 8\n\t"
        "srai   a6, a6, 4\n\t"                // ref_py
        "slli   a7, a6, 4\n\t"
        "add    a7, a7, a0\n\t"
        "sub    a7, a7, a4\n\t"               // oy
        "mul    a0, t3, a2\n\t"
        "mulh   a2, t3, a2\n\t"
        "mul    a3, t4, a7\n\t"
        "mulh   a7, t4, a7\n\t"
        "add    a0, a0, a3\n\t"
        "sltu   a3, a0, a3\n\t"
        "add    a2, a2, a7\n\t"
        "add    a2, a2, a3\n\t"               // a2:a0 = S
        "srai   a7, a2, 31\n\t"               // round(S / 16), ties away from zero: on |S|
        "xor    a3, a0, a7\n\t"
        "sub    a0, a3, a7\n\t"
        "sltu   a3, a0, a3\n\t"
        "xor    a2, a2, a7\n\t"
        "add    a2, a2, a3\n\t"
        "addi   a0, a0, 8\n\t"
        "sltiu  a3, a0, 8\n\t"
        "add    a2, a2, a3\n\t"
        "srli   a0, a0, 4\n\t"
        "slli   a2, a2, 28\n\t"
        "or     a0, a0, a2\n\t"
        "xor    a0, a0, a7\n\t"
        "sub    a0, a0, a7\n\t"
        "add    t5, a5, a0\n\t"               // s0 + round: z_ref - 2^31
        "lui    a0, 0x80000\n\t"
        "xor    t5, t5, a0\n\t"               // z_ref
        "mul    a0, t3, a1\n\t"
        "sub    t5, t5, a0\n\t"
        "mul    a0, t4, a6\n\t"
        "sub    t5, t5, a0\n\t"
        "lw     t6, %[stride](s0)\n\t"
        // The long edge (top -> bottom) on row y0: the left edge for an even permutation.
        "lw     a0, 0(sp)\n\t"
        "lw     a1, 4(sp)\n\t"
        "lw     a2, 16(sp)\n\t"
        "lw     a3, 20(sp)\n\t"
        "mv     a4, s3\n\t"
        "jal    t2, 80f\n\t"
        "mv     a5, s3\n\t"
        "bnez   s2, 1f\n\t"
        "jal    t2, 84f\n\t"
        "j      2f\n"
        "1:\n\t"
        "jal    t2, 86f\n"
        "2:\n\t"
        // The short edge on row y0: top -> mid above the middle row, mid -> bottom from it on.
        "bge    s3, s4, 1f\n\t"
        "lw     a0, 0(sp)\n\t"
        "lw     a1, 4(sp)\n\t"
        "lw     a2, 8(sp)\n\t"
        "lw     a3, 12(sp)\n\t"
        "j      2f\n"
        "1:\n\t"
        "lw     a0, 8(sp)\n\t"
        "lw     a1, 12(sp)\n\t"
        "lw     a2, 16(sp)\n\t"
        "lw     a3, 20(sp)\n"
        "2:\n\t"
        "mv     a4, s3\n\t"
        "jal    t2, 80f\n\t"
        "mv     a5, s3\n\t"
        "beqz   s2, 1f\n\t"
        "jal    t2, 84f\n\t"
        "j      2f\n"
        "1:\n\t"
        "jal    t2, 86f\n"
        "2:\n\t"
        "sb     s2, %[next_left](s1)\n\t"     // the short edges are on the left when odd
        // The lower short edge from the middle row, when it starts inside [y0, y1).
        "bge    s3, s4, 1f\n\t"
        "bge    s4, s5, 1f\n\t"
        "lw     a0, 8(sp)\n\t"
        "lw     a1, 12(sp)\n\t"
        "lw     a2, 16(sp)\n\t"
        "lw     a3, 20(sp)\n\t"
        "mv     a4, s4\n\t"
        "jal    t2, 80f\n\t"
        "mv     a5, s4\n\t"
        "jal    t2, 88f\n"
        "1:\n\t"
        "li     a0, 1\n\t"                    // kernel
        "j      95f\n"
        "90:\n\t"
        "li     a0, 0\n\t"                    // none
        "j      95f\n"
        "91:\n\t"
        "li     a0, 1\n\t"                    // kernel, no rows
        "j      95f\n"
        "92:\n\t"
        "li     a0, 2\n"                      // generic (also a depth step of 2^31 or more)
        "95:\n\t"
        "lw     s0, 24(sp)\n\t"
        "lw     s1, 28(sp)\n\t"
        "lw     s2, 32(sp)\n\t"
        "lw     s3, 36(sp)\n\t"
        "lw     s4, 40(sp)\n\t"
        "lw     s5, 44(sp)\n\t"
        "addi   sp, sp, 112\n\t"
        "ret\n"
        // Rounded plane quotient: a1:a0 = n -> a0 = round(n / area), ties away from zero (area t0);
        // the generic exit when it is 2^31 or more. Scratch a1 a2 a7 t5 t6; link t3.
        "70:\n\t"
        "srai   a7, a1, 31\n\t"               // sign
        "xor    t6, a0, a7\n\t"
        "sub    a0, t6, a7\n\t"
        "sltu   t6, a0, t6\n\t"
        "xor    a1, a1, a7\n\t"
        "add    a1, a1, t6\n\t"               // |n|
        "srli   t6, t0, 1\n\t"
        "add    a0, a0, t6\n\t"
        "sltu   t6, a0, t6\n\t"
        "add    a1, a1, t6\n\t"               // m = |n| + area / 2
        "slli   t6, a1, 1\n\t"
        "srli   a2, a0, 31\n\t"
        "or     t6, t6, a2\n\t"
        "bgeu   t6, t0, 92b\n\t"              // m / area >= 2^31
        "srli   t6, t0, 16\n\t"
        "bnez   t6, 72f\n\t"
        "slli   t6, a1, 16\n\t"               // two 16-bit digits
        "srli   a2, a0, 16\n\t"
        "or     t6, t6, a2\n\t"
        "divu   a2, t6, t0\n\t"
        "remu   t6, t6, t0\n\t"
        "slli   t6, t6, 16\n\t"
        "slli   a1, a0, 16\n\t"
        "srli   a1, a1, 16\n\t"
        "or     t6, t6, a1\n\t"
        "divu   t6, t6, t0\n\t"
        "slli   a2, a2, 16\n\t"
        "add    a0, a2, t6\n"
        "71:\n\t"
        "xor    a0, a0, a7\n\t"
        "sub    a0, a0, a7\n\t"
        "jr     t3\n"
        "72:\n\t"                             // area >= 2^16: udiv64_32
        "sw     ra, 48(sp)\n\t"
        "sw     t3, 52(sp)\n\t"
        "sw     a3, 56(sp)\n\t"
        "sw     a4, 60(sp)\n\t"
        "sw     a5, 64(sp)\n\t"
        "sw     a6, 68(sp)\n\t"
        "sw     a7, 72(sp)\n\t"
        "sw     t0, 76(sp)\n\t"
        "sw     t1, 80(sp)\n\t"
        "sw     t2, 84(sp)\n\t"
        "sw     t4, 88(sp)\n\t"
        "mv     a2, t0\n\t"
        "call   hider_kernel_udiv64\n\t"
        "lw     ra, 48(sp)\n\t"
        "lw     t3, 52(sp)\n\t"
        "lw     a3, 56(sp)\n\t"
        "lw     a4, 60(sp)\n\t"
        "lw     a5, 64(sp)\n\t"
        "lw     a6, 68(sp)\n\t"
        "lw     a7, 72(sp)\n\t"
        "lw     t0, 76(sp)\n\t"
        "lw     t1, 80(sp)\n\t"
        "lw     t2, 84(sp)\n\t"
        "lw     t4, 88(sp)\n\t"
        "j      71b\n"
        // Walker (edge.hpp). Scratch a5 a6.
        "80:\n\t"
        "sub    a2, a2, a0\n\t"               // dx
        "sub    a3, a3, a1\n\t"               // dy
        "lw     a5, 4(s0)\n\t"
        "slli   a4, a4, 4\n\t"
        "add    a4, a4, a5\n\t"
        "sub    a4, a4, a1\n\t"               // yc - yu
        "lw     a5, 0(s0)\n\t"
        "sub    a5, a5, a0\n\t"
        "mul    a5, a5, a3\n\t"
        "mul    a4, a4, a2\n\t"
        "sub    a5, a5, a4\n\t"               // g0 = dy (x_origin - xu) - dx (yc - yu)
        "slli   a6, a3, 4\n\t"                // a = 16 dy
        "bltz   a5, 81f\n\t"
        "divu   a0, a5, a6\n\t"               // px = -floor(g0 / a), g = g0 mod a
        "remu   a1, a5, a6\n\t"
        "neg    a0, a0\n\t"
        "j      82f\n"
        "81:\n\t"
        "not    a5, a5\n\t"                   // -g0 - 1 = q' a + r': floor = -q' - 1, g = a - 1 - r'
        "divu   a0, a5, a6\n\t"
        "remu   a1, a5, a6\n\t"
        "addi   a0, a0, 1\n\t"
        "sub    a1, a6, a1\n\t"
        "addi   a1, a1, -1\n"
        "82:\n\t"
        "sub    a1, a1, a6\n\t"               // g - a
        "slli   a2, a2, 4\n\t"
        "neg    a2, a2\n\t"                   // dg = -16 dx
        "bltz   a2, 76f\n\t"
        "bgeu   a2, a6, 83f\n\t"
        "li     a4, 0\n\t"                    // 0 <= dg < a: q = 0, m = dg
        "mv     a3, a2\n\t"
        "mv     a2, a6\n\t"
        "jr     t2\n"
        "83:\n\t"
        "divu   a4, a2, a6\n\t"               // dg >= a
        "remu   a3, a2, a6\n\t"
        "neg    a4, a4\n\t"
        "mv     a2, a6\n\t"
        "jr     t2\n"
        "76:\n\t"
        "add    a3, a2, a6\n\t"
        "bltz   a3, 77f\n\t"
        "li     a4, 1\n\t"                    // -a <= dg < 0: q = 1, m = dg + a
        "mv     a2, a6\n\t"
        "jr     t2\n"
        "77:\n\t"
        "not    a2, a2\n\t"                   // dg < -a
        "divu   a4, a2, a6\n\t"
        "remu   a3, a2, a6\n\t"
        "addi   a4, a4, 1\n\t"
        "sub    a3, a6, a3\n\t"
        "addi   a3, a3, -1\n\t"
        "mv     a2, a6\n\t"
        "jr     t2\n"
        // Edge stores: a0 px, a1 g - a, a2 a, a3 m, a4 q, a5 the row; left (with its depth), right, next.
        "84:\n\t"
        "slli   a6, a0, 1\n\t"
        "sw     a6, 0(s1)\n\t"                // lx
        "sw     a1, 4(s1)\n\t"                // lg
        "sw     a2, 20(s1)\n\t"               // la
        "sw     a3, 24(s1)\n\t"               // lm
        "slli   a6, a4, 1\n\t"
        "add    a6, a6, t6\n\t"
        "sw     a6, 28(s1)\n\t"               // lstep = 2 q + stride
        "mul    a6, t3, a0\n\t"
        "mul    a7, t4, a5\n\t"
        "add    a6, a6, a7\n\t"
        "add    a6, a6, t5\n\t"
        "sw     a6, 8(s1)\n\t"                // lz = plane.at(px, row)
        "mul    a6, t3, a4\n\t"
        "add    a6, a6, t4\n\t"
        "sw     a6, 32(s1)\n\t"               // ldz = dzdy + dzdx q
        "jr     t2\n"
        "86:\n\t"
        "slli   a6, a0, 1\n\t"
        "sw     a6, 12(s1)\n\t"               // rx
        "sw     a1, 16(s1)\n\t"               // rg
        "sw     a2, 36(s1)\n\t"               // ra
        "sw     a3, 40(s1)\n\t"               // rm
        "slli   a6, a4, 1\n\t"
        "add    a6, a6, t6\n\t"
        "sw     a6, 44(s1)\n\t"               // rstep
        "jr     t2\n"
        "88:\n\t"
        "slli   a6, a0, 1\n\t"
        "sw     a6, 64(s1)\n\t"               // next_x
        "sw     a1, 68(s1)\n\t"               // next_g
        "sw     a2, 72(s1)\n\t"               // next_a
        "sw     a3, 76(s1)\n\t"               // next_m
        "slli   a6, a4, 1\n\t"
        "add    a6, a6, t6\n\t"
        "sw     a6, 80(s1)\n\t"               // next_step
        "beqz   s2, 1f\n\t"
        "mul    a6, t3, a0\n\t"
        "mul    a7, t4, a5\n\t"
        "add    a6, a6, a7\n\t"
        "add    a6, a6, t5\n\t"
        "sw     a6, 84(s1)\n\t"               // next_z
        "mul    a6, t3, a4\n\t"
        "add    a6, a6, t4\n\t"
        "sw     a6, 88(s1)\n"                 // next_dz
        "1:\n\t"
        "jr     t2\n"
        :
        : [y_first] "i"(offsetof(KernelBand, y_first)), [y_last] "i"(offsetof(KernelBand, y_last)),
          [x_last] "i"(offsetof(KernelBand, x_last)), [row_from] "i"(offsetof(KernelBand, row_from)),
          [row_end] "i"(offsetof(KernelBand, row_end)), [stride] "i"(offsetof(KernelBand, stride_bytes)),
          [top] "i"(offsetof(KernelTriangle, top)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)), [next_left] "i"(offsetof(KernelTriangle, next_left)));
}
#endif

/// Sets up (a, b, c) with signed_area io.area != 0 (either winding) for the rows of *io.band into
/// *io.out, leaving out.k.color to the caller: the Thumb-2 set-up on ARMv7-M, else
/// kernel_setup_portable() (identical results). On `none` and `generic`, *io.out is unspecified.
/// Cost: the two plane quotients and one division per edge walker (two for flat edges).
__attribute__((always_inline)) inline KernelSetup kernel_setup(const ScreenVertex& a, const ScreenVertex& b,
                                                               const ScreenVertex& c, KernelSetupIo& io) {
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    return static_cast<KernelSetup>(kernel_setup_v7m(&a, &b, &c, &io));
#elif defined(__ARM_ARCH_6M__)
    return static_cast<KernelSetup>(kernel_setup_v6m(&a, &b, &c, &io));
#elif defined(__riscv) && __riscv_xlen == 32
    return static_cast<KernelSetup>(kernel_setup_rv32(&a, &b, &c, &io));
#else
    return kernel_setup_portable(a, b, c, io.area, *io.band, *io.out);
#endif
}

}  // namespace hider

// kernel_setup_portable() (kernel_triangle.hpp) in RV32IM, its state in registers. Part of
// kernel_setup_asm.hpp: include that header (or kernel_triangle.hpp), not this one.
#pragma once
#include <hider/raster/kernel_triangle.hpp>

namespace hider {

#if defined(HIDER_RV32_ASM)
/// RV32IM: the same set-up in registers (s0 band, s1 out, s2 odd, s3 y0, s4 mid, s5 y1; after the
/// plane t3 dzdx, t4 dzdy, t5 the plane's value at pixel (0, 0) of the frame, t6 the stride), the sorted
/// vertices in the frame. Plane quotients with the 32-bit divide in two 16-bit digits (areas below
/// 2^16; larger ones call hider_kernel_udiv64); walker divisions with divu/remu. Local subroutines
/// (link register t2 or t3): 80 walker (a0 xu, a1 yu, a2 xl, a3 yl, a4 row -> a0 px, a1 g - a,
/// a2 a, a3 m, a4 q), 84/86/88 left, right and next edge stores (a5 the row), 70 the rounded
/// plane quotient (a1:a0 -> a0, area in t0; link t3).
HIDER_NAKED inline uint32_t kernel_setup_rv32(const ScreenVertex*, const ScreenVertex*,
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
        "sw     a6, 80(s1)\n\t"               // next_step (a left one's depth: the kernel's switch)
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

}  // namespace hider

// kernel_setup_portable() (kernel_triangle.hpp) in Thumb-1 for ARMv6-M (Cortex-M0/M0+), with its state
// in a stack frame and the plane quotients from a reciprocal estimate. Part of kernel_setup_asm.hpp:
// include that header (or kernel_triangle.hpp), not this one.
#pragma once
#include <hider/raster/kernel_triangle.hpp>

namespace hider {

#if defined(HIDER_ARMV6M)
/// Thumb-1 (no long multiply, no divide, eight low registers): the same set-up with its state in a
/// 184-byte frame. Depth products by balanced 16-bit halves of s = z - 2^31 (the three differences sum
/// to zero, so each half's sum stays in 32 bits); the two plane quotients by one estimate of
/// 2^48 / (area normalised) (reciprocal_word()'s table and Newton step) in two 16-bit digits, each
/// corrected against its exact remainder; the walkers' floor divisions through __aeabi_uidivmod.
/// Subroutines: 40 walker (r0, r1 the upper and lower vertex as packed x | y << 16, r2 the row; results
/// in the frame), 44/46/48 the left, right and next edge stores (r2 the row), 50 floor division
/// (r0 n, r1 a > 0 -> r0 floor(n / a), r1 the remainder), 59 the area's shift, normalised value and
/// estimate, 60 the rounded plane quotient (r1:r0 -> r0, or the generic exit).
HIDER_NAKED inline uint32_t kernel_setup_v6m(const ScreenVertex*, const ScreenVertex*,
                                                                  const ScreenVertex*, KernelSetupIo*) {
    // The record's field offsets as assembler symbols hks_k_*, for the body below (whose own operands
    // would pass GCC's limit of 30).
    __asm__ volatile(
        ".equ hks_k_top, %c[top]\n\t" ".equ hks_k_row, %c[row]\n\t" ".equ hks_k_mid, %c[mid]\n\t"
        ".equ hks_k_end, %c[end]\n\t"
        ".equ hks_k_lx, %c[lx]\n\t" ".equ hks_k_lg, %c[lg]\n\t" ".equ hks_k_lz, %c[lz]\n\t" ".equ hks_k_la, %c[la]\n\t"
        ".equ hks_k_lm, %c[lm]\n\t" ".equ hks_k_lstep, %c[lstep]\n\t" ".equ hks_k_ldz, %c[ldz]\n\t"
        ".equ hks_k_rx, %c[rx]\n\t"
        ".equ hks_k_rg, %c[rg]\n\t" ".equ hks_k_ra, %c[ra]\n\t" ".equ hks_k_rm, %c[rm]\n\t"
        ".equ hks_k_rstep, %c[rstep]\n\t"
        ".equ hks_k_dzdx, %c[dzdx]\n\t" ".equ hks_k_next_x, %c[next_x]\n\t" ".equ hks_k_next_g, %c[next_g]\n\t"
        ".equ hks_k_next_a, %c[next_a]\n\t"
        ".equ hks_k_next_m, %c[next_m]\n\t" ".equ hks_k_next_step, %c[next_step]\n\t"
        ".equ hks_k_next_left, %c[next_left]\n\t"
        :
        : [top] "i"(offsetof(KernelTriangle, top)), [row] "i"(offsetof(KernelTriangle, row)),
          [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)),
          [lx] "i"(offsetof(RowKernel, lx)), [lg] "i"(offsetof(RowKernel, lg)),
          [lz] "i"(offsetof(RowKernel, lz)), [la] "i"(offsetof(RowKernel, la)),
          [lm] "i"(offsetof(RowKernel, lm)), [lstep] "i"(offsetof(RowKernel, lstep)),
          [ldz] "i"(offsetof(RowKernel, ldz)), [rx] "i"(offsetof(RowKernel, rx)),
          [rg] "i"(offsetof(RowKernel, rg)), [ra] "i"(offsetof(RowKernel, ra)),
          [rm] "i"(offsetof(RowKernel, rm)), [rstep] "i"(offsetof(RowKernel, rstep)),
          [dzdx] "i"(offsetof(RowKernel, dzdx)), [next_x] "i"(offsetof(KernelTriangle, next_x)),
          [next_g] "i"(offsetof(KernelTriangle, next_g)), [next_a] "i"(offsetof(KernelTriangle, next_a)),
          [next_m] "i"(offsetof(KernelTriangle, next_m)), [next_step] "i"(offsetof(KernelTriangle, next_step)),
          [next_left] "i"(offsetof(KernelTriangle, next_left)));
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
        "ldr    r7, [r4, %[x_origin]]\n\t"
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
        "ldr    r7, [r4, %[y_origin]]\n\t"
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
        "strh   r0, [r6, #hks_k_top]\n\t"
        "strh   r5, [r6, #hks_k_row]\n\t"
        "strh   r1, [r6, #hks_k_mid]\n\t"
        "strh   r3, [r6, #hks_k_end]\n\t"
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
        "str    r0, [r6, #hks_k_dzdx]\n\t"
        "hks_numerator hks_e\n\t"
        "bl     60f\n\t"                      // dzdy
        "str    r0, [sp, #hks_dzdy]\n\t"
        ".purgem hks_numerator\n\t"
        // Reference pixel (the cell holding v0) and z_ref = z0 + round((dzdx ox + dzdy oy) / 16).
        "ldr    r4, [sp, #hks_band]\n\t"
        "ldr    r1, [r4, %[x_origin]]\n\t"
        "ldr    r2, [sp, #hks_x0]\n\t"
        "subs   r3, r2, r1\n\t"
        "adds   r3, #8\n\t"
        "asrs   r3, r3, #4\n\t"
        "str    r3, [sp, #hks_refpx]\n\t"
        "lsls   r3, r3, #4\n\t"
        "adds   r3, r3, r1\n\t"
        "subs   r3, r3, r2\n\t"               // ox
        "ldr    r1, [r4, %[y_origin]]\n\t"
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
        "movs   r1, #hks_k_next_left\n\t"
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
        // The edge stores: hks_edge stores the walker in the frame (x 2 px, g, a, m and 2 q + stride) at
        // the record offsets given; hks_depth the plane at (px, r2) and dzdy + dzdx q (the left edge's).
        ".macro hks_edge x, g, a, m, step\n\t"
        "ldr    r6, [sp, #hks_out]\n\t"
        "ldr    r4, [sp, #hks_band]\n\t"
        "ldr    r0, [sp, #hks_px]\n\t"
        "lsls   r1, r0, #1\n\t"
        "str    r1, [r6, #\\x]\n\t"
        "ldr    r1, [sp, #hks_g]\n\t"
        "str    r1, [r6, #\\g]\n\t"
        "ldr    r1, [sp, #hks_a]\n\t"
        "str    r1, [r6, #\\a]\n\t"
        "ldr    r1, [sp, #hks_mm]\n\t"
        "str    r1, [r6, #\\m]\n\t"
        "ldr    r3, [sp, #hks_q]\n\t"
        "lsls   r1, r3, #1\n\t"
        "ldr    r5, [r4, %[stride]]\n\t"
        "adds   r1, r1, r5\n\t"
        "str    r1, [r6, #\\step]\n\t"       // 2 q + stride
        ".endm\n\t"
        ".macro hks_depth z, dz\n\t"
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
        "str    r0, [r6, #\\z]\n\t"          // plane.at(px, row)
        "muls   r3, r5, r3\n\t"
        "adds   r3, r3, r7\n\t"
        "str    r3, [r6, #\\dz]\n\t"         // dzdy + dzdx q
        ".endm\n"
        "44:\n\t"                            // the left edge, r2 its row
        "hks_edge hks_k_lx, hks_k_lg, hks_k_la, hks_k_lm, hks_k_lstep\n\t"
        "hks_depth hks_k_lz, hks_k_ldz\n\t"
        "bx     lr\n"
        "46:\n\t"                            // the right edge
        "hks_edge hks_k_rx, hks_k_rg, hks_k_ra, hks_k_rm, hks_k_rstep\n\t"
        "bx     lr\n"
        "48:\n\t"                            // the next (lower short) edge
        "hks_edge hks_k_next_x, hks_k_next_g, hks_k_next_a, hks_k_next_m, hks_k_next_step\n\t"
        "bx     lr\n"                        // (a left one's depth: the kernel's switch)
        ".purgem hks_edge\n\t"
        ".purgem hks_depth\n"
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
          [x_origin] "i"(offsetof(KernelBand, x_origin)), [y_origin] "i"(offsetof(KernelBand, y_origin)),
          [table] "i"(kReciprocalTableData));
}
#endif

}  // namespace hider

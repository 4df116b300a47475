// kernel_setup_portable() (kernel_triangle.hpp) in Thumb-2 for ARMv7-M. At -Os GCC keeps about a
// hundred bytes of the set-up on the stack (three vertices, the sorted ones, the plane, three walkers);
// here the sorted vertices, the plane and the walkers each live in registers while they are used, and
// move between phases with one load- or store-multiple. Part of kernel_setup_asm.hpp: include that header
// (or kernel_triangle.hpp), not this one.
#pragma once
#include <hider/raster/kernel_triangle.hpp>

namespace hider {

#if defined(HIDER_ARMV7M)
/// The Thumb-2 set-up's text, shared by kernel_setup_v7m() and kernel_draw_v7m(): HIDER_V7M_SETUP_MACROS
/// (the assembler macros below), HIDER_V7M_SETUP (from the entry to the complete record: on to local label
/// 16 without a lower short edge in [y0, end), to 17 with one and lr = end; r4 the band, r6 the record),
/// HIDER_V7M_SETUP_EXITS (labels 90..93, then the large-divisor quotients), HIDER_V7M_SETUP_PURGE and the
/// operands HIDER_V7M_SETUP_OPERANDS. Stack at 16: the plane (5 words), the rows (10: mid, odd, y0, xt,
/// yt, xm, ym, xb, yb, y1), the vertices and |area| (4), then the nine saved registers.
#define HIDER_V7M_SETUP_MACROS \
/* Rounded quotient of the signed 64-bit \hi:\lo by d = r9 into \lo (|q| < 2^31, else generic); */ \
/* scratch r1 r2 r11 r12. Small divisors: two 16-bit digits, one udiv each. */                     \
    ".macro hider_divr lo, hi, far, back\n\t"                                                       \
    "asr    r11, \\hi, #31\n\t"                                                                     \
    "eor    \\lo, \\lo, r11\n\t"                                                                    \
    "eor    \\hi, \\hi, r11\n\t"                                                                    \
    "subs   \\lo, \\lo, r11\n\t"                                                                    \
    "sbc    \\hi, \\hi, r11\n\t"          /* |n| */                                                 \
    "adds   \\lo, \\lo, r9, lsr #1\n\t"                                                             \
    "adc    \\hi, \\hi, #0\n\t"           /* m = |n| + d / 2 */                                     \
    "lsl    r1, \\hi, #1\n\t"                                                                       \
    "orr    r1, r1, \\lo, lsr #31\n\t"                                                              \
    "cmp    r1, r9\n\t"                                                                             \
    "bhs    93f\n\t"                      /* m / d >= 2^31 */                                       \
    "cmp    r9, #0x10000\n\t"                                                                       \
    "bhs    \\far\\()f\n\t"               /* a large divisor: out of line (hider_divr_far) */       \
    "lsl    r1, \\hi, #16\n\t"                                                                      \
    "orr    r1, r1, \\lo, lsr #16\n\t"    /* m >> 16, below d 2^16 */                               \
    "udiv   r2, r1, r9\n\t"                                                                         \
    "mls    r1, r2, r9, r1\n\t"                                                                     \
    "lsl    r1, r1, #16\n\t"                                                                        \
    "bfi    r1, \\lo, #0, #16\n\t"                                                                  \
    "udiv   r1, r1, r9\n\t"                                                                         \
    "add    r2, r1, r2, lsl #16\n"                                                                  \
    "\\back:\n\t"                                                                                   \
    "eor    \\lo, r2, r11\n\t"                                                                      \
    "sub    \\lo, \\lo, r11\n\t"                                                                    \
    ".endm\n\t"                                                                                     \
/* The large-divisor quotient of hider_divr, after the exits: m / d in two 16-bit digits of the normalised */ \
/* divisor (Hacker's Delight divlu: each digit a udiv by its top half; the high one, below 2^15 as q < 2^31, */   \
/* needs one correction at most, the low one two), q into r2, back to label `back`; r4-r7 saved around */       \
/* it, r1 r12 and lo hi clobbered. Local labels 65, 69, 70. */                                              \
    ".macro hider_divr_far lo, hi, far, back\n"                                                               \
    "\\far:\n\t"                                                                                              \
    "push   {r4-r7}\n\t"                                                                                      \
    "clz    r12, r9\n\t"                  /* s */                                                             \
    "lsl    r1, r9, r12\n\t"              /* v = d << s */                                                    \
    "lsl    \\hi, \\hi, r12\n\t"                                                                              \
    "rsb    r2, r12, #32\n\t"                                                                                 \
    "lsr    r2, \\lo, r2\n\t"             /* lo >> (32 - s): 0 for s = 0 */                                   \
    "orr    \\hi, \\hi, r2\n\t"           /* un32 */                                                          \
    "lsl    r5, \\lo, r12\n\t"            /* un10 */                                                          \
    "lsr    r12, r1, #16\n\t"             /* vn1 */                                                           \
    "uxth   r4, r1\n\t"                   /* vn0 */                                                           \
    "udiv   r2, \\hi, r12\n\t"            /* q1 */                                                            \
    "mls    r6, r2, r12, \\hi\n"          /* rhat */                                                          \
    "mul    r7, r2, r4\n\t"                                                                                   \
    "lsr    \\lo, r5, #16\n\t"                                                                                \
    "orr    \\lo, \\lo, r6, lsl #16\n\t"  /* rhat b + un1 */                                                  \
    "cmp    r7, \\lo\n\t"                                                                                     \
    "it     hi\n\t"                                                                                           \
    "subhi  r2, r2, #1\n"                 /* one correction at most: q < 2^31 keeps q1 <= 2^15 */             \
    "lsr    r7, r5, #16\n\t"                                                                                  \
    "add    r7, r7, \\hi, lsl #16\n\t"                                                                        \
    "mls    r7, r2, r1, r7\n\t"           /* un21 = un32 b + un1 - q1 v */                                    \
    "udiv   \\hi, r7, r12\n\t"            /* q0 */                                                            \
    "mls    r6, \\hi, r12, r7\n"          /* rhat */                                                          \
    "69:\n\t"                                                                                                 \
    "cmp    \\hi, #0x10000\n\t"                                                                               \
    "bhs    70f\n\t"                                                                                          \
    "mul    \\lo, \\hi, r4\n\t"                                                                               \
    "uxth   r7, r5\n\t"                                                                                       \
    "orr    r7, r7, r6, lsl #16\n\t"      /* rhat b + un0 */                                                  \
    "cmp    \\lo, r7\n\t"                                                                                     \
    "bls    65f\n"                                                                                            \
    "70:\n\t"                                                                                                 \
    "sub    \\hi, \\hi, #1\n\t"                                                                               \
    "add    r6, r6, r12\n\t"                                                                                  \
    "cmp    r6, #0x10000\n\t"                                                                                 \
    "blo    69b\n"                                                                                            \
    "65:\n\t"                                                                                                 \
    "orr    r2, \\hi, r2, lsl #16\n\t"    /* q = q1 b + q0 */                                                 \
    "pop    {r4-r7}\n\t"                                                                                      \
    "b      \\back\\()b\n\t"                                                                                  \
    ".endm\n\t"                                                                                               \
/* Walker (edge.hpp), inline: in r5 xu, r7 yu, r8 xl, r9 yl, r3 row; out r0 px, r1 g - a, r2 a, */ \
/* r3 m, r12 q (local labels 81..89). */                                                           \
    ".macro hider_walk\n\t"                                                                        \
    "sub    r8, r8, r5\n\t"               /* dx */                                                 \
    "sub    r9, r9, r7\n\t"               /* dy */                                                 \
    "lsl    r2, r9, #4\n\t"               /* a = 16 dy */                                          \
    "add    r12, r11, r3, lsl #4\n\t"     /* row centre */                                         \
    "sub    r12, r12, r7\n\t"                                                                      \
    "sub    r0, r10, r5\n\t"                                                                       \
    "mul    r0, r9, r0\n\t"                                                                        \
    "mls    r3, r8, r12, r0\n\t"          /* g0 = dy (x_origin - xu) - dx (yc - yu) */             \
    "cmp    r3, #0\n\t"                                                                            \
    "blt    81f\n\t"                                                                               \
    "udiv   r0, r3, r2\n\t"               /* px = -floor(g0 / a) */                                \
    "neg    r0, r0\n\t"                                                                            \
    "b      82f\n"                                                                                 \
    "81:\n\t"                                                                                      \
    "mvn    r0, r3\n\t"                                                                            \
    "udiv   r0, r0, r2\n\t"                                                                        \
    "add    r0, r0, #1\n"                                                                          \
    "82:\n\t"                                                                                      \
    "mla    r1, r0, r2, r3\n\t"           /* g = g0 + px a */                                      \
    "sub    r1, r1, r2\n\t"               /* biased by -a */                                       \
    "lsl    r3, r8, #4\n\t"                                                                        \
    "negs   r3, r3\n\t"                  /* dg = -16 dx */                                         \
    "blt    83f\n\t"                                                                               \
    "cmp    r3, r2\n\t"                                                                            \
    "bge    88f\n\t"                                                                               \
    "movs   r12, #0\n\t"                  /* 0 <= dg < a: q = 0, m = dg */                         \
    "b      87f\n"                                                                                 \
    "83:\n\t"                                                                                      \
    "cmn    r3, r2\n\t"                                                                            \
    "blt    89f\n\t"                                                                               \
    "movs   r12, #1\n\t"                  /* -a <= dg < 0: q = 1, m = dg + a */                    \
    "add    r3, r3, r2\n\t"                                                                        \
    "b      87f\n"                                                                                 \
    "88:\n\t"                                                                                      \
    "udiv   r12, r3, r2\n\t"              /* dg >= a: q = -floor(dg / a) */                        \
    "neg    r12, r12\n\t"                                                                          \
    "mla    r3, r12, r2, r3\n\t"                                                                   \
    "b      87f\n"                                                                                 \
    "89:\n\t"                                                                                      \
    "mvn    r12, r3\n\t"                  /* dg < -a */                                            \
    "udiv   r12, r12, r2\n\t"                                                                      \
    "add    r12, r12, #1\n\t"                                                                      \
    "mla    r3, r12, r2, r3\n"                                                                     \
    "87:\n\t"                                                                                      \
    ".endm\n\t"                                                                                    \
/* Left edge store: r0 px, r1 g - a, r2 a, r3 m, r12 q, r9 its row; depth from the plane at sp. */ \
    ".macro hider_left\n\t"                                                                        \
    "lsl    r8, r0, #1\n\t"                                                                        \
    "strd   r8, r1, [r6, %[lx]]\n\t"                                                               \
    "ldr    r8, [r4, %[stride]]\n\t"                                                               \
    "add    r8, r8, r12, lsl #1\n\t"                                                               \
    "add    r1, r6, %[la]\n\t"                                                                     \
    "stm    r1, {r2, r3, r8}\n\t"                                                                  \
    "ldm    sp, {r1, r2, r3, r5, r7}\n\t"  /* dzdx ref_px z_ref dzdy ref_py */                     \
    "sub    r0, r0, r2\n\t"                                                                        \
    "mla    r3, r1, r0, r3\n\t"                                                                    \
    "sub    r9, r9, r7\n\t"                                                                        \
    "mla    r3, r5, r9, r3\n\t"                                                                    \
    "mla    r5, r1, r12, r5\n\t"                                                                   \
    "str    r3, [r6, %[lz]]\n\t"                                                                   \
    "str    r5, [r6, %[ldz]]\n\t"                                                                  \
    ".endm\n\t"                                                                                    \
/* Right edge store. */                                                                            \
    ".macro hider_right\n\t"                                                                       \
    "lsl    r8, r0, #1\n\t"                                                                        \
    "strd   r8, r1, [r6, %[rx]]\n\t"                                                               \
    "ldr    r8, [r4, %[stride]]\n\t"                                                               \
    "add    r8, r8, r12, lsl #1\n\t"                                                               \
    "add    r1, r6, %[ra]\n\t"                                                                     \
    "stm    r1, {r2, r3, r8}\n\t"                                                                  \
    ".endm\n\t"

#define HIDER_V7M_SETUP \
    "push   {r4-r11, lr}\n\t"                                                                        \
    "ldm    r3, {r4, r5, r6}\n\t"         /* band, area, out */                                      \
    "cmp    r5, #0\n\t"                                                                              \
    "itttt  lt\n\t"                       /* clockwise on the image: a, c, b */                      \
    "movlt  r7, r1\n\t"                                                                              \
    "movlt  r1, r2\n\t"                                                                              \
    "movlt  r2, r7\n\t"                                                                              \
    "neglt  r5, r5\n\t"                                                                              \
    "push   {r0, r1, r2, r5}\n\t"                                                                    \
    "ldrsh  r7, [r0]\n\t"                 /* r7 r8: top, r9 r10: mid, r11 r12: bottom */             \
    "ldrsh  r8, [r0, #2]\n\t"                                                                        \
    "ldrsh  r9, [r1]\n\t"                                                                            \
    "ldrsh  r10, [r1, #2]\n\t"                                                                       \
    "ldrsh  r11, [r2]\n\t"                                                                           \
    "ldrsh  r12, [r2, #2]\n\t"                                                                       \
    "movs   r3, #0\n\t"                   /* 1: odd permutation, the long edge on the right */       \
    "cmp    r10, r8\n\t"                                                                             \
    "bge    1f\n\t"                                                                                  \
    "mov    r0, r7\n\t" "mov r7, r9\n\t" "mov r9, r0\n\t"                                            \
    "mov    r0, r8\n\t" "mov r8, r10\n\t" "mov r10, r0\n\t"                                          \
    "eor    r3, r3, #1\n"                                                                            \
    "1:\n\t"                                                                                         \
    "cmp    r12, r10\n\t"                                                                            \
    "bge    2f\n\t"                                                                                  \
    "mov    r0, r9\n\t" "mov r9, r11\n\t" "mov r11, r0\n\t"                                          \
    "mov    r0, r10\n\t" "mov r10, r12\n\t" "mov r12, r0\n\t"                                        \
    "eor    r3, r3, #1\n"                                                                            \
    "2:\n\t"                                                                                         \
    "cmp    r10, r8\n\t"                                                                             \
    "bge    3f\n\t"                                                                                  \
    "mov    r0, r7\n\t" "mov r7, r9\n\t" "mov r9, r0\n\t"                                            \
    "mov    r0, r8\n\t" "mov r8, r10\n\t" "mov r10, r0\n\t"                                          \
    "eor    r3, r3, #1\n"                                                                            \
    "3:\n\t"                                                                                         \
    "cmp    r7, r9\n\t"                   /* r0 = x_min, r1 = x_max */                               \
    "itete  lt\n\t"                                                                                  \
    "movlt  r0, r7\n\t"                                                                              \
    "movge  r0, r9\n\t"                                                                              \
    "movlt  r1, r9\n\t"                                                                              \
    "movge  r1, r7\n\t"                                                                              \
    "cmp    r11, r0\n\t"                                                                             \
    "it     lt\n\t"                                                                                  \
    "movlt  r0, r11\n\t"                                                                             \
    "cmp    r11, r1\n\t"                                                                             \
    "it     gt\n\t"                                                                                  \
    "movgt  r1, r11\n\t"                                                                             \
    "ldrd   r2, r5, [r4, %[y_first]]\n\t"                                                            \
    "cmp    r12, r2\n\t"                                                                             \
    "blt    90f\n\t"                      /* below the band's first centre: none */                  \
    "cmp    r8, r5\n\t"                                                                              \
    "bgt    90f\n\t"                      /* above its last: none */                                 \
    "ldrd   r2, r5, [r4]\n\t"             /* x_origin, y_origin */                                   \
    "ldr    lr, [r4, %[x_last]]\n\t"                                                                 \
    "cmp    r0, r2\n\t"                                                                              \
    "blt    92f\n\t"                      /* past the columns: generic */                            \
    "cmp    r1, lr\n\t"                                                                              \
    "bgt    92f\n\t"                                                                                 \
    "sub    r0, r0, r2\n\t"                                                                          \
    "add    r0, r0, #15\n\t"                                                                         \
    "bic    r0, r0, #15\n\t"                                                                         \
    "add    r0, r0, r2\n\t"                                                                          \
    "cmp    r0, r1\n\t"                                                                              \
    "bgt    90f\n\t"                      /* no column centre in the box: none */                    \
    "sub    r0, r8, r5\n\t"                                                                          \
    "add    r0, r0, #15\n\t"                                                                         \
    "bic    r1, r0, #15\n\t"                                                                         \
    "add    r1, r1, r5\n\t"                                                                          \
    "cmp    r1, r12\n\t"                                                                             \
    "bgt    90f\n\t"                      /* no row centre in the box: none */                       \
    "asr    r0, r0, #4\n\t"               /* top row */                                              \
    "sub    r1, r10, r5\n\t"                                                                         \
    "add    r1, r1, #15\n\t"                                                                         \
    "asr    r1, r1, #4\n\t"               /* middle row */                                           \
    "sub    r2, r12, r5\n\t"                                                                         \
    "add    r2, r2, #15\n\t"                                                                         \
    "asr    r2, r2, #4\n\t"               /* bottom row */                                           \
    "ldrd   r5, lr, [r4, %[row_from]]\n\t"                                                           \
    "cmp    r0, r5\n\t"                                                                              \
    "it     gt\n\t"                                                                                  \
    "movgt  r5, r0\n\t"                   /* y0 = max(top, row_from) */                              \
    "cmp    r2, lr\n\t"                                                                              \
    "it     lt\n\t"                                                                                  \
    "movlt  lr, r2\n\t"                   /* y1 = min(bottom, row_end) */                            \
    "strh   r0, [r6, %[top]]\n\t"                                                                    \
    "strh   r5, [r6, %[row]]\n\t"                                                                    \
    "strh   r1, [r6, %[mid]]\n\t"                                                                    \
    "strh   lr, [r6, %[end]]\n\t"                                                                    \
    "cmp    r5, lr\n\t"                                                                              \
    "bge    91f\n\t"                      /* no row: set up, nothing to draw */                      \
    "push   {r1, r3, r5, r7-r12, lr}\n\t" /* mid odd y0 xt yt xm ym xb yb y1 */                      \
/* The plane (plane.hpp): numerators from three long multiplies each, then two rounded quotients. */ \
    "add    r0, sp, #40\n\t"                                                                         \
    "ldm    r0, {r0, r1, r2, r9}\n\t"     /* v0 v1 v2 area */                                        \
    "ldr    r8, [r0, #4]\n\t"                                                                        \
    "ldrsh  r5, [r0]\n\t"                 /* x0 */                                                   \
    "ldrsh  r7, [r0, #2]\n\t"             /* y0 */                                                   \
    "ldrsh  r10, [r1, #2]\n\t"                                                                       \
    "ldr    r11, [r1, #4]\n\t"                                                                       \
    "ldrsh  r1, [r1]\n\t"                                                                            \
    "ldrsh  r12, [r2]\n\t"                                                                           \
    "ldrsh  lr, [r2, #2]\n\t"                                                                        \
    "ldr    r2, [r2, #4]\n\t"                                                                        \
    "lsl    r1, r1, #4\n\t"               /* the differences times 16 (below 2^20): the */           \
    "sub    r1, r1, r5, lsl #4\n\t"       /* numerators come out whole, no 64-bit shift */           \
    "lsl    r10, r10, #4\n\t"                                                                        \
    "sub    r10, r10, r7, lsl #4\n\t"     /* 16 dy1 */                                               \
    "lsl    r12, r12, #4\n\t"                                                                        \
    "sub    r12, r12, r5, lsl #4\n\t"     /* 16 dx2 */                                               \
    "lsl    lr, lr, #4\n\t"                                                                          \
    "sub    lr, lr, r7, lsl #4\n\t"       /* 16 dy2 */                                               \
    "eor    r8, r8, #0x80000000\n\t"      /* s = z - 2^31 */                                         \
    "eor    r11, r11, #0x80000000\n\t"                                                               \
    "eor    r2, r2, #0x80000000\n\t"                                                                 \
    "sub    r3, r10, lr\n\t"              /* npx = 16 (s0 (dy1 - dy2) + s1 dy2 - s2 dy1) */          \
    "smull  r0, r3, r8, r3\n\t"                                                                      \
    "smlal  r0, r3, r11, lr\n\t"                                                                     \
    "neg    r10, r10\n\t"                                                                            \
    "smlal  r0, r3, r2, r10\n\t"                                                                     \
    "sub    lr, r12, r1\n\t"              /* nqy = 16 (s0 (dx2 - dx1) + s2 dx1 - s1 dx2) */          \
    "smull  r10, lr, r8, lr\n\t"                                                                     \
    "smlal  r10, lr, r2, r1\n\t"                                                                     \
    "neg    r12, r12\n\t"                                                                            \
    "smlal  r10, lr, r11, r12\n\t"                                                                   \
    "hider_divr r0, r3, 60, 61\n\t"       /* dzdx */                                                 \
    "hider_divr r10, lr, 62, 63\n\t"      /* dzdy */                                                 \
    "ldrd   r1, r2, [r4]\n\t"             /* reference pixel: the cell holding v0 */                 \
    "sub    r5, r5, r1\n\t"                                                                          \
    "add    r3, r5, #8\n\t"                                                                          \
    "bic    r3, r3, #15\n\t"                                                                         \
    "sub    r5, r3, r5\n\t"               /* ox */                                                   \
    "asr    r3, r3, #4\n\t"               /* ref_px */                                               \
    "sub    r7, r7, r2\n\t"                                                                          \
    "add    r12, r7, #8\n\t"                                                                         \
    "bic    r12, r12, #15\n\t"                                                                       \
    "sub    r7, r12, r7\n\t"              /* oy */                                                   \
    "asr    r12, r12, #4\n\t"             /* ref_py */                                               \
    "smull  r1, r2, r0, r5\n\t"           /* z_ref = z0 + round((dzdx ox + dzdy oy) / 16) */         \
    "smlal  r1, r2, r10, r7\n\t"                                                                     \
    "asr    r11, r2, #31\n\t"                                                                        \
    "add    r11, r11, #8\n\t"            /* 8, less 1 below zero: halves away from zero */          \
    "adds   r1, r1, r11\n\t"                                                                         \
    "adc    r2, r2, #0\n\t"                                                                          \
    "lsr    r1, r1, #4\n\t"                                                                          \
    "orr    r1, r1, r2, lsl #28\n\t"                                                                 \
    "eor    r8, r8, #0x80000000\n\t"                                                                 \
    "add    r8, r8, r1\n\t"                                                                          \
    "str    r0, [r6, %[dzdx]]\n\t"                                                                   \
    "push   {r0, r3, r8, r10, r12}\n\t"   /* dzdx ref_px z_ref dzdy ref_py; the rows at sp + 20 */   \
    "ldrd   r10, r11, [r4]\n\t"           /* x_origin, y_origin for the walkers */                   \
/* The long edge (top -> bottom) on row y0: the left edge for an even permutation. */                \
    "ldrd   r5, r7, [sp, #32]\n\t"        /* xt yt */                                                \
    "ldrd   r8, r9, [sp, #48]\n\t"        /* xb yb */                                                \
    "ldr    r3, [sp, #28]\n\t"            /* y0 */                                                   \
    "hider_walk\n\t"                                                                                 \
    "ldr    lr, [sp, #24]\n\t"                                                                       \
    "cmp    lr, #0\n\t"                                                                              \
    "bne    10f\n\t"                                                                                 \
    "ldr    r9, [sp, #28]\n\t"                                                                       \
    "hider_left\n\t"                      /* left, with its depth */                                 \
    "b      11f\n"                                                                                   \
    "10:\n\t"                                                                                        \
    "hider_right\n"                        /* right */                                               \
    "11:\n\t"                                                                                        \
/* The short edge on row y0: top -> mid above the middle row, mid -> bottom from it on. */           \
    "ldrd   r3, r1, [sp, #20]\n\t"        /* mid, odd */                                             \
    "ldr    r2, [sp, #28]\n\t"            /* y0 */                                                   \
    "cmp    r2, r3\n\t"                                                                              \
    "bge    12f\n\t"                                                                                 \
    "ldrd   r5, r7, [sp, #32]\n\t"        /* xt yt */                                                \
    "ldrd   r8, r9, [sp, #40]\n\t"        /* xm ym */                                                \
    "b      13f\n"                                                                                   \
    "12:\n\t"                                                                                        \
    "ldrd   r5, r7, [sp, #40]\n\t"        /* xm ym */                                                \
    "ldrd   r8, r9, [sp, #48]\n\t"        /* xb yb */                                                \
    "13:\n\t"                                                                                        \
    "mov    r3, r2\n\t"                                                                              \
    "hider_walk\n\t"                                                                                 \
    "ldr    lr, [sp, #24]\n\t"                                                                       \
    "cmp    lr, #0\n\t"                                                                              \
    "beq    14f\n\t"                                                                                 \
    "ldr    r9, [sp, #28]\n\t"                                                                       \
    "hider_left\n\t"                      /* left */                                                 \
    "b      15f\n"                                                                                   \
    "14:\n\t"                                                                                        \
    "hider_right\n"                        /* right */                                               \
    "15:\n\t"                                                                                        \
/* The lower short edge from the middle row, when it starts inside [y0, y1). */                      \
    "ldr    r1, [sp, #24]\n\t"                                                                       \
    "strb   r1, [r6, %[next_left]]\n\t"                                                              \
    "ldrd   r3, r1, [sp, #20]\n\t"        /* mid (odd unused) */                                     \
    "ldr    r2, [sp, #28]\n\t"            /* y0 */                                                   \
    "cmp    r2, r3\n\t"                                                                              \
    "bge    16f\n\t"                      /* y0 >= mid: no upper part */                             \
    "ldr    lr, [sp, #56]\n\t"            /* y1, kept in lr for label 17 (the walker leaves it) */   \
    "cmp    r3, lr\n\t"                                                                              \
    "bge    16f\n\t"                      /* mid >= y1: the lower edge never runs */                 \
    "ldrd   r5, r7, [sp, #40]\n\t"        /* xm ym */                                                \
    "ldrd   r8, r9, [sp, #48]\n\t"        /* xb yb */                                                \
    "hider_walk\n\t"                                                                                 \
    "lsl    r8, r0, #1\n\t"                                                                          \
    "strd   r8, r1, [r6, %[next_x]]\n\t"                                                             \
    "ldr    r8, [r4, %[stride]]\n\t"                                                                 \
    "add    r8, r8, r12, lsl #1\n\t"      /* step = 2 q + stride */                                  \
    "add    r9, r6, %[next_a]\n\t"                                                                   \
    "stm    r9, {r2, r3, r8}\n\t"        /* a m step (a left one's depth: the kernel's switch) */    \
    "b      17f\n"

#define HIDER_V7M_SETUP_EXITS \
    "90:\n\t"                                                                         \
    "movs   r0, #0\n\t"                   /* none */                                  \
    "add    sp, sp, #16\n\t"                                                          \
    "pop    {r4-r11, pc}\n"                                                           \
    "91:\n\t"                                                                         \
    "movs   r0, #1\n\t"                   /* kernel, no rows */                       \
    "add    sp, sp, #16\n\t"                                                          \
    "pop    {r4-r11, pc}\n"                                                           \
    "92:\n\t"                                                                         \
    "movs   r0, #2\n\t"                   /* generic */                               \
    "add    sp, sp, #16\n\t"                                                          \
    "pop    {r4-r11, pc}\n"                                                           \
    "93:\n\t"                                                                         \
    "movs   r0, #2\n\t"                   /* generic: a depth step of 2^31 or more */ \
    "add    sp, sp, #56\n\t"                                                          \
    "pop    {r4-r11, pc}\n\t"                                                         \
    "hider_divr_far r0, r3, 60, 61\n\t"                                               \
    "hider_divr_far r10, lr, 62, 63\n"

#define HIDER_V7M_SETUP_PURGE \
    ".purgem hider_divr\n\t" \
    ".purgem hider_divr_far\n\t" \
    ".purgem hider_walk\n\t" \
    ".purgem hider_left\n\t" \
    ".purgem hider_right\n"

#define HIDER_V7M_SETUP_OPERANDS \
    [y_first] "i"(offsetof(KernelBand, y_first)), [x_last] "i"(offsetof(KernelBand, x_last)), \
    [row_from] "i"(offsetof(KernelBand, row_from)), [stride] "i"(offsetof(KernelBand, stride_bytes)), \
    [top] "i"(offsetof(KernelTriangle, top)), [row] "i"(offsetof(KernelTriangle, row)), \
    [mid] "i"(offsetof(KernelTriangle, mid)), [end] "i"(offsetof(KernelTriangle, end)), \
    [dzdx] "i"(offsetof(RowKernel, dzdx)), \
    [lx] "i"(offsetof(RowKernel, lx)), [lz] "i"(offsetof(RowKernel, lz)), [la] "i"(offsetof(RowKernel, la)), \
    [ldz] "i"(offsetof(RowKernel, ldz)), [rx] "i"(offsetof(RowKernel, rx)), [ra] "i"(offsetof(RowKernel, ra)), \
    [next_x] "i"(offsetof(KernelTriangle, next_x)), [next_a] "i"(offsetof(KernelTriangle, next_a)), \
    [next_left] "i"(offsetof(KernelTriangle, next_left))

/// Returns the KernelSetup value. Stack while the plane is computed: sorted vertices and rows (10 words)
/// below v0 v1 v2 |area| (4 words, the higher addresses); during the walkers the plane (5 words) below
/// the rows. The walker is an
/// assembler macro expanded at each of its three uses (hider_walk: no call and return): in r5 xu, r7 yu,
/// r8 xl, r9 yl, r3 row, r10 x_origin, r11 y_origin; out r0 px, r1 g - a, r2 a, r3 m, r12 q; the edge
/// stores (hider_left, hider_right) turn px and q into the kernel's bytes (2 px, 2 q + stride).
HIDER_NAKED inline uint32_t kernel_setup_v7m(const ScreenVertex*, const ScreenVertex*,
                                                                  const ScreenVertex*, KernelSetupIo*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V7M_SETUP_MACROS
        HIDER_V7M_SETUP
        "16:\n"
        "17:\n\t"
        "movs   r0, #1\n\t"                   // kernel
        "add    sp, sp, #76\n\t"
        "pop    {r4-r11, pc}\n"
        HIDER_V7M_SETUP_EXITS
        HIDER_V7M_SETUP_PURGE
        :
        : HIDER_V7M_SETUP_OPERANDS);
}

/// kernel_draw_v7m()'s entry to the row loop, common to its labels 16 and 17: from r5 = y0, lr = end, r4
/// the band and r6 the record, the stop and n (r11) rows (none: to 95), `row` moved on, r1 the depth row
/// of y0, r9 the one after the last, r8 -1 (no rows after a switch).
#define HIDER_V7M_DRAW_ENTRY \
    "ldr    r2, [r4, %[b_stop]]\n\t" \
    "cmp    r2, lr\n\t" \
    "it     gt\n\t" \
    "movgt  r2, lr\n\t"                 /* stop = min(end, band stop) */ \
    "subs   r11, r2, r5\n\t"            /* n rows */ \
    "ble    95f\n\t"                    /* none before the stop: `row` stays y0 */ \
    "strh   r2, [r6, %[row]]\n\t"       /* the row after this call */ \
    "ldrd   r12, r9, [r4, %[stride]]\n\t"  /* stride, depth origin */ \
    "mla    r1, r5, r12, r9\n\t"        /* the depth row of y0 */ \
    "mla    r9, r11, r12, r1\n\t"       /* the depth row after the last */ \
    "mov    r8, #-1\n\t"                /* rows after a switch: none */

/// kernel_setup_v7m() and, for a set-up with rows, run_kernel_triangle_v7m() in one call: the set-up's
/// registers and frame go straight into the row loop (HIDER_V7M_ROWS) from io->band's depth_origin, stop
/// and color_less_2, without the record's round trip through the caller. The caller stores the colour
/// in io->out first. Returns the KernelSetup value; a kernel set-up has drawn its rows before
/// min(end, stop) and left `row` there (on `y0` when none lies before the stop), as the separate calls do.
HIDER_NAKED inline uint32_t kernel_draw_v7m(const ScreenVertex*, const ScreenVertex*, const ScreenVertex*,
                                            KernelSetupIo*) {
    __asm__ volatile(
        ".syntax unified\n\t"
        HIDER_V7M_SETUP_MACROS
        HIDER_V7M_SETUP
        // run_kernel_triangle_v7m()'s entry, from the set-up's frame. 16: no switch to a lower short edge
        // in this call; 17: a lower short edge from mid, y0 < mid < end (the switch, if mid <= stop).
        "16:\n\t"
        "ldr    r5, [sp, #28]\n\t"          // y0
        "ldr    lr, [sp, #56]\n\t"          // end
        HIDER_V7M_DRAW_ENTRY
        "b      1f\n"
        "17:\n\t"
        "ldr    r5, [sp, #28]\n\t"          // y0; lr = end
        HIDER_V7M_DRAW_ENTRY
        "ldr    r3, [sp, #20]\n\t"          // mid
        "sub    r7, r3, r5\n\t"             // m = mid - y0 > 0
        "cmp    r7, r11\n\t"
        "bgt    1f\n\t"                     // the middle row lies past this call
        "sub    r8, r11, r7\n\t"
        "mov    r11, r7\n\t"
        "mla    r7, r7, r12, r1\n"           // the middle row's depth row
        "1:\n\t"
        "add    sp, sp, #64\n\t"
        "stm    sp, {r7, r8, r9}\n\t"       // HIDER_V7M_ROWS's three words
        "ldr    r7, [r4, %[b_color]]\n\t"   // colour offset less the post-increment
        "mov    r9, r1\n\t"
        "ldrd   r8, r10, [r6, %[dzdx]]\n\t" // dzdx, colour
        "ldm    r6, {r1-r5}\n\t"            // lx lg lz rx rg
        "add    r1, r1, r9\n\t"             // lp
        "add    r4, r4, r9\n\t"             // rp
        "add    r0, r6, %[ra]\n\t"
        "mov    r6, r11\n"                   // rows before a switch
        HIDER_V7M_ROWS
        "add    sp, sp, #12\n\t"
        "movs   r0, #1\n\t"                 // kernel
        "pop    {r4-r11, pc}\n"
        "95:\n\t"
        "movs   r0, #1\n\t"                 // kernel, no row before the stop
        "add    sp, sp, #76\n\t"
        "pop    {r4-r11, pc}\n"
        HIDER_V7M_SETUP_EXITS
        HIDER_V7M_SETUP_PURGE
        :
        : HIDER_V7M_SETUP_OPERANDS, [b_stop] "i"(offsetof(KernelBand, stop)),
          [b_color] "i"(offsetof(KernelBand, color_less_2)),
          HIDER_V7M_ROWS_OPERANDS, HIDER_V7M_ROWS_STACK(0));
}
#endif

}  // namespace hider

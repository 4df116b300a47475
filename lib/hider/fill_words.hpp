// fill_words(): one 32-bit word stored to n words (the frame clears, the vertex cache's marks), with
// store-multiples on Cortex-M: eight 12-register ones per 96 words on ARMv7-M, eight 7-register ones per
// 56 words on ARMv6-M, each with its tail in assembly too; RV32 (no store-multiple) in 64-store runs.
#pragma once
#include <hider/base.hpp>

namespace hider {

namespace detail {
using AliasWord = uint32_t __attribute__((may_alias));  // fills 16-bit buffers two elements per store

#if defined(HIDER_ARMV7M)
/// Stores `word` to [p, blocks_end), a whole number of 96-word blocks (eight 12-register
/// store-multiples a pass), and first to the `tail` < 96 words after it: 8-register store-multiples,
/// then 4, 2 and 1 words by the tail's low bits.
HIDER_NAKED inline void fill_words_v7m(AliasWord*, AliasWord*, uint32_t, uint32_t) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        ".irp   reg, r4, r5, r6, r7, r8, r9, r10, r11\n\t"
        "mov    \\reg, r2\n\t"
        ".endr\n\t"
        "mov    r12, r1\n\t"              // the tail
        "subs   r3, r3, #8\n\t"
        "blt    3f\n"
        "2:\n\t"
        "stmia  r12!, {r4-r11}\n\t"
        "subs   r3, r3, #8\n\t"
        "bge    2b\n"
        "3:\n\t"                          // r3's low three bits: the tail's
        "tst    r3, #4\n\t"
        "it     ne\n\t"
        "stmiane r12!, {r4-r7}\n\t"
        "tst    r3, #2\n\t"
        "it     ne\n\t"
        "stmiane r12!, {r4, r5}\n\t"
        "tst    r3, #1\n\t"
        "it     ne\n\t"
        "strne  r4, [r12]\n\t"
        "cmp    r0, r1\n\t"
        "beq    5f\n\t"                   // no whole block
        "mov    r12, r1\n\t"
        ".irp   reg, r1, r3, lr\n\t"
        "mov    \\reg, r2\n\t"
        ".endr\n"
        "1:\n\t"
        ".rept  8\n\t"
        "stmia  r0!, {r1-r11, lr}\n\t"
        ".endr\n\t"
        "cmp    r0, r12\n\t"
        "bne    1b\n"
        "5:\n\t"
        "pop    {r4-r11, pc}\n");
}
#elif defined(__arm__) && defined(__thumb__)
/// n / 56 for n < 2^16 by a multiply (ARMv6-M has no divide instruction): fill_words()'s blocks.
constexpr uint32_t v6m_blocks_of_56(uint32_t n) { return ((n >> 3) * 9363) >> 16; }

/// fill_words()'s divisions by multiplies on ARMv6-M, checked for every value they meet: its blocks
/// (v6m_blocks_of_56()) and fill_words_v6m()'s tail / 7 = (37 tail) >> 8 for a tail below 56.
constexpr bool v6m_fill_divisions_exact() {
    for (uint32_t n = 0; n < 65536; ++n)
        if (v6m_blocks_of_56(n) != n / 56) return false;
    for (uint32_t t = 0; t < 56; ++t)
        if (((t * 37) >> 8) != t / 7) return false;
    return true;
}
static_assert(v6m_fill_divisions_exact(), "fill_words_v6m()'s multiplies divide exactly");

/// Stores `word` to [p, blocks_end), a whole number of 56-word blocks (eight 7-register store-multiples
/// a pass), then to the `tail` < 56 words after it: tail / 7 store-multiples, entered by a computed jump
/// into their ladder, and single stores for the rest.
HIDER_NAKED inline void fill_words_v6m(AliasWord*, AliasWord*, uint32_t, uint32_t) {
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r7, lr}\n\t"
        "mov    r12, r1\n\t"
        "mov    lr, r3\n\t"
        ".irp   reg, r1, r3, r4, r5, r6, r7\n\t"
        "movs   \\reg, r2\n\t"
        ".endr\n\t"
        "cmp    r0, r12\n\t"
        "beq    2f\n"
        "1:\n\t"
        ".rept  8\n\t"
        "stmia  r0!, {r1-r7}\n\t"
        ".endr\n\t"
        "cmp    r0, r12\n\t"
        "bne    1b\n"
        "2:\n\t"
        "mov    r1, lr\n\t"               // the tail
        "movs   r3, #37\n\t"
        "muls   r3, r1, r3\n\t"
        "lsrs   r3, r3, #8\n\t"           // c = tail / 7 (exact below 56)
        "movs   r4, #7\n\t"
        "muls   r4, r3, r4\n\t"
        "subs   r1, r1, r4\n\t"
        "mov    lr, r1\n\t"               // the single stores after them
        "lsls   r3, r3, #1\n\t"
        "adr    r4, 3f\n\t"
        "adds   r4, r4, #14\n\t"
        "subs   r4, r4, r3\n\t"           // the ladder's last c store-multiples
        "mov    r12, r4\n\t"
        ".irp   reg, r1, r3, r4\n\t"
        "movs   \\reg, r2\n\t"
        ".endr\n\t"
        "mov    pc, r12\n\t"
        ".balign 4\n"
        "3:\n\t"
        ".rept  7\n\t"
        "stmia  r0!, {r1-r7}\n\t"
        ".endr\n\t"
        "mov    r1, lr\n\t"
        "cmp    r1, #0\n\t"
        "beq    5f\n"
        "4:\n\t"
        "stmia  r0!, {r2}\n\t"
        "subs   r1, r1, #1\n\t"
        "bne    4b\n"
        "5:\n\t"
        "pop    {r4-r7, pc}\n");
}
#endif

}  // namespace detail

/// Stores `word` to the n 32-bit words at p (4-byte aligned; any object type: the stores may alias it),
/// with store-multiples where the CPU has them: clears and per-frame marks are a visible share of a
/// small frame's cost.
inline void fill_words(void* p, size_t n, uint32_t word) {
    detail::AliasWord* w = static_cast<detail::AliasWord*>(p);
#if defined(HIDER_ARMV7M)
    // Cortex-M3/M4: eight 12-register store-multiples per 96 words (GCC -Os emits one str per word, and
    // shorter store-multiples cost more per word), the tail in store-multiples too.
    const size_t blocks = n / 96;
    detail::fill_words_v7m(w, w + blocks * 96, word, static_cast<uint32_t>(n - blocks * 96));
    return;
#elif defined(__arm__) && defined(__thumb__)
    // Cortex-M0/M0+: eight 7-register store-multiples per 56 words (GCC -Os emits one str per word, and
    // shorter store-multiples cost more per word), the tail in 7-word ones too. n / 56 by a multiply
    // below 2^16 words, exact there (a 320 x 240 frame's 16-bit buffers hold 38,400 each), else the
    // library's division.
    const size_t blocks = n < 65536 ? detail::v6m_blocks_of_56(static_cast<uint32_t>(n)) : n / 56;
    detail::fill_words_v6m(w, w + blocks * 56, word, static_cast<uint32_t>(n - blocks * 56));
    return;
#elif defined(__riscv) && __riscv_xlen == 32
    // RV32 has no store-multiple: 64 stores and one pointer step per 256 bytes (GCC's loop below spends
    // three more instructions per 8 words on its pointer and count).
    if (size_t blocks = n / 64) {
        detail::AliasWord* const end = w + blocks * 64;
        __asm__ volatile("1:\n\t"
                         ".irp off, 0, 4, 8, 12, 16, 20, 24, 28, 32, 36, 40, 44, 48, 52, 56, 60, 64, 68, 72, 76, "
                         "80, 84, 88, 92, 96, 100, 104, 108, 112, 116, 120, 124, 128, 132, 136, 140, 144, 148, 152, "
                         "156, 160, 164, 168, 172, 176, 180, 184, 188, 192, 196, 200, 204, 208, 212, 216, 220, 224, "
                         "228, 232, 236, 240, 244, 248, 252\n\t"
                         "sw %2, \\off(%0)\n\t"
                         ".endr\n\t"
                         "addi %0, %0, 256\n\tbne %0, %1, 1b"
                         : "+r"(w)
                         : "r"(end), "r"(word)
                         : "memory");
        n -= blocks * 64;
    }
#endif
    for (; n >= 8; n -= 8, w += 8) {
        w[0] = word; w[1] = word; w[2] = word; w[3] = word;
        w[4] = word; w[5] = word; w[6] = word; w[7] = word;
    }
    for (; n != 0; --n) *w++ = word;
}

}  // namespace hider

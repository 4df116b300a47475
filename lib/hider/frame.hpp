// Frame views over caller-owned memory: colour rows in a pixel format (RGB565 default, RGB888,
// 8-bit grey), an optional depth buffer (uint16_t or uint32_t, smaller = nearer), and the band of
// rows [y0, y1) of the full frame the view holds. Rendering band by band gives the full frame's bytes.
#pragma once
#include <hider/base.hpp>

namespace hider {

/// A colour with 8 bits per channel; what shading produces before packing.
struct Rgb {
    uint8_t r, g, b;
    friend constexpr bool operator==(Rgb x, Rgb y) { return x.r == y.r && x.g == y.g && x.b == y.b; }
};

/// RGB888 storage: 3 bytes, r first (the byte order of a PPM).
struct Rgb888 {
    uint8_t r, g, b;
};
static_assert(sizeof(Rgb888) == 3, "Rgb888 must pack to 3 bytes");

/// RGB565 in a uint16_t: bits 15..11 red, 10..5 green, 4..0 blue (native byte order in memory).
struct Rgb565Format {
    using Pixel = uint16_t;
    __attribute__((always_inline)) static constexpr Pixel pack(Rgb c) {
        return static_cast<Pixel>(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3));
    }
    /// Expands by bit replication, so 0 -> 0 and 31 -> 255.
    static constexpr Rgb unpack(Pixel p) {
        const auto r = static_cast<uint8_t>((p >> 11) & 31), g = static_cast<uint8_t>((p >> 5) & 63),
                   b = static_cast<uint8_t>(p & 31);
        return {static_cast<uint8_t>((r << 3) | (r >> 2)), static_cast<uint8_t>((g << 2) | (g >> 4)),
                static_cast<uint8_t>((b << 3) | (b >> 2))};
    }
};

struct Rgb888Format {
    using Pixel = Rgb888;
    static constexpr Pixel pack(Rgb c) { return {c.r, c.g, c.b}; }
    static constexpr Rgb unpack(Pixel p) { return {p.r, p.g, p.b}; }
};

/// 8-bit grey: luma = (77 r + 150 g + 29 b) >> 8 (BT.601 weights in 1/256).
struct Grey8Format {
    using Pixel = uint8_t;
    static constexpr Pixel pack(Rgb c) { return static_cast<Pixel>((77 * c.r + 150 * c.g + 29 * c.b) >> 8); }
    static constexpr Rgb unpack(Pixel p) { return {p, p, p}; }
};

/// Depth buffer element traits: stored value = 32-bit depth >> (32 - bits); the clear value is the farthest.
template <class Depth> struct DepthTraits;
template <> struct DepthTraits<uint16_t> {
    static constexpr int kShift = 16;
    static constexpr uint16_t kClear = 0xFFFF;
};
template <> struct DepthTraits<uint32_t> {
    static constexpr int kShift = 0;
    static constexpr uint32_t kClear = 0xFFFFFFFFu;
};

/// Largest frame side lib/ accepts; keeps every screen coordinate inside the guard band.
constexpr int32_t kMaxFrameSide = 1024;

/// Largest row stride (elements) lib/ accepts: a row's bytes, and a band's, stay far inside 32 bits
/// (the row kernels step rows by the stride in bytes as a 32-bit value).
constexpr int32_t kMaxStride = int32_t{1} << 16;

/// A band of rows [y0, y1) of a width x height frame. `color` and `depth` point at row y0; both
/// use `stride` elements per row. The view borrows the memory; the caller owns it.
template <class Format, class Depth = uint16_t>
struct FrameView {
    using Pixel = typename Format::Pixel;
    using DepthType = Depth;
    Pixel* color = nullptr;
    Depth* depth = nullptr;  ///< may be null for algorithms without a depth buffer
    int32_t width = 0;
    int32_t height = 0;  ///< of the full frame
    int32_t stride = 0;  ///< elements per row, >= width
    int32_t y0 = 0;      ///< first row held
    int32_t y1 = 0;      ///< one past the last row held

    __attribute__((always_inline)) Pixel* row(int32_t y) const { return color + static_cast<ptrdiff_t>(y - y0) * stride; }
    __attribute__((always_inline)) Depth* depth_row(int32_t y) const { return depth + static_cast<ptrdiff_t>(y - y0) * stride; }
    int32_t rows() const { return y1 - y0; }
    /// True when the geometry is usable: sizes in range (stride from width to kMaxStride), band inside
    /// the frame, colour memory given.
    bool valid() const {
        return color != nullptr && width > 0 && height > 0 && width <= kMaxFrameSide &&
               height <= kMaxFrameSide && stride >= width && stride <= kMaxStride && 0 <= y0 && y0 < y1 && y1 <= height;
    }
};

/// View of rows [y0, y1) of a width x height frame, stored in buffers of (y1 - y0) rows.
template <class Format, class Depth = uint16_t>
constexpr FrameView<Format, Depth> band_view(typename Format::Pixel* color, Depth* depth, int32_t width,
                                             int32_t height, int32_t y0, int32_t y1) {
    FrameView<Format, Depth> v;
    v.color = color;
    v.depth = depth;
    v.width = width;
    v.height = height;
    v.stride = width;
    v.y0 = y0;
    v.y1 = y1;
    return v;
}

/// Rows [y0, y1) of the frame `buffers` belongs to, in buffers' own memory and stride: the band
/// renderers draw every band of a frame into one band-sized buffer.
template <class Format, class Depth>
constexpr FrameView<Format, Depth> band_in(const FrameView<Format, Depth>& buffers, int32_t y0, int32_t y1) {
    // Field by field, not a copy of buffers: GCC copied the whole view through the stack for each band.
    FrameView<Format, Depth> v = band_view<Format, Depth>(buffers.color, buffers.depth, buffers.width, buffers.height, y0, y1);
    v.stride = buffers.stride;
    return v;
}

/// View of a whole width x height frame.
template <class Format, class Depth = uint16_t>
constexpr FrameView<Format, Depth> frame_view(typename Format::Pixel* color, Depth* depth, int32_t width,
                                              int32_t height) {
    return band_view<Format, Depth>(color, depth, width, height, 0, height);
}

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

namespace detail {
/// Sets n elements at p to v. 16-bit elements go out as 32-bit words (fill_words()).
template <class T>
void fill(T* p, size_t n, T v) {
    if constexpr (sizeof(T) == 2) {
        if (n != 0 && (reinterpret_cast<uintptr_t>(p) & 2u) != 0) { *p++ = v; --n; }
        uint16_t bits;
        __builtin_memcpy(&bits, &v, 2);
        fill_words(p, n / 2, bits * 0x00010001u);
        if ((n & 1) != 0) p[n - 1] = v;
    } else {
        for (; n != 0; --n) *p++ = v;
    }
}
}  // namespace detail

/// Fills the band's colour with `background` and its depth (if any) with the farthest value.
/// Cost: about one store per two 16-bit elements. Precondition: f.valid() (it writes f.width elements
/// at every f.stride; the draws refuse an invalid frame with invalid_argument, clear() cannot say so).
template <class Format, class Depth>
void clear(const FrameView<Format, Depth>& f, Rgb background) {
    const typename Format::Pixel c = Format::pack(background);
    const bool packed = f.stride == f.width;  // one run for the whole band
    for (int32_t y = f.y0; y < f.y1; y = packed ? f.y1 : y + 1) {
        const size_t n = packed ? static_cast<size_t>(f.width) * static_cast<size_t>(f.rows()) : static_cast<size_t>(f.width);
        detail::fill(f.row(y), n, c);
        if (f.depth != nullptr) detail::fill(f.depth_row(y), n, DepthTraits<Depth>::kClear);
    }
}

}  // namespace hider

// Frame views over caller-owned memory: colour rows in a pixel format (RGB565 default, RGB888,
// 8-bit grey), an optional depth buffer (uint16_t or uint32_t, smaller = nearer), and the band of
// rows [y0, y1) of the full frame the view holds. Rendering band by band gives the full frame's bytes.
#pragma once
#include <hider/base.hpp>
#include <hider/fill_words.hpp>

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

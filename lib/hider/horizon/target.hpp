// Where the floating-horizon plotter puts its pixels: vertical runs of one colour in one column.
// FrameTarget draws into a FrameView of any pixel format (its band of rows only); MonoFrame is a
// 1-bit frame in the page layout of SSD1306/SH1106 OLED controllers (a byte holds 8 rows of one
// column, bit 0 on top), held whole or as a band of pages. Both borrow caller memory.
#pragma once
#include <hider/frame.hpp>

namespace hider::horizon {

/// Draws into a FrameView<Format, Depth> (the depth buffer, if any, is not touched).
template <class Format, class Depth = uint16_t>
class FrameTarget {
public:
    using Pixel = typename Format::Pixel;

    explicit FrameTarget(const FrameView<Format, Depth>& f) : f_(f) {}
    bool valid() const { return f_.valid(); }
    int32_t width() const { return f_.width; }
    int32_t height() const { return f_.height; }
    int32_t band_begin() const { return f_.y0; }
    int32_t band_end() const { return f_.y1; }
    static Pixel pack(Rgb c) { return Format::pack(c); }

    /// Rows [y_first, y_last] of column x. Precondition: all inside the band and the frame.
    void vline(int32_t x, int32_t y_first, int32_t y_last, Pixel p) const {
        Pixel* q = f_.row(y_first) + x;
        const ptrdiff_t stride = f_.stride;
        for (int32_t n = y_last - y_first; n >= 0; --n, q += stride) *q = p;
    }

private:
    FrameView<Format, Depth> f_;
};

/// A 1-bit frame (or band) in OLED page layout: page p holds rows [8p, 8p + 8), byte x of a page is
/// column x with bit (y - 8p) set for a lit pixel. `pages` points at page `page0`; the band is pages
/// [page0, page1), `width` bytes each. Rows run 0..height-1 with height <= 8 * pages of the frame.
struct MonoFrame {
    uint8_t* pages = nullptr;
    int32_t width = 0;
    int32_t height = 0;  ///< of the full frame
    int32_t page0 = 0;   ///< first page held
    int32_t page1 = 0;   ///< one past the last page held

    bool valid() const {
        return pages != nullptr && width > 0 && height > 0 && width <= kMaxFrameSide && height <= kMaxFrameSide &&
               0 <= page0 && page0 < page1 && page1 <= (height + 7) / 8;  // no page1 * 8: it wrapped past 2^28 pages
    }
    /// Bytes of the band: width per page.
    size_t bytes() const { return static_cast<size_t>(width) * static_cast<size_t>(page1 - page0); }
    /// Whether pixel (x, y) of the band is lit. Precondition: inside the band.
    bool lit(int32_t x, int32_t y) const { return (pages[(y / 8 - page0) * width + x] >> (y & 7) & 1) != 0; }
};

/// Unlights every pixel of the band.
inline void clear(const MonoFrame& f) {
    uint8_t* p = f.pages;
    for (size_t n = f.bytes(); n != 0; --n) *p++ = 0;
}

/// Draws into a MonoFrame: a pixel value of 1 lights, 0 unlights. pack() lights any colour but black.
class MonoTarget {
public:
    using Pixel = uint8_t;

    explicit MonoTarget(const MonoFrame& f) : f_(f) {}
    bool valid() const { return f_.valid(); }
    int32_t width() const { return f_.width; }
    int32_t height() const { return f_.height; }
    int32_t band_begin() const { return f_.page0 * 8; }
    int32_t band_end() const { return min(f_.page1 * 8, f_.height); }
    static Pixel pack(Rgb c) { return (c.r | c.g | c.b) != 0 ? 1 : 0; }

    /// Rows [y_first, y_last] of column x: one byte and one mask per page (most runs are one page).
    __attribute__((always_inline)) void vline(int32_t x, int32_t y_first, int32_t y_last, Pixel p) const {
        uint8_t* q = f_.pages + ((y_first >> 3) - f_.page0) * f_.width + x;  // rows are >= 0
        if ((y_first >> 3) == (y_last >> 3)) {
            const uint32_t mask = ((2u << (y_last - y_first)) - 1u) << (y_first & 7);
            *q = static_cast<uint8_t>(p != 0 ? *q | mask : *q & ~mask);
            return;
        }
        vline_pages(q, static_cast<uint32_t>(y_first), static_cast<uint32_t>(y_last), p);
    }

private:
    void vline_pages(uint8_t* q, uint32_t y, uint32_t last, Pixel p) const {
        for (;;) {
            const uint32_t page_last = (y | 7u) < last ? (y | 7u) : last;
            const uint32_t mask = ((2u << (page_last - y)) - 1u) << (y & 7u);
            *q = static_cast<uint8_t>(p != 0 ? *q | mask : *q & ~mask);
            if (page_last == last) return;
            y = page_last + 1;
            q += f_.width;
        }
    }

    MonoFrame f_;
};

}  // namespace hider::horizon

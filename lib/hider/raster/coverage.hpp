// One coverage bit per pixel of a band, for drawing front to back: a pixel already painted is never
// painted (or shaded) again, and whole polygons or subtrees whose screen box is already covered can be
// skipped unseen. Doom's solidsegs (r_bsp.c) is the one-dimensional form of the same idea.
#pragma once
#include <hider/frame.hpp>
#include <hider/raster/screen.hpp>

namespace hider {

/// 32-bit words of coverage per row of a band `width` pixels wide.
constexpr int32_t coverage_words(int32_t width) { return (width + 31) / 32; }

/// Coverage of rows [y0, y1) of a frame `width` pixels wide (width and rows at most kMaxFrameSide), over
/// caller memory of at least rows * coverage_words(width) words. Borrows the words; reset() clears them.
class Coverage {
public:
    /// Takes `words` for the band and clears them; false (nothing kept) when they are too few or a size
    /// is out of range.
    bool reset(Span<uint32_t> words, int32_t width, int32_t y0, int32_t y1) {
        // Sizes checked before any arithmetic on them: width + 31 and y1 - y0 overflowed int32 for a
        // frame draw_bsp_front() had not checked yet (it resets the coverage first).
        if (width < 1 || width > kMaxFrameSide || y1 <= y0 || int64_t{y1} - y0 > kMaxFrameSide) return false;
        const int32_t wpr = coverage_words(width);
        if (words.size() < static_cast<size_t>(wpr) * static_cast<size_t>(y1 - y0)) return false;
        words_ = words.data();
        width_ = width;
        wpr_ = wpr;
        y0_ = y0;
        y1_ = y1;
        for (size_t i = 0; i < static_cast<size_t>(wpr) * static_cast<size_t>(y1 - y0); ++i) words_[i] = 0;
        remaining_ = static_cast<uint32_t>(width) * static_cast<uint32_t>(y1 - y0);
        return true;
    }

    /// True when every pixel of the band is covered.
    bool full() const { return remaining_ == 0; }
    /// Pixels of the band not covered yet.
    uint32_t remaining() const { return remaining_; }

    /// True when every pixel of columns [r.x0, r.x1) and rows [r.y0, r.y1) is covered (an empty
    /// rectangle counts as covered). Cost: one word test per 32 columns of each row; a rectangle within
    /// one word column (the common query) tests two rows at a time.
    bool covered(const PixelRect& r) const {
        if (r.x0 >= r.x1 || r.y0 >= r.y1) return true;
        if (remaining_ == 0) return true;
        const int32_t w0 = r.x0 >> 5, w1 = (r.x1 - 1) >> 5;
        const uint32_t last = ~uint32_t{0} >> (31 - ((r.x1 - 1) & 31));
        const uint32_t first = (~uint32_t{0} << (r.x0 & 31)) & (w0 == w1 ? last : ~uint32_t{0});
        const uint32_t* row = words_ + static_cast<ptrdiff_t>(r.y0 - y0_) * wpr_;
        if (w0 == w1) {
            // An offset, not a pointer, steps past the last pair: a pointer there could leave the array.
            const uint32_t* const col = words_ + w0;
            ptrdiff_t at = static_cast<ptrdiff_t>(r.y0 - y0_) * wpr_;
            int32_t rows = r.y1 - r.y0;
            for (; rows >= 2; rows -= 2, at += 2 * wpr_)
                if ((col[at] & col[at + wpr_] & first) != first) return false;
            return rows == 0 || (col[at] & first) == first;
        }
        for (int32_t y = r.y0; y < r.y1; ++y, row += wpr_) {
            if ((row[w0] & first) != first) return false;
            for (int32_t w = w0 + 1; w < w1; ++w)
                if (row[w] != ~uint32_t{0}) return false;
            if ((row[w1] & last) != last) return false;
        }
        return true;
    }

    /// Writes shade(z) to the uncovered pixels of [x0, x1) on row y (z stepped by dz per pixel) and
    /// marks them covered; returns how many it wrote. Precondition: 0 <= x0, x1 <= width, y in the band.
    template <class Pixel, class Shader>
    uint32_t paint_span(Pixel* crow, int32_t y, int32_t x0, int32_t x1, uint32_t z, uint32_t dz, const Shader& shader) {
        const Shader shade = shader;  // a local copy: the pixel stores cannot alias it, so a flat colour stays in a register
        uint32_t* word = words_ + static_cast<ptrdiff_t>(y - y0_) * wpr_ + (x0 >> 5);  // the word of x0
        uint32_t written = 0;
        for (int32_t x = x0; x < x1;) {
            const int32_t bit = x & 31;
            const int32_t n = min(x1 - x, 32 - bit);  // pixels of this span in this word
            const uint32_t want = (0xFFFFFFFFu >> (32 - n)) << bit;  // n in [1, 32]: shifts in [0, 31]
            const uint32_t have = *word;
            const uint32_t todo = want & ~have;
            if (todo == want) {  // nothing covered yet: the whole run
                for (int32_t k = 0; k < n; ++k, z += dz) crow[x + k] = shade(z);
                written += static_cast<uint32_t>(n);
            } else if (todo != 0) {  // up to the last pixel still to paint
                uint32_t bits = todo >> bit, zk = z;
                for (int32_t k = 0; bits != 0; ++k, zk += dz, bits >>= 1)
                    if ((bits & 1u) != 0) {
                        crow[x + k] = shade(zk);
                        ++written;
                    }
                z += dz * static_cast<uint32_t>(n);
            } else {
                z += dz * static_cast<uint32_t>(n);
            }
            *word++ = have | want;
            x += n;
        }
        remaining_ -= written;
        return written;
    }

    /// The words of row y (for tests and statistics).
    const uint32_t* row(int32_t y) const { return words_ + static_cast<ptrdiff_t>(y - y0_) * wpr_; }
    int32_t words_per_row() const { return wpr_; }

private:
    uint32_t* words_ = nullptr;
    int32_t width_ = 0, wpr_ = 0, y0_ = 0, y1_ = 0;
    uint32_t remaining_ = 0;
};

}  // namespace hider

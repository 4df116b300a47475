// Pieces of a triangle cut without cracks. A piece is its parent triangle (the three exact edges and the
// depth plane) plus cut lines: each keeps the pixel centres on one side of a line through two points of
// the 1/16-pixel grid. The two pieces of a cut take the two sides of the same line, and a centre on the
// line goes to exactly one of them (the side towards +x, or +y for a horizontal line: the top-left rule),
// so the pieces of a triangle cover exactly its pixels, each once: no T-junction can open where a cut
// meets a neighbour. Newell's cuts (sort/) and the BSP's (bsp/) both draw their pieces this way.
#pragma once
#include <hider/raster/triangle.hpp>

namespace hider {

/// Most cut lines one piece may carry.
constexpr int kMaxPieceCuts = 16;

/// A directed line from (x0, y0) to (x1, y1), in subpixels from the frame centre (|x|, |y| <=
/// kCoordLimit). It keeps the side where e(x, y) = (x1 - x0)(y - y0) - (y1 - y0)(x - x0) > 0, and
/// the centres with e == 0 when that side is the +x side (the +y side for a horizontal line).
struct CutLine {
    int16_t x0, y0, x1, y1;
};

/// The same line keeping the other side: every pixel centre is kept by exactly one of c and reversed(c).
constexpr CutLine reversed(const CutLine& c) { return {c.x1, c.y1, c.x0, c.y0}; }

/// The edge function of c at (x, y): > 0 on the kept side. Exact (int64) for any int32 point.
constexpr int64_t cut_side(const CutLine& c, int32_t x, int32_t y) {
    return int64_t{c.x1 - c.x0} * (int64_t{y} - c.y0) - int64_t{c.y1 - c.y0} * (int64_t{x} - c.x0);
}

/// True when c keeps the points exactly on its line (its kept side is towards +x, or +y if horizontal).
constexpr bool keeps_line(const CutLine& c) { return c.y1 < c.y0 || (c.y1 == c.y0 && c.x1 > c.x0); }

/// True when c keeps the point (x, y): what PieceRaster decides for a pixel centre.
constexpr bool cut_keeps(const CutLine& c, int32_t x, int32_t y) {
    const int64_t e = cut_side(c, x, y);
    return e > 0 || (e == 0 && keeps_line(c));
}

/// Narrows the span [lo, hi) of pixel row y to the centres `cut` keeps, as PieceRaster does (x_origin,
/// y_origin: the centre of pixel (0, 0)); a horizontal cut keeps the whole row or none of it. For one
/// row at a time (a division per call): PieceRaster steps its cuts from row to row instead.
inline void narrow_to_cut(const CutLine& cut, int32_t y, int32_t x_origin, int32_t y_origin, int32_t& lo, int32_t& hi) {
    if (cut.y0 == cut.y1) {
        if (!cut_keeps(cut, cut.x0, y * kSubpixel + y_origin)) hi = lo;
        return;
    }
    const bool down = cut.y1 > cut.y0;
    const int32_t xu = down ? cut.x0 : cut.x1, yu = down ? cut.y0 : cut.y1, xl = down ? cut.x1 : cut.x0, yl = down ? cut.y1 : cut.y0;
    const int32_t px = edge_walker(xu, yu, xl, yl, y, x_origin, y_origin).px;  // the first centre on or right of it
    if (keeps_line(cut)) lo = max(lo, px);
    else hi = min(hi, px);
}

/// A piece set up for traversal: TriangleRaster's rows with each span narrowed to the cut lines.
/// Same interface as TriangleRaster (setup, then scan/spans for any rows, bands included).
class PieceRaster {
public:
    /// Prepares triangle (a, b, c) of a width x height frame with `cuts` (at most kMaxPieceCuts; the
    /// caller's memory is not kept). False when nothing can be drawn: zero area, a degenerate cut line
    /// (two equal points), or (with a band) no pixel centre of the band in the triangle's box.
    bool setup(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, Span<const CutLine> cuts,
               int32_t width, int32_t height, const BandBounds* band = nullptr) {
        const int32_t area = TriangleRaster::signed_area(a, b, c);
        const bool ok = band != nullptr ? tr_.setup(a, b, c, area, width, height, *band) : tr_.setup(a, b, c, area, width, height);
        if (!ok || cuts.size() > static_cast<size_t>(kMaxPieceCuts)) return false;
        x_origin_ = pixel_centre_origin(width);
        y_origin_ = pixel_centre_origin(height);
        first_ = tr_.first_row();
        end_ = tr_.end_row();
        count_ = 0;
        for (const CutLine& cut : cuts) {
            if (cut.y0 == cut.y1) {
                if (cut.x0 == cut.x1) return false;
                // Horizontal: rows whose centres lie at or below the line (kept side +y) or above it.
                const int32_t row = (cut.y0 - y_origin_ + kSubpixel - 1) >> kSubpixelBits;  // first centre >= y0
                if (keeps_line(cut)) first_ = max(first_, row);
                else end_ = min(end_, row);
                continue;
            }
            Cut& k = cuts_[count_++];
            const bool down = cut.y1 > cut.y0;
            k.xu = down ? cut.x0 : cut.x1;
            k.yu = down ? cut.y0 : cut.y1;
            k.xl = down ? cut.x1 : cut.x0;
            k.yl = down ? cut.y1 : cut.y0;
            k.plus_x = keeps_line(cut);  // the kept side is +x: the walker's boundary is a left bound
        }
        return first_ < end_;
    }

    bool front() const { return tr_.front(); }
    int32_t first_row() const { return first_; }
    int32_t end_row() const { return end_; }
    uint32_t dzdx() const { return tr_.dzdx(); }

    /// TriangleRaster::scan() over the piece's pixels: rows.begin(y0) once, then rows(x0, x1, z) for
    /// every row of [y_begin, y_end) the piece touches (x0 >= x1 when a row holds none of its pixels).
    /// Returns the pixels covered when RowFn::kCountFragments, else 0. Cost per row: one step per cut.
    template <class RowFn>
    uint32_t scan(int32_t y_begin, int32_t y_end, RowFn& rows_fn) const {
        const int32_t y0 = max(first_, y_begin), y1 = min(end_, y_end);
        if (y0 >= y1) return 0;
        CutRows<RowFn> rows{&rows_fn, this, {}, 0, tr_.dzdx()};
        tr_.scan(y0, y1, rows);
        return rows.covered;
    }

    /// Convenience form of scan(): fn(y, x0, x1, z) for each row with a non-empty span.
    template <class Fn>
    uint32_t spans(int32_t y_begin, int32_t y_end, Fn&& fn) const {
        detail::SpanAdapter<Fn> rows{&fn, 0};
        return scan(y_begin, y_end, rows);
    }

private:
    struct Cut {
        int32_t xu, yu, xl, yl;  ///< the line from its upper to its lower point
        bool plus_x;             ///< kept side towards +x: pixels from the boundary on
    };

    /// Row functor between TriangleRaster and the caller's: narrows each span to the cut lines.
    template <class RowFn>
    struct CutRows {
        static constexpr bool kCountFragments = false;  // counted here, after the narrowing
        static constexpr bool kRowKernel = false;
        RowFn* inner;
        const PieceRaster* piece;
        EdgeWalker walkers[kMaxPieceCuts];
        uint32_t covered;
        uint32_t dzdx;

        void begin(int32_t y) {
            inner->begin(y);
            for (int i = 0; i < piece->count_; ++i) {
                const Cut& k = piece->cuts_[i];
                walkers[i] = edge_walker(k.xu, k.yu, k.xl, k.yl, y, piece->x_origin_, piece->y_origin_);
            }
        }
        void operator()(int32_t x0, int32_t x1, uint32_t z) {
            int32_t lo = x0, hi = x1;
            for (int i = 0; i < piece->count_; ++i) {
                if (piece->cuts_[i].plus_x) lo = max(lo, walkers[i].px);
                else hi = min(hi, walkers[i].px);
                step(walkers[i]);
            }
            if (lo < hi) {
                z += dzdx * static_cast<uint32_t>(lo - x0);
                if constexpr (RowFn::kCountFragments) covered += static_cast<uint32_t>(hi - lo);
            } else {
                hi = lo;
            }
            (*inner)(lo, hi, z);
        }
    };

    TriangleRaster tr_;
    Cut cuts_[kMaxPieceCuts];
    int count_ = 0;  ///< non-horizontal cuts (walked per row)
    int32_t first_ = 0, end_ = 0;
    int32_t x_origin_ = 0, y_origin_ = 0;
};

}  // namespace hider

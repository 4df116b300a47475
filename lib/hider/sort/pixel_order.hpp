// The order of two polygons at the pixel centres both draw, decided on the spans and depths the
// rasterizer produces (raster/piece.hpp), so exactly as the z-buffer would. Newell asks it only where
// the polygon tests and cuts cannot break a cycle: a pair whose shared pixels already agree with the
// order found needs no cut.
#pragma once
#include <hider/sort/poly.hpp>

namespace hider {

namespace detail {

/// Rows compared per pass (their spans are kept on the stack).
constexpr int32_t kPixelOrderRows = 16;

struct PixelRow {
    int16_t x0, x1;  ///< covered pixels [x0, x1), empty when x0 >= x1
    uint32_t z;      ///< depth at x0
};

/// The spans of polygon p (a whole triangle or a piece) on rows [y, y + kPixelOrderRows), as
/// PieceRaster draws them; dzdx its depth step. The triangle's rows narrowed cut by cut (no walkers on
/// the stack), out of line: on a chip it runs below Newell's deepest frames.
__attribute__((noinline)) inline void poly_rows(const ScreenPoly& p, Span<const PieceCut> cuts, int32_t width, int32_t height,
                                                int32_t y, PixelRow (&rows)[kPixelOrderRows], uint32_t& dzdx) {
    for (PixelRow& r : rows) r = {0, 0, 0};
    dzdx = 0;
    int n = 0;
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) {  // as piece_lines(): a chain PieceRaster would refuse draws nothing
        if (n++ == kMaxPieceCuts || c >= cuts.size()) return;
        const CutLine& l = cuts[c].line;
        if (l.x0 == l.x1 && l.y0 == l.y1) return;
    }
    TriangleRaster tr;
    if (!tr.setup(p.v[0], p.v[1], p.v[2], width, height)) return;
    dzdx = tr.dzdx();
    const int32_t x_origin = pixel_centre_origin(width), y_origin = pixel_centre_origin(height);
    tr.spans(y, y + kPixelOrderRows, [&](int32_t row, int32_t x0, int32_t x1, uint32_t z) {
        int32_t lo = x0, hi = x1;
        for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) narrow_to_cut(cuts[c].line, row, x_origin, y_origin, lo, hi);
        if (lo < hi) rows[row - y] = {static_cast<int16_t>(lo), static_cast<int16_t>(hi), z + dzdx * static_cast<uint32_t>(lo - x0)};
    });
}

/// The first pixel row whose centre is at or below subpixel y (so, for y + 1, the row after the last
/// whose centre is at or above y).
constexpr int32_t row_at_or_below(int32_t y, int32_t height) { return (y - pixel_centre_origin(height) + kSubpixel - 1) >> kSubpixelBits; }

}  // namespace detail

/// True when drawing p before q leaves the nearer one at every pixel centre both draw: there q's depth
/// is at most p's (a tie goes to q, drawn last). Cost: a set-up of each per kPixelOrderRows rows of
/// their shared box, and per row a division for each cut (narrow_to_cut()).
inline bool drawn_under(const ScreenPoly& p, const ScreenPoly& q, Span<const PieceCut> cuts, int32_t width, int32_t height) {
    const int32_t y_begin = max(int32_t{0}, detail::row_at_or_below(max(p.ymin, q.ymin), height));
    const int32_t y_end = min(height, detail::row_at_or_below(min(p.ymax, q.ymax) + 1, height));
    detail::PixelRow pr[detail::kPixelOrderRows], qr[detail::kPixelOrderRows];
    for (int32_t y = y_begin; y < y_end; y += detail::kPixelOrderRows) {
        uint32_t pdz, qdz;
        detail::poly_rows(p, cuts, width, height, y, pr, pdz);
        detail::poly_rows(q, cuts, width, height, y, qr, qdz);
        for (int32_t i = 0; i < min(detail::kPixelOrderRows, y_end - y); ++i) {  // the last pass may be short
            const int32_t lo = max(pr[i].x0, qr[i].x0), hi = min(pr[i].x1, qr[i].x1);
            if (lo >= hi) continue;
            // Both depths step by a constant along the row, so their difference is linear: its two ends decide.
            const uint32_t p_lo = pr[i].z + pdz * static_cast<uint32_t>(lo - pr[i].x0);
            const uint32_t q_lo = qr[i].z + qdz * static_cast<uint32_t>(lo - qr[i].x0);
            const uint32_t last = static_cast<uint32_t>(hi - 1 - lo);
            if (p_lo < q_lo || p_lo + pdz * last < q_lo + qdz * last) return false;
        }
    }
    return true;
}

}  // namespace hider

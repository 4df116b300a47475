// The box of a piece's exact region, for the pieces Newell keeps: the band test (with_poly_raster) and
// Newell's extent tests and grid trust it to hold every pixel the piece draws. Computed from the lines
// alone (no outline, no depths), when a cut is kept.
#pragma once
#include <hider/sort/plane.hpp>

namespace hider {

namespace detail {
/// floor(n / d) and ceil(n / d) for 0 < d < 2^32 and |n| < d * 2^32, by one udiv64_32() (no 64-bit
/// library division).
inline void floor_ceil(int64_t n, int64_t d, int32_t& lo, int32_t& hi) {
    uint32_t r = 0;
    const int32_t q = static_cast<int32_t>(udiv64_32(n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n),
                                                     static_cast<uint32_t>(d), r));
    const int32_t inexact = r != 0 ? 1 : 0;
    lo = n < 0 ? -q - inexact : q;
    hi = n < 0 ? -q : q + inexact;
}
}  // namespace detail

/// Sets the box of `piece`, cut from p by `line` (its newest cut record's line), to the bounding box of
/// the region PieceRaster draws it from: p's triangle with its edges, p's cut chain and `line` as closed
/// half-planes. The region's vertices are the crossings of two of these lines that every other line
/// keeps, exact as (x / d, y / d); their floor and ceiling, one subpixel wider (Newell's extent tests
/// use <=), within p's box. 8 bytes of stack a line; for L = 4 + the cuts lines, L (L - 1) / 2
/// crossings each tested against up to L - 2 lines, and two 64/32-bit divisions per vertex.
inline void piece_box(const ScreenPoly& p, Span<const PieceCut> cuts, const CutLine& line, ScreenPoly& piece) {
    detail::LineEquation lines[4 + kMaxPieceCuts];
    const int64_t turn = cut_side({p.v[0].x, p.v[0].y, p.v[1].x, p.v[1].y}, p.v[2].x, p.v[2].y);
    if (turn == 0) return;  // a degenerate triangle draws nothing
    for (int i = 0; i < 3; ++i) {
        const ScreenVertex &s = p.v[i], &t = p.v[i == 2 ? 0 : i + 1];
        const CutLine edge{s.x, s.y, t.x, t.y};
        lines[i] = detail::line_equation(turn > 0 ? edge : reversed(edge));  // its inside kept
    }
    lines[3] = detail::line_equation(line);
    int n = 4;
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) {
        if (n == 4 + kMaxPieceCuts) return;  // longer than any chain cut_polygon() makes: keep the box
        lines[n++] = detail::line_equation(cuts[c].line);
    }
    // |d| < 2^31 and |x|, |y| < 2^46, so a side value a x + b y + c0 d stays below 2^62 + 2^61. A kept
    // crossing lies in the closed triangle: its quotients are within kCoordLimit.
    int32_t x0 = INT32_MAX, x1 = INT32_MIN, y0 = INT32_MAX, y1 = INT32_MIN;
    for (int i = 0; i < n; ++i) {
        const detail::LineEquation& li = lines[i];
        for (int j = i + 1; j < n; ++j) {
            const detail::LineEquation& lj = lines[j];
            int64_t d = int32_t{li.a} * lj.b - int32_t{lj.a} * li.b;
            if (d == 0) continue;  // parallel
            int64_t x = int64_t{li.b} * lj.c0 - int64_t{lj.b} * li.c0, y = int64_t{lj.a} * li.c0 - int64_t{li.a} * lj.c0;
            if (d < 0) {
                d = -d;
                x = -x;
                y = -y;
            }
            bool kept = true;
            for (int k = 0; k < n && kept; ++k)
                if (k != i && k != j) kept = lines[k].a * x + lines[k].b * y + lines[k].c0 * d >= 0;
            if (!kept) continue;
            int32_t lo, hi;
            detail::floor_ceil(x, d, lo, hi);
            x0 = min(x0, lo);
            x1 = max(x1, hi);
            detail::floor_ceil(y, d, lo, hi);
            y0 = min(y0, lo);
            y1 = max(y1, hi);
        }
    }
    if (x0 > x1) return;  // an empty region: no pixel centre, any box will do
    piece.xmin = static_cast<int16_t>(max<int32_t>(x0 - 1, p.xmin));
    piece.xmax = static_cast<int16_t>(min<int32_t>(x1 + 1, p.xmax));
    piece.ymin = static_cast<int16_t>(max<int32_t>(y0 - 1, p.ymin));
    piece.ymax = static_cast<int16_t>(min<int32_t>(y1 + 1, p.ymax));
}

}  // namespace hider

// The cut of a polygon by another's plane into two pieces whose pixels (raster/piece.hpp) are exactly
// its own: the cut line through two grid points found near the crossing (crossing_line(): box borders,
// moved ends, ends beyond the box, pivots), then the two pieces (cut_polygon()).
#pragma once
#include <hider/sort/crossing.hpp>

namespace hider {

namespace detail {
/// A candidate line of crossing_line() and what it is checked against: crossing k over triangle v, the
/// pixel centres within box[] (x0, x1, y0, y1), the vertex farthest from the plane and its side (to
/// orient a line across the gradient), and the major axis of points given as (major, minor).
struct LineFit {
    PlaneCrossing k;
    const ScreenPoly* p;
    int64_t box[4];
    int32_t x_origin, y_origin;
    int far;
    bool far_positive;
    bool along_x;

    /// The line through (xa, ya) and (xb, yb), kept side the plane's far side.
    CutLine oriented(int64_t xa, int64_t ya, int64_t xb, int64_t yb) const {
        const CutLine line{static_cast<int16_t>(xa), static_cast<int16_t>(ya), static_cast<int16_t>(xb), static_cast<int16_t>(yb)};
        const int64_t g = ((xb - xa) * k.nb - (yb - ya) * k.na) * (k.flip ? -1 : 1);  // below 2^62
        if (g != 0) return g > 0 ? line : reversed(line);
        // Across the gradient (a degenerate line): the vertex farthest from the plane lands on its own side.
        const bool keeps_far_vertex = cut_side(line, p->v[far].x, p->v[far].y) > 0;
        return keeps_far_vertex == far_positive ? line : reversed(line);
    }
    /// True, with `line` set, when the line through (xa, ya) and (xb, yb) puts every centre on the side
    /// of the crossing it is on; else `miss`, when given, holds the misplaced centre nearest the crossing
    /// (without it the walk stops at the first; `line` is set all the same). False for ends past the
    /// coordinate limits or equal ends.
    __attribute__((always_inline)) bool fits_xy(int64_t xa, int64_t ya, int64_t xb, int64_t yb, CutLine& line, int64_t (*miss)[2]) const {
        if (abs_value(xa) > kCoordLimit || abs_value(ya) > kCoordLimit || abs_value(xb) > kCoordLimit || abs_value(yb) > kCoordLimit ||
            (xa == xb && ya == yb))
            return false;
        line = oriented(xa, ya, xb, yb);
        return !misplaces_centre(line, k, p->v, box, x_origin, y_origin, miss);
    }
    /// fits_xy() for points (t0, m0) and (t1, m1) given as (major, minor); false when t0 == t1.
    __attribute__((always_inline)) bool fits(int64_t t0, int64_t m0, int64_t t1, int64_t m1, CutLine& line, int64_t (*miss)[2]) const {
        if (t0 == t1) return false;
        return along_x ? fits_xy(t0, m0, t1, m1, line, miss) : fits_xy(m0, t0, m1, t1, line, miss);
    }
};

/// The ends near_grid() found beyond each side of the box (major, minor), where it found one.
struct CrossingEnds {
    bool a = false, b = false;
    int64_t ta = 0, ma = 0, tb = 0, mb = 0;
    int64_t lo = 0, hi = 0;  ///< the triangle's box along the major axis
};

/// crossing_line()'s last resort: pivots where the crossing meets the line of centres (along the major
/// axis) through the misplaced centre nearest it, which the line must pass in the same gap. Each pivot
/// with each end and with a step along the crossing's slope; in a second round, for the centre the
/// first pivot's lines misplaced, also with the first pivot, and the point between the two centres where
/// the crossing nearly meets a grid point with the same partners (two centres on opposite sides, each
/// close to the crossing). True, with `line` set, when one fits.
__attribute__((noinline)) inline bool pivot_search(const LineFit& f, const CrossingEnds& e, int64_t (&nearest)[2], CutLine& line) {
    const int64_t m = f.along_x ? f.k.na : f.k.nb, d = f.along_x ? f.k.nb : f.k.na;  // |m| <= |d|, d != 0
    // The step: 2 kCrossingSearch along the major axis and the crossing's rise over it, at least one.
    const int64_t run = 2 * kCrossingSearch;
    int64_t rise = div_round(-m * run, d);  // |m| run < 2^57
    if (rise == 0 && m != 0) rise = (m < 0) == (d < 0) ? -1 : 1;
    int64_t first[2] = {0, 0}, first_miss[2] = {0, 0};  // the first round's pivot and centre
    for (int round = 0; round < 2; ++round) {
        int64_t pivots[2][2];
        if (!centre_line_pivot(f.k, f.along_x, nearest, f.along_x ? f.x_origin : f.y_origin, pivots[0][0], pivots[0][1])) return false;
        int count = 1;
        if (round > 0) {
            const int64_t c0 = f.along_x ? nearest[0] : nearest[1], c1 = f.along_x ? first_miss[0] : first_miss[1];
            // Strictly between the two centres: the crossing passes a hair from one of them.
            if (abs_value(c0 - c1) > 1 && near_grid(f.k, f.along_x, min(c0, c1) + 1, max(c0, c1) - 1, pivots[1][0], pivots[1][1])) count = 2;
        }
        int64_t next[2] = {nearest[0], nearest[1]};
        bool moved = false;  // next holds another centre one of these lines misplaced
        for (int q = 0; q < count; ++q) {
            const int64_t tp = pivots[q][0], mp = pivots[q][1];
            for (int i = 0; i < 5; ++i) {
                int64_t t1 = first[0], m1 = first[1];  // i = 4, in the second round
                if (i < 2) {
                    if (!(i == 0 ? e.a : e.b)) continue;
                    t1 = i == 0 ? e.ta : e.tb;
                    m1 = i == 0 ? e.ma : e.mb;
                } else if (i < 4) {  // rise != 0: m != 0, or there would be no pivot
                    t1 = i == 2 ? tp + run : tp - run;
                    m1 = i == 2 ? mp + rise : mp - rise;
                } else if (round == 0) {
                    continue;
                }
                int64_t at[2] = {nearest[0], nearest[1]};
                if (f.fits(tp, mp, t1, m1, line, &at) && stays_near(line, f.k, f.box)) return true;
                if (!moved && (at[0] != nearest[0] || at[1] != nearest[1])) {
                    next[0] = at[0];
                    next[1] = at[1];
                    moved = true;
                }
            }
        }
        if (!moved) return false;
        first[0] = pivots[0][0];
        first[1] = pivots[0][1];
        first_miss[0] = nearest[0];
        first_miss[1] = nearest[1];
        nearest[0] = next[0];
        nearest[1] = next[1];
    }
    return false;
}
}  // namespace detail

/// How crossing_line() went.
enum class CrossingResult : uint8_t {
    none,     ///< the planes are parallel, or their crossing misses the triangle's box
    exact,    ///< every pixel centre of the triangle lies on the side of the line its plane side says
    inexact,  ///< no line tried does that: a centre within a tiny distance of the crossing goes wrong
};

namespace detail {
/// crossing_line()'s set-up, out of line so that its frame is gone while lines are checked: the crossing
/// and what a line is checked against (f), the box's extent along the major axis (e.lo, e.hi), and the
/// ends on the box's border of the crossing's longest stretch in it (x, y, x, y). False when the planes
/// are parallel or the crossing misses the box.
__attribute__((noinline)) inline bool crossing_setup(const ScreenPlane& pl, const ScreenPoly& p, int32_t width, int32_t height, LineFit& f,
                                                     CrossingEnds& e, int32_t (&border)[4]) {
    Int128 h[3];
    int bits = 0;
    for (int i = 0; i < 3; ++i) {
        h[i] = side(pl, p.v[i]);
        bits = max(bits, detail::magnitude_bits(h[i]));
    }
    // A common shift brings |h| below 2^28: the products below then stay inside int64.
    const int shift = max(0, bits - 28);
    int64_t hs[3];
    for (int i = 0; i < 3; ++i) hs[i] = detail::shift_down(h[i], shift);
    const int64_t x0 = p.v[0].x, y0 = p.v[0].y;
    const int64_t dx1 = p.v[1].x - x0, dy1 = p.v[1].y - y0, dx2 = p.v[2].x - x0, dy2 = p.v[2].y - y0;
    const int64_t na = (hs[1] - hs[0]) * dy2 - (hs[2] - hs[0]) * dy1;  // gradient of h times the area
    const int64_t nb = (hs[2] - hs[0]) * dx1 - (hs[1] - hs[0]) * dx2;
    const int64_t area = dx1 * dy2 - dx2 * dy1;
    const int64_t h0 = hs[0] * area;
    if (na == 0 && nb == 0) return false;
    // Where na (x - x0) + nb (y - y0) + h0 = 0 meets the four sides of the box.
    const int64_t bx0 = min(p.v[0].x, min(p.v[1].x, p.v[2].x)), bx1 = max(p.v[0].x, max(p.v[1].x, p.v[2].x));
    const int64_t by0 = min(p.v[0].y, min(p.v[1].y, p.v[2].y)), by1 = max(p.v[0].y, max(p.v[1].y, p.v[2].y));
    int64_t px[4], py[4];
    int n = 0;
    const int64_t xs[2] = {bx0, bx1}, ys[2] = {by0, by1};
    for (int64_t xb : xs)
        if (nb != 0) {
            const int64_t y = y0 + div_round(-(na * (xb - x0) + h0), nb);
            if (y >= by0 && y <= by1) { px[n] = xb; py[n] = y; ++n; }
        }
    for (int64_t yb : ys)
        if (na != 0) {
            const int64_t x = x0 + div_round(-(nb * (yb - y0) + h0), na);
            if (x >= bx0 && x <= bx1) { px[n] = x; py[n] = yb; ++n; }
        }
    int64_t best = 0;
    int ia = -1, ib = -1;
    for (int i = 0; i < n; ++i)
        for (int k = i + 1; k < n; ++k) {
            const int64_t d = (px[i] - px[k]) * (px[i] - px[k]) + (py[i] - py[k]) * (py[i] - py[k]);
            if (d > best) { best = d; ia = i; ib = k; }
        }
    if (ia < 0) return false;
    // Orient by the crossing's gradient: the line keeps the side where the plane is farther.
    int far = 0;
    for (int i = 1; i < 3; ++i)
        if (abs_value(hs[i]) > abs_value(hs[far])) far = i;
    if (hs[far] == 0) return false;
    // The centres to check: the triangle's box within the frame's.
    const int32_t x_origin = pixel_centre_origin(width), y_origin = pixel_centre_origin(height);
    // Member by member: no temporary LineFit on this frame (a chip's stack).
    f.k.na = na;
    f.k.nb = nb;
    f.k.h0 = h0;
    f.k.x0 = x0;
    f.k.y0 = y0;
    f.k.flip = area < 0;
    f.k.shift = shift;
    f.k.area = area;
    f.k.plane = &pl;
    f.k.v = p.v;
    f.p = &p;
    f.box[0] = max<int64_t>(bx0, x_origin);
    f.box[1] = min<int64_t>(bx1, x_origin + (width - 1) * kSubpixel);
    f.box[2] = max<int64_t>(by0, y_origin);
    f.box[3] = min<int64_t>(by1, y_origin + (height - 1) * kSubpixel);
    f.x_origin = x_origin;
    f.y_origin = y_origin;
    f.far = far;
    f.far_positive = hs[far] > 0;
    f.along_x = abs_value(na) <= abs_value(nb);  // the crossing is mostly horizontal: ends by x
    e.lo = f.along_x ? bx0 : by0;
    e.hi = f.along_x ? bx1 : by1;
    border[0] = static_cast<int32_t>(px[ia]);
    border[1] = static_cast<int32_t>(py[ia]);
    border[2] = static_cast<int32_t>(px[ib]);
    border[3] = static_cast<int32_t>(py[ib]);
    return true;
}

/// crossing_line() up to its pivots, out of line so that its frame is gone while they run: the line
/// through the box borders (`first`), moved ends, then ends near the grid beyond the box (`e`). When none
/// fits (inexact), `f` and `nearest` (the centre the last line misplaced nearest the crossing) are set.
__attribute__((noinline)) inline CrossingResult first_lines(const ScreenPlane& pl, const ScreenPoly& p, int32_t width, int32_t height,
                                                            LineFit& f, CrossingEnds& e, int64_t (&nearest)[2], CutLine& first,
                                                            CutLine& far_side) {
    int32_t px[4];  // x, y, x, y: the ends on the box border
    if (!crossing_setup(pl, p, width, height, f, e, px)) return CrossingResult::none;
    if (f.fits_xy(px[0], px[1], px[2], px[3], far_side, &nearest)) return CrossingResult::exact;
    first = far_side;
    // Move the box border ends across the line, a subpixel or two each.
    const bool line_along_x = abs_value(px[2] - px[0]) >= abs_value(px[3] - px[1]);
    static constexpr int8_t kMoves[24][2] = {{1, 1}, {-1, -1}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1},
                                             {2, 2}, {-2, -2}, {2, 1}, {1, 2}, {-2, -1}, {-1, -2}, {2, 0}, {-2, 0},
                                             {0, 2}, {0, -2}, {2, -1}, {-1, 2}, {-2, 1}, {1, -2}, {2, -2}, {-2, 2}};
    for (const auto& mv : kMoves) {
        const int64_t xa = px[0] + (line_along_x ? 0 : mv[0]), ya = px[1] + (line_along_x ? mv[0] : 0);
        const int64_t xb = px[2] + (line_along_x ? 0 : mv[1]), yb = px[3] + (line_along_x ? mv[1] : 0);
        if (f.fits_xy(xa, ya, xb, yb, far_side, nullptr)) return CrossingResult::exact;
    }
    // Then ends where the crossing nearly meets a grid point, beyond each side of the box: the line
    // through them is far closer to the crossing than one through rounded box borders.
    e.a = near_grid(f.k, f.along_x, e.lo - kCrossingSearch, e.lo, e.ta, e.ma);
    e.b = near_grid(f.k, f.along_x, e.hi, e.hi + kCrossingSearch, e.tb, e.mb);
    if (e.a && e.b && f.fits(e.ta, e.ma, e.tb, e.mb, far_side, &nearest)) return CrossingResult::exact;
    return CrossingResult::inexact;
}
}  // namespace detail

/// The line where plane pl crosses the plane of polygon p on the screen, through two grid points near
/// the border of p's triangle's bounding box, oriented to keep pl's far side (side() > 0). The line is
/// the zero set of the plane's side function, which is affine over p's triangle. Its ends are rounded to
/// the grid, so it can pass a pixel centre of a width x height frame on the wrong side of the crossing:
/// then ends moved by a subpixel or two, ends beyond the box where the crossing nearly meets a grid
/// point, and pivots where it meets the row of centres it passes closest (pivot_search()) are tried for
/// one that puts every centre of the triangle on its own side (exact), else the line stays as found
/// (inexact). None when the planes are parallel or the line misses the box.
inline CrossingResult crossing_line(const ScreenPlane& pl, const ScreenPoly& p, int32_t width, int32_t height, CutLine& far_side) {
    detail::LineFit f{};
    detail::CrossingEnds e;
    int64_t nearest[2] = {0, 0};
    CutLine first{};
    const CrossingResult r = detail::first_lines(pl, p, width, height, f, e, nearest, first, far_side);
    if (r != CrossingResult::inexact) return r;
    if (detail::pivot_search(f, e, nearest, far_side)) return CrossingResult::exact;
    far_side = first;  // the nearest line through the box borders, as found
    return CrossingResult::inexact;
}

/// How one polygon's cut by a plane went.
enum class CutResult : uint8_t {
    cut,        ///< two pieces, each wholly on one side
    cut_inexact,  ///< two pieces, but the line puts a pixel centre within a tiny distance of the crossing
                  ///< on the wrong side (crossing_line(): inexact)
    far_only,   ///< no region of nonzero area is left on the near side: the polygon counts as far
    near_only,  ///< ... on the far side: it counts as near
    no_line,    ///< the planes do not cross inside the polygon's box
    too_deep,   ///< the polygon already carries kMaxPieceCuts cuts
};

namespace detail {
/// cut_polygon() once the line is found: the pieces of p on each side of `line` (keeping the far side).
/// Out of line, so that its outlines are off the stack while crossing_line() runs.
__attribute__((noinline)) inline CutResult split_along(const ScreenPoly& p, Span<const PieceCut> cuts, const CutLine& line,
                                                       uint32_t plane, ScreenPoly& far, ScreenPoly& near, PieceCut& far_cut,
                                                       PieceCut& near_cut) {
    // One outline at a time (a chip's stack): the far side's, then the near side's from p's again.
    Outline o;
    outline_of(p, cuts, o);
    // Each side keeps a region of nonzero area exactly when some vertex lies strictly on it.
    const int sides = clip_outline(o, line, p.v);
    const bool far_ok = (sides & kKeptSide) != 0, near_ok = (sides & kCutSide) != 0;
    if (!far_ok || !near_ok) return far_ok ? CutResult::far_only : (near_ok ? CutResult::near_only : CutResult::no_line);
    far_cut = {line, p.cut, plane | kCutFar};
    near_cut = {reversed(line), p.cut, plane};
    auto make = [&p](const Outline& piece, ScreenPoly& out) {
        out = p;  // p's box holds the piece; piece_box() narrows it for a piece that is kept
        out.cut = kNoCut;
        out.moved_at = kNotMoved;
        out.zmin = piece.v[0].z;
        out.zmax = piece.v[0].z;
        for (int i = 1; i < piece.count; ++i) {
            out.zmin = min(out.zmin, piece.v[i].z);
            out.zmax = max(out.zmax, piece.v[i].z);
        }
    };
    make(o, far);
    outline_of(p, cuts, o);
    clip_outline(o, reversed(line), p.v);
    make(o, near);
    return CutResult::cut;
}
}  // namespace detail

/// Cuts polygon p by plane pl (named `plane`, plane_name()) into far and near pieces, each
/// keeping p's triangle, tri and flags, with one more cut record in far_cut / near_cut. The caller
/// stores the records in the pool `cuts` holds p's chain in and sets far.cut / near.cut to their indices.
/// The pieces keep p's box, which holds them; piece_box() (sort/piece_box.hpp) gives a piece that is
/// kept the box of its exact region (a trial cut needs no box).
inline CutResult cut_polygon(const ScreenPoly& p, Span<const PieceCut> cuts, const ScreenPlane& pl, uint32_t plane,
                             int32_t width, int32_t height, ScreenPoly& far, ScreenPoly& near, PieceCut& far_cut, PieceCut& near_cut) {
    int depth = 0;
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) ++depth;
    if (depth >= kMaxPieceCuts) return CutResult::too_deep;
    CutLine line{};
    const CrossingResult crossing = crossing_line(pl, p, width, height, line);
    if (crossing == CrossingResult::none) return CutResult::no_line;
    const CutResult r = detail::split_along(p, cuts, line, plane, far, near, far_cut, near_cut);
    if (crossing == CrossingResult::exact || r == CutResult::no_line) return r;
    // A side decided from an inexact line could be wrong at the centre it misplaces: undecided instead.
    return r == CutResult::cut ? CutResult::cut_inexact : CutResult::no_line;
}

}  // namespace hider

// Newell's geometry on screen polygons: exact plane-side tests (128-bit sums of products) with a
// slack for the grid rounding of cut points (outline.hpp), and the cut of a polygon by another's plane
// into two pieces whose pixels (raster/piece.hpp) are exactly its own.
#pragma once
#include <hider/sort/outline.hpp>

namespace hider {

/// Plane of a screen triangle, oriented so that side() > 0 means farther (larger z) than the plane.
struct ScreenPlane {
    int64_t a, b, c;  ///< coefficients of x, y, z (c > 0 for any triangle with nonzero area)
    ScreenVertex origin;
    bool narrow;      ///< |a|, |b| < 2^45 and c < 2^29: every side() fits int64 (most triangles of a small frame)
};

/// The plane of polygon p: its (parent) triangle's, which every piece of it shares. It is the plane the
/// rasterizer steps depth through, so the tests below decide on exactly what is drawn.
inline ScreenPlane plane_of(const ScreenPoly& p) {
    const int64_t dx1 = p.v[1].x - p.v[0].x, dy1 = p.v[1].y - p.v[0].y, dz1 = int64_t{p.v[1].z} - p.v[0].z;
    const int64_t dx2 = p.v[2].x - p.v[0].x, dy2 = p.v[2].y - p.v[0].y, dz2 = int64_t{p.v[2].z} - p.v[0].z;
    ScreenPlane pl{dy1 * dz2 - dz1 * dy2, dz1 * dx2 - dx1 * dz2, dx1 * dy2 - dy1 * dx2, p.v[0], false};
    if (pl.c < 0) { pl.a = -pl.a; pl.b = -pl.b; pl.c = -pl.c; }
    // |x - x0|, |y - y0| < 2^16 and |z - z0| < 2^32: each product then stays below 2^61, the sum below 2^63.
    pl.narrow = abs_value(pl.a) < (int64_t{1} << 45) && abs_value(pl.b) < (int64_t{1} << 45) && pl.c < (int64_t{1} << 29);
    return pl;
}

/// Exact signed distance (scaled) of v (a ScreenVertex or an OutlinePoint) from the plane: > 0 farther,
/// 0 on it, < 0 nearer.
template <class V>
inline Int128 side(const ScreenPlane& pl, const V& v) {
    return mul128(pl.a, v.x - pl.origin.x) + mul128(pl.b, v.y - pl.origin.y) + mul128(pl.c, int64_t{v.z} - pl.origin.z);
}

/// How far side() can put a point cut onto the plane once rounded to the grid: half a subpixel in x and
/// y, and three depth units in z (its depth is the plane's at the exact point, rounded: half a unit, with room).
inline Int128 rounding_slack(const ScreenPlane& pl) {
    return mul128(abs_value(pl.a) + abs_value(pl.b), 1).shr(1) + mul128(pl.c, 3);
}

/// Side of v: +1 farther, -1 nearer, 0 on the plane or within `slack` of it (a vertex shared with the
/// plane's triangle is exactly on it). A narrow plane decides in 64 bits, with the same result.
template <class V>
inline int classify(const ScreenPlane& pl, const Int128& slack, const V& v) {
    if (pl.narrow) {
        const int64_t d = pl.a * (v.x - pl.origin.x) + pl.b * (v.y - pl.origin.y) + pl.c * (int64_t{v.z} - pl.origin.z);
        const int64_t t = static_cast<int64_t>(slack.lo);  // slack < 2^47 for a narrow plane
        return d > t ? 1 : (d < -t ? -1 : 0);
    }
    const Int128 d = side(pl, v);
    if ((d - slack).sign() > 0) return 1;
    if ((d + slack).sign() < 0) return -1;
    return 0;
}

namespace detail {
/// Number of significant bits of |v| (0 for 0). Precondition: |v| < 2^127.
inline int magnitude_bits(const Int128& v) {
    const Int128 m = v.sign() < 0 ? -v : v;
    if (m.hi != 0) return 128 - clz64(static_cast<uint64_t>(m.hi));
    return 64 - clz64(m.lo);
}

/// floor(v / 2^s) for 0 <= s < 128 and a result that fits int64.
inline int64_t shift_down(const Int128& v, int s) {
    if (s == 0) return static_cast<int64_t>(v.lo);
    if (s < 64) return static_cast<int64_t>(v.shr(s).lo);
    return v.hi >> (s - 64);
}

}  // namespace detail

/// Side of an outline: -1 if every vertex is nearer than the plane or on it, +1 if every one is farther
/// or on it (a polygon in the plane gives +1), 0 if it straddles the plane. A piece's outline, with cut
/// points rounded to the grid, is classified within the rounding slack; a whole triangle exactly: its
/// vertices are where the rasterizer draws them, and a surface closer to a parallel one than half a
/// subpixel's depth slope must not be taken for coplanar (the later one would be drawn on top).
inline int side_of(const ScreenPlane& pl, const Outline& o) {
    const Int128 slack = o.rounded ? rounding_slack(pl) : Int128{};
    bool near = false, far = false;
    for (int i = 0; i < o.count; ++i) {
        const int s = classify(pl, slack, o.v[i]);
        near = near || s < 0;
        far = far || s > 0;
    }
    if (near && far) return 0;
    return near ? -1 : 1;
}

/// The side of the plane of mesh triangle `plane_tri` that a cut of p's chain put it on (+1 far, -1
/// near), or 0 when no cut of p came from that plane.
inline int known_side(const ScreenPoly& p, Span<const PieceCut> cuts, uint32_t plane_tri) {
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev)
        if ((cuts[c].plane & ~kCutFar) == plane_tri) return (cuts[c].plane & kCutFar) != 0 ? 1 : -1;
    return 0;
}

/// How far beyond a triangle's box crossing_line() looks for a better end of a cut line (subpixels).
constexpr int64_t kCrossingSearch = 1024;

namespace detail {
/// Where a plane crosses a triangle's plane, as an affine function of the screen point whose sign is
/// the point's side of the plane (on the triangle's plane): side(x, y) = sign(na (x - x0) + nb (y - y0)
/// + h0), negated when `flip`. From the vertices' sides shifted down by `shift` bits to 28
/// (crossing_line()): within the triangle the rounding moves the value by less than |area|, so a point
/// whose value is that small has its side decided exactly from the plane, in 128 bits (exact_sign()).
/// value() is below 2^62 in the box.
struct PlaneCrossing {
    int64_t na, nb, h0, x0, y0;
    bool flip;
    int shift;
    int64_t area;              ///< the triangle's doubled area (v[0] to v[1], v[0] to v[2])
    const ScreenPlane* plane;  ///< the cutting plane, for the exact decisions
    const ScreenVertex* v;     ///< the triangle's three vertices (v[0] at x0, y0)
    int64_t value(int64_t x, int64_t y) const { return na * (x - x0) + nb * (y - y0) + h0; }
    int side(int64_t x, int64_t y) const {
        const int64_t val = value(x, y);
        const int s = shift > 0 && abs_value(val) <= abs_value(area) ? exact_sign(x, y) : (val > 0 ? 1 : (val < 0 ? -1 : 0));
        return flip ? -s : s;
    }
    /// The sign of the unshifted value at (x, y): the vertices' exact sides (below 2^66) interpolated,
    /// each term below 2^99. Out of line: rare, and its 128-bit products off the common path's stack.
    __attribute__((noinline)) int exact_sign(int64_t x, int64_t y) const {
        const int64_t w[3] = {area, (x - x0) * (v[2].y - y0) - (y - y0) * (v[2].x - x0),  // below 2^32
                              (v[1].x - x0) * (y - y0) - (v[1].y - y0) * (x - x0)};
        Int128 sum, h0s;
        for (int i = 0; i < 3; ++i) {
            // side(pl, v[i]) written out: a call would add a frame to the deepest Newell path on the M0+.
            const ScreenPlane& pl = *plane;
            Int128 h = mul128(pl.a, v[i].x - pl.origin.x) + mul128(pl.b, v[i].y - pl.origin.y) +
                       mul128(pl.c, int64_t{v[i].z} - pl.origin.z);
            if (i == 0) h0s = h;
            else h = h - h0s;
            sum = sum + mul128(h, w[i]);
        }
        return sum.sign();
    }
};

/// True when point (x, y) lies in triangle v or on its border.
inline bool in_triangle(const ScreenVertex (&v)[3], int64_t x, int64_t y) {
    int neg = 0, pos = 0;
    for (int i = 0; i < 3; ++i) {
        const ScreenVertex &a = v[i], &b = v[next3(i)];
        const int64_t e = int64_t{b.x - a.x} * (y - a.y) - int64_t{b.y - a.y} * (x - a.x);
        neg += e < 0;
        pos += e > 0;
    }
    return neg == 0 || pos == 0;
}

/// True when `line` lies within less than a subpixel of crossing k (across the line's major axis) over
/// box[]: then a centre between them is one of the two next to the line, all misplaces_centre() looks
/// at. Lines through points near the crossing on both sides of the box always do; a line through two
/// close points may stray (exact in 128 bits: the distance is linear, so the box's ends decide).
inline bool stays_near(const CutLine& line, const PlaneCrossing& k, const int64_t (&box)[4]) {
    const int64_t ldx = line.x1 - line.x0, ldy = line.y1 - line.y0;
    const bool along_x = abs_value(ldx) >= abs_value(ldy);
    const int64_t m = along_x ? k.na : k.nb, d = along_x ? k.nb : k.na;  // below 2^45
    if (d == 0) return false;  // the crossing runs across the line's major axis
    const int64_t o_major = along_x ? k.x0 : k.y0, o_minor = along_x ? k.y0 : k.x0;
    const int64_t pa = along_x ? line.x0 : line.y0, pb = along_x ? line.y0 : line.x0;
    int64_t la = along_x ? ldx : ldy, lb = along_x ? ldy : ldx;  // la != 0, both below 2^15
    if (la < 0) { la = -la; lb = -lb; }
    const Int128 limit = mul128(kSubpixel * la, abs_value(d));
    const int64_t ends[2] = {along_x ? box[0] : box[2], along_x ? box[1] : box[3]};
    for (const int64_t a : ends) {
        // la times the crossing's value at the line's point over a: la (m (a - o_major) + h0) + d (la (pb - o_minor) + (a - pa) lb).
        Int128 v = mul128(m * la, a - o_major) + mul128(k.h0, la) + mul128(d, la * (pb - o_minor) + (a - pa) * lb);
        if (v.sign() < 0) v = -v;
        if ((limit - v).sign() <= 0) return false;  // |value| / |d| >= kSubpixel: the line's minor is that far off
    }
    return true;
}

/// True when `line` (kept side: the plane's far side) puts a pixel centre of triangle v within box[]
/// (x0, x1, y0, y1: the triangle's box within the frame's centres) on the other side from the crossing
/// k (a centre exactly on the crossing goes either way). With the line within a few subpixels of the
/// crossing, such a centre lies between them: one of the two centres next to the line on each row or
/// column of centres along it. With `nearest`, the walk goes on and leaves there the misplaced centre
/// nearest the crossing (where a better line must pass closest).
inline bool misplaces_centre(const CutLine& line, const PlaneCrossing& k, const ScreenVertex (&v)[3], const int64_t (&box)[4],
                             int32_t x_origin, int32_t y_origin, int64_t (*nearest)[2] = nullptr) {
    const int64_t ldx = line.x1 - line.x0, ldy = line.y1 - line.y0;
    const bool along_x = abs_value(ldx) >= abs_value(ldy);  // walk the major axis: a, the minor one: b
    const int64_t a0 = along_x ? box[0] : box[2], a1 = along_x ? box[1] : box[3];
    const int64_t b0 = along_x ? box[2] : box[0], b1 = along_x ? box[3] : box[1];
    const int64_t ao = along_x ? x_origin : y_origin, bo = along_x ? y_origin : x_origin;
    const int64_t pa = along_x ? line.x0 : line.y0, pb = along_x ? line.y0 : line.x0;
    int64_t la = along_x ? ldx : ldy, lb = along_x ? ldy : ldx;  // la != 0
    if (la < 0) { la = -la; lb = -lb; }
    int64_t a = ao + kSubpixel * div_floor(a0 - ao + kSubpixel - 1, kSubpixel);  // the first centre at or after a0
    if (a > a1) return false;
    // The line's b at a is pb + (a - pa) lb / la; j indexes the last centre before it (exactly, stepped).
    const int64_t den = la * kSubpixel, step = lb * kSubpixel;
    int64_t num = (pb - bo) * la + (a - pa) * lb;
    int64_t j = div_floor(num, den), rem = num - j * den;  // rem in [0, den)
    int64_t least = -1;  // |k.value()| of the nearest misplaced centre so far
    for (; a <= a1; a += kSubpixel) {
        for (int64_t b = bo + j * kSubpixel, i = 0; i < 2; ++i, b += kSubpixel) {
            if (b < b0 || b > b1) continue;
            const int64_t x = along_x ? a : b, y = along_x ? b : a;
            const int s = k.side(x, y);
            if (s == 0 || cut_keeps(line, static_cast<int32_t>(x), static_cast<int32_t>(y)) == (s > 0) || !in_triangle(v, x, y)) continue;
            if (nearest == nullptr) return true;
            const int64_t d = abs_value(k.value(x, y));
            if (least < 0 || d < least) {
                least = d;
                (*nearest)[0] = x;
                (*nearest)[1] = y;
            }
        }
        rem += step;  // |step| <= den
        while (rem >= den) { rem -= den; ++j; }
        while (rem < 0) { rem += den; --j; }
    }
    return least >= 0;
}
/// The point of [from, to] (within the coordinate limits) on the major axis (x when along_x) where
/// crossing k comes nearest to a grid point, and that grid point's minor coordinate; false when none
/// is in range. The remainder is stepped along the axis, without a division per step.
inline bool near_grid(const PlaneCrossing& k, bool along_x, int64_t from, int64_t to, int64_t& at, int64_t& minor) {
    from = max<int64_t>(from, -kCoordLimit);
    to = min<int64_t>(to, kCoordLimit);
    if (from > to) return false;
    const int64_t m = along_x ? k.na : k.nb, d = along_x ? k.nb : k.na, o_major = along_x ? k.x0 : k.y0;
    const int64_t o_minor = along_x ? k.y0 : k.x0, ad = abs_value(d);  // |m| <= |d|, d != 0
    // The minor coordinate at t is o_minor + num / d, num = -(m (t - o_major) + h0): its nearest grid
    // point q and the remainder r = num - q d (in units of d's sign, |r| <= |d| / 2).
    const int64_t num = -(m * (from - o_major) + k.h0), step = d < 0 ? m : -m;
    int64_t q = div_round(num, d), r = (d < 0 ? -1 : 1) * (num - q * d), best = -1;
    for (int64_t t = from; t <= to; ++t, r += step) {
        while (2 * r > ad) { r -= ad; ++q; }
        while (2 * r < -ad) { r += ad; --q; }
        if (abs_value(o_minor + q) > kCoordLimit || (best >= 0 && abs_value(r) >= best)) continue;
        best = abs_value(r);
        at = t;
        minor = o_minor + q;
    }
    return best >= 0;
}
/// The grid point where crossing k meets the line of pixel centres through centre c along the major
/// axis (x when along_x; `centre_origin` the major coordinate of a centre), rounded and moved off a
/// centre toward the crossing, within kCrossingSearch of c: a line through it passes that line of
/// centres in the same gap as the crossing. False when the crossing does not meet it there.
inline bool centre_line_pivot(const PlaneCrossing& k, bool along_x, const int64_t (&c)[2], int64_t centre_origin, int64_t& at,
                              int64_t& minor) {
    const int64_t m = along_x ? k.na : k.nb, d = along_x ? k.nb : k.na;
    const int64_t o_major = along_x ? k.x0 : k.y0, o_minor = along_x ? k.y0 : k.x0;
    const int64_t c_major = along_x ? c[0] : c[1];
    minor = along_x ? c[1] : c[0];
    if (m == 0) return false;
    // m (t - o_major) + d (minor - o_minor) + h0 = 0; |m| <= |d| < 2^45, |h0| < 2^61: |num| < 2^61.
    const int64_t num = -(d * (minor - o_minor) + k.h0);
    const int64_t ahead = div_round(num, m);  // the crossing's t - o_major, rounded
    if (abs_value(ahead + o_major - c_major) > kCrossingSearch) return false;
    at = o_major + ahead;
    if ((at - centre_origin) % kSubpixel == 0) {  // on a centre: one subpixel toward the crossing
        const int64_t exact2 = 2 * num, r2 = exact2 - 2 * ahead * m;  // sign of (num / m - ahead) times m's
        if (r2 == 0) return false;                                     // the crossing passes the centre itself
        at += ((r2 > 0) == (m > 0)) ? 1 : -1;
    }
    return abs_value(at) <= kCoordLimit && abs_value(minor) <= kCoordLimit;
}

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
                                                       uint32_t plane_tri, ScreenPoly& far, ScreenPoly& near, PieceCut& far_cut,
                                                       PieceCut& near_cut) {
    // One outline at a time (a chip's stack): the far side's, then the near side's from p's again.
    Outline o;
    outline_of(p, cuts, o);
    // Each side keeps a region of nonzero area exactly when some vertex lies strictly on it.
    const int sides = clip_outline(o, line, p.v);
    const bool far_ok = (sides & kKeptSide) != 0, near_ok = (sides & kCutSide) != 0;
    if (!far_ok || !near_ok) return far_ok ? CutResult::far_only : (near_ok ? CutResult::near_only : CutResult::no_line);
    far_cut = {line, p.cut, plane_tri | kCutFar};
    near_cut = {reversed(line), p.cut, plane_tri};
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

/// Cuts polygon p by plane pl (the plane of mesh triangle plane_tri) into far and near pieces, each
/// keeping p's triangle, tri and flags, with one more cut record in far_cut / near_cut. The caller
/// stores the records in the pool `cuts` holds p's chain in and sets far.cut / near.cut to their indices.
/// The pieces keep p's box, which holds them; piece_box() (sort/piece_box.hpp) gives a piece that is
/// kept the box of its exact region (a trial cut needs no box).
inline CutResult cut_polygon(const ScreenPoly& p, Span<const PieceCut> cuts, const ScreenPlane& pl, uint32_t plane_tri,
                             int32_t width, int32_t height, ScreenPoly& far, ScreenPoly& near, PieceCut& far_cut, PieceCut& near_cut) {
    int depth = 0;
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) ++depth;
    if (depth >= kMaxPieceCuts) return CutResult::too_deep;
    CutLine line{};
    const CrossingResult crossing = crossing_line(pl, p, width, height, line);
    if (crossing == CrossingResult::none) return CutResult::no_line;
    const CutResult r = detail::split_along(p, cuts, line, plane_tri, far, near, far_cut, near_cut);
    if (crossing == CrossingResult::exact || r == CutResult::no_line) return r;
    // A side decided from an inexact line could be wrong at the centre it misplaces: undecided instead.
    return r == CutResult::cut ? CutResult::cut_inexact : CutResult::no_line;
}

}  // namespace hider

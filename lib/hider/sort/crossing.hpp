// Where another polygon's plane crosses a screen triangle (PlaneCrossing: an affine function of the
// screen point whose sign is the point's side) and the checks a candidate cut line must pass against it:
// every pixel centre of the triangle on its own side of the crossing, and the line near it over the box.
#pragma once
#include <hider/sort/plane.hpp>

namespace hider {

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
}  // namespace detail

}  // namespace hider

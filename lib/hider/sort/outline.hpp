// The outline of a Newell polygon: its triangle clipped by its cut lines, kept as the exact lines of
// its edges (every vertex is an exact crossing of two lines) and as grid points for the tests. A new
// point is the exact crossing of the cut with the edge's own line, rounded once, with the plane's depth
// there: every point is within half a subpixel of the region PieceRaster draws, at any cutting angle.
#pragma once
#include <hider/int128.hpp>
#include <hider/sort/poly.hpp>

namespace hider {

namespace detail {
/// A line as a x + b y + c0, equal to cut_side() of its CutLine (kept side >= 0). Endpoints within
/// kCoordLimit (2^14 - 1) give |a|, |b| < 2^15 and |c0| < 2^30.
struct LineEquation {
    int16_t a, b;
    int32_t c0;
};
constexpr LineEquation line_equation(const CutLine& c) {
    return {static_cast<int16_t>(c.y0 - c.y1), static_cast<int16_t>(c.x1 - c.x0),
            (int32_t{c.y1} - c.y0) * c.x0 - (int32_t{c.x1} - c.x0) * c.y0};
}

/// The crossing of two lines, exactly (x / d, y / d) with d > 0: |x|, |y| < 2^46 and d < 2^31.
struct ExactPoint {
    int64_t x, y, d;
};
/// False when the lines are parallel.
inline bool crossing(const LineEquation& l, const LineEquation& m, ExactPoint& p) {
    int64_t d = int32_t{l.a} * m.b - int32_t{m.a} * l.b;
    if (d == 0) return false;
    int64_t x = int64_t{l.b} * m.c0 - int64_t{m.b} * l.c0, y = int64_t{m.a} * l.c0 - int64_t{l.a} * m.c0;
    if (d < 0) {
        d = -d;
        x = -x;
        y = -y;
    }
    p = {x, y, d};
    return true;
}
/// The line's value at p times p.d (its sign is the side): below 3 x 2^61 in magnitude.
inline int64_t line_value(const LineEquation& l, const ExactPoint& p) { return l.a * p.x + l.b * p.y + l.c0 * p.d; }

/// n / d and the remainder for d != 0 in two 64/32-bit steps (no 64-bit library division).
inline uint64_t udiv64_by_32_steps(uint64_t n, uint32_t d, uint32_t& rem) {
    const uint32_t hi = static_cast<uint32_t>(n >> 32);
    const uint32_t q1 = hi / d;
    const uint64_t low = (uint64_t{hi - q1 * d} << 32) | static_cast<uint32_t>(n);
    const uint32_t q0 = udiv64_32(low, d, rem);
    return (uint64_t{q1} << 32) | q0;
}

/// n / d and the remainder for d != 0: native where the CPU divides 64 bits, else in 64/32-bit steps.
inline uint64_t udiv64_by_32(uint64_t n, uint32_t d, uint32_t& rem) {
    if constexpr (kSlow64BitDivide) return udiv64_by_32_steps(n, d, rem);
    rem = static_cast<uint32_t>(n % d);
    return n / d;
}

/// floor((u1 2^64 + u0) / d) and the remainder, for d != 0 and u1 < d: Hacker's Delight's divlu at
/// twice the width (32-bit digits, 64/32-bit steps), exact, with no 128-bit library division.
inline uint64_t udiv128_64(uint64_t u1, uint64_t u0, uint64_t d, uint64_t& rem) {
    const uint32_t d_hi = static_cast<uint32_t>(d >> 32);
    const int s = d_hi != 0 ? clz32(d_hi) : 32 + clz32(static_cast<uint32_t>(d));  // d != 0
    d <<= s;
    const uint64_t vn1 = d >> 32, vn0 = d & 0xFFFFFFFFu;
    const uint64_t un64 = s == 0 ? u1 : (u1 << s) | (u0 >> (64 - s)), un10 = u0 << s;
    const uint64_t un1 = un10 >> 32, un0 = un10 & 0xFFFFFFFFu;
    uint32_t r32 = 0;
    uint64_t q1 = udiv64_by_32(un64, static_cast<uint32_t>(vn1), r32), rhat = r32;
    while (q1 > 0xFFFFFFFFu || q1 * vn0 > ((rhat << 32) | un1)) {
        --q1;
        rhat += vn1;
        if (rhat > 0xFFFFFFFFu) break;
    }
    const uint64_t un21 = (un64 << 32) + un1 - q1 * d;
    uint64_t q0 = udiv64_by_32(un21, static_cast<uint32_t>(vn1), r32);
    rhat = r32;
    while (q0 > 0xFFFFFFFFu || q0 * vn0 > ((rhat << 32) | un0)) {
        --q0;
        rhat += vn1;
        if (rhat > 0xFFFFFFFFu) break;
    }
    rem = ((un21 << 32) + un0 - q0 * d) >> s;
    return (q1 << 32) | q0;
}

/// round(n / d), ties away from zero, for d > 0 and |n| < d x 2^34 (else +-2^34).
inline int64_t div_round_128(const Int128& n, int64_t d) {
    const bool negative = n.sign() < 0;
    const Int128 m = negative ? -n : n;
    const Int128 top = m.shr(34);
    const uint64_t ud = static_cast<uint64_t>(d);
    if (top.hi != 0 || top.lo >= ud) return negative ? -(int64_t{1} << 34) : (int64_t{1} << 34);
    uint64_t r = 0;
    uint64_t q = udiv128_64(static_cast<uint64_t>(m.hi), m.lo, ud, r);  // m.hi < d: the quotient fits
    if (r >= ud - r) ++q;
    return negative ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
}

/// The depth of triangle v's plane at the exact point p (in the closed triangle), rounded, within the
/// triangle's depth range.
inline uint32_t depth_at(const ScreenVertex (&v)[3], const ExactPoint& p) {
    const int64_t e1x = v[1].x - v[0].x, e1y = v[1].y - v[0].y, e2x = v[2].x - v[0].x, e2y = v[2].y - v[0].y;
    int64_t area = e1x * e2y - e1y * e2x;  // |area| < 2^31
    const uint32_t lo = min(v[0].z, min(v[1].z, v[2].z)), hi = max(v[0].z, max(v[1].z, v[2].z));
    if (area == 0) return lo;
    // u, w < 2^47; each weight below 2^63: the point's barycentric coordinates times area x d.
    const int64_t u = p.x - v[0].x * p.d, w = p.y - v[0].y * p.d;
    const int64_t w1 = u * e2y - w * e2x, w2 = e1x * w - e1y * u;
    Int128 num = mul128(int64_t{v[1].z} - v[0].z, w1) + mul128(int64_t{v[2].z} - v[0].z, w2);
    if (area < 0) {
        area = -area;
        num = -num;
    }
    const int64_t z = int64_t{v[0].z} + div_round_128(num, area * p.d);
    return z < lo ? lo : (z > hi ? hi : static_cast<uint32_t>(z));
}
}  // namespace detail

/// A point of an outline: a screen position and depth (no default values, so outlines cost no clearing).
struct OutlinePoint {
    int16_t x, y;
    uint32_t z;
};

/// The convex outline of a polygon: its triangle clipped by its cut lines, vertices in the triangle's
/// winding. edge[i] is the exact line from v[i] to v[i + 1] (inside >= 0), so vertex i is exactly the
/// crossing of edge[i - 1] and edge[i]; v[i] is that crossing rounded to the grid, with its depth. A
/// whole triangle's outline gets its edges when a first cut needs them (most are never cut).
struct Outline {
    OutlinePoint v[3 + kMaxPieceCuts];
    detail::LineEquation edge[3 + kMaxPieceCuts];
    int count = 0;
    bool rounded = false;  ///< some point is a cut point rounded to the grid (else the triangle's own vertices)
    bool edges = false;    ///< edge[] is set (else the outline is triangle v[0..2])
};

namespace detail {
/// Vertex i of o exactly; its grid point when its edges are parallel (a degenerate outline).
inline ExactPoint outline_vertex(const Outline& o, int i) {
    ExactPoint p;
    if (!crossing(o.edge[i == 0 ? o.count - 1 : i - 1], o.edge[i], p)) p = {o.v[i].x, o.v[i].y, 1};
    return p;
}

/// Which sides of a line an outline has vertices strictly on (clip_outline's result).
constexpr int kKeptSide = 1, kCutSide = 2;

/// The point where edge i of o (whose ends lie strictly on both sides of `line`) crosses it, rounded to
/// the grid with the plane's depth there.
inline OutlinePoint cut_point(const Outline& o, int i, const LineEquation& line, const ScreenVertex (&v)[3]) {
    ExactPoint p;
    if (!crossing(o.edge[i], line, p)) return o.v[i];  // parallel: only in a degenerate outline
    return {static_cast<int16_t>(div_round(p.x, p.d)), static_cast<int16_t>(div_round(p.y, p.d)), depth_at(v, p)};
}

/// The lines of triangle outline o's three edges (its grid points are the triangle's vertices), each
/// keeping the triangle's inside (>= 0).
inline void triangle_edges(const Outline& o, LineEquation* out) {
    const bool turn = cut_side({o.v[0].x, o.v[0].y, o.v[1].x, o.v[1].y}, o.v[2].x, o.v[2].y) >= 0;
    for (int i = 0; i < 3; ++i) {
        const OutlinePoint &a = o.v[i], &b = o.v[next3(i)];
        const CutLine edge{a.x, a.y, b.x, b.y};
        out[i] = line_equation(turn ? edge : reversed(edge));
    }
}

/// Line l's value at vertex i of o with the sign of the exact vertex: its grid point is within half a
/// subpixel of the vertex, so farther than that from the line it is on the vertex's side.
__attribute__((always_inline)) inline int64_t vertex_side(const Outline& o, int i, const LineEquation& l) {
    const int64_t e = int64_t{l.a} * o.v[i].x + int64_t{l.b} * o.v[i].y + l.c0;
    if (!o.rounded || 2 * abs_value(e) > abs_value(int64_t{l.a}) + abs_value(int64_t{l.b})) return e;  // unrounded: exact
    return line_value(l, outline_vertex(o, i));
}

/// Clips outline o of triangle v (without edges: the triangle itself) by the half-plane cut_side(line)
/// >= 0, in place, each vertex's side decided exactly. Returns kKeptSide and/or kCutSide: the sides o
/// had vertices strictly on before (the outline is unchanged without kCutSide).
inline int clip_outline(Outline& o, const CutLine& cut, const ScreenVertex (&v)[3]) {
    if (!o.edges) {  // the whole triangle: its three edges, its inside kept
        triangle_edges(o, o.edge);
        o.edges = true;
    }
    const LineEquation line = line_equation(cut);
    const int n = o.count;
    int8_t s[3 + kMaxPieceCuts];
    int sides = 0;
    for (int i = 0; i < n; ++i) {
        const int64_t e = vertex_side(o, i, line);
        s[i] = static_cast<int8_t>(e > 0 ? 1 : (e < 0 ? -1 : 0));
        sides |= e > 0 ? kKeptSide : (e < 0 ? kCutSide : 0);
    }
    if ((sides & kCutSide) == 0) return sides;
    o.rounded = true;
    // A convex outline keeps one run of vertices (s >= 0): from `first`, after a vertex cut away, to `last`.
    int first = 0;
    while (first < n && !(s[first] >= 0 && s[first == 0 ? n - 1 : first - 1] < 0)) ++first;
    if (first == n) {
        o.count = 0;  // nothing kept
        return sides;
    }
    int kept = 1;
    while (kept < n && s[(first + kept) % n] >= 0) ++kept;
    const int last = (first + kept - 1) % n, before = first == 0 ? n - 1 : first - 1;
    // The crossing entering the run, on the edge before it, and the one leaving it, on the run's last edge
    // (none where the run starts or ends on the line). At least one vertex goes: kept + 2 <= n + 1 points.
    const int enters = s[first] > 0 ? 1 : 0, leaves = s[last] > 0 ? 1 : 0;
    const OutlinePoint in = enters ? cut_point(o, before, line, v) : o.v[first];
    const LineEquation in_edge = o.edge[before];
    const OutlinePoint out = leaves ? cut_point(o, last, line, v) : o.v[last];
    // The new points take the place of the vertices cut away: [in] run [out], cyclically.
    const int from = first, to = first <= last ? enters : last + 1 + leaves + enters;
    const int moved = first <= last ? kept : n - first;  // the run, or its part from `first` to the end
    if (to > from)
        for (int i = moved - 1; i >= 0; --i) {
            o.v[to + i] = o.v[from + i];
            o.edge[to + i] = o.edge[from + i];
        }
    else if (to < from)
        for (int i = 0; i < moved; ++i) {
            o.v[to + i] = o.v[from + i];
            o.edge[to + i] = o.edge[from + i];
        }
    const int last_at = first <= last ? enters + kept - 1 : last, in_at = first <= last ? 0 : last + 1 + leaves;
    if (enters) {
        o.v[in_at] = in;
        o.edge[in_at] = in_edge;
    }
    if (leaves) {
        o.v[last_at + 1] = out;
        o.edge[last_at + 1] = line;
    } else {
        o.edge[last_at] = line;  // the run ends on the line
    }
    // No two edges of the result lie on one line: a kept vertex on the line with an edge along it would
    // put every vertex on one side of the line, and then nothing is clipped (or nothing of area is left).
    o.count = kept + enters + leaves;
    return sides;
}
}  // namespace detail

/// The outline of polygon p (cut chain in `cuts`).
inline void outline_of(const ScreenPoly& p, Span<const PieceCut> cuts, Outline& o) {
    o.count = 3;
    o.rounded = false;
    o.edges = false;
    for (int i = 0; i < 3; ++i) o.v[i] = {p.v[i].x, p.v[i].y, p.v[i].z};
    for (uint32_t c = p.cut; c != kNoCut && o.count > 0; c = cuts[c].prev) detail::clip_outline(o, cuts[c].line, p.v);
}

/// True when the projections of two convex outlines share no pixel-centre interior: the exact line of
/// some edge of one has every vertex of the other, exactly, on its outer side or on it (separating
/// axis). Exact lines matter: the grid points of a short edge between two cuts can point anywhere.
inline bool projections_disjoint(const Outline& p, const Outline& q) {
    auto separated_by = [](const Outline& s, const Outline& o) {
        if (s.count < 3) return false;
        detail::LineEquation tri[3];
        const detail::LineEquation* edges = s.edge;
        if (!s.edges) {  // a whole triangle: the lines through its vertices
            if (cut_side({s.v[0].x, s.v[0].y, s.v[1].x, s.v[1].y}, s.v[2].x, s.v[2].y) == 0) return false;
            detail::triangle_edges(s, tri);
            edges = tri;
        }
        for (int i = 0; i < s.count; ++i) {
            const detail::LineEquation& l = edges[i];
            if (l.a == 0 && l.b == 0) continue;
            bool all_out = true;
            for (int k = 0; k < o.count && all_out; ++k) all_out = detail::vertex_side(o, k, l) <= 0;
            if (all_out) return true;
        }
        return false;
    };
    return separated_by(p, q) || separated_by(q, p);
}

}  // namespace hider

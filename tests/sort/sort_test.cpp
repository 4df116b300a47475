// Building blocks of the object-space algorithms: the exact 128-bit arithmetic, the O(n) radix sort,
// plane-side classification and splitting, and Newell's pool at capacity N and N - 1.
#include <hider/int128.hpp>
#include <hider/sort/newell.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "support/assert_trap.hpp"
#include "support/hand_made.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {
/// The bounds of a whole w x h frame, geometry only (no buffers): what with_poly_raster() needs.
FrameView<Grey8Format> whole_frame(int w, int h) {
    FrameView<Grey8Format> f;
    f.width = w;
    f.height = h;
    f.y0 = 0;
    f.y1 = h;
    return f;
}
}  // namespace

TEST_CASE("mul128 and Int128 sums are exact (checked against unsigned __int128 on the host)") {
    std::mt19937_64 rng(5);
    for (int i = 0; i < 100000; ++i) {
        const auto a = static_cast<int64_t>(rng()) >> (rng() % 63), b = static_cast<int64_t>(rng()) >> (rng() % 63);
        const auto c = static_cast<int64_t>(rng()) >> (rng() % 63), d = static_cast<int64_t>(rng()) >> (rng() % 63);
        const __int128 want = static_cast<__int128>(a) * b - static_cast<__int128>(c) * d;
        const Int128 got = mul128(a, b) - mul128(c, d);
        CHECK(got.lo == static_cast<uint64_t>(want));
        CHECK(got.hi == static_cast<int64_t>(want >> 64));
        CHECK(got.sign() == (want > 0) - (want < 0));
    }
    CHECK(mul128(INT64_MIN, INT64_MIN).hi == int64_t{1} << 62);
    CHECK(mul128(INT64_MIN, -1).fits64() == false);
    CHECK(mul128(-3, 5).fits64());
}

TEST_CASE("radix_sort sorts 32-bit keys ascending and stably in O(n)") {
    std::mt19937 rng(9);
    for (size_t n : {0u, 1u, 2u, 100u, 70000u}) {
        std::vector<SortKey> keys(n), scratch(n);
        for (size_t i = 0; i < n; ++i) keys[i] = {static_cast<uint32_t>(rng() % (n < 100 ? 7u : 0xFFFFFFFFu)), static_cast<uint32_t>(i)};
        std::vector<SortKey> want = keys;
        std::stable_sort(want.begin(), want.end(), [](SortKey a, SortKey b) { return a.key < b.key; });
        radix_sort({keys.data(), n}, {scratch.data(), n});
        bool same = true;
        for (size_t i = 0; i < n; ++i) same = same && keys[i].key == want[i].key && keys[i].index == want[i].index;
        CHECK(same);
    }
}

TEST_CASE("a plane classifies its own vertices as on it and cuts a straddling triangle into two exact pieces") {
    auto sv = [](int x, int y, uint32_t z) { ScreenVertex v; v.x = static_cast<int16_t>(x); v.y = static_cast<int16_t>(y); v.z = z; return v; };
    ScreenPoly wall{{sv(-800, -800, 1u << 30), sv(800, -800, 1u << 30), sv(0, 800, 1u << 30)}, 0, 0, 0, 0, 0, 0, 3, kNotMoved, kNoCut, 0, 0};
    update_extents(wall);
    const ScreenPlane pl = plane_of(wall);
    for (const ScreenVertex& v : wall.v) CHECK(side(pl, v).sign() == 0);
    CHECK(side(pl, sv(5, 5, (1u << 30) + 1)).sign() > 0);  // farther
    CHECK(side(pl, sv(5, 5, (1u << 30) - 1)).sign() < 0);
    const Int128 slack = rounding_slack(pl);
    CHECK(classify(pl, slack, sv(5, 5, (1u << 30) + 4)) > 0);
    CHECK(classify(pl, slack, sv(5, 5, (1u << 30) - 4)) < 0);
    CHECK(classify(pl, slack, sv(5, 5, (1u << 30) + 3)) == 0);  // within the rounding slack of a cut point
    // A triangle's own vertices are where the rasterizer draws them: one depth unit off the plane is off it.
    // Only a piece's outline (Outline::rounded: it has cut points) gets the slack; with it on every
    // triangle, a surface within half a subpixel's depth slope of a parallel one counted as coplanar, and
    // Newell drew the later one on top.
    ScreenPoly under{{sv(-100, -100, (1u << 30) - 1), sv(100, -100, (1u << 30) - 1), sv(0, 100, (1u << 30) - 1)}, 0, 0, 0, 0, 0, 0, 5,
                     kNotMoved, kNoCut, 0, 0};
    Outline near_outline;
    outline_of(under, {}, near_outline);
    CHECK(!near_outline.rounded);
    CHECK(side_of(pl, near_outline) == -1);
    // The same points in a piece's outline: within the rounding slack but off the plane, so the side is
    // uncertain (0: Newell's trial cut decides). Taken as on the plane (+1, "wholly farther"), a piece of
    // a nearly parallel stack that straddles the plane went first, and Newell drew it over a nearer one
    // (a red team's stacks of 3 to 11 triangles 1e-4 apart). Points exactly on it still count as on it.
    near_outline.rounded = true;
    CHECK(side_of(pl, near_outline) == 0);
    Outline on_outline;
    outline_of(wall, {}, on_outline);
    on_outline.rounded = true;
    CHECK(side_of(pl, on_outline) == 1);
    ScreenPoly stick{{sv(-400, 0, 1u << 29), sv(400, 0, 3u << 29), sv(0, 300, 3u << 29)}, 0, 0, 0, 0, 0, 0, 7, kNotMoved, kNoCut, kPolyFront, 0};
    update_extents(stick);
    Outline whole;
    outline_of(stick, {}, whole);
    CHECK(side_of(pl, whole) == 0);
    std::vector<PieceCut> cuts;
    ScreenPoly far{}, near{};
    PieceCut far_cut{}, near_cut{};
    REQUIRE(cut_polygon(stick, {}, pl, wall.tri, 100, 50, far, near, far_cut, near_cut) == CutResult::cut);  // the frame below
    far.cut = 0;
    near.cut = 1;
    cuts = {far_cut, near_cut};
    CHECK(far.cut == 0);
    CHECK(near.cut == 1);
    CHECK(known_side(far, {cuts.data(), cuts.size()}, wall.tri) == 1);
    CHECK(known_side(near, {cuts.data(), cuts.size()}, wall.tri) == -1);
    CHECK(known_side(far, {cuts.data(), cuts.size()}, 99) == 0);
    const ScreenPoly pieces[2] = {far, near};
    for (int k = 0; k < 2; ++k) {
        CHECK(pieces[k].tri == 7);
        CHECK(pieces[k].flags == kPolyFront);
        Outline o;
        outline_of(pieces[k], {cuts.data(), cuts.size()}, o);
        CHECK(o.count >= 3);
        CHECK(o.rounded);  // the points on the cut line
        CHECK(side_of(pl, o) == (k == 0 ? 1 : -1));  // each piece lies on one side of the plane
    }
    // The two pieces cover exactly the stick's pixels, each once (a 100x50 frame around it).
    const int w = 100, h = 50;
    std::vector<int> count(w * h, 0), want(w * h, 0);
    const FrameView<Grey8Format> frame = whole_frame(w, h);
    const BandBounds bb = band_bounds(frame);
    auto cover = [&](const ScreenPoly& p, std::vector<int>& c) {
        with_poly_raster(p, {cuts.data(), cuts.size()}, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
            return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t) { for (int32_t x = x0; x < x1; ++x) ++c[y * w + x]; });
        });
    };
    cover(stick, want);
    cover(far, count);
    cover(near, count);
    CHECK(count == want);
    CHECK(std::count(want.begin(), want.end(), 1) > 100);
}

TEST_CASE("detail::floor_ceil rounds n / d down and up exactly") {
    std::mt19937_64 rng(17);
    for (int i = 0; i < 200000; ++i) {
        const int64_t d = static_cast<int64_t>(rng() % (uint64_t{1} << (1 + rng() % 31))) + 1;  // 1 .. 2^31
        const int64_t q = static_cast<int64_t>(rng() % 131071) - 65535;                          // |q| < 2^16 (points need 2^15)
        const int64_t n = q * d + static_cast<int64_t>(rng() % static_cast<uint64_t>(d)) * (i % 3 == 0 ? 0 : 1);
        int32_t lo = 0, hi = 0;
        detail::floor_ceil(n, d, lo, hi);
        const int64_t want_lo = div_floor(n, d), want_hi = -div_floor(-n, d);
        if (lo != want_lo || hi != want_hi) {
            INFO("n ", n, " d ", d);
            CHECK(lo == want_lo);
            CHECK(hi == want_hi);
        }
    }
    int32_t lo = 0, hi = 0;
    detail::floor_ceil(-7, 2, lo, hi);
    CHECK((lo == -4 && hi == -3));
    detail::floor_ceil(6, 3, lo, hi);
    CHECK((lo == 2 && hi == 2));
    detail::floor_ceil(0, 5, lo, hi);
    CHECK((lo == 0 && hi == 0));
}

namespace {
/// Points of outline o of piece p that are not a vertex of p's exact region (the triangle's and the
/// chain's half-planes) rounded to the nearest grid point with the plane's depth there (within a unit),
/// checked in floating point; also counts an outline with fewer than 3 points.
long outline_errors(const ScreenPoly& p, Span<const PieceCut> cuts, const Outline& o) {
    struct Line { double a, b, c; };
    std::vector<Line> lines;
    const double turn = double(p.v[1].x - p.v[0].x) * (p.v[2].y - p.v[0].y) - double(p.v[1].y - p.v[0].y) * (p.v[2].x - p.v[0].x);
    auto add = [&](double x0, double y0, double x1, double y1, double sign) {  // keeps sign * cut_side >= 0
        lines.push_back({sign * (y0 - y1), sign * (x1 - x0), sign * ((y1 - y0) * x0 - (x1 - x0) * y0)});
    };
    for (int i = 0; i < 3; ++i) add(p.v[i].x, p.v[i].y, p.v[(i + 1) % 3].x, p.v[(i + 1) % 3].y, turn > 0 ? 1 : -1);
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) add(cuts[c].line.x0, cuts[c].line.y0, cuts[c].line.x1, cuts[c].line.y1, 1);
    const double ax = p.v[1].x - p.v[0].x, ay = p.v[1].y - p.v[0].y, cx = p.v[2].x - p.v[0].x, cy = p.v[2].y - p.v[0].y;
    const double area = ax * cy - ay * cx;
    long bad = o.count < 3 ? 1 : 0;
    for (int k = 0; k < o.count; ++k) {
        // Some vertex of the region (a crossing of two lines that every line keeps) within half a
        // subpixel, with the plane's depth there within a unit.
        bool found = false;
        for (size_t i = 0; i < lines.size() && !found; ++i)
            for (size_t j = i + 1; j < lines.size() && !found; ++j) {
                const Line &l = lines[i], &m = lines[j];
                const double d = l.a * m.b - m.a * l.b;
                if (d == 0) continue;
                const double x = (l.b * m.c - m.b * l.c) / d, y = (m.a * l.c - l.a * m.c) / d;
                if (std::abs(x - o.v[k].x) > 0.5 + 1e-9 || std::abs(y - o.v[k].y) > 0.5 + 1e-9) continue;
                bool kept = true;
                for (const Line& n : lines) kept = kept && n.a * x + n.b * y + n.c >= -1e-9 * (std::abs(n.a) + std::abs(n.b)) * 16384;
                const double ux = x - p.v[0].x, uy = y - p.v[0].y;
                const double z = p.v[0].z + (ux * cy - uy * cx) / area * (double(p.v[1].z) - p.v[0].z) +
                                 (ax * uy - ay * ux) / area * (double(p.v[2].z) - p.v[0].z);
                found = kept && std::abs(z - o.v[k].z) <= 1.0;
            }
        bad += !found;
    }
    return bad;
}
}  // namespace

namespace {
ScreenVertex screen_vertex(int32_t x, int32_t y, uint32_t z) {
    ScreenVertex v;
    v.x = static_cast<int16_t>(x);
    v.y = static_cast<int16_t>(y);
    v.z = z;
    return v;
}

/// Random coordinates and depths of a w x h frame's test scenes.
struct RandomScreen {
    std::mt19937& rng;
    int32_t coord(int32_t half) { return static_cast<int32_t>(rng() % static_cast<uint32_t>(2 * half + 1)) - half; }
    ScreenVertex vertex(int32_t hx, int32_t hy) {  // named steps: argument order is unspecified in C++
        const int32_t x = coord(hx), y = coord(hy);
        return screen_vertex(x, y, (1u << 29) + static_cast<uint32_t>(rng() % (1u << 28)));
    }
    /// A random triangle (mesh triangle `id`) reaching a little past the frame; false when it has no area.
    bool triangle(int w, int h, uint32_t id, ScreenPoly& tri) {
        tri = ScreenPoly{{}, 0, 0, 0, 0, 0, 0, id, kNotMoved, kNoCut, 0, 0};
        for (ScreenVertex& v : tri.v) v = vertex(w * 10, h * 10);
        if (TriangleRaster::signed_area(tri.v[0], tri.v[1], tri.v[2]) == 0) return false;
        update_extents(tri);
        return true;
    }
};

/// Cuts the pieces in `live` (their cut records in `cuts`) `rounds` times over by the planes of random
/// triangles, first by `first_wall`'s when given; each cut keeps both pieces when both are non-empty,
/// their boxes narrowed as Newell does. With `shallow`, the walls are slightly moved copies of one, so
/// that the cut lines of a chain meet at shallow angles.
void cut_randomly(RandomScreen& rs, int w, int h, bool shallow, int rounds, const ScreenPoly* first_wall, std::vector<PieceCut>& cuts,
                  std::vector<ScreenPoly>& live) {
    ScreenPoly base{{}, 0, 0, 0, 0, 0, 0, 99, kNotMoved, kNoCut, 0, 0};
    for (ScreenVertex& v : base.v) v = rs.vertex(w * 12, h * 12);
    for (int round = 0; round < rounds; ++round) {
        std::vector<ScreenPoly> next;
        for (size_t i = 0; i < live.size(); ++i) {
            const ScreenPoly& p = live[i];
            ScreenPoly wall{{}, 0, 0, 0, 0, 0, 0, 100u + static_cast<uint32_t>(round), kNotMoved, kNoCut, 0, 0};
            for (ScreenVertex& v : wall.v) v = rs.vertex(w * 12, h * 12);
            if (shallow)
                for (int k = 0; k < 3; ++k) {
                    const int32_t dx = rs.coord(6), dy = rs.coord(6), dz = rs.coord(1 << 20);
                    wall.v[k] = screen_vertex(base.v[k].x + dx, base.v[k].y + dy, base.v[k].z + static_cast<uint32_t>(dz));
                }
            if (round == 0 && first_wall != nullptr) wall = *first_wall;
            if (TriangleRaster::signed_area(wall.v[0], wall.v[1], wall.v[2]) == 0) {
                next.push_back(p);
                continue;
            }
            ScreenPoly far{}, near{};
            PieceCut far_cut{}, near_cut{};
            if (cut_polygon(p, {cuts.data(), cuts.size()}, plane_of(wall), wall.tri, w, h, far, near, far_cut, near_cut) != CutResult::cut) {
                next.push_back(p);
                continue;
            }
            piece_box(p, {cuts.data(), cuts.size()}, far_cut.line, far);
            piece_box(p, {cuts.data(), cuts.size()}, near_cut.line, near);
            far.cut = static_cast<uint32_t>(cuts.size());
            cuts.push_back(far_cut);
            near.cut = static_cast<uint32_t>(cuts.size());
            cuts.push_back(near_cut);
            next.push_back(far);
            next.push_back(near);
        }
        live.swap(next);
    }
}
}  // namespace

TEST_CASE("a piece's box holds every pixel centre it draws, after chains of cuts at any angle") {
    // Random triangles cut again and again by the planes of random triangles: each cut keeps both pieces
    // when both are non-empty, down to chains of 8. Every pixel centre PieceRaster draws for a piece must
    // lie in its box (the band test and Newell's extent tests trust it), and the pieces of a triangle
    // must cover exactly its pixels. Each point of a piece's outline must be a vertex of the region it
    // draws, rounded once to the grid, with the depth of the triangle's plane there (within a unit, against
    // a floating-point reference): so the outline's box, one subpixel wider, holds every centre too. (Cut
    // points clipped from already rounded points drifted far along a cut that met an earlier one at a
    // shallow angle, outside that box, and Newell then misordered single pixels.)
    const int w = 48, h = 40;
    const FrameView<Grey8Format> frame = whole_frame(w, h);
    const BandBounds bb = band_bounds(frame);
    const int32_t ox = kSubpixel / 2 - w * (kSubpixel / 2), oy = kSubpixel / 2 - h * (kSubpixel / 2);
    long pieces_checked = 0, centres = 0, outside = 0, outside_rounded = 0, coverage_errors = 0, points = 0, bad_points = 0;
    for (uint32_t seed = 1; seed <= 6000; ++seed) {
        std::mt19937 rng(seed);
        RandomScreen rs{rng};
        std::vector<PieceCut> cuts;
        cuts.reserve(64);
        ScreenPoly tri;
        if (!rs.triangle(w, h, 1, tri)) continue;
        std::vector<ScreenPoly> live{tri};
        cut_randomly(rs, w, h, seed % 2 == 1, 8, nullptr, cuts, live);
        std::vector<int> count(static_cast<size_t>(w) * h, 0), want(static_cast<size_t>(w) * h, 0);
        auto cover = [&](const ScreenPoly& p, std::vector<int>& c, const ScreenPoly* rounded_box) {
            with_poly_raster(p, {cuts.data(), cuts.size()}, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
                return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
                    for (int32_t x = x0; x < x1; ++x) {
                        ++c[static_cast<size_t>(y) * w + x];
                        if (rounded_box == nullptr) continue;
                        const int32_t cx = ox + x * kSubpixel, cy = oy + y * kSubpixel;
                        const ScreenPoly& rb = *rounded_box;
                        ++centres;
                        outside += cx < p.xmin || cx > p.xmax || cy < p.ymin || cy > p.ymax;
                        outside_rounded += cx < rb.xmin || cx > rb.xmax || cy < rb.ymin || cy > rb.ymax;
                    }
                });
            });
        };
        cover(tri, want, nullptr);  // the whole triangle's pixels (its box is its vertices')
        for (const ScreenPoly& p : live) {
            // The box a piece had before piece_box(): its rounded outline's, one subpixel wider.
            Outline o;
            outline_of(p, {cuts.data(), cuts.size()}, o);
            bad_points += outline_errors(p, {cuts.data(), cuts.size()}, o);
            points += o.count;
            ScreenPoly rounded = p;
            rounded.xmin = rounded.ymin = INT16_MAX;
            rounded.xmax = rounded.ymax = INT16_MIN;
            for (int k = 0; k < o.count; ++k) {
                rounded.xmin = std::min<int16_t>(rounded.xmin, static_cast<int16_t>(o.v[k].x - 1));
                rounded.xmax = std::max<int16_t>(rounded.xmax, static_cast<int16_t>(o.v[k].x + 1));
                rounded.ymin = std::min<int16_t>(rounded.ymin, static_cast<int16_t>(o.v[k].y - 1));
                rounded.ymax = std::max<int16_t>(rounded.ymax, static_cast<int16_t>(o.v[k].y + 1));
            }
            cover(p, count, &rounded);
            ++pieces_checked;
        }
        coverage_errors += count != want;
    }
    MESSAGE("pieces " << pieces_checked << ", pixel centres " << centres << ", outside their box " << outside
                      << ", outside their outline's box " << outside_rounded << "; outline points " << points
                      << ", not a rounded vertex of the region " << bad_points);
    CHECK(pieces_checked > 40000);
    CHECK(centres > 1000000);
    CHECK(outside == 0);
    CHECK(outside_rounded == 0);
    CHECK(points > 150000);
    CHECK(bad_points == 0);
    CHECK(coverage_errors == 0);
}

/// The pixel centres of a w x h frame that the pieces of `tri` cut_polygon() made (far keeps the first
/// record, near the second) draw on the other side of plane pl than theirs, exactly in 128 bits (a
/// centre on the plane goes either way); `centres` counts those drawn.
long wrong_side_centres(const ScreenPoly& tri, const ScreenPlane& pl, ScreenPoly far, ScreenPoly near, const PieceCut (&records)[2],
                        int w, int h, long& centres) {
    const FrameView<Grey8Format> frame = whole_frame(w, h);
    const BandBounds bb = band_bounds(frame);
    const int32_t ox = pixel_centre_origin(w), oy = pixel_centre_origin(h);
    far.cut = 0;
    near.cut = 1;
    long bad = 0;
    for (const ScreenPoly* piece : {&far, &near})
        with_poly_raster(*piece, {records, 2}, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
            return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
                for (int32_t x = x0; x < x1; ++x) {
                    // The plane's side at the centre on the triangle's plane: side() at the centre with the
                    // triangle's exact depth there, times the triangle's doubled area (barycentric, exact).
                    const __int128 cx = ox + x * kSubpixel, cy = oy + y * kSubpixel;
                    const ScreenVertex* v = tri.v;
                    __int128 area = __int128{v[1].x - v[0].x} * (v[2].y - v[0].y) - __int128{v[2].x - v[0].x} * (v[1].y - v[0].y);
                    __int128 w1 = (cx - v[0].x) * (v[2].y - v[0].y) - (cy - v[0].y) * (v[2].x - v[0].x);
                    __int128 w2 = __int128{v[1].x - v[0].x} * (cy - v[0].y) - __int128{v[1].y - v[0].y} * (cx - v[0].x);
                    const __int128 z_area = __int128{v[0].z} * area + w1 * (__int128{v[1].z} - v[0].z) + w2 * (__int128{v[2].z} - v[0].z);
                    __int128 side = (pl.a * (cx - pl.origin.x) + pl.b * (cy - pl.origin.y)) * area + pl.c * (z_area - __int128{pl.origin.z} * area);
                    if (area < 0) side = -side;
                    ++centres;
                    bad += piece == &far ? side < 0 : side > 0;
                }
            });
        });
    return bad;
}

TEST_CASE("a cut line puts every pixel centre of its triangle on the side of the plane the piece takes, or says it cannot") {
    // The line through two grid points that cut_polygon() cuts along is within a subpixel of where the
    // planes cross, so a pixel centre closer than that to the crossing could go to the wrong piece, and
    // Newell would draw it in the wrong order (single pixels in random soups). For a cut that returns
    // `cut`, every centre the far piece draws must lie on the far side of the plane or on it (exactly,
    // in 128 bits), every centre the near piece draws on the near side or on it; a line that cannot be
    // placed so returns cut_inexact (Newell reports it). Three seed sequences at 64x48, one at 320x240
    // (where the pivots of crossing_line() work more: a pivot line through two close points once
    // strayed from the crossing across the box; and a centre within the rounding of the crossing's
    // 28-bit form was put on the wrong side of an exact cut until such centres were decided exactly).
    long cuts_made = 0, centres = 0, wrong = 0, wrong_cuts = 0, inexact = 0, inexact_wrong = 0;
    for (uint32_t seed = 1; seed <= 66000; ++seed) {
        static constexpr uint32_t kMultipliers[3] = {104729u, 32452843u, 1000003u};
        const bool large = seed > 60000;
        const int w = large ? 320 : 64, h = large ? 240 : 48;
        std::mt19937 rng(large ? seed * 2246822519u : seed / 3 * kMultipliers[seed % 3]);
        RandomScreen rs{rng};
        ScreenPoly tri, wall;
        if (!rs.triangle(w, h, 1, tri) || !rs.triangle(w, h, 2, wall)) continue;
        const ScreenPlane pl = plane_of(wall);
        ScreenPoly far{}, near{};
        PieceCut far_cut{}, near_cut{};
        const CutResult result = cut_polygon(tri, {}, pl, wall.tri, w, h, far, near, far_cut, near_cut);
        if (result != CutResult::cut && result != CutResult::cut_inexact) continue;
        ++cuts_made;
        const PieceCut records[2] = {far_cut, near_cut};
        const long bad = wrong_side_centres(tri, pl, far, near, records, w, h, centres);
        if (result == CutResult::cut_inexact) {
            ++inexact;
            inexact_wrong += bad;
        } else {
            wrong += bad;
            wrong_cuts += bad != 0;
        }
    }
    MESSAGE("cuts " << cuts_made << ", pixel centres " << centres << ", on the wrong side " << wrong << " (in " << wrong_cuts
                    << " cuts); inexact cuts " << inexact << " with " << inexact_wrong << " centres on the wrong side");
    CHECK(cuts_made > 33000);
    CHECK(centres > 15000000);
    CHECK(wrong == 0);
    CHECK(inexact * 10000 < cuts_made);  // under 0.01%: 1,524 of the first 12,283 cuts misplaced a centre before the check
}

TEST_CASE("a cut line through a pivot stays near the crossing over the whole triangle") {
    // Found by review: a crossing that passes two centres within a hair, where crossing_line() paired a
    // pivot with a grid point one subpixel away, and took that line for exact after checking only the
    // centres next to it: 4,697 of the triangle's 6,262 centres went to the wrong piece (640x480).
    ScreenPoly tri{{}, 0, 0, 0, 0, 0, 0, 0, kNotMoved, kNoCut, 0, 0}, wall = tri;
    wall.tri = 1;
    const int32_t tv[3][3] = {{-2916, -3108, 673101319}, {2857, -53, 700511433}, {4540, 1393, 794502009}};
    const int32_t wv[3][3] = {{-3999, -1330, 670872209}, {-1290, -2009, 649112307}, {211, 1118, 769785124}};
    for (int i = 0; i < 3; ++i) {
        tri.v[i] = {static_cast<int16_t>(tv[i][0]), static_cast<int16_t>(tv[i][1]), static_cast<uint32_t>(tv[i][2])};
        wall.v[i] = {static_cast<int16_t>(wv[i][0]), static_cast<int16_t>(wv[i][1]), static_cast<uint32_t>(wv[i][2])};
    }
    update_extents(tri);
    update_extents(wall);
    const ScreenPlane pl = plane_of(wall);
    ScreenPoly far{}, near{};
    PieceCut far_cut{}, near_cut{};
    const CutResult result = cut_polygon(tri, {}, pl, 1, 640, 480, far, near, far_cut, near_cut);
    REQUIRE((result == CutResult::cut || result == CutResult::cut_inexact));
    const PieceCut records[2] = {far_cut, near_cut};
    long centres = 0;
    const long bad = wrong_side_centres(tri, pl, far, near, records, 640, 480, centres);
    INFO("result " << static_cast<int>(result) << ", centres " << centres << ", on the wrong side " << bad);
    CHECK(centres > 6000);
    if (result == CutResult::cut) CHECK(bad == 0);
    else CHECK(bad < 10);  // inexact: a centre within a hair of the crossing, not a line off it
}

TEST_CASE("projections_disjoint() and drawn_under() agree with the pixels two cut triangles draw") {
    // Two random triangles, each cut four times over (on odd seeds by planes close to one another, so
    // that the pieces have edges a few subpixels long between cuts). For every pair of pieces of the
    // two: when projections_disjoint() says disjoint, no pixel centre may be drawn by both (an outline's
    // grid points can turn a short edge any way; separating on them let Newell draw a piece first that
    // lay in front of another over 47 pixels); drawn_under() must say whether the second's depth is at
    // most the first's at every shared centre, as a pixel-by-pixel comparison of the depths drawn.
    const int w = 40, h = 32;
    const FrameView<Grey8Format> frame = whole_frame(w, h);
    const BandBounds bb = band_bounds(frame);
    long pairs = 0, disjoint = 0, disjoint_shared = 0, overlapping = 0, under = 0, under_wrong = 0;
    for (uint32_t seed = 1; seed <= 8000; ++seed) {
        std::mt19937 rng(seed * 7919u);
        RandomScreen rs{rng};
        std::vector<PieceCut> cuts;
        cuts.reserve(256);
        ScreenPoly ta, tb;
        if (!rs.triangle(w, h, 1, ta) || !rs.triangle(w, h, 2, tb)) continue;
        // On even seeds each is cut first by the other's plane, as Newell cuts a piercing pair: their
        // pieces then meet along nearly the same line.
        std::vector<ScreenPoly> a{ta}, b{tb};
        cut_randomly(rs, w, h, seed % 2 == 1, 5, seed % 2 == 0 ? &tb : nullptr, cuts, a);
        cut_randomly(rs, w, h, seed % 3 != 0, 5, seed % 2 == 0 ? &ta : nullptr, cuts, b);
        const Span<const PieceCut> cs{cuts.data(), cuts.size()};
        // Each piece's depth at every pixel centre it draws (0: not drawn), stepped pixel by pixel.
        auto depths = [&](const ScreenPoly& p) {
            std::vector<uint64_t> d(static_cast<size_t>(w) * h, 0);
            with_poly_raster(p, cs, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
                return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t z) {
                    for (int32_t x = x0; x < x1; ++x, z += r.dzdx()) d[static_cast<size_t>(y) * w + x] = uint64_t{z} + 1;
                });
            });
            return d;
        };
        std::vector<std::vector<uint64_t>> da, db;
        for (const ScreenPoly& p : a) da.push_back(depths(p));
        for (const ScreenPoly& p : b) db.push_back(depths(p));
        for (size_t i = 0; i < a.size(); ++i)
            for (size_t k = 0; k < b.size(); ++k) {
                Outline oa, ob;
                outline_of(a[i], cs, oa);
                outline_of(b[k], cs, ob);
                long shared = 0;
                bool want_under = true;
                for (size_t px = 0; px < da[i].size(); ++px)
                    if (da[i][px] != 0 && db[k][px] != 0) {
                        ++shared;
                        want_under = want_under && db[k][px] <= da[i][px];
                    }
                ++pairs;
                overlapping += shared != 0;
                if (projections_disjoint(oa, ob)) {
                    ++disjoint;
                    disjoint_shared += shared != 0;
                }
                const bool got_under = drawn_under(a[i], b[k], cs, w, h);
                under += got_under && shared != 0;
                under_wrong += got_under != want_under;
            }
    }
    MESSAGE("pairs " << pairs << ", sharing a pixel " << overlapping << ", disjoint " << disjoint << " (sharing a pixel: "
                     << disjoint_shared << "), drawn under with a shared pixel " << under << ", drawn_under() wrong " << under_wrong);
    CHECK(pairs > 150000);
    CHECK(overlapping > 10000);
    CHECK(disjoint > 100000);
    CHECK(under > 5000);
    CHECK(disjoint_shared == 0);
    CHECK(under_wrong == 0);
}

TEST_CASE("Newell's cut pool at capacity N finishes the frame exactly; at N - 1 it reports the drop") {
    tool::Scene s;
    std::string why;
    REQUIRE(test::scene_from_ref(ref::piercing(), s, why));
    tool::RenderOptions opt;
    opt.algo = tool::Algo::newell;
    opt.shade = Shade::id;
    opt.format = tool::PixelFormat::rgb888;
    tool::RenderResult big;
    REQUIRE(tool::render(s, opt, big, why));
    REQUIRE(big.stats.status == Status::ok);
    const size_t built = big.polygons - (big.polygons - s.tris.size() > 0 ? 0 : 0);
    (void)built;
    // The pool must hold every extra piece: polygons after cuts minus polygons before them.
    tool::RenderOptions probe = opt;
    probe.algo = tool::Algo::painter;
    tool::RenderResult painter;
    REQUIRE(tool::render(s, probe, painter, why));
    const size_t needed = big.polygons - painter.polygons;
    REQUIRE(needed > 0);
    opt.split_pool = needed;
    tool::RenderResult exact;
    REQUIRE(tool::render(s, opt, exact, why));
    CHECK(exact.stats.status == Status::ok);
    CHECK(exact.newell.dropped == 0);
    CHECK(exact.rgb == big.rgb);
    opt.split_pool = needed - 1;
    tool::RenderResult short_pool;
    REQUIRE(tool::render(s, opt, short_pool, why));
    CHECK(short_pool.stats.status == Status::capacity_exceeded);
    CHECK(short_pool.newell.dropped >= 1);
    CHECK(short_pool.rgb.size() == big.rgb.size());  // the frame still finishes
}

TEST_CASE("build_polys fills its list to capacity and counts what it drops") {
    const tool::Scene s = test::load_model("torus.obj");
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}) == Status::ok);
    std::vector<ScreenPoly> store(4000);
    BoundedList<ScreenPoly> all(store.data(), store.size());
    FrameStats st;
    build_polys(view, s.mesh(), {verts.data(), verts.size()}, true, all, st);
    REQUIRE(st.status == Status::ok);
    const size_t n = all.size();
    BoundedList<ScreenPoly> exact(store.data(), n);
    FrameStats st_exact;
    build_polys(view, s.mesh(), {verts.data(), verts.size()}, true, exact, st_exact);
    CHECK(st_exact.status == Status::ok);
    CHECK(exact.size() == n);
    CHECK(exact.dropped() == 0);
    BoundedList<ScreenPoly> short_list(store.data(), n - 1);
    FrameStats st_short;
    build_polys(view, s.mesh(), {verts.data(), verts.size()}, true, short_list, st_short);
    CHECK(st_short.status == Status::capacity_exceeded);
    CHECK(short_list.size() == n - 1);
    CHECK(short_list.dropped() == 1);
    CHECK(short_list.high_water() == n - 1);
    // Fewer projected vertices than the mesh has: refused like draw_zbuffer refuses it (it read past
    // them; a red-team pass).
    BoundedList<ScreenPoly> none(store.data(), store.size());
    FrameStats st_verts;
    build_polys(view, s.mesh(), {verts.data(), 10}, true, none, st_verts);
    CHECK(st_verts.status == Status::invalid_argument);
    CHECK(none.size() == 0);
}

TEST_CASE("newell_order refuses an order list or scratch smaller than the polygon pool") {
    View view;
    view.width = 32;
    view.height = 32;
    std::vector<ScreenPoly> store(10);
    std::vector<PieceCut> cut_store(10);
    std::vector<uint32_t> ord(10), heap(10), pos(10), links(20), cells(grid_cells(32, 32)), chain(10);
    BoundedList<ScreenPoly> polys(store.data(), store.size());
    BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
    std::vector<SortKey> keys(10), sort_scratch(10);
    NewellScratch scratch{{keys.data(), 10}, {sort_scratch.data(), 10}, {heap.data(), 10}, {pos.data(), 10},
                          {links.data(), 20},  {cells.data(), cells.size()},  {chain.data(), 10},
                          {}};
    NewellStats ns;
    BoundedList<uint32_t> order(ord.data(), ord.size());
    CHECK(newell_order(view, polys, cuts, scratch, order, ns) == Status::ok);
    BoundedList<uint32_t> short_order(ord.data(), 5);
    CHECK(newell_order(view, polys, cuts, scratch, short_order, ns) == Status::invalid_argument);
    NewellScratch short_heap = scratch;
    short_heap.heap = {heap.data(), 9};
    CHECK(newell_order(view, polys, cuts, short_heap, order, ns) == Status::invalid_argument);
    NewellScratch short_links = scratch;
    short_links.links = {links.data(), 19};
    CHECK(newell_order(view, polys, cuts, short_links, order, ns) == Status::invalid_argument);
    NewellScratch short_cells = scratch;
    short_cells.cells = {cells.data(), cells.size() - 1};
    CHECK(newell_order(view, polys, cuts, short_cells, order, ns) == Status::invalid_argument);
    for (size_t i = 0; i < 3; ++i) polys.push_back(ScreenPoly{});
    NewellScratch short_keys = scratch;
    short_keys.keys = {keys.data(), 2};
    CHECK(newell_order(view, polys, cuts, short_keys, order, ns) == Status::invalid_argument);
    NewellScratch short_chain = scratch;
    short_chain.chain = {chain.data(), 9};
    CHECK(newell_order(view, polys, cuts, short_chain, order, ns) == Status::invalid_argument);
}

TEST_CASE("Newell with a full pool never writes past a chain of N entries, and orders as with room to spare") {
    // Three bars lying each over the next (a cycle of 6 triangles), with no room for a cut: a chain of
    // moves can then run through every polygon and meet its first candidate again, N + 1 entries. Found
    // by the adversarial hunt: chain[N] was written (ASan: heap-buffer-overflow in newell.hpp).
    tool::ObjModel m;
    for (int k = 0; k < 3; ++k) {
        const double th = (90.0 + 120.0 * k) * 3.14159265358979323846 / 180.0, dx = std::cos(th), dy = std::sin(th);
        const double nx = -dy, ny = dx;
        auto at = [&](double t, double w) {
            return std::array<double, 3>{0.3 * nx + t * dx + w * nx, 0.3 * ny + t * dy + w * ny, 0.3 * t - 0.6 * w};
        };
        const int32_t base = static_cast<int32_t>(m.vertices.size());
        for (auto [t, w] : {std::pair{-1.0, 0.12}, {-1.0, -0.12}, {1.0, 0.12}, {1.0, -0.12}}) m.vertices.push_back(at(t, w));
        m.faces.push_back({{base, base + 1, base + 3}, static_cast<uint32_t>(2 * k + 1), 1});
        m.faces.push_back({{base, base + 3, base + 2}, static_cast<uint32_t>(2 * k + 2), 1});
    }
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{0, 0, 4};
    cam.target = tool::Vec3d{0, 0, 0};
    tool::Scene s;
    std::string why;
    REQUIRE_MESSAGE(tool::build_scene(m, cam, s, why), why);
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}) == Status::ok);
    struct Run {
        Status status;
        NewellStats ns;
        std::vector<uint32_t> order;
        bool chain_tail_intact;
    };
    auto run = [&](size_t spare, size_t chain_len) {
        const size_t cap = 6 + spare;
        std::vector<ScreenPoly> store(cap);
        BoundedList<ScreenPoly> polys(store.data(), cap);
        FrameStats st;
        build_polys(view, s.mesh(), {verts.data(), verts.size()}, false, polys, st);
        REQUIRE(polys.size() == 6);
        std::vector<PieceCut> cut_store(2 * cap);
        BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
        std::vector<SortKey> keys(cap), sort_scratch(cap);
        std::vector<uint32_t> heap(cap), pos(cap), links(2 * cap), cells(grid_cells(s.width, s.height)), ord(cap);
        std::vector<uint32_t> chain(chain_len + 4, 0xC0FFEEu);  // the caller's array, then 4 words it does not own
        const NewellScratch scratch{{keys.data(), cap}, {sort_scratch.data(), cap}, {heap.data(), cap}, {pos.data(), cap},
                                    {links.data(), 2 * cap}, {cells.data(), cells.size()}, {chain.data(), chain_len}, {}};
        BoundedList<uint32_t> order(ord.data(), cap);
        Run r;
        NewellOptions opt;
        opt.face_ids = s.mesh().ids;
        r.status = newell_order(view, polys, cuts, scratch, order, r.ns, opt);
        r.order.assign(order.data(), order.data() + order.size());
        r.chain_tail_intact = std::all_of(chain.begin() + static_cast<ptrdiff_t>(chain_len), chain.end(),
                                          [](uint32_t w) { return w == 0xC0FFEEu; });
        return r;
    };
    const Run full = run(0, 6), roomy = run(0, 16);
    MESSAGE("full pool: moves " << full.ns.moves << ", cycles " << full.ns.cycles << ", dropped " << full.ns.dropped);
    CHECK(full.status == Status::capacity_exceeded);
    CHECK(full.chain_tail_intact);
    CHECK(full.ns.cycles > 0);
    CHECK(full.order == roomy.order);  // the same decisions as with a chain to spare
    CHECK(full.ns.moves == roomy.ns.moves);
    CHECK(full.ns.dropped == roomy.ns.dropped);
    const Run spare = run(16, 22);  // room for the cuts: the cycle is cut, status ok
    CHECK(spare.status == Status::ok);
    CHECK(spare.chain_tail_intact);
}

TEST_CASE("Newell breaks a cycle at a pair its pixels order, and reports it when NewellScratch::reorders is full") {
    // boxes-69-10 without culling closes cycles of pieces that no plane cuts and whose closing pair's
    // shared pixels disagree with the order found: each is broken at another pair of the cycle, which
    // its pixels allow, kept in `reorders` while both wait. Without room there such a pair stays
    // unresolved (a wrong pixel) and the status says so; with room the status is ok, nothing unresolved.
    const tool::Scene s = test::generated_scene("boxes-69-10");
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}) == Status::ok);
    auto run = [&](size_t room, NewellStats& ns, bool& tail_intact) {
        const size_t cap = 2048;
        std::vector<ScreenPoly> store(cap);
        BoundedList<ScreenPoly> polys(store.data(), cap);
        FrameStats st;
        build_polys(view, s.mesh(), {verts.data(), verts.size()}, false, polys, st);
        std::vector<PieceCut> cut_store(2 * cap);
        BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
        std::vector<SortKey> keys(cap), sort_scratch(cap);
        std::vector<uint32_t> heap(cap), pos(cap), links(2 * cap), cells(grid_cells(s.width, s.height)), ord(cap), chain(cap);
        std::vector<uint32_t> reorders(room + 4, 0xC0FFEEu);  // the caller's array, then 4 words it does not own
        const NewellScratch scratch{{keys.data(), cap}, {sort_scratch.data(), cap}, {heap.data(), cap}, {pos.data(), cap},
                                    {links.data(), 2 * cap}, {cells.data(), cells.size()}, {chain.data(), cap},
                                    {reorders.data(), room}};
        BoundedList<uint32_t> order(ord.data(), cap);
        NewellOptions opt;
        opt.face_ids = s.mesh().ids;
        const Status status = newell_order(view, polys, cuts, scratch, order, ns, opt);
        tail_intact = std::all_of(reorders.begin() + static_cast<ptrdiff_t>(room), reorders.end(), [](uint32_t w) { return w == 0xC0FFEEu; });
        return status;
    };
    NewellStats with_room, without, odd;
    bool intact_room = false, intact_none = false, intact_odd = false;
    CHECK(run(kNewellReorders, with_room, intact_room) == Status::ok);
    CHECK(run(0, without, intact_none) == Status::capacity_exceeded);
    CHECK(run(1, odd, intact_odd) == Status::capacity_exceeded);  // one entry holds no pair
    MESSAGE("with room: pixel-ordered " << with_room.pixel_ordered << ", unresolved " << with_room.unresolved
                                        << "; without: pixel-ordered " << without.pixel_ordered << ", unresolved " << without.unresolved);
    CHECK(with_room.unresolved == 0);
    CHECK(with_room.pixel_ordered > 0);
    CHECK(without.unresolved > 0);
    CHECK(odd.unresolved == without.unresolved);
    CHECK((intact_room && intact_none && intact_odd));
    // The peak it reports is a size that repeats the run: the same statistics, status ok.
    CHECK(with_room.reorders_peak >= 2);
    CHECK(with_room.reorders_peak <= kNewellReorders);
    CHECK(without.reorders_peak == 0);
    NewellStats at_peak;
    bool intact_peak = false;
    CHECK(run(with_room.reorders_peak, at_peak, intact_peak) == Status::ok);
    CHECK(intact_peak);
    CHECK(at_peak.pair_tests == with_room.pair_tests);
    CHECK(at_peak.splits == with_room.splits);
    CHECK(at_peak.pixel_ordered == with_room.pixel_ordered);
    CHECK(at_peak.reorders_peak == with_room.reorders_peak);
    NewellStats below;  // and two words fewer does not (0 words here: the peak is one pair)
    bool intact_below = false;
    CHECK(run(with_room.reorders_peak - 2, below, intact_below) == Status::capacity_exceeded);
    CHECK(intact_below);
}

TEST_CASE("Newell's pair-test budget: any budget gives every polygon once, and ok only with the unlimited order") {
    // Three bars in a cycle with back faces: cycles whose consecutive pairs cannot be cut, broken by a cut
    // between two other polygons of the cycle. Whatever the budget, each polygon goes out once; the status
    // is ok only when nothing was cut short, so the order is the one an unlimited budget gives.
    const tool::Scene s = test::generated_scene("cyclic-bars");
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}) == Status::ok);
    const size_t cap = 2048;
    std::vector<ScreenPoly> store(cap);
    std::vector<PieceCut> cut_store(2 * cap);
    std::vector<SortKey> keys(cap), sort_scratch(cap);
    std::vector<uint32_t> heap(cap), pos(cap), links(2 * cap), cells(grid_cells(s.width, s.height)), ord(cap), chain(cap),
        reorders(kNewellReorders);
    auto run = [&](uint64_t budget, NewellStats& ns, std::vector<uint32_t>& out, size_t& polygons) {
        BoundedList<ScreenPoly> polys(store.data(), cap);
        FrameStats st;
        build_polys(view, s.mesh(), {verts.data(), verts.size()}, false, polys, st);
        BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
        const NewellScratch scratch{{keys.data(), cap}, {sort_scratch.data(), cap}, {heap.data(), cap}, {pos.data(), cap},
                                    {links.data(), 2 * cap}, {cells.data(), cells.size()}, {chain.data(), cap},
                                    {reorders.data(), reorders.size()}};
        BoundedList<uint32_t> order(ord.data(), cap);
        NewellOptions opt;
        opt.face_ids = s.mesh().ids;
        opt.max_pair_tests = budget;
        const Status status = newell_order(view, polys, cuts, scratch, order, ns, opt);
        out.assign(order.data(), order.data() + order.size());
        polygons = polys.size();
        return status;
    };
    NewellStats full;
    std::vector<uint32_t> full_order;
    size_t full_polygons = 0;
    REQUIRE(run(0, full, full_order, full_polygons) == Status::ok);
    REQUIRE(full.cycles > 0);
    REQUIRE(full.unresolved == 0);
    int ok = 0, cut_short = 0;
    for (uint64_t budget = 1; budget <= full.pair_tests + 4; ++budget) {
        NewellStats ns;
        std::vector<uint32_t> order;
        size_t polygons = 0;
        const Status status = run(budget, ns, order, polygons);
        INFO("budget " << budget);
        std::vector<uint32_t> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        bool each_once = sorted.size() == polygons;
        for (size_t i = 0; i < sorted.size() && each_once; ++i) each_once = sorted[i] == i;
        CHECK(each_once);
        CHECK(ns.pair_tests <= budget + 1);
        CHECK((status == Status::ok) == !ns.budget_exhausted);
        if (status == Status::ok) {
            CHECK(order == full_order);
            ++ok;
        } else {
            ++cut_short;
        }
    }
    MESSAGE("budgets: " << ok << " ok, " << cut_short << " cut short, of " << full.pair_tests << " pair tests unlimited");
    CHECK(ok >= 4);
    CHECK(cut_short > 1000);
}

TEST_CASE("newell_order on its own output (the same cuts) decides as on those polygons fresh: no chain of the first run survives") {
    // A second run restarted its chains at 0 while the polygons kept the chain numbers the first run
    // moved them in: a polygon moved once in the new chain counted as moved twice, a cycle that is not
    // there (a cut not needed, or capacity_exceeded with a pair unresolved; HIDER_ASSERT in the chain
    // search). Found by a red team on random soups: 156 of 3,000 second runs decided otherwise.
    int second_runs = 0, moved_before = 0;
    for (uint32_t seed = 0; seed < 400; ++seed) {
        std::mt19937 rng(seed * 7919u + 1u);
        auto coord = [&](int32_t spread) { return Q16::from_raw(static_cast<int32_t>(rng() % (2u * spread + 1)) - spread); };
        const int32_t width = 8 + static_cast<int32_t>(rng() % 90), height = 4 + static_cast<int32_t>(rng() % 70);
        const size_t n = 2 + rng() % 25;
        std::vector<Vec3q16> pos;
        std::vector<Tri> tris;
        for (size_t t = 0; t < n; ++t) {
            const Vec3q16 c{coord(65536), coord(65536), coord(65536)};
            for (int k = 0; k < 3; ++k) pos.push_back({c.x + coord(39322), c.y + coord(39322), c.z + coord(39322)});
            tris.push_back(Tri{{static_cast<uint16_t>(3 * t), static_cast<uint16_t>(3 * t + 1), static_cast<uint16_t>(3 * t + 2)}});
        }
        Camera cam;
        cam.eye = {coord(229376), coord(229376), Q16::from_raw(229376) + coord(65536)};
        cam.up = {Q16::from_raw(0), Q16::from_raw(65536), Q16::from_raw(0)};
        cam.fovy = Angle::from_degrees(Q16::from_int(20 + static_cast<int32_t>(rng() % 120)));
        cam.near = Q16::from_raw(3277);
        cam.far = Q16::from_int(50);
        View view;
        if (make_view(cam, width, height, view) != Status::ok) continue;
        Mesh mesh;
        mesh.positions = {pos.data(), pos.size()};
        mesh.tris = {tris.data(), tris.size()};
        std::vector<ScreenVertex> verts(pos.size());
        REQUIRE(project_vertices(view, mesh.positions, {verts.data(), verts.size()}) == Status::ok);
        const size_t cap = 7 * n + 512;
        std::vector<ScreenPoly> store(cap), fresh_store(cap);
        BoundedList<ScreenPoly> polys(store.data(), cap);
        FrameStats fs;
        build_polys(view, mesh, {verts.data(), verts.size()}, (rng() & 1u) != 0, polys, fs);
        std::vector<PieceCut> cut_store(1024), fresh_cut_store(1024);
        BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
        std::vector<SortKey> keys(cap), sort_scratch(cap);
        std::vector<uint32_t> heap(cap), heap_pos(cap), links(2 * cap), cells(grid_cells(width, height)), chain(cap), reorders(16);
        std::vector<uint32_t> ord(cap), fresh_ord(cap);
        const NewellScratch scratch{{keys.data(), cap}, {sort_scratch.data(), cap}, {heap.data(), cap}, {heap_pos.data(), cap},
                                    {links.data(), 2 * cap}, {cells.data(), cells.size()}, {chain.data(), cap},
                                    {reorders.data(), reorders.size()}};
        BoundedList<uint32_t> order(ord.data(), cap);
        NewellStats first;
        (void)newell_order(view, polys, cuts, scratch, order, first);
        moved_before += first.moves != 0;
        // The same polygons and cuts, fresh: as build_polys() and a first run leave them, never moved.
        BoundedList<ScreenPoly> fresh(fresh_store.data(), cap);
        for (size_t i = 0; i < polys.size(); ++i) {
            ScreenPoly p = polys[i];
            p.moved_at = kNotMoved;
            fresh.push_back(p);
        }
        BoundedList<PieceCut> fresh_cuts(fresh_cut_store.data(), fresh_cut_store.size());
        for (size_t i = 0; i < cuts.size(); ++i) fresh_cuts.push_back(cuts[i]);
        NewellStats again, want;
        const Status s_again = newell_order(view, polys, cuts, scratch, order, again);
        BoundedList<uint32_t> fresh_order(fresh_ord.data(), cap);
        const Status s_want = newell_order(view, fresh, fresh_cuts, scratch, fresh_order, want);
        ++second_runs;
        INFO("seed " << seed << ": again status " << std::string(status_name(s_again)) << " cycles " << again.cycles << " splits "
                     << again.splits << " unresolved " << again.unresolved << "; fresh status " << std::string(status_name(s_want))
                     << " cycles " << want.cycles << " splits " << want.splits << " unresolved " << want.unresolved);
        CHECK(s_again == s_want);
        CHECK(again.cycles == want.cycles);
        CHECK(again.moves == want.moves);
        CHECK(again.splits == want.splits);
        CHECK(again.unresolved == want.unresolved);
        CHECK(std::equal(order.data(), order.data() + order.size(), fresh_order.data(), fresh_order.data() + fresh_order.size()));
    }
    CHECK(second_runs > 350);
    CHECK(moved_before > 100);  // first runs that left chain numbers behind
}

#if defined(HIDER_ENABLE_ASSERTS)
TEST_CASE("With asserts, build_polys() checks hand-made vertices at entry, before appending any polygon") {
    test::HandMadeTriangle h;
    ScreenPoly store[4];
    BoundedList<ScreenPoly> polys(store, 4);
    FrameStats st;
    auto build = [&] { build_polys(h.view, h.mesh, {h.verts, 3}, false, polys, st); };
    CHECK_FALSE(test::assert_trap::fails(build));  // in range
    CHECK(polys.size() == 1);
    h.past_the_limit();
    polys.clear();
    CHECK(test::assert_trap::fails(build));
    CHECK(test::assert_trap::file().find("sort/poly.hpp") != std::string::npos);
    CHECK(polys.size() == 0);
}
#endif

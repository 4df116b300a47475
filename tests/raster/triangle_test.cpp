// Triangle traversal: the top-left fill rule on tiny ASCII rasters, exact coverage of shared edges
// (fans, random meshes, woody seen head-on), depth stepping that equals the closed-form plane, and the
// depth-free set-up covering exactly what the full one covers.
#include <hider/frame.hpp>
#include <hider/raster/triangle.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

namespace {

/// Screen vertex from pixel coordinates (origin at the top-left corner, in pixels) on a W x H frame.
ScreenVertex pv(double x, double y, int w, int h, uint32_t z = 1u << 20) {
    ScreenVertex v;
    v.x = static_cast<int16_t>(std::lround(x * kSubpixel) - w * kSubpixel / 2);
    v.y = static_cast<int16_t>(std::lround(y * kSubpixel) - h * kSubpixel / 2);
    v.z = z;
    return v;
}

struct Grid {
    int w, h;
    std::vector<int> n;
    Grid(int width, int height) : w(width), h(height), n(static_cast<size_t>(width) * height, 0) {}
    void draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int y0 = 0, int y1 = -1) {
        TriangleRaster t;
        if (!t.setup(a, b, c, w, h)) return;
        const int end = y1 < 0 ? h : y1;
        t.spans(std::max(y0, t.first_row()), std::min(end, t.end_row()), [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
            for (int32_t x = x0; x < x1; ++x) ++n[static_cast<size_t>(y) * w + x];
        });
    }
    std::string ascii() const {
        std::string s;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const int c = n[static_cast<size_t>(y) * w + x];
                s += c == 0 ? '.' : static_cast<char>('0' + c);
            }
            s += '\n';
        }
        return s;
    }
};

}  // namespace

TEST_CASE("top-left rule: a hypotenuse through pixel centres belongs to the triangle on its left side") {
    Grid g(6, 5);
    g.draw(pv(0, 0, 6, 5), pv(4, 0, 6, 5), pv(0, 4, 6, 5));  // hypotenuse is a right edge: excluded
    CHECK(g.ascii() ==
          "111...\n"
          "11....\n"
          "1.....\n"
          "......\n"
          "......\n");
    g.draw(pv(4, 0, 6, 5), pv(4, 4, 6, 5), pv(0, 4, 6, 5));  // the other half: hypotenuse is its left edge
    CHECK(g.ascii() ==
          "1111..\n"
          "1111..\n"
          "1111..\n"
          "1111..\n"
          "......\n");
}

TEST_CASE("top-left rule: top and left edges through centres are in, bottom and right are out") {
    Grid g(6, 5);
    // Rectangle [0.5, 3.5] x [0.5, 2.5] made of two triangles, corners on pixel centres.
    g.draw(pv(0.5, 0.5, 6, 5), pv(3.5, 0.5, 6, 5), pv(3.5, 2.5, 6, 5));
    g.draw(pv(0.5, 0.5, 6, 5), pv(3.5, 2.5, 6, 5), pv(0.5, 2.5, 6, 5));
    CHECK(g.ascii() ==
          "111...\n"
          "111...\n"
          "......\n"
          "......\n"
          "......\n");
}

TEST_CASE("top-left rule: winding does not change coverage, only front()") {
    Grid a(8, 6), b(8, 6);
    const ScreenVertex p = pv(0.5, 0.5, 8, 6), q = pv(6.5, 1.5, 8, 6), r = pv(2.5, 5.5, 8, 6);
    a.draw(p, q, r);
    b.draw(p, r, q);
    CHECK(a.ascii() == b.ascii());
    TriangleRaster t1, t2;
    REQUIRE(t1.setup(p, q, r, 8, 6));
    REQUIRE(t2.setup(p, r, q, 8, 6));
    CHECK(t1.front() != t2.front());
    CHECK(TriangleRaster::signed_area(p, r, q) < 0);  // counter-clockwise on the image
    CHECK(t2.front());
}

TEST_CASE("a vertex exactly on a pixel centre is drawn once by the triangles meeting there") {
    // Four triangles around the centre of pixel (3, 3) forming a diamond whose corners are pixel centres:
    // the left corner lies on left edges (in), the top, right and bottom corners on top-right/bottom edges (out).
    Grid g(7, 7);
    const ScreenVertex c = pv(3.5, 3.5, 7, 7);
    const ScreenVertex ring[4] = {pv(3.5, 0.5, 7, 7), pv(6.5, 3.5, 7, 7), pv(3.5, 6.5, 7, 7), pv(0.5, 3.5, 7, 7)};
    for (int i = 0; i < 4; ++i) g.draw(c, ring[i], ring[(i + 1) % 4]);
    CHECK(g.ascii() ==
          ".......\n"
          "..11...\n"
          ".1111..\n"
          "111111.\n"
          ".1111..\n"
          "..11...\n"
          ".......\n");
}

TEST_CASE("zero-area and sub-pixel triangles cover nothing or exactly what their centres say") {
    Grid g(4, 4);
    g.draw(pv(0, 0, 4, 4), pv(2, 2, 4, 4), pv(4, 4, 4, 4));        // collinear
    g.draw(pv(1.1, 1.1, 4, 4), pv(1.3, 1.1, 4, 4), pv(1.1, 1.3, 4, 4));  // misses every centre
    CHECK(g.ascii() == "....\n....\n....\n....\n");
    TriangleRaster t;
    CHECK_FALSE(t.setup(pv(1, 1, 4, 4), pv(1, 1, 4, 4), pv(3, 2, 4, 4), 4, 4));
}

TEST_CASE("fans with random subpixel vertices cover every inside pixel exactly once") {
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 200; ++trial) {
        const int w = 64, h = 48;
        Grid g(w, h);
        const double cx = 32 + (rng() % 1000) / 100.0 - 5, cy = 24 + (rng() % 1000) / 100.0 - 5;
        const int n = 3 + static_cast<int>(rng() % 30);
        std::vector<ScreenVertex> ring;
        std::vector<std::pair<double, double>> pts;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * (i + (rng() % 100) / 250.0) / n;
            const double r = 10 + (rng() % 1200) / 100.0;
            const ScreenVertex v = pv(cx + r * std::cos(a), cy + r * std::sin(a), w, h);
            ring.push_back(v);
            pts.push_back({(v.x + w * 8) / 16.0, (v.y + h * 8) / 16.0});
        }
        const ScreenVertex c = pv(cx, cy, w, h);
        for (int i = 0; i < n; ++i) g.draw(c, ring[i], ring[(i + 1) % n]);
        const double ccx = (c.x + w * 8) / 16.0, ccy = (c.y + h * 8) / 16.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int count = g.n[static_cast<size_t>(y) * w + x];
                CHECK(count <= 1);
                // Centres clearly inside the star-shaped polygon must be covered (no cracks).
                const double px = x + 0.5, py = y + 0.5;
                bool inside = false;
                for (int i = 0; i < n && !inside; ++i) {
                    const auto& p = pts[i];
                    const auto& q = pts[(i + 1) % n];
                    auto e = [&](double ax, double ay, double bx, double by) { return (bx - ax) * (py - ay) - (by - ay) * (px - ax); };
                    const double e0 = e(ccx, ccy, p.first, p.second), e1 = e(p.first, p.second, q.first, q.second),
                                 e2 = e(q.first, q.second, ccx, ccy);
                    const double m = 0.01;
                    inside = (e0 > m && e1 > m && e2 > m) || (e0 < -m && e1 < -m && e2 < -m);
                    // On an inner edge (e0 or e2 ~ 0) the neighbouring triangle must take it: check via count.
                    if (!inside && std::fabs(e1) > m && ((e0 >= -m && e1 > m && e2 >= -m) || (e0 <= m && e1 < -m && e2 <= m)))
                        inside = true;
                }
                if (inside) CHECK(count == 1);
            }
    }
}

TEST_CASE("depth stepped along rows equals the closed-form plane at every pixel, in any band") {
    std::mt19937 rng(77);
    for (int trial = 0; trial < 300; ++trial) {
        const int w = 80, h = 60;
        auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
        const ScreenVertex a = pv(rnd(-20, 100), rnd(-20, 80), w, h, kDepthNear + rng() % (kDepthFar - kDepthNear));
        const ScreenVertex b = pv(rnd(-20, 100), rnd(-20, 80), w, h, kDepthNear + rng() % (kDepthFar - kDepthNear));
        const ScreenVertex c = pv(rnd(-20, 100), rnd(-20, 80), w, h, kDepthNear + rng() % (kDepthFar - kDepthNear));
        TriangleRaster t;
        if (!t.setup(a, b, c, w, h)) continue;
        std::vector<uint32_t> full(static_cast<size_t>(w) * h, 0), banded(full.size(), 0);
        auto collect = [&](std::vector<uint32_t>& out, int y0, int y1) {
            t.spans(std::max(y0, t.first_row()), std::min(y1, t.end_row()), [&](int32_t y, int32_t x0, int32_t x1, uint32_t z) {
                for (int32_t x = x0; x < x1; ++x, z += t.dzdx()) out[static_cast<size_t>(y) * w + x] = z;
            });
        };
        collect(full, 0, h);
        for (int y0 = 0; y0 < h; y0 += 7) collect(banded, y0, std::min(h, y0 + 7));
        CHECK(full == banded);
        // Every covered depth lies within the vertex range, widened by the stepping error bound.
        const uint32_t lo = std::min(a.z, std::min(b.z, c.z)), hi = std::max(a.z, std::max(b.z, c.z));
        for (uint32_t z : full)
            if (z != 0) {
                CHECK(z + uint32_t{(w + h) / 2 + 2} >= lo);
                CHECK(z <= hi + uint32_t{(w + h) / 2 + 2});
            }
    }
}

TEST_CASE("setup_flat covers the same rows and spans as setup in every band, with depth 0 throughout") {
    std::mt19937 rng(78);
    int drawn = 0, missed = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int w = 48, h = 40;
        auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
        const double size = trial % 3 == 0 ? 60 : 4;  // large triangles reaching past the frame, and sub-pixel-ish ones
        const double x = rnd(-10, 58), y = rnd(-10, 50);
        const ScreenVertex a = pv(x + rnd(-size, size), y + rnd(-size, size), w, h, kDepthNear + rng() % (kDepthFar - kDepthNear));
        const ScreenVertex b = pv(x + rnd(-size, size), y + rnd(-size, size), w, h, kDepthNear + rng() % (kDepthFar - kDepthNear));
        const ScreenVertex c = pv(x + rnd(-size, size), y + rnd(-size, size), w, h, kDepthNear + rng() % (kDepthFar - kDepthNear));
        const int32_t area = TriangleRaster::signed_area(a, b, c);
        for (int y0 = 0; y0 < h; y0 += 13) {
            FrameView<Grey8Format> band;
            band.width = w;
            band.height = h;
            band.y0 = y0;
            band.y1 = std::min(h, y0 + 13);
            const BandBounds bb = band_bounds(band);
            TriangleRaster full{}, flat{};  // value-initialised: GCC cannot see that setup() wrote them
            const bool ok = full.setup(a, b, c, area, w, h, bb), ok_flat = flat.setup_flat(a, b, c, area, w, h, bb);
            CHECK(ok_flat == ok);
            if (!ok || !ok_flat) { ++missed; continue; }
            ++drawn;
            CHECK(flat.first_row() == full.first_row());
            CHECK(flat.end_row() == full.end_row());
            CHECK(flat.front() == full.front());
            CHECK(flat.dzdx() == 0);
            std::vector<int32_t> spans_full, spans_flat;
            const int32_t r0 = std::max(band.y0, full.first_row()), r1 = std::min(band.y1, full.end_row());
            const auto record_full = [&](int32_t yy, int32_t x0, int32_t x1, uint32_t) {
                spans_full.insert(spans_full.end(), {yy, x0, x1});
            };
            const uint32_t n_full = full.spans(r0, r1, record_full);  // an lvalue functor, the other an rvalue
            const uint32_t n_flat = flat.spans(r0, r1, [&](int32_t yy, int32_t x0, int32_t x1, uint32_t z) {
                spans_flat.insert(spans_flat.end(), {yy, x0, x1});
                CHECK(z == 0);
            });
            CHECK(n_flat == n_full);
            CHECK(spans_flat == spans_full);
        }
    }
    CHECK(drawn > 1000);  // both kinds of outcome were exercised
    CHECK(missed > 100);
}

TEST_CASE("woody seen head-on: every pixel inside the outline is covered exactly once") {
    tool::CameraArgs cam;
    cam.fov_deg = 40;
    const tool::Scene s = test::load_model("woody.obj", cam);  // flat in z = 0, default eye on +z
    const std::vector<int> counts = test::coverage_counts(s, false);
    const std::vector<uint32_t> ref = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), false);
    long inside = 0, cracks = 0, doubles = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const size_t i = static_cast<size_t>(y) * s.width + x;
            if (counts[i] > 1) ++doubles;
            bool interior = ref[i] != 0;  // not next to the outline in the reference
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= s.width || ny >= s.height || ref[static_cast<size_t>(ny) * s.width + nx] == 0)
                        interior = false;
                }
            if (interior) {
                ++inside;
                if (counts[i] != 1) ++cracks;
            }
        }
    MESSAGE("woody: " << inside << " interior pixels, " << cracks << " not covered once, " << doubles << " double hits");
    CHECK(inside > 10000);
    CHECK(cracks == 0);
    CHECK(doubles == 0);
}

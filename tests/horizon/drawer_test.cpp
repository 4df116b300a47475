// The curve drawer against its horizons: crossings drawn by hand in ASCII (a curve given by two samples
// is drawn exactly up to where it passes behind nearer curves and again where it comes out below them),
// the fast walk (walk kernel + queued columns) equal to the general line_to() path on random curves,
// curves far outside the frame touching nothing outside the horizon arrays or the frame, bands equal
// to the whole frame, batches, undrawn lines, and the 1-bit page target.
#include <hider/horizon/drawer.hpp>
#include <hider/horizon/target.hpp>

#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

using namespace hider;
using namespace hider::horizon;

namespace {

using GreyTarget = FrameTarget<Grey8Format, uint16_t>;

/// A width x height grey frame with its horizons; curves are drawn with pixel value = curve number.
struct Canvas {
    int w, h;
    std::vector<uint8_t> pixels;
    std::vector<int16_t> upper, lower;
    Horizon hz;
    Canvas(int width, int height)
        : w(width), h(height), pixels(static_cast<size_t>(width) * height, 0), upper(width), lower(width) {
        REQUIRE(make_horizon({upper.data(), upper.size()}, {lower.data(), lower.size()}, w, h, hz) == Status::ok);
    }
    GreyTarget target() { return GreyTarget(frame_view<Grey8Format, uint16_t>(pixels.data(), nullptr, w, h)); }

    /// Draws the polyline of `pts` (pixel coordinates, 1/16 resolution) as curve `id`.
    void curve(const std::vector<PlotPoint>& pts, uint8_t id, bool fast) {
        const GreyTarget t = target();
        CurveDrawer<GreyTarget> d(hz, t);
        d.set_pixel(id);
        d.set_compact(true);
        d.move_to(pts[0]);
        if (fast) {
            d.walk(pts.data() + 1, pts.data() + pts.size());
        } else {
            for (size_t i = 1; i < pts.size(); ++i) d.line_to(pts[i]);
        }
        d.finish();
    }
    std::string ascii() const {
        std::string s;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const uint8_t v = pixels[static_cast<size_t>(y) * w + x];
                s += v == 0 ? '.' : static_cast<char>('0' + v);
            }
            s += '\n';
        }
        return s;
    }
};

/// Point at pixel (px, py) + (dx, dy) sixteenths.
PlotPoint at(int px, int py, int dx = 8, int dy = 8) { return {px * 16 + dx, py * 16 + dy}; }

}  // namespace

TEST_CASE("A curve of two samples is drawn up to where it passes behind nearer curves and from where it comes out below") {
    for (bool fast : {false, true}) {
        CAPTURE(fast);
        Canvas c(12, 8);
        c.curve({at(0, 2, 0), at(12, 2, 0)}, 1, fast);  // nearer curves: rows 2 and 4 across the frame
        c.curve({at(0, 4, 0), at(12, 4, 0)}, 2, fast);
        c.curve({{8, 13}, {200, 109}}, 3, fast);         // one segment, half a row per column, from row 0 to 6
        CHECK(c.ascii() ==
              "3...........\n"
              ".33.........\n"
              "111111111111\n"
              "............\n"
              "222222222222\n"
              ".........33.\n"
              "...........3\n"
              "............\n");
        // The horizons: rows 0..4 in columns 0..2 (upper from curve 3), down to 6 at the right.
        CHECK(c.upper == std::vector<int16_t>{0, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2});
        CHECK(c.lower == std::vector<int16_t>{4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 6});
    }
}

TEST_CASE("A steep segment inside one column shows only its rows outside the horizons") {
    for (bool fast : {false, true}) {
        CAPTURE(fast);
        Canvas c(6, 8);
        c.curve({at(0, 3), at(6, 3, 0)}, 1, fast);
        c.curve({at(0, 4), at(6, 4, 0)}, 2, fast);
        c.curve({at(0, 6), at(2, 6), at(2, 0, 10), at(3, 0, 6), at(3, 7), at(6, 7, 0)}, 3, fast);
        CHECK(c.ascii() ==
              "..33..\n"
              "..33..\n"
              "..33..\n"
              "111111\n"
              "222222\n"
              "..33..\n"
              "3333..\n"
              "...333\n");
    }
}

TEST_CASE("The first curve sets both horizons; a later curve dipping between them is hidden there") {
    // Regression: a run wholly above an unset upper horizon must set the lower horizon too. The curves
    // have a point in every column, so the fast walk queues their columns.
    auto dense = [](std::vector<int> rows) {
        std::vector<PlotPoint> pts;
        for (size_t c = 0; c < rows.size(); ++c) pts.push_back(at(static_cast<int>(c), rows[c]));
        return pts;
    };
    for (bool fast : {false, true}) {
        CAPTURE(fast);
        Canvas c(8, 6);
        c.curve(dense({4, 4, 4, 4, 4, 4, 4, 4}), 1, fast);
        c.curve(dense({2, 2, 2, 2, 2, 2, 2, 2}), 2, fast);
        c.curve(dense({1, 1, 1, 1, 3, 1, 1, 1}), 3, fast);  // dips to row 3 in column 4
        CHECK(c.ascii() ==
              "........\n"
              "3333.333\n"
              "22222222\n"
              "........\n"
              "11111111\n"
              "........\n");
        CHECK(c.upper == std::vector<int16_t>{1, 1, 1, 1, 2, 1, 1, 1});
        CHECK(c.lower == std::vector<int16_t>{4, 4, 4, 4, 4, 4, 4, 4});
    }
}

TEST_CASE("make_horizon rejects short arrays and sizes outside 1..kMaxFrameSide, and resets the horizons") {
    std::vector<int16_t> u(8, 7), l(8, 7);
    Horizon h;
    CHECK(make_horizon({u.data(), 7}, {l.data(), 8}, 8, 4, h) == Status::invalid_argument);
    CHECK(make_horizon({u.data(), 8}, {nullptr, 8}, 8, 4, h) == Status::invalid_argument);
    CHECK(make_horizon({u.data(), 8}, {l.data(), 8}, 0, 4, h) == Status::invalid_argument);
    CHECK(make_horizon({u.data(), 8}, {l.data(), 8}, 8, kMaxFrameSide + 1, h) == Status::invalid_argument);
    CHECK(u == std::vector<int16_t>(8, 7));
    REQUIRE(make_horizon({u.data(), 8}, {l.data(), 8}, 8, 4, h) == Status::ok);
    CHECK(u == std::vector<int16_t>(8, INT16_MAX));
    CHECK(l == std::vector<int16_t>(8, INT16_MIN));
    u[3] = 2;
    reset(h);
    CHECK(u[3] == INT16_MAX);
}

namespace {

/// A random polyline: mostly dense (steps of a few pixels, the walk kernel's case) with long jumps,
/// steep runs, points far outside the frame and back steps, in x and y within the compact range.
std::vector<PlotPoint> random_curve(std::mt19937& rng, int w, int h, int n) {
    std::uniform_int_distribution<int> kind(0, 19), small(-8, 40), dy(-60, 60), far(-20000, 20000);
    std::vector<PlotPoint> pts;
    PlotPoint p{std::uniform_int_distribution<int>(-64, w * 16 + 64)(rng), std::uniform_int_distribution<int>(-64, h * 16 + 64)(rng)};
    for (int i = 0; i < n; ++i) {
        pts.push_back(p);
        const int k = kind(rng);
        if (k == 0) {
            p = {far(rng), far(rng)};                      // far outside (and back later)
        } else if (k == 1) {
            p.x += std::uniform_int_distribution<int>(100, 900)(rng);  // long step
            p.y += dy(rng) * 4;
        } else if (k == 2) {
            p.y += dy(rng) * 8;                            // steep, same column
        } else {
            p.x += small(rng);
            p.y += dy(rng);
        }
        p.x = std::max(-30000, std::min(30000, p.x));
        p.y = std::max(-30000, std::min(30000, p.y));
    }
    return pts;
}

}  // namespace

TEST_CASE("The fast walk draws exactly what line_to draws, with the same horizons, on random curves") {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        CAPTURE(seed);
        std::mt19937 rng(seed);
        const int w = 16 + static_cast<int>(seed * 7 % 120), h = 8 + static_cast<int>(seed * 13 % 90);
        Canvas general(w, h), fast(w, h);
        for (int k = 0; k < 12; ++k) {
            const std::vector<PlotPoint> pts = random_curve(rng, w, h, 20 + k * 9);
            general.curve(pts, static_cast<uint8_t>(1 + k % 9), false);
            fast.curve(pts, static_cast<uint8_t>(1 + k % 9), true);
        }
        CHECK(fast.pixels == general.pixels);
        CHECK(fast.upper == general.upper);
        CHECK(fast.lower == general.lower);
        long lit = 0;
        for (uint8_t v : general.pixels) lit += v != 0;
        CHECK(lit > 0);
    }
}

TEST_CASE("Curves far outside the frame never touch memory outside the horizons or the frame") {
    // Horizons and pixels sit inside larger buffers filled with a canary; ASan (host-asan) checks the rest.
    const int w = 24, h = 16, pad = 64;
    std::vector<int16_t> upper(w + 2 * pad, 0x5A5A), lower(w + 2 * pad, 0x5A5A);
    std::vector<uint8_t> pixels(static_cast<size_t>(w) * (h + 4) + 2 * pad, 0xA5);
    Horizon hz;
    REQUIRE(make_horizon({upper.data() + pad, static_cast<size_t>(w)}, {lower.data() + pad, static_cast<size_t>(w)}, w, h, hz) == Status::ok);
    const GreyTarget t(frame_view<Grey8Format, uint16_t>(pixels.data() + pad, nullptr, w, h));
    for (int i = 0; i < w * h; ++i) pixels[static_cast<size_t>(pad + i)] = 0;
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(-(1 << 24) + 1, (1 << 24) - 1), near_frame(-400, 800);
    for (int k = 0; k < 200; ++k) {
        CurveDrawer<GreyTarget> d(hz, t);
        d.set_pixel(static_cast<uint8_t>(1 + k % 200));
        d.set_compact(false);
        std::vector<PlotPoint> pts;
        for (int i = 0; i < 30; ++i) pts.push_back(k % 2 ? PlotPoint{coord(rng), coord(rng)} : PlotPoint{near_frame(rng), near_frame(rng)});
        d.move_to(pts[0]);
        for (size_t i = 1; i < pts.size(); ++i) d.line_to(pts[i]);
        d.finish();
    }
    for (int i = 0; i < pad; ++i) {
        CHECK(upper[static_cast<size_t>(i)] == 0x5A5A);
        CHECK(lower[static_cast<size_t>(i)] == 0x5A5A);
        CHECK(upper[static_cast<size_t>(pad + w + i)] == 0x5A5A);
        CHECK(lower[static_cast<size_t>(pad + w + i)] == 0x5A5A);
        CHECK(pixels[static_cast<size_t>(i)] == 0xA5);
    }
    for (size_t i = static_cast<size_t>(pad + w * h); i < pixels.size(); ++i) CHECK(pixels[i] == 0xA5);
    for (int c = 0; c < w; ++c) {  // stored rows stay clamped to [-1, h]
        CHECK(upper[static_cast<size_t>(pad + c)] >= -1);
        CHECK(lower[static_cast<size_t>(pad + c)] <= h);
    }
}

TEST_CASE("Band by band the drawer writes exactly the bytes of the whole frame") {
    std::mt19937 rng(11);
    const int w = 40, h = 30;
    std::vector<std::vector<PlotPoint>> curves;
    for (int k = 0; k < 10; ++k) curves.push_back(random_curve(rng, w, h, 40));
    Canvas whole(w, h);
    for (size_t k = 0; k < curves.size(); ++k) whole.curve(curves[k], static_cast<uint8_t>(1 + k), true);
    for (int rows : {1, 3, 7, 16, 30}) {
        CAPTURE(rows);
        std::vector<uint8_t> frame(static_cast<size_t>(w) * h, 0), band(static_cast<size_t>(w) * rows);
        std::vector<int16_t> upper(w), lower(w);
        Horizon hz;
        REQUIRE(make_horizon({upper.data(), upper.size()}, {lower.data(), lower.size()}, w, h, hz) == Status::ok);
        for (int y0 = 0; y0 < h; y0 += rows) {
            const int y1 = std::min(h, y0 + rows);
            std::fill(band.begin(), band.end(), 0);
            const GreyTarget t(band_view<Grey8Format, uint16_t>(band.data(), nullptr, w, h, y0, y1));
            reset(hz);
            for (size_t k = 0; k < curves.size(); ++k) {
                CurveDrawer<GreyTarget> d(hz, t);
                d.set_pixel(static_cast<uint8_t>(1 + k));
                d.set_compact(true);
                d.move_to(curves[k][0]);
                d.walk(curves[k].data() + 1, curves[k].data() + curves[k].size());
                d.finish();
            }
            std::copy(band.begin(), band.begin() + (y1 - y0) * w, frame.begin() + y0 * w);
        }
        CHECK(frame == whole.pixels);
    }
}

TEST_CASE("In a batch curves are tested against the horizons from before it; end_batch merges them") {
    Canvas c(6, 6);
    c.curve({at(0, 3, 0), at(6, 3, 0)}, 1, false);
    std::vector<int16_t> pu(6, INT16_MAX), pl(6, INT16_MIN);
    const GreyTarget t = c.target();
    CurveDrawer<GreyTarget> d(c.hz, t);
    d.begin_batch(pu.data(), pl.data());
    d.set_pixel(2);
    d.move_to(at(0, 1, 0));
    d.line_to(at(6, 1, 0));
    d.finish();
    d.set_pixel(3);  // row 2 would be hidden by curve 2 without the batch
    d.move_to(at(0, 2, 0));
    d.line_to(at(6, 2, 0));
    d.finish();
    CHECK(c.upper == std::vector<int16_t>(6, 3));  // unchanged until the batch ends
    d.end_batch();
    CHECK(c.upper == std::vector<int16_t>(6, 1));
    CHECK(pu == std::vector<int16_t>(6, INT16_MAX));  // pending arrays emptied again
    CHECK(c.ascii() == "......\n222222\n333333\n111111\n......\n......\n");
}

TEST_CASE("An undrawn line widens the horizons by its middle row only and draws nothing") {
    Canvas c(4, 8);
    c.curve({at(0, 6, 0), at(4, 6, 0)}, 1, false);
    const GreyTarget t = c.target();
    CurveDrawer<GreyTarget> d(c.hz, t);
    d.set_pixel(2);
    d.set_visible(false);
    d.move_to(at(1, 1));
    d.line_to(at(1, 5, 8, 8));  // rows 1..5 in column 1: middle row 3
    d.finish();
    CHECK(c.upper == std::vector<int16_t>{6, 3, 6, 6});
    CHECK(c.ascii().find('2') == std::string::npos);
}

TEST_CASE("The 1-bit page target lights the same pixels as a grey frame, whole and in bands of pages") {
    std::mt19937 rng(5);
    const int w = 37, h = 29;
    std::vector<std::vector<PlotPoint>> curves;
    for (int k = 0; k < 8; ++k) curves.push_back(random_curve(rng, w, h, 50));
    Canvas grey(w, h);
    for (const auto& pts : curves) grey.curve(pts, 1, true);
    for (int pages_per_band : {1, 2, 4}) {
        CAPTURE(pages_per_band);
        std::vector<uint8_t> all(static_cast<size_t>(w) * ((h + 7) / 8), 0xFF), band(static_cast<size_t>(w) * pages_per_band);
        std::vector<int16_t> upper(w), lower(w);
        Horizon hz;
        REQUIRE(make_horizon({upper.data(), upper.size()}, {lower.data(), lower.size()}, w, h, hz) == Status::ok);
        for (int p0 = 0; p0 * 8 < h; p0 += pages_per_band) {
            const int p1 = std::min((h + 7) / 8, p0 + pages_per_band);
            const MonoFrame f{band.data(), w, h, p0, p1};
            REQUIRE(f.valid());
            horizon::clear(f);
            const MonoTarget t(f);
            reset(hz);
            for (const auto& pts : curves) {
                CurveDrawer<MonoTarget> d(hz, t);
                d.set_pixel(MonoTarget::pack({255, 255, 255}));
                d.set_compact(true);
                d.move_to(pts[0]);
                d.walk(pts.data() + 1, pts.data() + pts.size());
                d.finish();
            }
            std::copy(band.begin(), band.begin() + (p1 - p0) * w, all.begin() + p0 * w);
        }
        const MonoFrame whole{all.data(), w, h, 0, (h + 7) / 8};
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                CAPTURE(x);
                CAPTURE(y);
                CHECK(whole.lit(x, y) == (grey.pixels[static_cast<size_t>(y) * w + x] != 0));
            }
    }
    CHECK(MonoTarget::pack({0, 0, 0}) == 0);
    CHECK(MonoTarget::pack({0, 1, 0}) == 1);
}

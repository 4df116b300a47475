// Column windows (<hider/view.hpp>: centred_window(), window_view()): a frame drawn through a centred
// window must give exactly the whole frame's bytes and statistics in the window's columns, with nothing
// but background outside them (checked against the whole z-buffer frame and against the independent
// reference rasterizer), for every shipped model, generated scenes that clip, objects off centre and
// random soups around the eye; the window is as narrow as its rule allows, and the whole width whenever
// a vertex is clipped or reaches past a side.
#include <hider/raster/binned.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/render.hpp"
#include "support/reference.hpp"
#include "support/projected.hpp"
#include "support/soup.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

constexpr Rgb kBackground{7, 9, 11};

ScreenVertex at_x(int32_t x, uint32_t z = 1u << 20) {
    ScreenVertex v;
    v.x = static_cast<int16_t>(x);
    v.y = 0;
    v.z = z;
    return v;
}

/// The largest |x| of the vertices (all projected).
int32_t largest_reach(const std::vector<ScreenVertex>& verts) {
    int32_t r = 0;
    for (const ScreenVertex& v : verts) r = std::max<int32_t>(r, v.x < 0 ? -v.x : v.x);
    return r;
}

/// Whether a centred window of margin m holds every x within its first and last column centres.
bool holds(int32_t m, int32_t width, int32_t reach) {
    const int32_t origin = pixel_centre_origin(width);
    return origin + kSubpixel * m <= -reach && origin + kSubpixel * (width - 1 - m) >= reach;
}

/// The window's rule on `verts`: whole width for a clipped vertex or one reaching past a side; else a
/// centred window whose edge column centres hold every vertex, and whose margin one larger would not hold
/// them at a reach of one subpixel more (the rule rounds |x| up by at most one subpixel).
void check_rule(const std::vector<ScreenVertex>& verts, int32_t width, const ColumnWindow& w) {
    CAPTURE(width);
    CAPTURE(w.x0);
    REQUIRE(w.x0 >= 0);
    REQUIRE(w.width == width - 2 * w.x0);
    REQUIRE(w.width >= 1);
    const bool clipped = std::any_of(verts.begin(), verts.end(), [](const ScreenVertex& v) { return v.z == 0; });
    if (verts.empty() || clipped) {
        CHECK(w.x0 == 0);
        return;
    }
    const int32_t reach = largest_reach(verts);
    if (w.x0 > 0) CHECK(holds(w.x0, width, reach));  // the whole width holds nothing that reaches past a side
    CHECK(!holds(w.x0 + 1, width, reach + 1));
}

using test::Projected;
using test::project;

void check_same_stats(const FrameStats& a, const FrameStats& b) {
    CHECK(a.status == b.status);
    CHECK(a.triangles_in == b.triangles_in);
    CHECK(a.triangles_drawn == b.triangles_drawn);
    CHECK(a.triangles_culled == b.triangles_culled);
    CHECK(a.triangles_clipped == b.triangles_clipped);
    CHECK(a.triangles_outside == b.triangles_outside);
    CHECK(a.fragments == b.fragments);
    CHECK(a.pixels_written == b.pixels_written);
}

/// Columns [x0, x0 + width) of a whole frame's rows.
template <class Pixel>
std::vector<Pixel> columns_of(const std::vector<Pixel>& frame, int32_t frame_width, int32_t height, int32_t x0, int32_t width) {
    std::vector<Pixel> out;
    for (int32_t y = 0; y < height; ++y) {
        const Pixel* row = frame.data() + static_cast<size_t>(y) * frame_width;
        out.insert(out.end(), row + x0, row + x0 + width);
    }
    return out;
}

template <class Pixel>
bool same_bytes(const std::vector<Pixel>& a, const std::vector<Pixel>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Pixel)) == 0;
}

/// clear() + draw_zbuffer<kCount>() of a width-wide frame through `view`.
template <bool kCount, class Format, class Depth>
std::vector<typename Format::Pixel> zbuffer_frame(const tool::Scene& s, const View& view, const Projected& p, int32_t width,
                                                  FrameStats& st) {
    std::vector<typename Format::Pixel> color(static_cast<size_t>(width) * s.height);
    std::vector<Depth> depth(color.size());
    const auto frame = frame_view<Format, Depth>(color.data(), depth.data(), width, s.height);
    clear(frame, kBackground);
    st = draw_zbuffer<kCount>(view, s.mesh(), {p.verts.data(), p.verts.size()}, frame, p.opt);
    return color;
}

/// draw_zbuffer_binned() of a width-wide frame through `view` in bands of `rows` rows.
template <class Format, class Depth>
std::vector<typename Format::Pixel> binned_frame(const tool::Scene& s, const View& view, const Projected& p, int32_t width,
                                                 int32_t rows, size_t slots, FrameStats& st) {
    std::vector<typename Format::Pixel> color(static_cast<size_t>(width) * rows), out;
    std::vector<Depth> depth(color.size());
    std::vector<uint16_t> next(s.tris.size()), head(static_cast<size_t>((s.height + rows - 1) / rows));
    std::vector<KernelTriangle> carried(slots);
    std::vector<uint8_t> order(3 * slots);
    const BinnedScratch scratch{{next.data(), next.size()}, {head.data(), head.size()}, {carried.data(), carried.size()},
                                {order.data(), order.size()}};
    st = draw_zbuffer_binned(view, s.mesh(), {p.verts.data(), p.verts.size()},
                             band_view<Format, Depth>(color.data(), depth.data(), width, s.height, 0, rows), p.opt,
                             kBackground, scratch, [&](const FrameView<Format, Depth>& band) {
                                 for (int32_t y = band.y0; y < band.y1; ++y) out.insert(out.end(), band.row(y), band.row(y) + width);
                                 return true;
                             });
    return out;
}

struct Tally {
    long narrowed = 0, whole = 0, saved_columns = 0;
};

/// One scene through its window against the whole frame: the count and row-kernel z-buffer paths and
/// bands of several heights; background outside the window in the whole frame and in the reference.
template <class Format, class Depth>
void check_scene(const std::string& name, const tool::Scene& s, bool cull, Shade shade, Tally& tally) {
    CAPTURE(name);
    CAPTURE(cull);
    const Projected p = project(s, cull, shade);
    const ColumnWindow w = centred_window({p.verts.data(), p.verts.size()}, s.width);
    check_rule(p.verts, s.width, w);
    View narrow;
    REQUIRE(window_view(p.view, w, narrow) == Status::ok);
    CHECK(narrow.width == w.width);
    (w.x0 > 0 ? tally.narrowed : tally.whole) += 1;
    tally.saved_columns += 2 * w.x0;
    using Pixel = typename Format::Pixel;
    const Pixel background = Format::pack(kBackground);
    FrameStats whole_st, st;
    const auto whole = zbuffer_frame<true, Format, Depth>(s, p.view, p, s.width, whole_st);
    REQUIRE(whole_st.ok());
    // Nothing outside the window, in the whole frame and in the reference rasterizer's.
    long outside = 0;
    for (int32_t y = 0; y < s.height; ++y)
        for (int32_t x = 0; x < s.width; ++x)
            if ((x < w.x0 || x >= w.x0 + w.width) && std::memcmp(&whole[static_cast<size_t>(y) * s.width + x], &background, sizeof(Pixel)) != 0)
                ++outside;
    CHECK(outside == 0);
    if (w.x0 > 0) {
        const std::vector<uint32_t> ids = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), cull);
        long ref_outside = 0;
        for (int32_t y = 0; y < s.height; ++y)
            for (int32_t x = 0; x < s.width; ++x)
                if ((x < w.x0 || x >= w.x0 + w.width) && ids[static_cast<size_t>(y) * s.width + x] != 0) ++ref_outside;
        CHECK(ref_outside == 0);
    }
    const auto expected = columns_of(whole, s.width, s.height, w.x0, w.width);
    // The counting path, the row-kernel path and bands, each through the narrowed view.
    CHECK(same_bytes(zbuffer_frame<true, Format, Depth>(s, narrow, p, w.width, st), expected));
    check_same_stats(st, whole_st);
    FrameStats fast_whole;
    (void)zbuffer_frame<false, Format, Depth>(s, p.view, p, s.width, fast_whole);
    CHECK(same_bytes(zbuffer_frame<false, Format, Depth>(s, narrow, p, w.width, st), expected));
    check_same_stats(st, fast_whole);
    for (int32_t rows : {1, 3, 7, s.height}) {
        if (rows > s.height) continue;
        CAPTURE(rows);
        for (size_t slots : {size_t{0}, size_t{4}, size_t{64}}) {
            CHECK(same_bytes(binned_frame<Format, Depth>(s, narrow, p, w.width, rows, slots, st), expected));
            CHECK(st.ok());
            CHECK(st.triangles_drawn == whole_st.triangles_drawn);
            CHECK(st.triangles_culled == whole_st.triangles_culled);
            CHECK(st.triangles_clipped == whole_st.triangles_clipped);
            CHECK(st.triangles_outside == whole_st.triangles_outside);
        }
    }
}

template <class Format, class Depth>
void check_both_windings(const std::string& name, const tool::Scene& s, Shade shade, Tally& tally) {
    check_scene<Format, Depth>(name, s, true, shade, tally);
    check_scene<Format, Depth>(name, s, false, shade, tally);
}

}  // namespace

TEST_CASE("centred_window: the narrowest centred window holding every vertex, or the whole width") {
    const int32_t w320 = 320;
    // Empty, a clipped vertex, a vertex past either side: the whole width.
    CHECK(centred_window({}, w320).x0 == 0);
    CHECK(centred_window({}, w320).width == w320);
    std::vector<ScreenVertex> v = {at_x(-100), at_x(100)};
    CHECK(centred_window({v.data(), v.size()}, w320).x0 > 0);
    v.push_back(at_x(0, 0));  // z == 0: outside a clip plane
    CHECK(centred_window({v.data(), v.size()}, w320).x0 == 0);
    for (int32_t x : {-2552, -2553, 2552, 2553, -16383, 16383}) {  // the first/last column centres are -+2552
        CAPTURE(x);
        v = {at_x(0), at_x(x)};
        const ColumnWindow w = centred_window({v.data(), v.size()}, w320);
        check_rule(v, w320, w);
        CHECK(w.x0 == 0);
    }
    // The torus's extent at 320x240 (x in [-1542, 1536]: pixel centres of columns 64..255 inside): the
    // window's edge centres at or beyond it, columns 63..256.
    v = {at_x(-1542), at_x(1536)};
    ColumnWindow w = centred_window({v.data(), v.size()}, w320);
    check_rule(v, w320, w);
    CHECK(w.x0 == 63);
    CHECK(w.width == 194);
    // A clipped vertex anywhere (each lane of the four-a-turn loop and the tail): the whole width.
    for (size_t n = 1; n <= 13; ++n)
        for (size_t at = 0; at < n; ++at) {
            CAPTURE(n);
            CAPTURE(at);
            v.assign(n, at_x(40));
            v[at] = at_x(3, 0);
            CHECK(centred_window({v.data(), v.size()}, w320).x0 == 0);
            v[at] = at_x(-3);
            CHECK(centred_window({v.data(), v.size()}, w320).x0 > 0);
        }
    // Widths outside [1, kMaxFrameSide]: the whole (given) width, no arithmetic on them.
    v = {at_x(10)};
    for (int32_t width : {0, -5, kMaxFrameSide + 1, INT32_MAX}) {
        CAPTURE(width);
        w = centred_window({v.data(), v.size()}, width);
        CHECK(w.x0 == 0);
        CHECK(w.width == width);
    }
    // Every reach on a few widths (odd, even, 1, the largest): the rule.
    long narrowed = 0;
    for (int32_t width : {1, 2, 3, 17, 160, 320, 1024})
        for (int32_t reach = 0; reach <= 8 * width + 24; ++reach)
            for (int sign : {1, -1}) {
                v = {at_x(sign * reach), at_x(-sign * (reach / 3))};
                w = centred_window({v.data(), v.size()}, width);
                check_rule(v, width, w);
                narrowed += w.x0 > 0;
            }
    CHECK(narrowed > 10000);
}

TEST_CASE("window_view refuses a window that is not centred in the view's frame") {
    const tool::Scene s = test::load_model("torus.obj");
    View view, out;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    CHECK(window_view(view, {10, s.width - 20}, out) == Status::ok);
    CHECK(out.width == s.width - 20);
    CHECK(out.height == view.height);
    CHECK(out.k_q8 == view.k_q8);
    for (const ColumnWindow bad : {ColumnWindow{10, s.width - 21}, ColumnWindow{-1, s.width + 2}, ColumnWindow{0, s.width + 1},
                                   ColumnWindow{s.width / 2, 0}, ColumnWindow{0, 0}, ColumnWindow{INT32_MAX, 2}}) {
        CAPTURE(bad.x0);
        CAPTURE(bad.width);
        out = View{};
        CHECK(window_view(view, bad, out) == Status::invalid_argument);
        CHECK(out.width == 0);  // untouched
    }
}

TEST_CASE("a frame drawn through its window equals the whole frame there, on every shipped model") {
    std::vector<std::string> models;
    for (const auto& e : std::filesystem::directory_iterator(std::string(HIDER_TEST_DATA) + "/models"))
        if (e.path().extension() == ".obj") models.push_back(e.path().filename().string());
    std::sort(models.begin(), models.end());
    REQUIRE(models.size() >= 9);
    Tally tally;
    for (const std::string& name : models) {
        tool::CameraArgs cam;
        cam.width = 96;
        cam.height = 64;
        const tool::Scene s = test::load_model(name, cam);
        if (s.tris.size() > 65535) continue;  // the band renderer refuses it (binned_test.cpp)
        check_both_windings<Rgb565Format, uint16_t>(name, s, Shade::headlight, tally);  // row kernel
        check_scene<Rgb888Format, uint32_t>(name, s, false, Shade::id, tally);        // TriangleRaster
        // Off centre: eye and target moved sideways (world x is the screen's), so the object sits left
        // or right of the centre and its window is wider than its extent.
        for (int32_t shift_units : {-120, 170}) {
            tool::Scene moved = s;
            moved.camera.eye.x = Q16::from_raw(moved.camera.eye.x.raw() + shift_units * 65536);
            moved.camera.target.x = Q16::from_raw(moved.camera.target.x.raw() + shift_units * 65536);
            check_scene<Rgb565Format, uint16_t>(name + " off centre " + std::to_string(shift_units), moved, true,
                                                Shade::headlight, tally);
        }
    }
    MESSAGE("narrowed " << tally.narrowed << ", whole " << tally.whole << ", columns left out " << tally.saved_columns);
    CHECK(tally.narrowed > 20);
}

TEST_CASE("windows of random soups, eyes inside and outside, in small frames: the whole frame's bytes and counts") {
    // Eyes inside the soup clip triangles (the whole width then); eyes outside give narrow windows,
    // wide ones, and soups reaching past a side. Odd and even widths from 1 to 40 columns.
    test::Xorshift64 rng{0x9E3779B97F4A7C15ull};
    auto next = [&rng] { return rng.next(); };
    auto uniform = [&rng](double lo, double hi) { return rng.uniform(lo, hi); };
    Tally tally;
    long clipped_scenes = 0;
    for (int seed = 0; seed < 1500; ++seed) {
        const double spread = uniform(0.05, 1);  // narrow and wide soups
        const tool::ObjModel m = test::random_soup(rng, 30, 30, spread);
        tool::CameraArgs cam;
        const bool inside = next() % 3 == 0;
        cam.eye = inside ? tool::Vec3d{uniform(-0.5, 0.5), uniform(-0.5, 0.5), uniform(-0.5, 0.5)}
                         : tool::Vec3d{uniform(-1, 1), uniform(-1, 1), uniform(2, 6)};
        cam.target = tool::Vec3d{uniform(-0.6, 0.6), uniform(-0.6, 0.6), uniform(-0.6, 0.6)};
        cam.fov_deg = uniform(20, 120);
        cam.near = uniform(0.01, 0.3);
        cam.width = 1 + static_cast<int>(next() % 40);
        cam.height = 1 + static_cast<int>(next() % 24);
        tool::Scene s;
        std::string why;
        if (!tool::build_scene(m, cam, s, why)) continue;  // e.g. the eye on the target
        const std::string name = "soup " + std::to_string(seed);
        const bool cull = (next() & 1) != 0;
        check_scene<Rgb565Format, uint16_t>(name, s, cull, Shade::headlight, tally);  // row kernel
        check_scene<Grey8Format, uint32_t>(name, s, !cull, Shade::depth, tally);      // TriangleRaster, depth shading
        FrameStats st;
        const Projected p = project(s, false, Shade::headlight);
        (void)zbuffer_frame<true, Rgb565Format, uint16_t>(s, p.view, p, s.width, st);
        clipped_scenes += st.triangles_clipped > 0;
    }
    MESSAGE("narrowed " << tally.narrowed << ", whole " << tally.whole << ", scenes that clip " << clipped_scenes);
    CHECK(tally.narrowed > 500);
    CHECK(tally.whole > 500);
    CHECK(clipped_scenes > 200);
}

TEST_CASE("the tools' z-buffer render (RenderOptions::window) gives the whole frame's bytes and counts through the window") {
    long narrowed = 0;
    for (const char* name : {"torus.obj", "cow.obj", "teapot.obj"}) {
        for (int band_rows : {0, 5}) {
            tool::CameraArgs cam;
            cam.width = 120;
            cam.height = 90;
            const tool::Scene s = test::load_model(name, cam);
            tool::RenderOptions opt;
            opt.band_rows = band_rows;
            opt.background = kBackground;
            tool::RenderResult whole, windowed;
            std::string why;
            REQUIRE(tool::render(s, opt, whole, why));
            opt.window = true;
            REQUIRE(tool::render(s, opt, windowed, why));
            CAPTURE(name);
            CAPTURE(band_rows);
            CHECK(windowed.rgb == whole.rgb);
            CHECK(windowed.pixels_covered == whole.pixels_covered);
            CHECK(windowed.stats.fragments == whole.stats.fragments);
            CHECK(windowed.stats.triangles_drawn == whole.stats.triangles_drawn);
            const Projected p = project(s, true, Shade::headlight);
            narrowed += centred_window({p.verts.data(), p.verts.size()}, s.width).x0 > 0;
        }
    }
    CHECK(narrowed >= 4);  // the window is narrower than the frame on most of them
}

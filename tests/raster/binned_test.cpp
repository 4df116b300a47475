// The binned band renderer against the whole frame: draw_zbuffer_binned() through one band-sized buffer
// must give exactly clear() + draw_zbuffer() on the whole frame, with the same statistics, for every
// shipped model, pixel format, depth size and shading, any band height and any number of carried slots
// (none, too few, plenty); and it refuses what it cannot do.
#include <hider/raster/binned.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/assert_trap.hpp"
#include "support/hand_made.hpp"
#include "support/projected.hpp"
#include "support/soup.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

constexpr Rgb kBackground{7, 9, 11};

template <class Pixel>
bool same_bytes(const std::vector<Pixel>& a, const std::vector<Pixel>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Pixel)) == 0;
}

using test::Projected;
using test::project;

template <class Format, class Depth>
std::vector<typename Format::Pixel> whole_frame(const tool::Scene& s, const Projected& p, FrameStats& st) {
    std::vector<typename Format::Pixel> color(static_cast<size_t>(s.width) * s.height);
    std::vector<Depth> depth(color.size());
    const auto frame = frame_view<Format, Depth>(color.data(), depth.data(), s.width, s.height);
    clear(frame, kBackground);
    st = draw_zbuffer<false>(p.view, s.mesh(), {p.verts.data(), p.verts.size()}, frame, p.opt);
    return color;
}

/// Scratch sized for the mesh, with `slots` carried set-ups.
struct Scratch {
    std::vector<uint16_t> next, head;
    std::vector<KernelTriangle> carried;
    std::vector<uint8_t> order;
    BinnedScratch view;
    Scratch(size_t tris, size_t bands, size_t slots)
        : next(tris), head(bands), carried(slots), order(3 * slots),
          view{{next.data(), next.size()}, {head.data(), head.size()}, {carried.data(), carried.size()},
               {order.data(), order.size()}} {}
};

/// The frame through draw_zbuffer_binned() in bands of `rows` rows, with `slots` carried set-ups, into
/// band buffers of `pad` spare elements a row (stride = width + pad), which nothing may touch.
template <class Format, class Depth>
std::vector<typename Format::Pixel> binned(const tool::Scene& s, const Projected& p, int32_t rows, size_t slots,
                                           FrameStats& st, BinnedStats& bs, int32_t pad = 0) {
    using Pixel = typename Format::Pixel;
    const int32_t stride = s.width + pad;
    Pixel sentinel{};
    std::memset(&sentinel, 0x5A, sizeof sentinel);
    std::vector<Pixel> color(static_cast<size_t>(stride) * rows, sentinel), out;
    std::vector<Depth> depth(color.size(), Depth(0x5A5A5A5Au));
    auto buffers = band_view<Format, Depth>(color.data(), depth.data(), s.width, s.height, 0, rows);
    buffers.stride = stride;
    Scratch scratch(s.tris.size(), static_cast<size_t>((s.height + rows - 1) / rows), slots);
    int32_t next_row = 0;
    bool pad_kept = true;
    st = draw_zbuffer_binned(p.view, s.mesh(), {p.verts.data(), p.verts.size()}, buffers, p.opt, kBackground, scratch.view,
                             [&](const FrameView<Format, Depth>& band) {
                                 CHECK(band.y0 == next_row);
                                 CHECK(band.stride == stride);
                                 next_row = band.y1;
                                 for (int32_t y = band.y0; y < band.y1; ++y) {
                                     out.insert(out.end(), band.row(y), band.row(y) + s.width);
                                     for (int32_t x = s.width; x < stride; ++x)
                                         pad_kept = pad_kept && std::memcmp(band.row(y) + x, &sentinel, sizeof sentinel) == 0 &&
                                                    band.depth_row(y)[x] == Depth(0x5A5A5A5Au);
                                 }
                                 return true;
                             }, &bs);
    CHECK(next_row == s.height);
    CHECK(pad_kept);
    return out;
}

/// The bands of `heights` rows (those up to the frame's), each with 0, 2 and 255 carried slots, against the
/// whole frame: the same bytes and statistics. Returns the set-ups repeated (BinnedStats::set_up_again).
template <class Format, class Depth>
long check_bands(const std::string& name, const tool::Scene& s, bool cull, Shade shade, const std::vector<int32_t>& heights) {
    const Projected p = project(s, cull, shade);
    FrameStats full_st;
    const auto full = whole_frame<Format, Depth>(s, p, full_st);
    REQUIRE(full_st.ok());
    long set_up_again = 0;
    for (int32_t rows : heights) {
        if (rows > s.height) continue;
        for (size_t slots : {size_t{0}, size_t{2}, size_t{255}}) {
            CAPTURE(name);
            CAPTURE(rows);
            CAPTURE(slots);
            FrameStats st;
            BinnedStats bs;
            const auto got = binned<Format, Depth>(s, p, rows, slots, st, bs);
            CHECK(st.ok());
            CHECK(same_bytes(got, full));
            CHECK(st.triangles_in == full_st.triangles_in);
            CHECK(st.triangles_drawn == full_st.triangles_drawn);
            CHECK(st.triangles_culled == full_st.triangles_culled);
            CHECK(st.triangles_clipped == full_st.triangles_clipped);
            CHECK(st.triangles_outside == full_st.triangles_outside);
            CHECK(bs.carried_high_water <= slots);
            if (slots == 0) CHECK(bs.carried == 0);
            set_up_again += bs.set_up_again;
        }
    }
    return set_up_again;
}

template <class Format, class Depth>
void check_model(const std::string& name, const tool::Scene& s, bool cull, Shade shade) {
    (void)check_bands<Format, Depth>(name, s, cull, shade, {1, 3, 8, 61, s.height});
}

tool::CameraArgs torus_view() {
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{0, 0, -2.5};
    cam.target = tool::Vec3d{0, 0, 0};
    cam.fov_deg = 73.7398;
    cam.near = 0.25;
    return cam;
}

}  // namespace

TEST_CASE("binned bands give exactly the whole frame on every shipped model, format and slot count") {
    std::vector<std::string> models;
    for (const auto& e : std::filesystem::directory_iterator(std::string(HIDER_TEST_DATA) + "/models"))
        if (e.path().extension() == ".obj") models.push_back(e.path().filename().string());
    std::sort(models.begin(), models.end());
    REQUIRE(models.size() >= 9);
    for (const std::string& name : models) {
        const tool::Scene s = test::load_model(name, name == "torus.obj" ? torus_view() : tool::CameraArgs{});
        if (s.tris.size() > 65535) continue;  // refused: see the next test
        check_model<Rgb565Format, uint16_t>(name, s, true, Shade::headlight);
        check_model<Rgb565Format, uint16_t>(name, s, false, Shade::id);
        check_model<Rgb888Format, uint32_t>(name, s, true, Shade::headlight);
        check_model<Grey8Format, uint16_t>(name, s, false, Shade::depth);
    }
}

TEST_CASE("binned bands give exactly the whole frame on scenes that clip: through the near plane, behind the eye") {
    // Clipped triangles are binned by their highest piece; the other pieces start in later bands and
    // must count as drawn once, in their own first band, as the whole frame counts them.
    uint32_t clipped = 0;
    auto check = [&clipped](const std::string& name, const tool::Scene& s) {
        check_model<Rgb565Format, uint16_t>(name, s, true, Shade::headlight);
        check_model<Rgb565Format, uint16_t>(name, s, false, Shade::headlight);
        check_model<Grey8Format, uint16_t>(name, s, false, Shade::id);
        FrameStats st;
        (void)whole_frame<Rgb565Format, uint16_t>(s, project(s, false, Shade::headlight), st);
        clipped += st.triangles_clipped;
    };
    for (const char* name : {"huge-1", "huge-2", "huge-3", "grid-4-16-6", "grid-5-24-12", "city-6-5-5-street",
                             "dense-7-300", "mikado-8-80"})
        check(name, test::generated_scene(name));
    // The far plane through the torus: its pieces lie inside the frame's columns, so they are kernel
    // set-ups, and a fan's later pieces start rows below the first.
    for (double far : {2.3, 2.6, 3.0}) {
        tool::CameraArgs cam = torus_view();
        cam.far = far;
        check("torus far " + std::to_string(far), test::load_model("torus.obj", cam));
    }
    CHECK(clipped > 300);  // the scenes do clip
}

TEST_CASE("binned bands after empty bands: gaps between objects, above and below them") {
    // Two tori one above the other, with empty rows above, between and below them: a band after one into
    // which nothing is listed or carried skips its clear (that band's clear left the background), and the
    // first empty band after drawn rows must clear. Every band height and slot count against the frame.
    tool::CameraArgs cam = torus_view();
    cam.width = 40;
    cam.height = 160;
    const tool::Scene one = test::load_model("torus.obj", cam);
    tool::Scene s = one;
    s.positions.clear();
    s.tris.clear();
    s.normals.clear();
    s.ids.clear();
    for (const int32_t dy : {-1, 1}) {
        const auto base = static_cast<uint16_t>(s.positions.size());
        for (Vec3q16 v : one.positions) {
            v.y = Q16::from_raw(v.y.raw() + dy * (Q16::kOne + Q16::kOne / 4));  // 1.25 world units up or down
            s.positions.push_back(v);
        }
        for (Tri t : one.tris) {
            for (uint16_t& k : t.v) k = static_cast<uint16_t>(k + base);
            s.tris.push_back(t);
        }
        s.normals.insert(s.normals.end(), one.normals.begin(), one.normals.end());
        for (uint32_t id : one.ids) s.ids.push_back(id + (dy > 0 ? static_cast<uint32_t>(one.tris.size()) : 0u));
    }
    // The frame's rows that draw nothing: some above, some below and a run between the tori.
    FrameStats st;
    const Projected p = project(s, true, Shade::headlight);
    const auto full = whole_frame<Rgb565Format, uint16_t>(s, p, st);
    const uint16_t bg = Rgb565Format::pack(kBackground);
    std::vector<bool> empty_row(static_cast<size_t>(s.height));
    for (int32_t y = 0; y < s.height; ++y)
        empty_row[static_cast<size_t>(y)] = std::all_of(full.begin() + y * s.width, full.begin() + (y + 1) * s.width,
                                                        [bg](uint16_t px) { return px == bg; });
    int32_t first = 0, last = s.height - 1, gap = 0, run = 0;
    while (first < s.height && empty_row[static_cast<size_t>(first)]) ++first;
    while (last >= 0 && empty_row[static_cast<size_t>(last)]) --last;
    for (int32_t y = first; y <= last; ++y) {
        run = empty_row[static_cast<size_t>(y)] ? run + 1 : 0;
        gap = std::max(gap, run);
    }
    CAPTURE(first);
    CAPTURE(last);
    REQUIRE(first >= 8);
    REQUIRE(s.height - 1 - last >= 8);
    REQUIRE(gap >= 8);  // two empty bands of up to 4 rows between the tori
    for (const bool cull : {true, false})
        (void)check_bands<Rgb565Format, uint16_t>("two tori", s, cull, Shade::headlight, {1, 2, 3, 4});
}

TEST_CASE("binned bands honour a band buffer's stride: rows of width + pad, the pad untouched") {
    // The RGB565 kernel path drew rows stride apart but cleared and handed done() rows width apart: a
    // frame shifted by a column per row, with status ok (found by a red-team fuzzer).
    const tool::Scene s = test::load_model("torus.obj", [] {
        tool::CameraArgs c = torus_view();
        c.width = 53;
        c.height = 37;
        return c;
    }());
    for (const bool cull : {true, false}) {
        for (const int32_t pad : {1, 3, 8}) {
            for (const int32_t rows : {1, 4, 37}) {
                CAPTURE(cull);
                CAPTURE(pad);
                CAPTURE(rows);
                const Projected p = project(s, cull, Shade::headlight);
                FrameStats full_st, st;
                BinnedStats bs;
                CHECK(same_bytes(binned<Rgb565Format, uint16_t>(s, p, rows, 4, st, bs, pad),
                                 whole_frame<Rgb565Format, uint16_t>(s, p, full_st)));
                CHECK(st.ok());
                const Projected q = project(s, cull, Shade::depth);
                CHECK(same_bytes(binned<Rgb888Format, uint32_t>(s, q, rows, 4, st, bs, pad),
                                 whole_frame<Rgb888Format, uint32_t>(s, q, full_st)));
                CHECK(st.ok());
            }
        }
    }
}

TEST_CASE("binned bands carry set-ups across bands, and set them up again when the slots run out") {
    const tool::Scene s = test::load_model("torus.obj", torus_view());
    const Projected p = project(s, true, Shade::headlight);
    FrameStats st;
    BinnedStats plenty, none, few;
    (void)binned<Rgb565Format, uint16_t>(s, p, 4, 255, st, plenty);
    (void)binned<Rgb565Format, uint16_t>(s, p, 4, 0, st, none);
    (void)binned<Rgb565Format, uint16_t>(s, p, 4, 8, st, few);
    const uint32_t continuations = plenty.carried + plenty.set_up_again;
    CHECK(plenty.carried > 1000);      // about 12 rows a triangle in 4-row bands
    CHECK(plenty.set_up_again < 10);   // only the few triangles the kernel set-up leaves to TriangleRaster
    CHECK(plenty.carried_high_water > 8);
    CHECK(none.carried == 0);
    CHECK(none.set_up_again == continuations);  // every continuation set up again
    CHECK(few.carried_high_water == 8);
    CHECK(few.carried + few.set_up_again == continuations);
    CHECK(few.set_up_again > plenty.set_up_again);
    // The figures are the frame's: a struct kept across frames (to size the slots) is not added to.
    BinnedStats kept = few;
    (void)binned<Rgb565Format, uint16_t>(s, p, 4, 8, st, kept);
    CHECK(kept.carried == few.carried);
    CHECK(kept.set_up_again == few.set_up_again);
    CHECK(kept.carried_high_water == few.carried_high_water);
    kept = plenty;
    (void)binned<Rgb565Format, uint16_t>(s, p, 4, 0, st, kept);
    CHECK(kept.carried_high_water == 0);
}

TEST_CASE("draw_zbuffer_binned refuses scratch too small, big meshes and a sink that stops") {
    const tool::Scene s = test::load_model("torus.obj", torus_view());
    const Projected p = project(s, true, Shade::headlight);
    std::vector<uint16_t> color(static_cast<size_t>(s.width) * 8), depth(color.size());
    const auto buffers = band_view<Rgb565Format, uint16_t>(color.data(), depth.data(), s.width, s.height, 0, 8);
    const Mesh mesh = s.mesh();
    int calls = 0;
    auto count = [&](const FrameView<Rgb565Format, uint16_t>&) { return ++calls < 3; };
    auto draw = [&](Scratch& sc) {
        return draw_zbuffer_binned(p.view, mesh, {p.verts.data(), p.verts.size()}, buffers, p.opt, kBackground, sc.view, count);
    };
    SUBCASE("next shorter than the triangles") {
        Scratch sc(s.tris.size() - 1, 30, 4);
        CHECK(draw(sc).status == Status::invalid_argument);
        CHECK(calls == 0);
    }
    SUBCASE("head shorter than the bands") {
        Scratch sc(s.tris.size(), 29, 4);
        CHECK(draw(sc).status == Status::invalid_argument);
    }
    SUBCASE("slots fewer than three per carried set-up") {
        Scratch sc(s.tris.size(), 30, 4);
        sc.view.slots = {sc.order.data(), 11};
        CHECK(draw(sc).status == Status::invalid_argument);
    }
    SUBCASE("more than 255 carried slots") {
        Scratch sc(s.tris.size(), 30, 256);
        CHECK(draw(sc).status == Status::invalid_argument);
    }
    SUBCASE("a stride past kMaxStride") {  // a red team's 2^30: its byte count overflowed 32 bits
        for (int32_t stride : {int32_t{1} << 30, kMaxStride + 1}) {
            auto wide = buffers;
            wide.stride = stride;
            Scratch sc(s.tris.size(), 30, 4);
            CHECK(draw_zbuffer_binned(p.view, mesh, {p.verts.data(), p.verts.size()}, wide, p.opt, kBackground, sc.view,
                                      count).status == Status::invalid_argument);
            CHECK(calls == 0);
        }
    }
    SUBCASE("a sink that stops after its third band") {
        Scratch sc(s.tris.size(), 30, 4);
        CHECK(draw(sc).status == Status::invalid_argument);
        CHECK(calls == 3);
    }
    SUBCASE("a mesh of more than 65,535 triangles") {
        const tool::Scene bunny = test::load_model("stanford-bunny.obj");
        REQUIRE(bunny.tris.size() > 65535);
        const Projected bp = project(bunny, true, Shade::headlight);
        Scratch sc(bunny.tris.size(), 30, 4);
        const auto bb = band_view<Rgb565Format, uint16_t>(color.data(), depth.data(), bunny.width, bunny.height, 0, 8);
        CHECK(draw_zbuffer_binned(bp.view, bunny.mesh(), {bp.verts.data(), bp.verts.size()}, bb, bp.opt, kBackground,
                                  sc.view, count).status == Status::invalid_argument);
    }
}

TEST_CASE("binned bands give the whole frame's bytes and counts on random soups around the eye, in tiny frames") {
    // Eyes inside the soup (or on one of its vertices) clip many triangles into pieces; tiny frames and
    // 1- to 5-row bands put pieces with no pixel row (their box holds a centre their edges exclude)
    // below the band of their triangle's list: the whole frame counts each as drawn, so the bands must
    // carry the triangle on to the band of that piece's first row (found by the adversarial hunt: 9 of
    // 3,000 random scenes were short by 1 or 2 drawn triangles).
    test::Xorshift64 rng{0x2545F4914F6CDD1Dull};
    auto next = [&rng] { return rng.next(); };
    auto uniform = [&rng](double lo, double hi) { return rng.uniform(lo, hi); };
    long clipped = 0, set_up_again = 0;
    for (int seed = 0; seed < 4000; ++seed) {
        const tool::ObjModel m = test::random_soup(rng, 40, 40);
        tool::CameraArgs cam;
        const auto& on = m.vertices[0];
        cam.eye = next() % 4 == 0 ? tool::Vec3d{on[0], on[1], on[2]} : tool::Vec3d{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        cam.target = tool::Vec3d{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
        cam.fov_deg = uniform(20, 150);
        cam.near = uniform(0.001, 0.3);
        cam.width = 1 + static_cast<int>(next() % 24);
        cam.height = 1 + static_cast<int>(next() % 24);
        tool::Scene s;
        std::string why;
        if (!tool::build_scene(m, cam, s, why)) continue;  // e.g. the eye on the target
        const std::string name = "soup " + std::to_string(seed);
        const bool cull = (next() & 1) != 0;
        const std::vector<int32_t> heights = {1, 2, 3, 5, s.height};
        set_up_again += check_bands<Rgb565Format, uint16_t>(name, s, cull, Shade::headlight, heights);  // kernel set-ups
        set_up_again += check_bands<Rgb565Format, uint32_t>(name, s, cull, Shade::id, heights);         // TriangleRaster
        set_up_again += check_bands<Grey8Format, uint32_t>(name, s, !cull, Shade::depth, heights);
        FrameStats st;
        (void)whole_frame<Rgb565Format, uint16_t>(s, project(s, false, Shade::headlight), st);
        clipped += st.triangles_clipped;
    }
    MESSAGE("clipped triangles " << clipped << ", set up again " << set_up_again);
    CHECK(clipped > 1000);
}

namespace {
/// BinnedStats of one frame of `verts` / `tris` (screen space) in bands of `rows` rows, 4 slots.
template <class Format, class Depth>
BinnedStats bands_of(const View& view, const std::vector<ScreenVertex>& verts, const std::vector<Tri>& tris, int32_t rows, Shade shade) {
    const std::vector<Vec3q16> positions(verts.size());
    Mesh mesh;
    mesh.positions = {positions.data(), positions.size()};
    mesh.tris = {tris.data(), tris.size()};
    std::vector<typename Format::Pixel> color(static_cast<size_t>(view.width) * rows);
    std::vector<Depth> depth(color.size());
    Scratch scratch(tris.size(), static_cast<size_t>((view.height + rows - 1) / rows), 4);
    DrawOptions opt;
    opt.cull = false;
    opt.shade = shade;
    BinnedStats bs;
    const FrameStats st = draw_zbuffer_binned(view, mesh, {verts.data(), verts.size()},
                                              band_view<Format, Depth>(color.data(), depth.data(), view.width, view.height, 0, rows),
                                              opt, kBackground, scratch.view, [](const FrameView<Format, Depth>&) { return true; }, &bs);
    CHECK(st.ok());
    CHECK(st.triangles_drawn == tris.size());
    return bs;
}
}  // namespace

TEST_CASE("binned bands count no set-up again below the last band") {
    // A 16x8 frame; one triangle from row 5 down past the bottom, crossing the right side (the kernel set-up
    // leaves it to TriangleRaster, which the other formats use for every triangle): in one band of 8 rows,
    // or starting in the last of two 4-row bands, there is no next band to set it up in; in 3-row bands
    // (0-2, 3-5, 6-7) it continues once, from band 1 into band 2.
    Camera cam;
    cam.eye = {Q16::from_int(0), Q16::from_int(0), Q16::from_int(1)};
    cam.target = {Q16::from_int(0), Q16::from_int(0), Q16::from_int(0)};
    cam.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
    cam.fovy = Angle::from_degrees(Q16::from_int(60));
    cam.near = Q16::from_raw(6553);
    cam.far = Q16::from_int(100);
    View view;
    REQUIRE(make_view(cam, 16, 8, view) == Status::ok);
    const int32_t ox = pixel_centre_origin(16), oy = pixel_centre_origin(8);  // centre of pixel (0, 0)
    auto at = [&](int32_t x, int32_t y) {
        ScreenVertex v;
        v.x = static_cast<int16_t>(ox + x * kSubpixel);
        v.y = static_cast<int16_t>(oy + y * kSubpixel);
        v.z = 0x40000000u;
        return v;
    };
    const std::vector<ScreenVertex> verts = {at(4, 5), at(20, 12), at(2, 12)};
    const std::vector<Tri> tris = {{{0, 1, 2}}};
    for (const int32_t rows : {8, 4, 3}) {
        CAPTURE(rows);
        const uint32_t expected = rows == 3 ? 1 : 0;
        const BinnedStats kernel = bands_of<Rgb565Format, uint16_t>(view, verts, tris, rows, Shade::headlight);
        CHECK(kernel.carried == 0);
        CHECK(kernel.set_up_again == expected);
        const BinnedStats generic = bands_of<Grey8Format, uint32_t>(view, verts, tris, rows, Shade::depth);
        CHECK(generic.set_up_again == expected);
    }
}

TEST_CASE("the ARMv7-M binning loop's band of a subpixel row is exact for every band height of a 1,024-row frame") {
    // The loop takes floor(v * band_scale_v(rows) / 2^32) for v = y - y_lift in [0, 16 * height - 1];
    // the C++ loop the band of the row v >> 4. Checked on every v where the exact band steps (v = 16 rows q
    // and the v below it) and at the ends.
    int failures = 0;
    for (uint32_t rows = 1; rows <= static_cast<uint32_t>(kMaxFrameSide); ++rows) {
        const uint64_t scale = detail::band_scale_v(rows);
        const uint32_t v_end = 16u * static_cast<uint32_t>(kMaxFrameSide);
        auto check = [&](uint32_t v) {
            const uint64_t band = (v * scale) >> 32;
            if (band != (v >> 4) / rows) ++failures;
        };
        for (uint32_t step = 0; step < v_end; step += 16 * rows) {
            check(step);
            if (step > 0) check(step - 1);
        }
        check(v_end - 1);
    }
    CHECK(failures == 0);
}

#if defined(HIDER_ENABLE_ASSERTS)
TEST_CASE("With asserts, draw_zbuffer_binned() checks hand-made vertices at entry, before any band") {
    test::HandMadeTriangle h;
    constexpr int n = test::HandMadeTriangle::kSize;
    uint16_t color[n * 4], depth[n * 4], next[1], head[4];
    const auto band = band_view<Rgb565Format, uint16_t>(color, depth, n, n, 0, 4);  // 4-row bands
    const BinnedScratch scratch{{next, 1}, {head, 4}, {}, {}};
    DrawOptions opt;
    opt.cull = false;
    int bands = 0;
    auto done = [&bands](const FrameView<Rgb565Format, uint16_t>&) { return ++bands != 0; };
    FrameStats st;
    auto draw = [&] { st = draw_zbuffer_binned(h.view, h.mesh, {h.verts, 3}, band, opt, Rgb{0, 0, 0}, scratch, done); };
    CHECK_FALSE(test::assert_trap::fails(draw));  // in range
    CHECK(st.ok());
    CHECK(st.triangles_drawn == 1);
    CHECK(bands == 4);
    h.past_the_limit();
    bands = 0;
    CHECK(test::assert_trap::fails(draw));
    CHECK(test::assert_trap::file().find("raster/binned.hpp") != std::string::npos);
    CHECK(bands == 0);  // no band drawn before it
}
#endif

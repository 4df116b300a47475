// The z-buffer renderer end to end on small scenes: intersection lines, near-plane crossing, culling,
// shading, band rendering == full frame in every format, and the documented depth resolution.
#include <hider/raster/zbuffer.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/assert_trap.hpp"
#include "support/hand_made.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

tool::Scene scene_of(const std::vector<std::array<tool::Vec3d, 3>>& tris, const tool::CameraArgs& cam) {
    tool::ObjModel m;
    uint32_t id = 1;
    for (const auto& t : tris) {
        tool::ObjFace f;
        for (const auto& v : t) {
            f.v.push_back(static_cast<int32_t>(m.vertices.size()));
            m.vertices.push_back(v);
        }
        f.id = id++;
        m.faces.push_back(f);
    }
    tool::Scene s;
    std::string why;
    const bool ok = tool::build_scene(m, cam, s, why);
    REQUIRE_MESSAGE(ok, why);
    return s;
}

tool::CameraArgs front_camera(double z = 5) {
    tool::CameraArgs c;
    c.eye = tool::Vec3d{0, 0, z};
    c.target = tool::Vec3d{0, 0, 0};
    c.up = tool::Vec3d{0, 1, 0};
    c.fov_deg = 40;
    c.near = 0.5;
    c.far = 20;
    return c;
}

tool::RenderResult render(const tool::Scene& s, tool::RenderOptions opt) {
    tool::RenderResult r;
    std::string why;
    const bool ok = tool::render(s, opt, r, why);
    REQUIRE_MESSAGE(ok, why);
    return r;
}

}  // namespace

TEST_CASE("two interpenetrating triangles split exactly along their intersection line") {
    // A lies in z = 0, B in z = x / 2: they cross on x = 0, the centre column of the image.
    const tool::Scene s = scene_of({{{{-2, -1, 0}, {2, -1, 0}, {0, 2, 0}}}, {{{-2, -1, -1}, {2, -1, 1}, {0, 2, 0}}}},
                                   front_camera());
    for (int bits : {16, 32}) {
        const std::vector<uint32_t> ids = test::hider_ids(s, true, bits);
        int checked = 0;
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const uint32_t id = ids[static_cast<size_t>(y) * s.width + x];
                if (id == 0) continue;
                if (x <= s.width / 2 - 2) { CHECK(id == 1); ++checked; }
                if (x >= s.width / 2 + 1) { CHECK(id == 2); ++checked; }
            }
        CHECK(checked > 5000);
    }
}

TEST_CASE("culling keeps counter-clockwise faces, drops clockwise ones, and --no-cull draws both") {
    const std::array<tool::Vec3d, 3> ccw{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}};
    const std::array<tool::Vec3d, 3> cw{{{-1, -1, 0}, {0, 1, 0}, {1, -1, 0}}};
    tool::RenderOptions opt;
    opt.format = tool::PixelFormat::rgb888;
    const size_t centre = (120 * 320 + 160) * 3;
    const tool::RenderResult front = render(scene_of({ccw}, front_camera()), opt);
    CHECK(front.rgb[centre] == 255);  // facing the eye: N.z = 1
    CHECK(front.stats.triangles_culled == 0);
    const tool::RenderResult back = render(scene_of({cw}, front_camera()), opt);
    CHECK(back.rgb[centre] == 0);
    CHECK(back.stats.triangles_culled == 1);
    opt.cull = false;
    const tool::RenderResult both = render(scene_of({cw}, front_camera()), opt);
    CHECK(both.rgb[centre] == 255);  // back side lit with -N.z
}

TEST_CASE("headlight brightness is N.z of the view-space face normal") {
    // A face tilted 60 degrees from the view axis about y: N.z = cos 60 = 0.5.
    const double c = std::cos(M_PI / 3), s = std::sin(M_PI / 3);
    const tool::Scene sc = scene_of({{{{-c, -1, s}, {c, -1, -s}, {0, 1, 0}}}}, front_camera());
    tool::RenderOptions opt;
    opt.format = tool::PixelFormat::rgb888;
    const tool::RenderResult r = render(sc, opt);
    const size_t centre = (120 * 320 + 160) * 3;
    CHECK(std::abs(r.rgb[centre] - 128) <= 1);
}

TEST_CASE("nothing behind the eye shows, and a triangle crossing the near plane is cut, not dropped") {
    tool::CameraArgs cam = front_camera(0);
    cam.target = tool::Vec3d{0, 0, -1};
    cam.near = 0.5;
    cam.far = 50;
    SUBCASE("wholly behind the eye: nothing drawn") {
        const tool::Scene s = scene_of({{{{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}}}, {{{-50, -50, -40}, {50, -50, -40}, {0, 50, -40}}}}, cam);
        const std::vector<uint32_t> ids = test::hider_ids(s, false);
        for (uint32_t id : ids) CHECK(id != 1);
    }
    SUBCASE("a floor from behind the eye to far away is drawn up to the near plane") {
        const tool::Scene s = scene_of({{{{-10, -1, 10}, {10, -1, 10}, {0, -1, -40}}}}, cam);
        const std::vector<uint32_t> ids = test::hider_ids(s, false);
        const std::vector<uint32_t> ref = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), false);
        const ref::Agreement a = ref::compare_ids(ids, ref, s.width, s.height);
        CHECK(a.rate() >= 0.999);
        long covered = 0;
        for (uint32_t id : ids) covered += id != 0;
        CHECK(covered > 10000);
        tool::RenderOptions opt;
        CHECK(render(s, opt).stats.triangles_clipped == 1);
    }
}

TEST_CASE("band by band gives exactly the bytes of the full frame in every format and depth size") {
    std::vector<tool::Scene> scenes;
    tool::CameraArgs torus_cam;
    torus_cam.eye = tool::Vec3d{0, 0, -2.5};
    torus_cam.target = tool::Vec3d{0, 0, 0};
    torus_cam.fov_deg = 73.7398;
    torus_cam.near = 0.25;
    scenes.push_back(test::load_model("torus.obj", torus_cam));
    scenes.push_back(test::load_model("teapot.obj"));
    tool::Scene huge;
    std::string why;
    REQUIRE(test::scene_from_ref(ref::huge_triangles(3), huge, why));
    scenes.push_back(huge);
    for (const tool::Scene& s : scenes)
        for (tool::PixelFormat fmt : {tool::PixelFormat::rgb565, tool::PixelFormat::rgb888, tool::PixelFormat::grey8})
            for (int bits : {16, 32})
                for (Shade shade : {Shade::headlight, Shade::depth}) {
                    tool::RenderOptions opt;
                    opt.format = fmt;
                    opt.depth_bits = bits;
                    opt.shade = shade;
                    opt.cull = bits == 16;
                    const tool::RenderResult full = render(s, opt);
                    for (int rows : {1, 7, 16, 61}) {
                        opt.band_rows = rows;
                        const tool::RenderResult banded = render(s, opt);
                        CHECK(banded.rgb == full.rgb);
                        CHECK(banded.stats.fragments == full.stats.fragments);
                        CHECK(banded.stats.triangles_drawn == full.stats.triangles_drawn);
                        CHECK(banded.stats.triangles_culled == full.stats.triangles_culled);
                    }
                }
}

TEST_CASE("the 16-bit buffer separates surfaces one stored LSB apart and merges closer ones") {
    // Two screen-filling parallel quads at view distance w: the farther drawn first, then the nearer.
    const double n = 1, f = 100, w = 50;
    const double lsb16 = w * w * (1 / n - 1 / f) * 65536.0 / (4294967296.0 - 73728);  // CONVENTIONS.md
    auto run = [&](double gap, int bits, double at) {
        const double zf = -at - gap / 2, zn = -at + gap / 2, e = 200;
        tool::CameraArgs cam;
        cam.eye = tool::Vec3d{0, 0, 0};
        cam.target = tool::Vec3d{0, 0, -1};
        cam.fov_deg = 40;
        cam.near = n;
        cam.far = f;
        cam.width = 64;
        cam.height = 48;
        // The fit must not rescale: keep the scene bounding box fixed by adding far corners to both cases.
        const tool::Scene s = scene_of({{{{-e, -e, zf}, {e, -e, zf}, {0, e, zf}}}, {{{-e, -e, zn}, {e, -e, zn}, {0, e, zn}}},
                                        {{{-99, -99, -99}, {-99, -99, -99}, {-99, -99, -99}}}, {{{99, 99, 0}, {99, 99, 0}, {99, 99, 0}}}},
                                       cam);
        const std::vector<uint32_t> ids = test::hider_ids(s, true, bits);
        long nearer = 0;
        for (uint32_t id : ids) nearer += id == 2;
        return static_cast<double>(nearer) / ids.size();
    };
    MESSAGE("16-bit resolution at w = 50 (near 1, far 100): " << lsb16 << " units");
    CHECK(run(3 * lsb16, 16, w) == 1.0);    // separated everywhere
    // 1/16 LSB apart: tied (the first drawn, farther, stays) unless a stored step falls between the two,
    // about one distance in 16; at 16 distances across a stored LSB, most tie.
    int tied = 0;
    for (int k = 0; k < 16; ++k) tied += run(lsb16 / 16, 16, w + k * lsb16 / 16) < 0.25;
    MESSAGE("1/16 LSB apart: tied at " << tied << " of 16 distances");
    CHECK(tied >= 12);
    // 32-bit: limited by the stepping error, (W + H) / 2 LSB of 2^32.
    const double lsb32 = w * w * (1 / n - 1 / f) * (64 + 48) / 2 / (4294967296.0 - 73728);
    MESSAGE("32-bit resolution at w = 50: " << lsb32 << " units");
    CHECK(run(3 * lsb16 / 64, 32, w) == 1.0);  // far below the 16-bit limit, still separated with 32 bits
    CHECK(run(4 * lsb32, 32, w) == 1.0);
}

TEST_CASE("the 16-bit buffer draws a surface up to the far plane, however far that is from the near one") {
    // The last 2^-16 of the depth range once stored 0xFFFF, the clear value, in a 16-bit buffer, which no
    // surface beats: with near 1/256 and far 8000 a triangle 300 units away drew 0 of its pixels (a
    // red-team fuzzer: about 2% of its random scenes). Every distance to just inside the far plane, both
    // paths (counting and row kernel) against the 32-bit buffer.
    const auto u = [](double x) { return Q16::from_raw(static_cast<int32_t>(std::lround(x * 65536))); };
    for (const double far : {8000.0, 100.0}) {
        for (const double dist : {1.0, 50.0, 200.0, 300.0, 1000.0, 4000.0, 7990.0, 99.9}) {
            if (dist >= far) continue;
            CAPTURE(far);
            CAPTURE(dist);
            const double e = dist * 0.3;
            const Vec3q16 pos[3] = {{u(-e), u(-e), u(-dist)}, {u(e), u(-e), u(-dist)}, {u(0), u(e), u(-dist)}};
            const Tri tris[1] = {{{0, 1, 2}}};
            Mesh mesh;
            mesh.positions = {pos, 3};
            mesh.tris = {tris, 1};
            Camera cam;
            cam.eye = {u(0), u(0), u(0)};
            cam.target = {u(0), u(0), u(-1)};
            cam.up = {u(0), u(1), u(0)};
            cam.fovy = Angle::from_degrees(u(60));
            cam.near = Q16::from_raw(kMinNearRaw);
            cam.far = u(far);
            View view;
            REQUIRE(make_view(cam, 16, 16, view) == Status::ok);
            ScreenVertex verts[3];
            REQUIRE(project_vertices(view, mesh.positions, {verts, 3}) == Status::ok);
            CHECK((verts[0].z >> 16) < 0xFFFFu);
            std::vector<uint16_t> c16(256), d16(256), c32(256);
            std::vector<uint32_t> d32(256);
            const auto f16 = frame_view<Rgb565Format, uint16_t>(c16.data(), d16.data(), 16, 16);
            const auto f32 = frame_view<Rgb565Format, uint32_t>(c32.data(), d32.data(), 16, 16);
            clear(f16, Rgb{0, 0, 0});
            clear(f32, Rgb{0, 0, 0});
            const FrameStats s16 = draw_zbuffer<true>(view, mesh, {verts, 3}, f16, DrawOptions{});
            const FrameStats s32 = draw_zbuffer<true>(view, mesh, {verts, 3}, f32, DrawOptions{});
            CHECK(s16.pixels_written > 10);
            CHECK(s16.pixels_written == s32.pixels_written);
            CHECK(c16 == c32);
            std::vector<uint16_t> k16(256), kd16(256);
            const auto fk = frame_view<Rgb565Format, uint16_t>(k16.data(), kd16.data(), 16, 16);
            clear(fk, Rgb{0, 0, 0});
            (void)draw_zbuffer<false>(view, mesh, {verts, 3}, fk, DrawOptions{});  // the row kernel
            CHECK(k16 == c16);
        }
    }
}

TEST_CASE("draw_zbuffer rejects a frame it cannot use") {
    const tool::Scene s = scene_of({{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}}}, front_camera());
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}) == Status::ok);
    std::vector<uint16_t> color(static_cast<size_t>(s.width) * s.height), depth(color.size());
    DrawOptions opt;
    auto frame = frame_view<Rgb565Format>(color.data(), depth.data(), s.width, s.height);
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, frame, opt).status == Status::ok);
    auto no_depth = frame_view<Rgb565Format, uint16_t>(color.data(), nullptr, s.width, s.height);
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, no_depth, opt).status == Status::invalid_argument);
    auto small = frame_view<Rgb565Format>(color.data(), depth.data(), s.width - 1, s.height);
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, small, opt).status == Status::invalid_argument);
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), 1}, frame, opt).status == Status::invalid_argument);
    auto bad_band = band_view<Rgb565Format>(color.data(), depth.data(), s.width, s.height, 10, 5);
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, bad_band, opt).status == Status::invalid_argument);
    // A stride past kMaxStride (a red team's 2^31 - 1 and 2^30, on a one-row band: the stride never
    // addressed memory, but its byte count overflowed 32 bits in the row kernel's set-up). At
    // kMaxStride the one-row band draws the full frame's row.
    for (int32_t stride : {INT32_MAX, int32_t{1} << 30, kMaxStride + 1}) {
        auto wide = band_view<Rgb565Format>(color.data(), depth.data(), s.width, s.height, s.height / 2, s.height / 2 + 1);
        wide.stride = stride;
        CHECK_FALSE(wide.valid());
        CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, wide, opt).status == Status::invalid_argument);
    }
    auto row = band_view<Rgb565Format>(color.data(), depth.data(), s.width, s.height, s.height / 2, s.height / 2 + 1);
    row.stride = kMaxStride;
    REQUIRE(row.valid());
    clear(row, Rgb{0, 0, 0});
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, row, opt).status == Status::ok);
    const std::vector<uint16_t> middle(color.begin(), color.begin() + s.width);
    clear(frame, Rgb{0, 0, 0});
    CHECK(draw_zbuffer(view, s.mesh(), {verts.data(), verts.size()}, frame, opt).status == Status::ok);
    CHECK(std::equal(middle.begin(), middle.end(), color.begin() + static_cast<ptrdiff_t>(s.height / 2) * s.width));
    CHECK(std::count(middle.begin(), middle.end(), uint16_t{0}) < s.width);  // the triangle crosses that row
    std::vector<ScreenVertex> few(1);
    CHECK(project_vertices(view, s.mesh().positions, {few.data(), few.size()}) == Status::invalid_argument);
}

TEST_CASE("make_view and validate reject out-of-range cameras and meshes") {
    Camera cam;
    cam.eye = {Q16::from_int(0), Q16::from_int(0), Q16::from_int(5)};
    cam.target = {};
    cam.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
    cam.fovy = Angle::from_bam(0x20000000u);
    cam.near = Q16::from_int(1);
    cam.far = Q16::from_int(10);
    View v;
    CHECK(make_view(cam, 320, 240, v) == Status::ok);
    CHECK(make_view(cam, 0, 240, v) == Status::invalid_argument);
    CHECK(make_view(cam, 2048, 240, v) == Status::invalid_argument);
    Camera c2 = cam;
    c2.far = c2.near;
    CHECK(make_view(c2, 320, 240, v) == Status::invalid_argument);
    c2 = cam;
    c2.near = Q16::from_raw(kMinNearRaw - 1);
    CHECK(make_view(c2, 320, 240, v) == Status::invalid_argument);
    c2 = cam;
    c2.fovy = Angle::from_bam(0x80000000u);
    CHECK(make_view(c2, 320, 240, v) == Status::invalid_argument);
    c2 = cam;
    c2.eye.z = Q16::from_int(9000);
    CHECK(make_view(c2, 320, 240, v) == Status::out_of_range);
    const Vec3q16 pts[3] = {{Q16::from_int(0), Q16::from_int(0), Q16::from_int(0)},
                            {Q16::from_int(1), Q16::from_int(0), Q16::from_int(0)},
                            {Q16::from_int(8192), Q16::from_int(0), Q16::from_int(0)}};
    const Tri good{{0, 1, 0}}, bad{{0, 1, 3}};
    Mesh m{{pts, 2}, {&good, 1}, {}, {}};
    CHECK(validate(m) == Status::ok);
    m.tris = {&bad, 1};
    CHECK(validate(m) == Status::bad_data);
    m = Mesh{{pts, 3}, {&good, 1}, {}, {}};
    CHECK(validate(m) == Status::out_of_range);
}

TEST_CASE("validate(mesh, model) refuses a rigid model transform that carries a valid mesh out of the world") {
    // A floor quad across the world, turned half a turn about the y axis through the camera target (as
    // firmware/spin's turn() builds it): its near corner goes to (-24000, -100, -24000), 45,255 units from
    // the eye, and its view coordinates wrapped, so the z-buffer drew 1,508 of the 64 x 48 pixels where
    // the double reference draws none, with status ok.
    auto p = [](int32_t x, int32_t y, int32_t z) { return Vec3q16{Q16::from_int(x), Q16::from_int(y), Q16::from_int(z)}; };
    const Vec3q16 pos[4] = {p(8000, -100, 8000), p(-8000, -100, 8000), p(-8000, -100, -8000), p(8000, -100, -8000)};
    const Tri tris[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    const Mesh mesh{{pos, 4}, {tris, 2}, {}, {}};
    REQUIRE(validate(mesh) == Status::ok);
    const Vec3q16 target = p(-8000, 0, -8000);
    auto turn = [&](uint32_t bam) {
        Transform t, r;
        t.rot = rotation_y(Angle::from_bam(bam));
        r.rot = t.rot;
        t.trans = target - apply(r, target);
        return t;
    };
    CHECK(validate(mesh, Transform{}) == Status::ok);
    CHECK(validate(mesh, turn(0)) == Status::ok);
    CHECK(validate(mesh, turn(0x80000000u)) == Status::out_of_range);
    CHECK(validate(mesh, turn(0x20000000u)) == Status::out_of_range);  // an eighth of a turn leaves it too
    // A small quad about the turn's axis stays inside under every turn.
    const Vec3q16 small[4] = {p(-7900, -100, -8100), p(-8100, -100, -8100), p(-8100, -100, -7900), p(-7900, -100, -7900)};
    const Mesh inner{{small, 4}, {tris, 2}, {}, {}};
    for (uint32_t k = 0; k < 64; ++k) CHECK(validate(inner, turn(k << 26)) == Status::ok);
    // validate(m)'s own errors come first; a scaled matrix is refused (Transform is rigid).
    const Tri bad{{0, 1, 4}};
    CHECK(validate(Mesh{{pos, 4}, {&bad, 1}, {}, {}}, Transform{}) == Status::bad_data);
    Transform scaled;
    scaled.rot.m[0][0] = Q30::from_raw(Q30::kOne + 1);
    CHECK(validate(inner, scaled) == Status::invalid_argument);
    scaled.rot.m[0][0] = Q30::from_raw(-Q30::kOne - 1);
    CHECK(validate(inner, scaled) == Status::invalid_argument);
    scaled.rot.m[0][0] = Q30::from_raw(-Q30::kOne);
    CHECK(validate(inner, scaled) == Status::ok);
    // The world range's edge: a placed coordinate of kWorldLimitRaw - 1 is inside, kWorldLimitRaw is not.
    const Vec3q16 origin_only[3] = {p(0, 0, 0), p(0, 0, 0), p(0, 0, 0)};
    const Tri one{{0, 1, 2}};
    const Mesh dot{{origin_only, 3}, {&one, 1}, {}, {}};
    for (int axis = 0; axis < 3; ++axis)
        for (int32_t sign : {1, -1}) {
            Transform edge;
            const int32_t inside = sign * (kWorldLimitRaw - 1), outside = sign * kWorldLimitRaw;
            auto at = [&](int32_t raw) {
                Vec3q16 t{};
                (axis == 0 ? t.x : axis == 1 ? t.y : t.z) = Q16::from_raw(raw);
                return t;
            };
            edge.trans = at(inside);
            CHECK(validate(dot, edge) == Status::ok);
            edge.trans = at(outside);
            CHECK(validate(dot, edge) == Status::out_of_range);
        }
    // A translation past 2^15 units wraps in apply(); the exact check still sees it.
    Transform far;
    far.trans = Vec3q16{Q16::from_raw(INT32_MAX), Q16::from_int(0), Q16::from_int(0)};
    CHECK(validate(inner, far) == Status::out_of_range);
}

TEST_CASE("project_vertices' depth range spans exactly the drawable vertices") {
    tool::CameraArgs cam = front_camera(0);
    cam.target = tool::Vec3d{0, 0, -1};
    cam.near = 0.5;
    cam.far = 50;
    // Two triangles in view at different depths, one wholly behind the eye, one past the far plane.
    const tool::Scene s = scene_of({{{{-1, -1, -3}, {1, -1, -3}, {0, 1, -4}}},
                                    {{{-2, -2, -9}, {2, -2, -9}, {0, 2, -8}}},
                                    {{{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}}},
                                    {{{-1, -1, -80}, {1, -1, -80}, {0, 1, -80}}}},
                                   cam);
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    DepthRange range;
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}, &range) == Status::ok);
    uint32_t lo = UINT32_MAX, hi = 0;
    int outside = 0;
    for (const ScreenVertex& v : verts) {
        if (v.outside() != 0) { ++outside; continue; }
        lo = std::min(lo, v.z);
        hi = std::max(hi, v.z);
    }
    CHECK(outside == 6);
    CHECK(range.min == lo);
    CHECK(range.max == hi);
    CHECK(range.min < range.max);
    // Nothing drawable: the empty range (min > max), as before any vertex.
    const tool::Scene behind = scene_of({{{{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}}}}, cam);
    std::vector<ScreenVertex> bverts(behind.positions.size());
    DepthRange empty;
    REQUIRE(project_vertices(view, behind.mesh().positions, {bverts.data(), bverts.size()}, &empty) == Status::ok);
    CHECK(empty.min == kDepthFar);
    CHECK(empty.max == kDepthNear);
}

#if defined(HIDER_ENABLE_ASSERTS)
TEST_CASE("With asserts, draw_zbuffer() checks hand-made vertices at entry, before drawing anything") {
    test::HandMadeTriangle h;
    constexpr int n = test::HandMadeTriangle::kSize;
    uint16_t color[n * n], depth[n * n];
    const auto frame = frame_view<Rgb565Format, uint16_t>(color, depth, n, n);
    DrawOptions opt;
    opt.cull = false;
    FrameStats st;
    auto draw = [&] { st = draw_zbuffer(h.view, h.mesh, {h.verts, 3}, frame, opt); };
    clear(frame, Rgb{0, 0, 0});
    CHECK_FALSE(test::assert_trap::fails(draw));  // in range
    CHECK(st.ok());
    CHECK(st.triangles_drawn == 1);
    CHECK(std::count(color, color + n * n, uint16_t{0}) < n * n / 2);  // half the frame and its diagonal
    h.past_the_limit();
    clear(frame, Rgb{0, 0, 0});
    CHECK(test::assert_trap::fails(draw));
    CHECK(test::assert_trap::file().find("raster/zbuffer.hpp") != std::string::npos);
    CHECK(std::count(color, color + n * n, uint16_t{0}) == n * n);  // nothing drawn before it
    CHECK(std::count(depth, depth + n * n, uint16_t{0xFFFF}) == n * n);
}
#endif

// Ray tracing (lib/hider/ray/trace.hpp, scene.hpp, cull.hpp) on small scenes with known answers: shadow
// rays (blocked, not blocked, blockers beyond the light, lights behind the surface), reflection depth
// and attenuation, the maximum distance, the tie rule, validate_scene's statuses; culled frames equal
// unculled ones on random scenes; the baked demo equals the scene file; no heap use in a frame.
#include <hider/ray/trace.hpp>

#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/ray_scene.hpp"
#include "common/render_ray.hpp"
#include "firmware/common/scenes/raytrace_demo.hpp"
#include "support/fixed_print.hpp"

namespace doctest {
template <>
struct StringMaker<hider::Rgb> {
    static String convert(hider::Rgb c) {
        return ("(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")").c_str();
    }
};
}  // namespace doctest

using namespace hider;
using namespace hider::ray;

namespace {

Vec3q16 p16(double x, double y, double z) {
    return {Q16::from_raw(int32_t(std::lround(x * 65536))), Q16::from_raw(int32_t(std::lround(y * 65536))),
            Q16::from_raw(int32_t(std::lround(z * 65536)))};
}
Vec3q30 u30(double x, double y, double z) {
    Vec3q30 u{};
    REQUIRE(unit_q30(int32_t(std::lround(x * 1e8)), int32_t(std::lround(y * 1e8)), int32_t(std::lround(z * 1e8)), u));
    return u;
}

/// A small scene owning its arrays.
struct Fixture {
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Light> lights;
    std::vector<Surface> surfaces;
    Scene scene() const {
        Scene s;
        s.spheres = {spheres.data(), spheres.size()};
        s.planes = {planes.data(), planes.size()};
        s.lights = {lights.data(), lights.size()};
        s.surfaces = {surfaces.data(), surfaces.size()};
        return s;
    }
};

BvhStackEntry g_stack[64];
Span<BvhStackEntry> stack() { return {g_stack, 64}; }

Rgb trace_down(const Scene& s, double x, double z, double from_y = 10) {
    TraceStats st;
    return trace(s, {p16(x, from_y, z), u30(0, -1, 0)}, stack(), st);
}

/// A white floor at y = 0 (surface 0) and a ball of radius 1 at height 3 (surface 1) with a point light
/// straight above it at height 8: the floor under the ball is in its shadow.
Fixture shadow_fixture() {
    Fixture f;
    f.surfaces = {{{200, 200, 200}, {}, {}, 0}, {{255, 0, 0}, {}, {}, 0}};
    f.planes = {{u30(0, 1, 0), Q16::from_int(0), 0}};
    f.spheres = {{p16(0, 3, 0), Q16::from_int(1), 1}};
    f.lights = {{LightKind::point, p16(0, 8, 0), {}, {255, 255, 255}}};
    return f;
}

}  // namespace

TEST_CASE("shadow rays: the floor under a ball is dark, beside it lit, and only blockers before the light count") {
    Fixture f = shadow_fixture();
    Scene s = f.scene();
    s.ambient = {51, 51, 51};  // 0.2
    REQUIRE(validate_scene(s, stack()) == Status::ok);
    // Under the ball (looking straight down from just below it): ambient only, 200 * 0.2 = 40.
    const Rgb shadowed = trace_down(s, 0, 0, 1.5);
    CHECK(shadowed == Rgb{40, 40, 40});
    // Beside the ball, straight under the light's reach: ambient + n.l * light; at (3, 0, 0) n.l = 8/sqrt(73).
    const Rgb lit = trace_down(s, 3, 0, 1.5);
    const double expected = 200 * (0.2 + 8 / std::sqrt(73.0));
    CHECK(std::abs(lit.r - expected) <= 1);
    SUBCASE("a blocker beyond the light casts nothing") {
        f.lights[0].position = p16(0, 1.5, 0);  // now the light sits between the floor and the ball
        s = f.scene();
        s.ambient = {51, 51, 51};
        CHECK(trace_down(s, 0.5, 0, 1.2).r > 200);  // lit: n.l close to 1
    }
    SUBCASE("a light below the floor adds nothing; a directional light is blocked the same way") {
        f.lights = {{LightKind::point, p16(0, -5, 0), {}, {255, 255, 255}},
                    {LightKind::directional, {}, u30(0, 1, 0), {255, 255, 255}}};
        s = f.scene();
        s.ambient = {51, 51, 51};
        CHECK(trace_down(s, 0, 0, 1.5) == Rgb{40, 40, 40});
        CHECK(trace_down(s, 3, 0, 1.5) == Rgb{240, 240, 240});  // 200 (0.2 + 1): light may exceed 1
    }
    TraceStats st;
    (void)trace(s, {p16(3, 1.5, 0), u30(0, -1, 0)}, stack(), st);
    CHECK(st.rays == 1);
    CHECK(st.shadow_rays == 1);
}

TEST_CASE("reflection: a mirror shows what its reflected ray meets, weighted, up to the bounce depth") {
    Fixture f;
    // Surface 0: a floor that mirrors half; surface 1: a green wall facing it at x = -5.
    f.surfaces = {{{100, 100, 100}, {}, {}, kReflectOne / 2}, {{0, 200, 0}, {}, {}, 0}};
    f.planes = {{u30(0, 1, 0), Q16::from_int(0), 0}, {u30(1, 0, 0), Q16::from_int(-5), 1}};
    Scene s = f.scene();
    s.ambient = {255, 255, 255};  // full ambient: every surface shows its own colour
    s.background = {0, 0, 255};
    // Looking down at 45 degrees toward -x: the floor mirrors the ray into the wall.
    const Ray ray{p16(0, 2, 0), u30(-1, -1, 0)};
    TraceStats st;
    s.max_bounces = 0;
    CHECK(trace(s, ray, stack(), st) == Rgb{100, 100, 100});
    s.max_bounces = 1;
    CHECK(trace(s, ray, stack(), st) == Rgb{50, 150, 50});  // half floor, half wall
    SUBCASE("a reflected ray that meets nothing shows the background") {
        const Ray away{p16(0, 2, 0), u30(1, -1, 0)};
        CHECK(trace(s, away, stack(), st) == Rgb{50, 50, 177});  // (99.996 + 255) / 2 = 177.498, rounded
    }
    SUBCASE("a full mirror between two: depth counts the bounces") {
        f.surfaces[0].reflect_q15 = kReflectOne;
        f.planes.push_back({u30(0, -1, 0), Q16::from_int(-4), 0});  // mirror ceiling at y = 4
        s = f.scene();
        s.ambient = {255, 255, 255};
        s.background = {0, 0, 255};
        const Ray zig{p16(0, 2, 0), u30(-0.1, -1, 0)};  // needs ~26 bounces to reach the wall at x = -5
        s.max_bounces = 3;
        CHECK(trace(s, zig, stack(), st) == Rgb{100, 100, 100});  // the 4th surface shows its own colour
        s.max_bounces = 60;
        CHECK(trace(s, zig, stack(), st) == Rgb{0, 200, 0});
    }
}

TEST_CASE("a mirror triangle reflects as the same mirror plane: rays off a mesh's normal stay unit") {
    // A mesh's normal is a Normal14, unit only to its rounding (2^-13): reflected about it as it was, a ray
    // came out up to 2e-4 too long or short, and the sphere test, which takes rays as unit, put its hit off
    // the surface of a sphere seen from inside, which then shadowed itself (a red team's scene: 3,069 of
    // 3,072 pixels black, status ok; lit through the same mirror as a plane).
    auto render = [](const std::string& mirror, int radius) {
        const std::string text = "size 64 48\ncamera eye 0 0 0 target 0 0 -1 fov 40\nbounces 1\nsphere 0 0 0 " +
                                 std::to_string(radius) + " color 1 1 1\nlight point 0 15 0\n" + mirror +
                                 " color 0 0 0 reflect 1\n";
        std::istringstream in(text);
        tool::RayScene s;
        std::string why;
        REQUIRE_MESSAGE(tool::parse_ray_scene(in, "mirror.txt", ".", s, why), why);
        tool::RenderResult r;
        REQUIRE_MESSAGE(tool::render_ray_scene(s, 64, 48, tool::RenderOptions{}, r, why), why);
        return r.rgb;
    };
    const std::string triangle = "triangle 0 58.83 -16.77  -49.85 -26.54 15.26  49.85 -32.29 -13.50";
    const std::string plane = "plane 0.282216 0.188154 0.940719 -4.706730";  // the triangle's plane, to 1e-6
    for (int radius : {20, 100, 500, 4000}) {
        const std::vector<uint8_t> a = render(triangle, radius), b = render(plane, radius);
        REQUIRE(a.size() == b.size());
        int lit = 0, off = 0;
        for (size_t i = 0; i < a.size(); i += 3) {
            lit += b[i] + b[i + 1] + b[i + 2] > 60;
            for (size_t c = 0; c < 3; ++c) off += std::abs(int{a[i + c]} - int{b[i + c]}) > 3 ? 1 : 0;
        }
        INFO("radius " << radius << ": lit through the plane " << lit << " of 3,072, channels off by more than 3: " << off);
        CHECK(lit > 1500);     // the sphere's inside shows in the mirror
        CHECK(off <= 10);  // both mirrors show it alike (rounded apart: 1 channel at radius 20)
    }
}

TEST_CASE("the maximum distance ends rays, and equal distances go to the first object") {
    Fixture f;
    f.surfaces = {{{255, 0, 0}, {}, {}, 0}, {{0, 255, 0}, {}, {}, 0}};
    f.spheres = {{p16(0, 0, -10), Q16::from_int(1), 0}, {p16(0, 0, -10), Q16::from_int(1), 1}};
    Scene s = f.scene();
    s.ambient = {255, 255, 255};
    s.background = {1, 2, 3};
    TraceStats st;
    const Ray ray{p16(0, 0, 0), u30(0, 0, -1)};
    CHECK(trace(s, ray, stack(), st) == Rgb{255, 0, 0});  // identical spheres: the first wins
    s.max_distance = Q16::from_int(9);
    CHECK(trace(s, ray, stack(), st) == Rgb{1, 2, 3});
    SUBCASE("a sphere touching a plane at the ray's hit: the sphere (tested first) wins") {
        f.planes = {{u30(0, 0, 1), Q16::from_int(-9), 1}};  // z = -9, the sphere's front point
        s = f.scene();
        s.ambient = {255, 255, 255};
        CHECK(trace(s, ray, stack(), st) == Rgb{255, 0, 0});
    }
}

TEST_CASE("validate_scene names what is wrong") {
    Fixture f = shadow_fixture();
    CHECK(validate_scene(f.scene(), stack()) == Status::ok);
    auto status = [&](auto&& change) {
        Fixture g = f;
        Scene s = g.scene();
        change(g, s);
        return validate_scene(s, stack());
    };
    CHECK(status([](Fixture& g, Scene& s) { g.surfaces[0].reflect_q15 = kReflectOne + 1; s = g.scene(); }) == Status::invalid_argument);
    CHECK(status([](Fixture& g, Scene& s) { g.surfaces[0].checker_size = Q16::from_raw(-1); s = g.scene(); }) == Status::invalid_argument);
    CHECK(status([](Fixture& g, Scene& s) { g.spheres[0].radius = Q16::from_raw(0); s = g.scene(); }) == Status::invalid_argument);
    CHECK(status([](Fixture& g, Scene& s) { g.spheres[0].centre.x = Q16::from_ratio(16383, 2); s = g.scene(); }) == Status::out_of_range);
    CHECK(status([](Fixture& g, Scene& s) { g.spheres[0].surface = 2; s = g.scene(); }) == Status::bad_data);
    CHECK(status([](Fixture& g, Scene& s) { g.planes[0].normal.y = Q30::from_raw(Q30::kOne / 2); s = g.scene(); }) == Status::invalid_argument);
    CHECK(status([](Fixture& g, Scene& s) { g.planes[0].offset = Q16::from_int(16384); s = g.scene(); }) == Status::out_of_range);
    CHECK(status([](Fixture& g, Scene& s) { g.lights[0].position.y = Q16::from_int(8192); s = g.scene(); }) == Status::out_of_range);
    CHECK(status([](Fixture& g, Scene& s) {
              g.lights[0] = {LightKind::directional, {}, {}, {255, 255, 255}};
              s = g.scene();
          }) == Status::invalid_argument);
    CHECK(status([](Fixture&, Scene& s) { s.max_distance = Q16::from_raw(0); }) == Status::invalid_argument);
    CHECK(status([](Fixture& g, Scene& s) {
              s.sphere_bound = enclosing_sphere({g.spheres.data(), g.spheres.size()});
              s.sphere_bound.radius = Q16::from_raw(s.sphere_bound.radius.raw() - 1);
          }) == Status::invalid_argument);
    CHECK(status([](Fixture& g, Scene& s) { s.sphere_bound = enclosing_sphere({g.spheres.data(), g.spheres.size()}); }) == Status::ok);
}

TEST_CASE("sphere rectangles change no pixel: culled and unculled frames are equal on random scenes") {
    std::mt19937 rng(47);
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    long culled_tests = 0;
    for (int scene_no = 0; scene_no < 40; ++scene_no) {
        Fixture f;
        for (int i = 0; i < 6; ++i) f.surfaces.push_back({{uint8_t(rng()), uint8_t(rng()), uint8_t(rng())}, {}, {}, uint16_t(rng() % kReflectOne)});
        const int n = 1 + int(rng() % 6);
        for (int i = 0; i < n; ++i)
            f.spheres.push_back({p16(uni(-6, 6), uni(-3, 3), uni(-6, 6)), Q16::from_raw(int32_t(uni(0.05, 2.5) * 65536)), uint16_t(rng() % 6)});
        f.planes.push_back({u30(uni(-0.3, 0.3), 1, uni(-0.3, 0.3)), Q16::from_int(-3), 0});
        f.lights.push_back({LightKind::point, p16(uni(-5, 5), 6, uni(-5, 5)), {}, {255, 240, 220}});
        Scene s = f.scene();
        s.max_bounces = 2;
        s.ambient = {30, 30, 30};
        s.sphere_bound = enclosing_sphere(s.spheres);
        REQUIRE(validate_scene(s, stack()) == Status::ok);
        // Cameras outside, at the edge of and inside the spheres, narrow and wide.
        const Vec3q16 eye = scene_no % 5 == 0 ? f.spheres[0].centre : p16(uni(-9, 9), uni(-2, 5), uni(-9, 9));
        const Camera cam{eye, p16(0, 0, 0), p16(0, 1, 0), Angle::from_bam(uint32_t(uni(5, 150) / 360 * 4294967296.0)),
                         Q16::from_raw(256), Q16::from_int(100)};
        PrimaryRays rays;
        const int w = 48 + int(rng() % 40), h = 32 + int(rng() % 30);
        if (make_primary_rays(cam, w, h, rays) != Status::ok) continue;
        std::vector<SphereRect> rects(s.spheres.size());
        REQUIRE(sphere_rects(s, rays, {rects.data(), rects.size()}) == Status::ok);
        CHECK(sphere_rects(s, rays, {rects.data(), rects.size() - 1}) == Status::invalid_argument);
        std::vector<uint16_t> a(w), b(w);
        for (int y = 0; y < h; ++y) {
            (void)trace_row<Rgb565Format>(s, rays, y, a.data(), stack(), {rects.data(), rects.size()});
            (void)trace_row<Rgb565Format>(s, rays, y, b.data(), stack());
            REQUIRE(a == b);
            for (int x = 0; x < w; ++x)
                for (const SphereRect& r : rects) culled_tests += !r.contains(x, y);
        }
    }
    MESSAGE("primary sphere tests skipped by the rectangles: " << culled_tests);
    CHECK(culled_tests > 10000);
}

TEST_CASE("the baked demo scene is the scene file, and renders the same") {
    tool::RayScene text;
    std::string why;
    REQUIRE_MESSAGE(tool::load_ray_scene(std::string(HIDER_TEST_DATA) + "/scenes/spheres.txt", text, why), why);
    namespace demo = scenes::raytrace_demo;
    const Scene baked = demo::scene();
    const Scene parsed = text.view();
    CHECK(demo::kWidth == text.width);
    CHECK(demo::kHeight == text.height);
    CHECK(demo::kCamera.eye == text.camera.eye);
    CHECK(demo::kCamera.fovy == text.camera.fovy);
    REQUIRE(baked.spheres.size() == parsed.spheres.size());
    REQUIRE(baked.planes.size() == parsed.planes.size());
    REQUIRE(baked.lights.size() == parsed.lights.size());
    REQUIRE(baked.surfaces.size() == parsed.surfaces.size());
    CHECK(baked.spheres.size() >= 3);
    for (size_t i = 0; i < baked.spheres.size(); ++i) {
        CHECK(baked.spheres[i].centre == parsed.spheres[i].centre);
        CHECK(baked.spheres[i].radius == parsed.spheres[i].radius);
        CHECK(baked.surfaces[baked.spheres[i].surface].reflect_q15 > 0);  // the demo's spheres all mirror
    }
    bool checker = false;
    for (const Surface& f : baked.surfaces) checker = checker || f.checker_size.raw() > 0;
    CHECK(checker);
    CHECK(baked.sphere_bound.radius == parsed.sphere_bound.radius);
    tool::RenderOptions opt;
    opt.format = tool::PixelFormat::rgb565;
    tool::RenderResult r;
    REQUIRE(tool::render_ray_scene(text, demo::kWidth, demo::kHeight, opt, r, why));
    PrimaryRays rays;
    REQUIRE(make_primary_rays(demo::kCamera, demo::kWidth, demo::kHeight, rays) == Status::ok);
    std::vector<uint16_t> row(demo::kWidth);
    std::vector<uint8_t> rgb;
    for (int y = 0; y < demo::kHeight; ++y) {
        (void)trace_row<Rgb565Format>(baked, rays, y, row.data(), stack());
        for (uint16_t p : row) {
            const Rgb c = Rgb565Format::unpack(p);
            rgb.insert(rgb.end(), {c.r, c.g, c.b});
        }
    }
    CHECK(rgb == r.rgb);
    CHECK(r.ray.shadow_rays > 10000);  // the demo has shadows and reflections
    CHECK(r.ray.rays > static_cast<uint64_t>(demo::kWidth * demo::kHeight) * 3 / 2);
}

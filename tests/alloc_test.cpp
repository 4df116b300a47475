// lib/ never allocates: the global operator new is replaced by a counting one, and a whole frame
// (view, vertex projection, clear, z-buffer draw, band by band) must not call it.
#include <hider/horizon/plot.hpp>
#include <hider/raster/zbuffer.hpp>
#include <hider/ray/cast.hpp>

#include <cstdlib>
#include <new>
#include <vector>

#include <doctest/doctest.h>

#include "common/bvh_build.hpp"
#include "common/ray_scene.hpp"
#include "support/scene_util.hpp"

namespace {
long g_allocations = 0;
}

// Every ordinary form is replaced, so each allocation and its release use the same pair (malloc/free).
void* operator new(std::size_t n) {
    ++g_allocations;
    if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
    std::abort();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    ++g_allocations;
    return std::malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace hider;

TEST_CASE("a whole frame makes no heap allocation") {
    const tool::Scene s = test::load_model("teapot.obj");
    std::vector<ScreenVertex> verts(s.positions.size());
    std::vector<uint16_t> color(static_cast<size_t>(s.width) * 16), depth(color.size());
    const Mesh mesh = s.mesh();
    const long before = g_allocations;
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    DrawOptions opt;
    REQUIRE(project_vertices(view, mesh.positions, {verts.data(), verts.size()}, &opt.depth_range) == Status::ok);
    uint32_t fragments = 0;
    for (int y0 = 0; y0 < s.height; y0 += 16) {
        const auto band = band_view<Rgb565Format>(color.data(), depth.data(), s.width, s.height, y0, std::min(s.height, y0 + 16));
        clear(band, {0, 0, 0});
        const FrameStats st = draw_zbuffer<true>(view, mesh, {verts.data(), verts.size()}, band, opt);
        CHECK(st.ok());
        fragments += st.fragments;
    }
    CHECK(g_allocations == before);
    CHECK(fragments > 5000);
    SUBCASE("the counter itself works") {
        std::vector<int>* v = new std::vector<int>(3);
        CHECK(g_allocations > before);
        delete v;
    }
}

TEST_CASE("a floating-horizon plot makes no heap allocation") {
    using namespace hider::horizon;
    Surface s;
    s.samples = 64;
    s.curves = 32;
    s.dx = Q16::from_ratio(2, 63);
    s.x0 = Q16::from_int(-1);
    s.dz = Q16::from_ratio(2, 31);
    s.z0 = Q16::from_int(-1);
    s.value_max = 255;
    s.y_unit_raw = 128;
    Camera cam;
    cam.eye = {Q16::from_raw(0), Q16::from_int(1), Q16::from_int(2)};
    cam.up = {Q16::from_raw(0), Q16::from_int(1), Q16::from_raw(0)};
    cam.fovy = Angle::from_degrees(Q16::from_int(50));
    cam.near = Q16::from_ratio(1, 10);
    cam.far = Q16::from_int(20);
    std::vector<uint8_t> heights(64 * 32), pages(128 * 8);
    for (size_t i = 0; i < heights.size(); ++i) heights[i] = static_cast<uint8_t>(i * 37 % 251);
    std::vector<PlotPoint> points(64);
    std::vector<int16_t> upper(128), lower(128);
    const Rgb white[] = {{255, 255, 255}};
    const long before = g_allocations;
    SurfaceProjection p;
    REQUIRE(p.prepare(cam, 128, 64, s) == Status::ok);
    Horizon hz;
    REQUIRE(make_horizon({upper.data(), upper.size()}, {lower.data(), lower.size()}, 128, 64, hz) == Status::ok);
    PlotBuffers b;
    b.current = {points.data(), points.size()};
    PlotStyle st;
    st.colours = white;
    const MonoFrame f{pages.data(), 128, 64, 0, 8};
    horizon::clear(f);
    const PlotStats r = plot(p, GridSource<uint8_t>{heights.data(), 64, 32, 0}, hz, b, MonoTarget(f), st);
    CHECK(g_allocations == before);
    CHECK(r.ok());
    CHECK(r.pixels > 100);
}

TEST_CASE("ray tracing and ray casting a frame make no heap allocation") {
    tool::RayScene scene;
    std::string why;
    REQUIRE_MESSAGE(tool::load_ray_scene(std::string(HIDER_TEST_DATA) + "/scenes/spheres.txt", scene, why), why);
    const tool::Scene torus = test::load_model("torus.obj");
    tool::BakedBvh bvh;
    REQUIRE(tool::build_bvh(torus.mesh(), bvh, why));
    std::vector<ray::BvhStackEntry> stack(64);
    std::vector<ray::SphereRect> rects(scene.spheres.size());
    std::vector<uint16_t> row(320);
    const ray::Scene s = scene.view();
    const long before = g_allocations;
    ray::PrimaryRays rays;
    REQUIRE(ray::make_primary_rays(scene.camera, 160, 128, rays) == Status::ok);
    REQUIRE(ray::validate_scene(s, {stack.data(), stack.size()}) == Status::ok);
    REQUIRE(ray::sphere_rects(s, rays, {rects.data(), rects.size()}) == Status::ok);
    uint32_t hits = 0;
    for (int y = 0; y < 128; ++y)
        hits += ray::trace_row<Rgb565Format>(s, rays, y, row.data(), {stack.data(), stack.size()}, {rects.data(), rects.size()}).hits;
    ray::PrimaryRays cast_rays;
    REQUIRE(ray::make_primary_rays(torus.camera, 320, 240, cast_rays) == Status::ok);
    REQUIRE(ray::validate_bvh(bvh.view(), torus.mesh(), {stack.data(), stack.size()}) == Status::ok);
    for (int y = 0; y < 240; ++y)
        hits += ray::cast_row<Rgb565Format>(cast_rays, torus.mesh(), bvh.view(), DrawOptions{}, {0, 0, 0}, y, row.data(), {stack.data(), stack.size()}).hits;
    CHECK(g_allocations == before);
    CHECK(hits > 20000);
}

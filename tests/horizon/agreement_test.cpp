// The floating-horizon plot against the independent double-precision reference
// (tests/support/horizon_reference.cpp: the surface as triangles, every line sampled densely and each
// sample ray-cast from the eye): hider's curve pixels and the reference's visible curve pixels agree,
// within one pixel, on >= 97% of them in both directions, for the built-in functions seen from above the
// front, from below, from behind, from above the middle and from the side, plain and with the mesh.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "hider-plot/plot.hpp"
#include "support/horizon_reference.hpp"

using namespace hider;

namespace {

struct NamedView {
    const char* name;
    plot::ViewArgs args;
};

plot::ViewArgs view_args(std::optional<plot::Vec3d> eye, std::optional<plot::Vec3d> up = std::nullopt) {
    plot::ViewArgs v;
    v.eye = eye;
    v.up = up;
    v.width = 320;
    v.height = 240;
    return v;
}

/// Decodes the RGB888 id image of an id plot.
std::vector<uint32_t> ids_of(const plot::Result& r) {
    std::vector<uint32_t> ids(static_cast<size_t>(r.width) * r.height);
    for (size_t p = 0; p < ids.size(); ++p)
        ids[p] = uint32_t{r.rgb[3 * p]} << 16 | uint32_t{r.rgb[3 * p + 1]} << 8 | r.rgb[3 * p + 2];
    return ids;
}

struct Measured {
    ref::LineAgreement curves, x_lines;
};

/// Plots `function` with ids and compares curves and constant-x lines with the reference.
Measured measure(const std::string& function, const plot::ViewArgs& args, bool mesh, int curves = 40, int samples = 120) {
    plot::HeightGrid g;
    REQUIRE(plot::sample_function(function, 0.5, curves, samples, g));
    plot::CameraD cam;
    std::string why;
    REQUIRE_MESSAGE(plot::resolve_camera(g, args, cam, why), why);
    plot::Options opt;
    opt.shade = plot::Shade::id;
    opt.mesh = mesh;
    plot::Result r;
    REQUIRE_MESSAGE(plot::render(g, cam, opt, r, why), why);
    // The reference sees exactly the surface lib/ got: the Q16 grid, back in doubles.
    const plot::FixedGrid fixed = plot::to_fixed(g);
    ref::HorizonSurface s;
    s.rows = curves;
    s.cols = samples;
    for (int i = 0; i < samples; ++i) s.x.push_back(fixed.x(i));
    for (int k = 0; k < curves; ++k) s.z.push_back(fixed.z(k));
    for (int k = 0; k < curves; ++k)
        for (int i = 0; i < samples; ++i) s.y.push_back(fixed.y(k, i));
    ref::HorizonCamera rc{};
    for (int a = 0; a < 3; ++a) {
        rc.eye[a] = cam.eye[a];
        rc.target[a] = cam.target[a];
        rc.up[a] = cam.up[a];
    }
    rc.fovy_deg = cam.fov_deg;
    rc.near = cam.near;
    rc.width = cam.width;
    rc.height = cam.height;
    const int step = plot::mesh_step(opt, curves, samples);
    const std::vector<ref::HorizonLine> lines = ref::horizon_lines(s, mesh, step);
    const auto visible = ref::visible_pixels(s, rc, lines);
    const std::vector<uint32_t> ids = ids_of(r);
    Measured m;
    m.curves = ref::compare_lines(ids, r.width, r.height, lines, visible, 1, static_cast<uint32_t>(curves));
    m.x_lines = ref::compare_lines(ids, r.width, r.height, lines, visible, static_cast<uint32_t>(curves) + 1, 0xFFFFFF);
    return m;
}

std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f%%", 100.0 * v);
    return buf;
}

void report(const std::string& what, const ref::LineAgreement& a) {
    MESSAGE(what << ": hider " << a.image_matched << "/" << a.image_pixels << " = " << percent(a.image_rate())
                 << ", reference " << a.ref_matched << "/" << a.ref_pixels << " = " << percent(a.ref_rate()));
}

}  // namespace

TEST_CASE("Curve pixels agree with the ray-cast reference on >= 97% for three functions, from above and from below") {
    const NamedView views[] = {
        {"above the front edge (default)", view_args(std::nullopt)},
        {"below the front edge", view_args(plot::Vec3d{0.3, -1.8, 2.6})},
    };
    for (const char* function : {"sinc", "hills", "waves"})
        for (const NamedView& v : views)
            for (bool mesh : {false, true}) {
                const std::string what = std::string(function) + ", " + v.name + (mesh ? ", mesh" : "");
                const Measured m = measure(function, v.args, mesh);
                report(what + ", curves", m.curves);
                CHECK_MESSAGE(m.curves.image_rate() >= 0.97, what);
                CHECK_MESSAGE(m.curves.ref_rate() >= 0.97, what);
                CHECK_MESSAGE(m.curves.image_pixels > 2000, what);
                if (mesh) {
                    report(what + ", constant-x lines", m.x_lines);
                    CHECK_MESSAGE(m.x_lines.image_rate() >= 0.97, what);
                    CHECK_MESSAGE(m.x_lines.ref_rate() >= 0.97, what);
                }
            }
}

TEST_CASE("Curve pixels agree with the reference from behind, from above the middle and from the side") {
    const NamedView views[] = {
        {"behind", view_args(plot::Vec3d{0.5, 1.5, -2.8})},
        {"above the middle", view_args(plot::Vec3d{0.2, 3.0, 0.3}, plot::Vec3d{0, 0, -1})},
        {"side", view_args(plot::Vec3d{3.0, 1.5, 0.3})},
        {"low grazing", view_args(plot::Vec3d{-0.4, 0.45, 3.2})},
    };
    for (const char* function : {"sinc", "saddle", "hills", "waves"})
        for (const NamedView& v : views)
            for (bool mesh : {false, true}) {
                const std::string what = std::string(function) + ", " + v.name + (mesh ? ", mesh" : "");
                const Measured m = measure(function, v.args, mesh);
                report(what + ", curves", m.curves);
                if (mesh) report(what + ", constant-x lines", m.x_lines);
                CHECK_MESSAGE(m.curves.image_rate() >= 0.97, what);
                CHECK_MESSAGE(m.curves.ref_rate() >= 0.97, what);
            }
}


TEST_CASE("Curve pixels agree with the reference from random views (8 seeds, all functions)") {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), elevation(-0.9, 1.2), dist(2.2, 4.0);
    const char* const functions[] = {"sinc", "saddle", "hills", "waves"};
    for (int seed = 0; seed < 8; ++seed) {
        const double a = angle(rng), e = elevation(rng), r = dist(rng);
        const plot::Vec3d eye{r * std::cos(e) * std::sin(a), r * std::sin(e), r * std::cos(e) * std::cos(a)};
        const std::string function = functions[seed % 4];
        const std::string what = function + " from (" + std::to_string(eye[0]) + ", " + std::to_string(eye[1]) + ", " +
                                 std::to_string(eye[2]) + ")";
        const Measured m = measure(function, view_args(eye), seed % 2 == 1, 30 + seed * 3, 80 + seed * 10);
        report(what + ", curves", m.curves);
        CHECK_MESSAGE(m.curves.image_rate() >= 0.97, what);
        CHECK_MESSAGE(m.curves.ref_rate() >= 0.97, what);
    }
}

// Primary rays (lib/hider/ray/camera.hpp): stepped along a row they equal the closed form exactly; each
// runs through its pixel's centre as the rasterizer projects it (project() lands within a subpixel of
// the centre); and they match gluLookAt + gluPerspective in double (tests/support/reference.hpp).
#include <hider/ray/camera.hpp>
#include <hider/raster/zbuffer.hpp>

#include <cmath>
#include <random>

#include <doctest/doctest.h>

#include "support/fixed_print.hpp"
#include "support/reference.hpp"

using namespace hider;
using namespace hider::ray;

namespace {

Camera camera(double ex, double ey, double ez, double tx, double ty, double tz, double fov_deg) {
    auto q = [](double v) { return Q16::from_raw(int32_t(std::lround(v * 65536))); };
    return {{q(ex), q(ey), q(ez)}, {q(tx), q(ty), q(tz)}, {q(0), q(1), q(0)},
            Angle::from_bam(uint32_t(std::llround(fov_deg / 360.0 * 4294967296.0))), q(0.25), q(200)};
}

struct Case {
    Camera cam;
    int w, h;
};

std::vector<Case> cases() {
    return {{camera(0, 0, 10, 0, 0, 0, 60), 320, 240},    {camera(3, 4, 5, 0, 1, 0, 73.7), 160, 128},
            {camera(-7, 2, -1, 2, 0, 3, 0.5), 64, 64},    {camera(1, 1, 1, 0, 0, 0, 179.5), 1024, 1},
            {camera(0, 9, 0.5, 0, 0, 0, 90), 1, 1024},    {camera(100, -50, 30, -20, 10, 0, 30), 1024, 768}};
}

}  // namespace

TEST_CASE("primary rays stepped along a row equal the closed form exactly") {
    for (const Case& c : cases()) {
        PrimaryRays p;
        REQUIRE(make_primary_rays(c.cam, c.w, c.h, p) == Status::ok);
        const Q30(&rot)[3][3] = p.view.to_view.rot.m;
        for (int y : {0, c.h / 2, c.h - 1}) {
            RowRays rr(p, y);
            for (int x = 0; x < c.w; ++x, rr.next()) {
                int32_t got[3];
                rr.raw_direction(got);
                for (int i = 0; i < 3; ++i) {
                    // D = k f + 2048 (2x + 1 - W) s + 2048 (H - 2y - 1) u, f = -row 2.
                    const int64_t d = int64_t{p.view.k_q8} * -int64_t{rot[2][i].raw()} + 2048 * int64_t{2 * x + 1 - c.w} * rot[0][i].raw() +
                                      2048 * int64_t{c.h - 2 * y - 1} * rot[1][i].raw();
                    REQUIRE(got[i] == static_cast<int32_t>(d >> p.shift));
                    REQUIRE(std::abs(got[i]) < (1 << 30));
                }
            }
        }
    }
}

TEST_CASE("a primary ray runs through its pixel centre as the rasterizer projects it") {
    std::mt19937 rng(41);
    for (const Case& c : cases()) {
        PrimaryRays p;
        REQUIRE(make_primary_rays(c.cam, c.w, c.h, p) == Status::ok);
        long checked = 0;
        for (int i = 0; i < 300; ++i) {
            const int x = int(rng() % uint32_t(c.w)), y = int(rng() % uint32_t(c.h));
            RowRays rr(p, y);
            for (int k = 0; k < x; ++k) rr.next();
            const Vec3q30 d = rr.direction();
            // A point 20 units along the ray, projected by the z-buffer's own code.
            const Vec3q16 q = point_along(p.eye, Q16::from_int(20).raw(), d);
            const ViewPoint v = to_view_point(p.view, q);
            if (outcode(p.view, v) != 0) continue;  // outside the guard band (very wide views)
            const ScreenVertex s = project(p.view, v);
            const double want_x = (x + 0.5 - c.w / 2.0) * 16, want_y = (y + 0.5 - c.h / 2.0) * 16;
            INFO("camera ", c.w, "x", c.h, " pixel ", x, ",", y, " projected ", s.x, ",", s.y);
            CHECK(std::fabs(s.x - want_x) <= 1);
            CHECK(std::fabs(s.y - want_y) <= 1);
            ++checked;
        }
        if (c.h > 1) CHECK(checked > 100);  // 1024x1 at 179.5 degrees: nearly every ray leaves the guard band
    }
}

// The rasterizer's projection scale k_q8 = H/2 cot(fov/2) 16 256 is an integer: x/w and y/w carry its
// rounding, a relative error of up to 0.5 / k_q8 (large for tiny frames: H = 1 gives k_q8 about 9 at 179.5
// degrees). Primary rays use exactly that k, so the bound is 2^-27 + (|x/w| + |y/w|) / k_q8.
TEST_CASE("primary rays match gluLookAt + gluPerspective in double within the projection's own rounding") {
    for (const Case& c : cases()) {
        PrimaryRays p;
        REQUIRE(make_primary_rays(c.cam, c.w, c.h, p) == Status::ok);
        auto d = [](Q16 v) { return v.raw() / 65536.0; };
        const ref::RefCamera rc{{d(c.cam.eye.x), d(c.cam.eye.y), d(c.cam.eye.z)},
                                {d(c.cam.target.x), d(c.cam.target.y), d(c.cam.target.z)},
                                {d(c.cam.up.x), d(c.cam.up.y), d(c.cam.up.z)},
                                c.cam.fovy.bam() / 4294967296.0 * 360.0, 0.25, 200, c.w, c.h};
        const double tan_half = std::tan(rc.fovy_deg * M_PI / 360), aspect = double(c.w) / c.h;
        double worst = 0;  // |error| / bound
        for (int y : {0, c.h / 3, c.h - 1})
            for (int x : {0, c.w / 2, c.w - 1}) {
                RowRays rr(p, y);
                for (int k = 0; k < x; ++k) rr.next();
                const Vec3q30 dir = rr.direction();
                // The ray's direction in view space, through the reference's own view transform.
                const ref::Vec3d e = rc.eye;
                const ref::Vec3d far_point{e.x + dir.x.raw() / 1073741824.0 * 10, e.y + dir.y.raw() / 1073741824.0 * 10,
                                           e.z + dir.z.raw() / 1073741824.0 * 10};
                const ref::Vec3d v = ref::to_view(rc, far_point);
                const double ndc_x = (2 * (x + 0.5) / c.w - 1), ndc_y = 1 - 2 * (y + 0.5) / c.h;
                const double want[3] = {ndc_x * tan_half * aspect, ndc_y * tan_half, -1};
                const double wl = std::sqrt(want[0] * want[0] + want[1] * want[1] + 1), vl = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
                const double got[3] = {v.x / vl, v.y / vl, v.z / vl};
                const double bound = std::ldexp(1.0, -27) + (std::fabs(want[0]) + std::fabs(want[1])) / p.view.k_q8;
                for (int i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(got[i] - want[i] / wl) / bound);
            }
        MESSAGE(c.w << "x" << c.h << " fov " << rc.fovy_deg << ": worst direction error / bound " << worst);
        CHECK(worst <= 1);
    }
}

// Surface projection against gluLookAt + gluPerspective computed here in double precision: the general
// project(), the row passes (8-bit heights), the level pass (cameras without yaw), the other integer
// types and the checked path all land within 0.2 pixel of the exact point; the near plane; prepare()'s
// errors; the sweep chosen for front and side views.
#include <hider/horizon/project.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

using namespace hider;
using namespace hider::horizon;

namespace {

struct V3 {
    double x, y, z;
};
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 unit(V3 a) {
    const double l = std::sqrt(dot(a, a));
    return {a.x / l, a.y / l, a.z / l};
}
double d(Q16 v) { return v.raw() / 65536.0; }
V3 d3(const Vec3q16& v) { return {d(v.x), d(v.y), d(v.z)}; }

/// A camera and its exact projection (in pixels from the top-left corner; depth along the view axis).
struct Exact {
    Camera cam;
    int w, h;
    double fov_deg;
    bool project(V3 p, double& x, double& y, double& depth) const {
        const V3 eye = d3(cam.eye), f = unit(sub(d3(cam.target), eye));
        const V3 s = unit(cross(f, d3(cam.up))), u = cross(s, f), q = sub(p, eye);
        depth = dot(q, f);
        if (depth <= 0) return false;
        const double t = std::tan(fov_deg * M_PI / 360.0);
        x = w * 0.5 * (1 + dot(q, s) / (depth * t * w / h));
        y = h * 0.5 * (1 - dot(q, u) / (depth * t));
        return true;
    }
};

Camera camera(V3 eye, V3 target, double fov_deg, V3 up = {0, 1, 0}) {
    auto q = [](double v) { return Q16::from_raw(static_cast<int32_t>(std::lround(v * 65536))); };
    Camera c;
    c.eye = {q(eye.x), q(eye.y), q(eye.z)};
    c.target = {q(target.x), q(target.y), q(target.z)};
    c.up = {q(up.x), q(up.y), q(up.z)};
    c.fovy = Angle::from_degrees(q(fov_deg));
    c.near = q(0.05);
    c.far = q(100);
    return c;
}

/// 128 x 64 samples over [-1, 1]^2, heights value * 0.5 / 255.
Surface grid_surface(int32_t vmin = 0, int32_t vmax = 255) {
    Surface s;
    s.samples = 128;
    s.curves = 64;
    s.dx = Q16::from_ratio(2, 127);
    s.x0 = Q16::from_raw(-63 * s.dx.raw() - s.dx.raw() / 2);
    s.dz = Q16::from_ratio(2, 63);
    s.z0 = Q16::from_raw(-31 * s.dz.raw() - s.dz.raw() / 2);
    s.value_min = vmin;
    s.value_max = vmax;
    s.y_unit_raw = 128;
    return s;
}

V3 world(const Surface& s, int i, int k, int32_t v) {
    return {(s.x0.raw() + double(i) * s.dx.raw()) / 65536.0, double(v) * s.y_unit_raw / 65536.0,
            (s.z0.raw() + double(k) * s.dz.raw()) / 65536.0};
}

/// Largest distance in pixels between `pts` (curve k, heights `vals`) and the exact projection.
template <class T>
double worst_error(const SurfaceProjection& p, const Exact& e, const T* vals, int k, const PlotPoint* pts) {
    double worst = 0;
    for (int i = 0; i < p.surface().samples; ++i) {
        double x = 0, y = 0, depth = 0;
        REQUIRE(e.project(world(p.surface(), i, k, static_cast<int32_t>(vals[i])), x, y, depth));
        worst = std::max({worst, std::fabs(pts[i].x / 16.0 - x), std::fabs(pts[i].y / 16.0 - y)});
    }
    return worst;
}

}  // namespace

TEST_CASE("Every projection path lands within 0.2 pixel of gluLookAt + gluPerspective in double") {
    struct View {
        const char* name;
        V3 eye, target;
        double fov;
        int w, h;
    };
    const View views[] = {
        {"waterfall (no yaw: level pass)", {0, 1.1, 2.3}, {0, 0.1, -0.2}, 44, 128, 64},
        {"yawed (row passes)", {1.3, 1.4, 2.2}, {0, 0, 0}, 40, 320, 240},
        {"from below", {0.4, -1.6, 2.5}, {0, 0.2, 0}, 50, 160, 128},
        {"wide and close", {0.2, 0.9, 1.6}, {0, 0, -0.3}, 90, 320, 240},
    };
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> byte(0, 255);
    for (const View& v : views) {
        CAPTURE(std::string(v.name));
        const Exact e{camera(v.eye, v.target, v.fov), v.w, v.h, v.fov};
        SurfaceProjection p;
        REQUIRE(p.prepare(e.cam, v.w, v.h, grid_surface()) == Status::ok);
        CHECK(p.compact());
        std::vector<uint8_t> vals(128);
        std::vector<int16_t> vals16(128);
        std::vector<PlotPoint> pts(128), pts16(128);
        double worst_row = 0, worst_point = 0, worst16 = 0;
        for (int k = 0; k < 64; k += 3) {
            for (int i = 0; i < 128; ++i) vals16[i] = static_cast<int16_t>(vals[i] = static_cast<uint8_t>(byte(rng)));
            const RowCounts c = p.project_row(vals.data(), k, pts.data());
            CHECK(c.behind == 0);
            worst_row = std::max(worst_row, worst_error(p, e, vals.data(), k, pts.data()));
            for (int i = 0; i < 128; ++i) {  // the general path, point by point
                RowCounts rc;
                const PlotPoint q = p.project(p.at(i, k, vals[i]), rc);
                pts16[i] = q;
            }
            worst_point = std::max(worst_point, worst_error(p, e, vals.data(), k, pts16.data()));
            (void)p.project_row(vals16.data(), k, pts16.data());  // int16: the generic-type loops
            worst16 = std::max(worst16, worst_error(p, e, vals16.data(), k, pts16.data()));
        }
        MESSAGE(std::string(v.name) << ": worst error in pixels: rows " << worst_row << ", points " << worst_point << ", int16 rows "
                                    << worst16 << "; bound " << p.error_bound_subpixels() / 16.0);
        CHECK(p.error_bound_subpixels() <= 16);  // hider-plot stays quiet
        CHECK(std::max({worst_row, worst_point, worst16}) * 16 <= p.error_bound_subpixels());
        CHECK(worst_row < 0.2);
        CHECK(worst_point < 0.2);
        CHECK(worst16 < 0.2);
    }
}

TEST_CASE("A tall height range seen from close by: the error bound holds and says more than a pixel") {
    // The int32 steps are scaled to the surface's box: when its corners reach far beyond the frame for the
    // distance of the nearest point, their rounding (half a unit a step) spreads over many pixels. Heights
    // 0..500 units under an eye 6 units away: the points in the frame lie up to a few pixels off, and
    // error_bound_subpixels() must cover them (hider-plot then warns).
    for (const int32_t y_unit : {128, 12850, 128502, 513000}) {  // heights up to 0.5, 50, 500, 2,000 units
        CAPTURE(y_unit);
        const Exact e{camera({0, 2, 6}, {0, 0, 0}, 60), 320, 240, 60};
        Surface s = grid_surface();
        s.y_unit_raw = y_unit;
        SurfaceProjection p;
        REQUIRE(p.prepare(e.cam, 320, 240, s) == Status::ok);
        std::vector<uint8_t> vals(128, 0);
        std::vector<PlotPoint> pts(128);
        double worst = 0;
        for (int k = 0; k < 64; ++k) {
            for (int i = 0; i < 128; ++i) vals[i] = static_cast<uint8_t>((i * 7 + k * 13) % 97 == 0 ? 255 : 0);
            (void)p.project_row(vals.data(), k, pts.data());
            for (int i = 0; i < 128; ++i) {
                double x = 0, y = 0, depth = 0;
                if (pts[i].x == kNoPoint || !e.project(world(s, i, k, vals[i]), x, y, depth)) continue;
                if (x < 0 || x > 320 || y < 0 || y > 240) continue;  // the bound is for points in the frame
                worst = std::max({worst, std::fabs(pts[i].x / 16.0 - x), std::fabs(pts[i].y / 16.0 - y)});
            }
        }
        MESSAGE("heights up to " << 255.0 * y_unit / 65536 << " units: worst error " << worst << " px, bound "
                                 << p.error_bound_subpixels() / 16.0 << " px");
        CHECK(worst * 16 <= p.error_bound_subpixels());
        CHECK(p.error_bound_subpixels() <= 4 * 16 * worst + 16);  // not far above it either
        if (y_unit >= 128502) CHECK(p.error_bound_subpixels() > 16);  // 500 units and up: over a pixel, hider-plot warns
    }
}

TEST_CASE("8-bit rows through the row passes equal project() point for point (yawed camera)") {
    const Camera cam = camera({1.3, 1.4, 2.2}, {0, 0, 0}, 40);
    SurfaceProjection p;
    REQUIRE(p.prepare(cam, 320, 240, grid_surface()) == Status::ok);
    std::vector<uint8_t> vals(128);
    std::vector<PlotPoint> pts(128);
    std::mt19937 rng(9);
    for (int k = 0; k < 64; k += 7) {
        for (uint8_t& v : vals) v = static_cast<uint8_t>(rng());
        (void)p.project_row(vals.data(), k, pts.data());
        for (int i = 0; i < 128; ++i) {
            RowCounts c;
            const PlotPoint q = p.project(p.at(i, k, vals[i]), c);
            CHECK(pts[i].x == q.x);
            CHECK(pts[i].y == q.y);
        }
    }
}

TEST_CASE("Heights outside the declared range are clamped and counted") {
    SurfaceProjection p;
    REQUIRE(p.prepare(camera({0, 1.5, 2.5}, {0, 0, 0}, 45), 160, 120, grid_surface(10, 200)) == Status::ok);
    std::vector<uint8_t> vals(128, 100);
    vals[5] = 3;
    vals[6] = 250;
    std::vector<PlotPoint> pts(128);
    const RowCounts c = p.project_row(vals.data(), 10, pts.data());
    CHECK(c.values_clamped == 2);
    RowCounts rc;
    const PlotPoint lo = p.project(p.at(5, 10, 10), rc), hi = p.project(p.at(6, 10, 200), rc);
    CHECK(pts[5].x == lo.x);
    CHECK(pts[5].y == lo.y);
    CHECK(pts[6].x == hi.x);
    CHECK(pts[6].y == hi.y);
}

TEST_CASE("Samples behind the near plane have no point; a segment crossing it ends on it") {
    // The eye inside the surface's box, looking across it: the samples behind it get kNoPoint.
    const Exact e{camera({0, 0.3, 0.2}, {0.8, 0.1, -0.6}, 70), 160, 120, 70};
    SurfaceProjection p;
    REQUIRE(p.prepare(e.cam, 160, 120, grid_surface()) == Status::ok);
    CHECK_FALSE(p.compact());
    std::vector<uint8_t> vals(128, 60);
    std::vector<PlotPoint> pts(128);
    int k_behind = -1;
    for (int k = 0; k < 64 && k_behind < 0; ++k) {
        const RowCounts c = p.project_row(vals.data(), k, pts.data());
        if (c.behind > 0 && c.behind < 128) k_behind = k;
    }
    REQUIRE(k_behind >= 0);
    (void)p.project_row(vals.data(), k_behind, pts.data());
    for (int i = 0; i < 128; ++i) {
        double x = 0, y = 0, depth = 0;
        const bool front = e.project(world(p.surface(), i, k_behind, 60), x, y, depth) && depth > 0.05 + 1e-3;
        if (depth > 0.05 + 1e-3 || depth < 0.05 - 1e-3) CHECK((pts[i].x != kNoPoint) == front);
    }
    // A crossing point lies on the near plane, on the segment: its exact depth is near.
    const Exact& ex = e;
    for (int k = 0; k < 64; ++k) {
        for (int i = 0; i + 1 < 128; ++i) {
            RowCounts c;
            const HomPoint a = p.at(i, k, 60), b = p.at(i + 1, k, 60);
            const PlotPoint pa = p.project(a, c), pb = p.project(b, c);
            if ((pa.x == kNoPoint) == (pb.x == kNoPoint)) continue;
            const PlotPoint q = pa.x != kNoPoint ? p.near_crossing(a, b, c) : p.near_crossing(b, a, c);
            REQUIRE(q.x != kNoPoint);
            // The exact crossing: where depth = near along the 3D segment.
            const V3 wa = world(p.surface(), i, k, 60), wb = world(p.surface(), i + 1, k, 60);
            double xa, ya, da, xb, yb, db;
            ex.project(wa, xa, ya, da);
            ex.project(wb, xb, yb, db);
            const double t = (da - 0.05) / (da - db);
            double x = 0, y = 0, depth = 0;
            REQUIRE(ex.project({wa.x + t * (wb.x - wa.x), wa.y + t * (wb.y - wa.y), wa.z + t * (wb.z - wa.z)}, x, y, depth));
            CHECK(std::fabs(q.x / 16.0 - x) < 1.0);
            CHECK(std::fabs(q.y / 16.0 - y) < 1.0);
        }
    }
}

TEST_CASE("A near plane beyond the whole surface leaves every sample behind it, however far") {
    // Its W threshold wrapped in int32 once the near plane lay about 8 times beyond the farthest corner:
    // every sample counted as in front, and the projection indexed its reciprocal table far out of range
    // (a red-team pass: near 100 drew 848 pixels of a surface 3 units away, status ok).
    for (const double near : {2.0, 10.0, 40.0, 100.0, 500.0, 4000.0}) {
        CAPTURE(near);
        Camera c = camera({0, 2, 3}, {0, 0, 0}, 60);
        c.near = Q16::from_raw(static_cast<int32_t>(near * 65536));
        c.far = Q16::from_raw(static_cast<int32_t>(8000.0 * 65536));
        SurfaceProjection p;
        REQUIRE(p.prepare(c, 64, 48, grid_surface()) == Status::ok);
        std::vector<uint8_t> vals(128, 200);
        std::vector<PlotPoint> pts(128);
        for (int k = 0; k < 64; k += 9) {
            const RowCounts rc = p.project_row(vals.data(), k, pts.data());
            if (near >= 10) CHECK(rc.behind == 128);  // every corner is nearer than 5 units
            for (const PlotPoint& pt : pts) if (near >= 10) CHECK(pt.x == kNoPoint);
        }
    }
}

TEST_CASE("prepare() rejects unusable surfaces and cameras") {
    const Camera cam = camera({0, 1.5, 2.5}, {0, 0, 0}, 45);
    SurfaceProjection p;
    Surface s = grid_surface();
    SUBCASE("too few samples or curves") {
        s.samples = 1;
        CHECK(p.prepare(cam, 64, 64, s) == Status::invalid_argument);
        s = grid_surface();
        s.curves = SurfaceProjection::kMaxCount + 1;
        CHECK(p.prepare(cam, 64, 64, s) == Status::invalid_argument);
    }
    SUBCASE("steps not positive, range inverted, unit below 1") {
        s.dx = Q16::from_raw(0);
        CHECK(p.prepare(cam, 64, 64, s) == Status::invalid_argument);
        s = grid_surface();
        s.dz = Q16::from_raw(-5);
        CHECK(p.prepare(cam, 64, 64, s) == Status::invalid_argument);
        s = grid_surface(10, 5);
        CHECK(p.prepare(cam, 64, 64, s) == Status::invalid_argument);
        s = grid_surface();
        s.y_unit_raw = 0;
        CHECK(p.prepare(cam, 64, 64, s) == Status::invalid_argument);
    }
    SUBCASE("a corner outside the world range") {
        s.dx = Q16::from_int(100);  // 127 samples * 100 units
        CHECK(p.prepare(cam, 64, 64, s) == Status::out_of_range);
        s = grid_surface(0, 255);
        s.y_unit_raw = 1 << 22;  // 255 * 64 units
        CHECK(p.prepare(cam, 64, 64, s) == Status::out_of_range);
    }
    SUBCASE("the camera's own errors") {
        Camera bad = cam;
        bad.target = bad.eye;
        CHECK(p.prepare(bad, 64, 64, s) == Status::invalid_argument);
        CHECK(p.prepare(cam, 0, 64, s) == Status::invalid_argument);
    }
}

TEST_CASE("The sweep follows the view: curves from the front or above, constant-x planes from the side") {
    SurfaceProjection p;
    REQUIRE(p.prepare(camera({0.3, 1.5, 2.5}, {0, 0, 0}, 45), 160, 120, grid_surface()) == Status::ok);
    CHECK(p.sweep() == Sweep::curves);
    REQUIRE(p.prepare(camera({0.2, 3.0, 0.1}, {0, 0, 0}, 45, {0, 0, -1}), 160, 120, grid_surface()) == Status::ok);
    CHECK(p.sweep() == Sweep::curves);
    REQUIRE(p.prepare(camera({3.0, 1.2, 0.4}, {0, 0, 0}, 45), 160, 120, grid_surface()) == Status::ok);
    CHECK(p.sweep() == Sweep::x_lines);
    REQUIRE(p.prepare(camera({-2.8, 1.0, -0.5}, {0, 0, 0}, 45), 160, 120, grid_surface()) == Status::ok);
    CHECK(p.sweep() == Sweep::x_lines);
}

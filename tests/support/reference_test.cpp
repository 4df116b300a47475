// Tests of the double reference renderer and scene generators: hand-checkable cases, plus exact agreement of the
// bucketed render_ids with an independent brute-force Moller-Trumbore caster (every pixel against every triangle).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "support/reference.hpp"
#include "support/scenes.hpp"

namespace {

using hider::ref::RefCamera;
using hider::ref::RefScene;
using hider::ref::RefTriangle;
using hider::ref::Vec3d;

constexpr double kPi = 3.14159265358979323846;

// Eye at the origin looking down -Z: view space equals world space.
RefCamera origin_camera(double near, double far) {
    return RefCamera{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}, 60.0, near, far, 320, 240};
}

uint32_t at(const std::vector<uint32_t>& ids, const RefCamera& cam, int px, int py) {
    return ids[static_cast<size_t>(py) * static_cast<size_t>(cam.width) + static_cast<size_t>(px)];
}

double tan_half_fovy(const RefCamera& cam) { return std::tan(cam.fovy_deg * kPi / 360.0); }

// View-space direction (x, y, -1) through the centre of pixel (px, py).
Vec3d pixel_ray(const RefCamera& cam, int px, int py) {
    const double t = tan_half_fovy(cam);
    const double aspect = static_cast<double>(cam.width) / static_cast<double>(cam.height);
    const double x_ndc = 2.0 * (px + 0.5) / cam.width - 1.0;
    const double y_ndc = 1.0 - 2.0 * (py + 0.5) / cam.height;
    return {x_ndc * t * aspect, y_ndc * t, -1.0};
}

// Pixel-space x of a view-space point.
double project_x(const RefCamera& cam, const Vec3d& v) {
    const double aspect = static_cast<double>(cam.width) / static_cast<double>(cam.height);
    return (v.x / -v.z / (tan_half_fovy(cam) * aspect) + 1.0) * cam.width / 2.0;
}

Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const Vec3d& a, const Vec3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Ray t of a Moller-Trumbore hit from the origin along dir (edges inclusive), or -1 on a miss.
double moller_trumbore(const Vec3d (&v)[3], const Vec3d& dir) {
    const Vec3d e1 = sub(v[1], v[0]);
    const Vec3d e2 = sub(v[2], v[0]);
    const Vec3d p = cross(dir, e2);
    const double det = dot(e1, p);
    if (det == 0.0) return -1.0;
    const Vec3d s = sub(Vec3d{0.0, 0.0, 0.0}, v[0]);
    const double u = dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return -1.0;
    const Vec3d q = cross(s, e1);
    const double w = dot(dir, q) / det;
    if (w < 0.0 || u + w > 1.0) return -1.0;
    return dot(e2, q) / det;
}

// Every pixel against every triangle, same conventions as render_ids (t == d because dir.z == -1).
std::vector<uint32_t> brute_force_ids(const std::vector<RefTriangle>& tris, const RefCamera& cam, bool cull) {
    std::vector<uint32_t> ids(static_cast<size_t>(cam.width) * static_cast<size_t>(cam.height), 0);
    for (int py = 0; py < cam.height; ++py) {
        for (int px = 0; px < cam.width; ++px) {
            const Vec3d dir = pixel_ray(cam, px, py);
            double best = std::numeric_limits<double>::infinity();
            uint32_t best_id = 0;
            for (const RefTriangle& tri : tris) {
                const Vec3d v[3] = {hider::ref::to_view(cam, tri.v[0]), hider::ref::to_view(cam, tri.v[1]),
                                    hider::ref::to_view(cam, tri.v[2])};
                const double facing = dot(cross(sub(v[1], v[0]), sub(v[2], v[0])), v[0]);
                if (facing == 0.0 || (cull && facing > 0.0)) continue;
                const double d = moller_trumbore(v, dir);
                if (d < cam.near || d > cam.far) continue;
                if (d < best || (d == best && tri.id < best_id)) {
                    best = d;
                    best_id = tri.id;
                }
            }
            ids[static_cast<size_t>(py) * static_cast<size_t>(cam.width) + static_cast<size_t>(px)] = best_id;
        }
    }
    return ids;
}

RefTriangle tri(Vec3d a, Vec3d b, Vec3d c, uint32_t id) { return RefTriangle{{a, b, c}, id}; }

RefTriangle reversed(RefTriangle t) {
    std::swap(t.v[1], t.v[2]);
    return t;
}

// Big CCW triangle in the plane z = `z`, covering the view centre.
RefTriangle facing_triangle(double z, uint32_t id) { return tri({-1.0, -1.0, z}, {1.0, -1.0, z}, {0.0, 1.0, z}, id); }

long count_id(const std::vector<uint32_t>& ids, uint32_t id) {
    long n = 0;
    for (uint32_t v : ids) n += v == id ? 1 : 0;
    return n;
}

bool same_vec(const Vec3d& a, const Vec3d& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool same_scene(const RefScene& a, const RefScene& b) {
    if (a.tris.size() != b.tris.size() || a.name != b.name) return false;
    if (!same_vec(a.cam.eye, b.cam.eye) || !same_vec(a.cam.target, b.cam.target) || a.cam.near != b.cam.near ||
        a.cam.far != b.cam.far) {
        return false;
    }
    for (size_t i = 0; i < a.tris.size(); ++i) {
        if (a.tris[i].id != b.tris[i].id) return false;
        for (int k = 0; k < 3; ++k) {
            if (!same_vec(a.tris[i].v[k], b.tris[i].v[k])) return false;
        }
    }
    return true;
}

}  // namespace

TEST_CASE("a big front-facing triangle shows its id at the centre pixel and leaves the corners empty") {
    const RefCamera cam = origin_camera(0.1, 100.0);
    const auto ids = hider::ref::render_ids({facing_triangle(-5.0, 7)}, cam, true);
    CHECK(ids.size() == 320u * 240u);
    if (ids.size() != 320u * 240u) return;
    CHECK(at(ids, cam, 160, 120) == 7);
    CHECK(at(ids, cam, 159, 119) == 7);
    CHECK(at(ids, cam, 0, 0) == 0);
    CHECK(at(ids, cam, 319, 0) == 0);
    CHECK(at(ids, cam, 0, 239) == 0);
    CHECK(at(ids, cam, 319, 239) == 0);
}

TEST_CASE("a back-facing triangle vanishes with culling and appears without it") {
    const RefCamera cam = origin_camera(0.1, 100.0);
    const RefTriangle back = reversed(facing_triangle(-5.0, 7));
    CHECK(count_id(hider::ref::render_ids({back}, cam, true), 0) == 320 * 240);
    const auto both_sides = hider::ref::render_ids({back}, cam, false);
    CHECK(at(both_sides, cam, 160, 120) == 7);
    CHECK(count_id(both_sides, 7) == count_id(hider::ref::render_ids({facing_triangle(-5.0, 7)}, cam, true), 7));
}

TEST_CASE("of two parallel triangles the nearer one wins whatever the order") {
    const RefCamera cam = origin_camera(0.1, 100.0);
    const RefTriangle far_tri = facing_triangle(-5.0, 1);
    const RefTriangle near_tri = facing_triangle(-3.0, 2);
    CHECK(at(hider::ref::render_ids({far_tri, near_tri}, cam, true), cam, 160, 120) == 2);
    CHECK(at(hider::ref::render_ids({near_tri, far_tri}, cam, true), cam, 160, 120) == 2);
}

TEST_CASE("coplanar triangles at the same depth go to the smaller id") {
    const RefCamera cam = origin_camera(0.1, 100.0);
    CHECK(at(hider::ref::render_ids({facing_triangle(-5.0, 9), facing_triangle(-5.0, 4)}, cam, true), cam, 160, 120) ==
          4);
    CHECK(at(hider::ref::render_ids({facing_triangle(-5.0, 4), facing_triangle(-5.0, 9)}, cam, true), cam, 160, 120) ==
          4);
}

TEST_CASE("two crossing triangles split the image along their intersection line") {
    // id 1 lies in z = -5 + 0.5 (x - 0.7), id 2 in z = -5 - 0.5 (x - 0.7): they cross along x = 0.7, z = -5, and
    // id 1 is nearer to the right of it.
    const RefCamera cam = origin_camera(0.1, 100.0);
    const auto z1 = [](double x) { return -5.0 + 0.5 * (x - 0.7); };
    const auto z2 = [](double x) { return -5.0 - 0.5 * (x - 0.7); };
    const RefTriangle a = tri({-4.0, -4.0, z1(-4.0)}, {4.0, -4.0, z1(4.0)}, {0.0, 6.0, z1(0.0)}, 1);
    const RefTriangle b = tri({-4.0, -4.0, z2(-4.0)}, {4.0, -4.0, z2(4.0)}, {0.0, 6.0, z2(0.0)}, 2);
    const auto ids = hider::ref::render_ids({a, b}, cam, true);
    const double split_x = project_x(cam, {0.7, 0.0, -5.0});  // about 189.1
    CHECK(split_x > 188.6);  // pixel centres 188.5 and 189.5 fall on either side
    CHECK(split_x < 189.4);
    for (int py = 100; py <= 140; ++py) {
        CHECK(at(ids, cam, 188, py) == 2);
        CHECK(at(ids, cam, 189, py) == 1);
        for (int px = 120; px <= 220; ++px) {
            const uint32_t expected = px + 0.5 < split_x ? 2u : 1u;
            if (at(ids, cam, px, py) != expected) FAIL_CHECK("pixel " << px << "," << py);
        }
    }
}

TEST_CASE("triangles beyond far or wholly before the near plane are invisible") {
    const RefCamera cam = origin_camera(0.1, 100.0);
    CHECK(count_id(hider::ref::render_ids({facing_triangle(-150.0, 3)}, cam, false), 0) == 320 * 240);
    CHECK(count_id(hider::ref::render_ids({facing_triangle(-0.05, 3)}, cam, false), 0) == 320 * 240);
    CHECK(count_id(hider::ref::render_ids({facing_triangle(5.0, 3)}, cam, false), 0) == 320 * 240);
    SUBCASE("the same triangle between near and far is drawn") {
        CHECK(at(hider::ref::render_ids({facing_triangle(-0.5, 3)}, cam, false), cam, 160, 120) == 3);
        CHECK(at(hider::ref::render_ids({facing_triangle(-99.0, 3)}, cam, false), cam, 160, 120) == 3);
    }
}

TEST_CASE("a triangle crossing the near plane is visible only where d >= near") {
    // Plane z = -0.25 - 0.25 y: along the ray (x, y, -1) it sits at d = 0.25 / (1 - 0.25 y), so with near = 0.25 it
    // shows exactly where the ray points upwards (rows 0..119); with near = 0.2 every row shows it.
    const RefTriangle wall = tri({-3.0, -3.0, 0.5}, {3.0, -3.0, 0.5}, {0.0, 3.0, -1.0}, 5);
    const RefCamera cam = origin_camera(0.25, 100.0);
    const auto ids = hider::ref::render_ids({wall}, cam, true);
    for (int py = 0; py < 240; ++py) CHECK(at(ids, cam, 160, py) == (py < 120 ? 5u : 0u));
    const auto closer = hider::ref::render_ids({wall}, origin_camera(0.2, 100.0), true);
    for (int py = 0; py < 240; ++py) CHECK(at(closer, cam, 160, py) == 5);
}

TEST_CASE("a floor passing under and behind the eye shows between the near and far distances") {
    // Plane y = -1: a ray with y-slope -k < 0 meets it at d = 1 / k, drawn iff near <= 1 / k <= far.
    const RefTriangle floor = tri({-1000.0, -1.0, 1000.0}, {1000.0, -1.0, 1000.0}, {0.0, -1.0, -1000.0}, 6);
    const RefCamera cam = origin_camera(0.5, 100.0);
    const auto ids = hider::ref::render_ids({floor}, cam, true);
    for (int py = 0; py < 240; ++py) {
        const double slope = pixel_ray(cam, 160, py).y;
        const bool drawn = slope < 0.0 && 1.0 / -slope >= cam.near && 1.0 / -slope <= cam.far;
        CHECK(at(ids, cam, 160, py) == (drawn ? 6u : 0u));
    }
    CHECK(at(ids, cam, 160, 121) == 0);  // d = 138 > far
    CHECK(at(ids, cam, 160, 122) == 6);  // d = 83
}

TEST_CASE("a triangle seen edge-on or of zero area covers nothing") {
    const RefCamera cam = origin_camera(0.1, 100.0);
    const RefTriangle edge_on = tri({-1.0, 0.0, -2.0}, {1.0, 0.0, -2.0}, {0.0, 0.0, -5.0}, 1);  // plane y = 0
    const RefTriangle collinear = tri({-1.0, 0.0, -5.0}, {0.0, 0.0, -5.0}, {1.0, 0.0, -5.0}, 2);
    CHECK(count_id(hider::ref::render_ids({edge_on, collinear}, cam, false), 0) == 320 * 240);
}

TEST_CASE("invalid cameras give an empty or blank image") {
    const std::vector<RefTriangle> tris = {facing_triangle(-5.0, 1)};
    RefCamera cam = origin_camera(0.1, 100.0);
    cam.width = 0;
    CHECK(hider::ref::render_ids(tris, cam, true).empty());
    cam = origin_camera(0.0, 100.0);
    CHECK(count_id(hider::ref::render_ids(tris, cam, true), 0) == 320 * 240);
    cam = origin_camera(0.1, 100.0);
    cam.up = {0.0, 0.0, 1.0};  // parallel to the view direction
    CHECK(count_id(hider::ref::render_ids(tris, cam, true), 0) == 320 * 240);
}

TEST_CASE("to_view builds the gluLookAt basis") {
    RefCamera cam = origin_camera(0.1, 100.0);
    cam.eye = {0.0, 0.0, 0.0};
    cam.target = {1.0, 0.0, 0.0};  // f = +x, s = f x up = +z, u = s x f = +y
    const Vec3d ahead = hider::ref::to_view(cam, {5.0, 0.0, 0.0});
    const Vec3d right = hider::ref::to_view(cam, {0.0, 0.0, 1.0});
    CHECK(same_vec(ahead, {0.0, 0.0, -5.0}));
    CHECK(same_vec(right, {1.0, 0.0, 0.0}));
    cam.eye = {1.0, 2.0, 3.0};
    cam.target = {1.0, 2.0, -7.0};
    cam.up = {0.0, 5.0, 1.0};  // re-orthogonalised to +y
    const Vec3d moved = hider::ref::to_view(cam, {2.0, 4.0, 0.0});
    CHECK(moved.x == doctest::Approx(1.0));
    CHECK(moved.y == doctest::Approx(2.0));
    CHECK(moved.z == doctest::Approx(-3.0));
}

TEST_CASE("compare_ids counts edges and mismatches on a 4x3 pair") {
    // a: a lone 2 in the corner makes (2..3, 1..2) edges. b: the 3|1 boundary makes columns 1 and 2 edges.
    // Off edge: column 0 (all mismatched, 1 vs 3) and (3, 0). Mismatches elsewhere: column 1 and (3, 2).
    const std::vector<uint32_t> a = {1, 1, 1, 1,  //
                                     1, 1, 1, 1,  //
                                     1, 1, 1, 2};
    const std::vector<uint32_t> b = {3, 3, 1, 1,  //
                                     3, 3, 1, 1,  //
                                     3, 3, 1, 1};
    const hider::ref::Agreement ab = hider::ref::compare_ids(a, b, 4, 3);
    CHECK(ab.off_edge == 4);
    CHECK(ab.off_edge_mismatch == 3);
    CHECK(ab.total_mismatch == 7);
    CHECK(ab.rate() == doctest::Approx(0.25));
    const hider::ref::Agreement ba = hider::ref::compare_ids(b, a, 4, 3);
    CHECK(ba.off_edge == 4);
    CHECK(ba.off_edge_mismatch == 3);
    CHECK(ba.total_mismatch == 7);
    SUBCASE("identical images agree everywhere") {
        const hider::ref::Agreement aa = hider::ref::compare_ids(a, a, 4, 3);
        CHECK(aa.off_edge == 8);
        CHECK(aa.off_edge_mismatch == 0);
        CHECK(aa.total_mismatch == 0);
        CHECK(aa.rate() == 1.0);
    }
    SUBCASE("no off-edge pixel gives rate 1") {
        const std::vector<uint32_t> checker = {1, 2, 1, 2, 2, 1, 2, 1, 1, 2, 1, 2};
        const hider::ref::Agreement cc = hider::ref::compare_ids(checker, a, 4, 3);
        CHECK(cc.off_edge == 0);
        CHECK(cc.rate() == 1.0);
    }
    SUBCASE("a size mismatch reports total failure") {
        const hider::ref::Agreement bad = hider::ref::compare_ids(a, std::vector<uint32_t>(11, 1), 4, 3);
        CHECK(bad.rate() == 0.0);
        CHECK(bad.total_mismatch == 12);
    }
}

TEST_CASE("scene generators are deterministic and produce the stated counts") {
    CHECK(same_scene(hider::ref::soup(11, 300), hider::ref::soup(11, 300)));
    CHECK(same_scene(hider::ref::slivers(11, 300), hider::ref::slivers(11, 300)));
    CHECK(same_scene(hider::ref::huge_triangles(11), hider::ref::huge_triangles(11)));
    CHECK(same_scene(hider::ref::boxes(11, 9), hider::ref::boxes(11, 9)));
    CHECK(same_scene(hider::ref::cyclic_bars(), hider::ref::cyclic_bars()));
    CHECK(same_scene(hider::ref::piercing(), hider::ref::piercing()));
    CHECK_FALSE(same_scene(hider::ref::soup(11, 300), hider::ref::soup(12, 300)));
    CHECK_FALSE(same_scene(hider::ref::boxes(11, 9), hider::ref::boxes(12, 9)));
    CHECK(hider::ref::soup(1, 300).tris.size() == 300);
    CHECK(hider::ref::slivers(1, 250).tris.size() == 250);
    CHECK(hider::ref::huge_triangles(1).tris.size() == 32);
    CHECK(hider::ref::cyclic_bars().tris.size() == 36);
    CHECK(hider::ref::piercing().tris.size() == 5);
    CHECK(hider::ref::boxes(1, 7).tris.size() == 84);
    CHECK(hider::ref::soup(1, 0).tris.empty());
    for (const RefScene& scene : {hider::ref::soup(2, 100), hider::ref::slivers(2, 100), hider::ref::huge_triangles(2),
                                  hider::ref::cyclic_bars(), hider::ref::piercing(), hider::ref::boxes(2, 5)}) {
        INFO(scene.name);
        CHECK(scene.cam.width == 320);
        CHECK(scene.cam.height == 240);
        CHECK(scene.cam.fovy_deg == 60.0);
        for (size_t i = 0; i < scene.tris.size(); ++i) CHECK(scene.tris[i].id == i + 1);
    }
}

TEST_CASE("scenes other than huge_triangles lie between near and far") {
    for (const RefScene& scene : {hider::ref::soup(3, 2000), hider::ref::slivers(3, 2000), hider::ref::cyclic_bars(),
                                  hider::ref::piercing(), hider::ref::boxes(3, 40)}) {
        INFO(scene.name);
        double d_min = std::numeric_limits<double>::infinity();
        double d_max = 0.0;
        for (const RefTriangle& t : scene.tris) {
            for (const Vec3d& p : t.v) {
                const double d = -hider::ref::to_view(scene.cam, p).z;
                d_min = std::min(d_min, d);
                d_max = std::max(d_max, d);
            }
        }
        CHECK(d_min > scene.cam.near);
        CHECK(d_max < scene.cam.far);
    }
}

TEST_CASE("slivers are at least 200 times longer than they are high") {
    for (const RefTriangle& t : hider::ref::slivers(5, 500).tris) {
        double longest2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const Vec3d e = sub(t.v[(k + 1) % 3], t.v[k]);
            longest2 = std::max(longest2, dot(e, e));
        }
        const Vec3d n = cross(sub(t.v[1], t.v[0]), sub(t.v[2], t.v[0]));
        const double ratio = longest2 / std::sqrt(dot(n, n));  // longest edge / altitude onto it
        CHECK(ratio >= 199.0);
        CHECK(ratio <= 1001.0);
    }
}

TEST_CASE("generated boxes are closed and wound counter-clockwise from outside") {
    const std::vector<RefTriangle> tris = hider::ref::boxes(6, 10).tris;
    for (size_t box = 0; box < tris.size() / 12; ++box) {
        Vec3d centre = {0.0, 0.0, 0.0};
        for (size_t i = 12 * box; i < 12 * box + 12; ++i) {
            for (const Vec3d& p : tris[i].v) centre = {centre.x + p.x / 36, centre.y + p.y / 36, centre.z + p.z / 36};
        }
        for (size_t i = 12 * box; i < 12 * box + 12; ++i) {
            const Vec3d* v = tris[i].v;
            const Vec3d mid = {(v[0].x + v[1].x + v[2].x) / 3, (v[0].y + v[1].y + v[2].y) / 3,
                               (v[0].z + v[1].z + v[2].z) / 3};
            CHECK(dot(cross(sub(v[1], v[0]), sub(v[2], v[0])), sub(mid, centre)) > 0.0);
            for (int k = 0; k < 3; ++k) {  // each directed edge is matched by exactly one reversed edge
                int reverse_count = 0;
                for (size_t j = 12 * box; j < 12 * box + 12; ++j) {
                    for (int m = 0; m < 3; ++m) {
                        reverse_count += same_vec(tris[j].v[m], v[(k + 1) % 3]) &&
                                         same_vec(tris[j].v[(m + 1) % 3], v[k]);
                    }
                }
                CHECK(reverse_count == 1);
            }
        }
    }
}

TEST_CASE("cyclic bars overlap in a cycle: 0 over 1, 1 over 2, 2 over 0") {
    const RefScene scene = hider::ref::cyclic_bars();
    std::vector<uint32_t> alone[3];
    for (size_t bar = 0; bar < 3; ++bar) {
        const std::vector<RefTriangle> part(scene.tris.begin() + 12 * bar, scene.tris.begin() + 12 * bar + 12);
        alone[bar] = hider::ref::render_ids(part, scene.cam, true);
    }
    const auto all = hider::ref::render_ids(scene.tris, scene.cam, true);
    for (size_t upper = 0; upper < 3; ++upper) {
        const size_t lower = (upper + 1) % 3;
        long overlap = 0;
        long upper_wins = 0;
        for (size_t i = 0; i < all.size(); ++i) {
            if (alone[upper][i] == 0 || alone[lower][i] == 0) continue;
            ++overlap;
            upper_wins += (all[i] - 1) / 12 == upper ? 1 : 0;
        }
        INFO("bar " << upper << " over bar " << lower);
        CHECK(overlap > 100);
        CHECK(upper_wins == overlap);
    }
}

TEST_CASE("piercing triangles swap order along their intersection lines") {
    const RefScene scene = hider::ref::piercing();
    const auto ids = hider::ref::render_ids(scene.tris, scene.cam, true);
    const double split_x = project_x(scene.cam, hider::ref::to_view(scene.cam, {-2.5, 0.0, 0.0}));  // about 95.05
    CHECK(split_x > 94.6);  // pixel centres 94.5 and 95.5 fall on either side
    CHECK(split_x < 95.4);
    for (int py = 110; py <= 130; ++py) {
        CHECK(at(ids, scene.cam, 94, py) == 2);
        CHECK(at(ids, scene.cam, 95, py) == 1);
    }
    // The spike (id 5) rises through the quad along y = 0: its lower half shows, its upper half is hidden.
    CHECK(count_id(ids, 5) > 200);
    for (int py = 0; py < 120; ++py) {
        for (int px = 160; px < 320; ++px) {
            if (at(ids, scene.cam, px, py) == 5) FAIL_CHECK("spike above the middle row at " << px << "," << py);
        }
    }
}

TEST_CASE("huge_triangles crosses the near plane, passes behind the eye and clips the wall at near") {
    const RefScene scene = hider::ref::huge_triangles(7);
    int crossing_near = 0;
    int behind_eye = 0;
    for (const RefTriangle& t : scene.tris) {
        int in_front = 0;
        int behind = 0;
        for (const Vec3d& p : t.v) {
            const double d = -hider::ref::to_view(scene.cam, p).z;
            in_front += d > scene.cam.near;
            behind += d < 0.0;
        }
        crossing_near += in_front > 0 && in_front < 3;
        behind_eye += behind > 0;
    }
    CHECK(crossing_near >= 3);
    CHECK(behind_eye >= 3);
    // The wall (id 8) is nearer than near for view rays with y-slope < 0.1, i.e. from row 100 down.
    const auto ids = hider::ref::render_ids(scene.tris, scene.cam, false);
    long wall_above = 0;
    for (int py = 0; py < 240; ++py) {
        for (int px = 0; px < 320; ++px) {
            if (at(ids, scene.cam, px, py) != 8) continue;
            if (py < 100) ++wall_above;
            else FAIL_CHECK("wall visible below the near line at " << px << "," << py);
        }
    }
    CHECK(wall_above > 1000);
}

TEST_CASE("bucketed render_ids agrees exactly with brute force on small scenes") {
    for (RefScene scene : {hider::ref::soup(1, 50), hider::ref::soup(9, 120), hider::ref::huge_triangles(1),
                           hider::ref::huge_triangles(4), hider::ref::slivers(2, 40), hider::ref::cyclic_bars(),
                           hider::ref::piercing(), hider::ref::boxes(3, 6)}) {
        scene.cam.width = 64;
        scene.cam.height = 48;
        for (bool cull : {true, false}) {
            INFO(scene.name << " cull=" << cull);
            const auto fast = hider::ref::render_ids(scene.tris, scene.cam, cull);
            const auto slow = brute_force_ids(scene.tris, scene.cam, cull);
            CHECK(fast.size() == slow.size());
            if (fast.size() != slow.size()) continue;
            long differ = 0;
            for (size_t i = 0; i < fast.size(); ++i) differ += fast[i] != slow[i];
            CHECK(differ == 0);
            CHECK(count_id(fast, 0) < static_cast<long>(fast.size()));  // the scene is in view
        }
    }
}

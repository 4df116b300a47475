// hider's face-id image against the independent double-precision ray caster: >= 99.9% agreement on
// pixels not adjacent to an id edge, for every test model and for generated hard scenes, with and
// without culling; closed meshes show no background pixel inside their silhouette (no cracks).
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

namespace {

/// Compares hider with the reference; besides the overall off-edge rate, the rate over off-edge pixels that
/// show a face in either image must hold too (background alone must not carry the figure).
void check_agreement(const tool::Scene& s, const std::string& name, bool cull, int bits = 16, long min_faces = 2000) {
    const std::vector<uint32_t> ids = test::hider_ids(s, cull, bits);
    const std::vector<uint32_t> ref = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), cull);
    const ref::Agreement a = ref::compare_ids(ids, ref, s.width, s.height);
    const ref::Agreement both_bg = ref::compare_ids(std::vector<uint32_t>(ids.size(), 0), std::vector<uint32_t>(ids.size(), 0), s.width, s.height);
    long face_pixels = 0;
    for (size_t i = 0; i < ids.size(); ++i) face_pixels += ids[i] != 0 || ref[i] != 0;
    // Background pixels off any edge are matches; take them out of the denominator for the surface rate.
    long covered_off_edge = a.off_edge - (both_bg.off_edge - face_pixels);
    const double surface_rate = covered_off_edge <= 0 ? 1.0 : 1.0 - static_cast<double>(a.off_edge_mismatch) / covered_off_edge;
    const std::string mode = std::string(cull ? " cull" : " no-cull") + " d" + std::to_string(bits);
    MESSAGE(name << mode << ": face pixels " << face_pixels << ", off-edge " << a.off_edge << ", mismatched "
                 << a.off_edge_mismatch << ", rate " << a.rate() << ", surface rate " << surface_rate);
    CHECK(face_pixels > min_faces);
    CHECK(a.rate() >= 0.999);
    CHECK(surface_rate >= 0.999);
}

/// Background pixels whose 8 neighbours all show a face in the reference (a hole in a closed surface).
long cracks(const tool::Scene& s, bool cull) {
    const std::vector<uint32_t> ids = test::hider_ids(s, cull);
    const std::vector<uint32_t> ref = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), cull);
    long n = 0;
    for (int y = 1; y + 1 < s.height; ++y)
        for (int x = 1; x + 1 < s.width; ++x) {
            if (ids[static_cast<size_t>(y) * s.width + x] != 0) continue;
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    interior = interior && ref[static_cast<size_t>(y + dy) * s.width + x + dx] != 0;
            n += interior;
        }
    return n;
}

}  // namespace

TEST_CASE("every test model agrees with the reference ray caster, culled and not" * doctest::test_suite("slow")) {
    for (const char* name : {"torus.obj", "teapot.obj", "suzanne.obj", "spot.obj", "cow.obj", "fandisk.obj",
                             "beetle.obj", "woody.obj", "stanford-bunny.obj"}) {
        const tool::Scene s = test::load_model(name);
        check_agreement(s, name, true);
        check_agreement(s, name, false);
    }
}

TEST_CASE("the torus standard view agrees with 16- and 32-bit depth") {
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{0, 0, -2.5};
    cam.target = tool::Vec3d{0, 0, 0};
    cam.fov_deg = 73.7398;
    cam.near = 0.25;
    const tool::Scene s = test::load_model("torus.obj", cam);
    check_agreement(s, "torus standard", true, 16);
    check_agreement(s, "torus standard", false, 32);
}

TEST_CASE("closed meshes have no cracks inside their silhouette" * doctest::test_suite("slow")) {
    for (const char* name : {"torus.obj", "cow.obj", "spot.obj", "fandisk.obj"}) {
        const tool::Scene s = test::load_model(name);
        CHECK_MESSAGE(cracks(s, true) == 0, name);
        CHECK_MESSAGE(cracks(s, false) == 0, name);
    }
}

TEST_CASE("generated hard scenes agree with the reference ray caster") {
    std::vector<ref::RefScene> scenes = {ref::soup(1, 200),  ref::soup(2, 2000), ref::slivers(3, 300),
                                         ref::huge_triangles(4), ref::huge_triangles(5), ref::cyclic_bars(),
                                         ref::piercing(),    ref::boxes(6, 40)};
    for (const ref::RefScene& rs : scenes) {
        tool::Scene s;
        std::string why;
        REQUIRE_MESSAGE(test::scene_from_ref(rs, s, why), why);
        for (bool cull : {true, false}) check_agreement(s, rs.name, cull, 16, 400);
    }
}

namespace {

/// A wall (a square, half size 1, through the origin, facing the eye at +z with a random tilt) and a
/// decal on it (a random quad inside the wall) lifted `offset` units along the wall's normal.
tool::Scene decal_scene(uint32_t seed, double offset) {
    uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
    auto uniform = [&](double lo, double hi) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    using V = std::array<double, 3>;
    auto unit = [](V a) {
        const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        return V{a[0] / l, a[1] / l, a[2] / l};
    };
    auto cross = [](V a, V b) { return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; };
    const V n = unit({uniform(-0.6, 0.6), uniform(-0.6, 0.6), 1.0});
    const V u = unit(cross({0, 1, 0}, n)), v = cross(n, u);
    auto at = [&](double a, double b, double lift) {
        return V{a * u[0] + b * v[0] + lift * n[0], a * u[1] + b * v[1] + lift * n[1], a * u[2] + b * v[2] + lift * n[2]};
    };
    tool::ObjModel m;
    for (auto [a, b] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) m.vertices.push_back(at(a, b, 0));
    const double ca = uniform(-0.4, 0.4), cb = uniform(-0.4, 0.4), r = uniform(0.1, 0.5);
    const double turn = uniform(0, 1.5707963);
    for (int k = 0; k < 4; ++k) {  // a square turned by `turn`, counter-clockwise seen from the eye like the wall
        const double t = turn + k * 1.5707963267948966;
        m.vertices.push_back(at(ca + r * std::cos(t), cb + r * std::sin(t), offset));
    }
    m.faces.push_back({{0, 1, 2, 3}, 1, 1});
    m.faces.push_back({{4, 5, 6, 7}, 2, 2});
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{uniform(-0.5, 0.5), uniform(-0.5, 0.5), 4};
    cam.target = tool::Vec3d{0, 0, 0};
    tool::Scene s;
    std::string why;
    REQUIRE_MESSAGE(tool::build_scene(m, cam, s, why), why);
    return s;
}

}  // namespace

TEST_CASE("a decal on a wall: 2e-3 units in front, every algorithm but the painter shows all of it; exactly on it, none leaves a hole") {
    // README "Depth resolution": faces on one plane have no defined winner (each algorithm and the z-buffer's
    // own pixels may show either); a decal lifted off the wall by more than that resolution shows in all.
    const tool::Algo algos[] = {tool::Algo::zbuffer, tool::Algo::painter, tool::Algo::newell, tool::Algo::reverse,
                                tool::Algo::bsp,     tool::Algo::bsp_front, tool::Algo::raycast};
    const char* names[] = {"zbuffer", "painter", "newell", "reverse", "bsp", "bsp-front", "raycast"};
    long decal_pixels = 0;
    for (uint32_t seed = 1; seed <= 12; ++seed)
        for (double offset : {2e-3, 0.0}) {
            const tool::Scene s = decal_scene(seed, offset);
            const std::vector<uint32_t> ref = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), true);
            for (size_t k = 0; k < sizeof algos / sizeof algos[0]; ++k) {
                tool::RenderOptions opt;
                opt.algo = algos[k];
                opt.shade = Shade::id;
                opt.format = tool::PixelFormat::rgb888;
                opt.depth_bits = 32;
                tool::RenderResult r;
                std::string why;
                REQUIRE_MESSAGE(tool::render(s, opt, r, why), why);
                const std::vector<uint32_t> ids = tool::decode_ids(r);
                const std::string name = names[k];
                INFO("seed ", seed, " offset ", offset, " ", name);
                const test::Defects d = test::count_defects(ids, ref, s.width, s.height);
                CHECK(d.holes == 0);
                if (offset > 0 && algos[k] != tool::Algo::painter) {  // the painter's key can put a wall
                    // triangle after the decal (README "Which algorithm"): seeds 5 and 12 here
                    const ref::Agreement a = ref::compare_ids(ids, ref, s.width, s.height);
                    CHECK(a.off_edge_mismatch == 0);
                    CHECK(d.cracks == 0);
                }
                if (offset > 0 && k == 0)
                    for (uint32_t id : ids) decal_pixels += id == 2;
            }
        }
    CHECK(decal_pixels > 12 * 500);
}

TEST_CASE("a triangle whose plane holds the eye, crossing the near plane, draws nothing in any algorithm") {
    // A red team's scene: two triangles in the planes z = 0 and x = 0, which hold the eye exactly, in
    // front of a wall. Rounded to view space, their planes missed the eye by 0.6 and 1.3 raw units, and the
    // near plane's clip turned that into a wedge: the z-buffer, painter, Newell and reverse painter drew 552
    // pixels of them at 320x240 with status ok, where the BSP (its exact eye test) and ray casting draw none.
    auto q = [](double v) { return Q16::from_raw(static_cast<int32_t>(v * 65536)); };
    auto p = [&q](double x, double y, double z) { return Vec3q16{q(x), q(y), q(z)}; };
    tool::Scene s;
    s.positions = {p(-20, 4, -20), p(20, 4, -20), p(0, 4, 20),  // the wall (id 1), values exact in Q16
                   p(2.3485565185546875, 3.8897857666015625, 0), p(-0.6499481201171875, -0.53326416015625, 0),
                   p(3.367950439453125, -1.7382354736328125, 0),  // in z = 0 (id 2)
                   p(0, 2.3911590576171875, -3.2352142333984375), p(0, -3.682830810546875, 0.260467529296875),
                   p(0, 2.708526611328125, 1.2936859130859375)};  // in x = 0 (id 2)
    s.tris = {{{0, 1, 2}}, {{3, 4, 5}}, {{6, 7, 8}}};
    s.ids = {1, 2, 2};
    s.camera.eye = p(0, -0.7282562255859375, 0);
    s.camera.target = p(-0.0565185546875, -0.3205413818359375, -0.0709686279296875);
    s.camera.up = p(0, 1, 0);
    s.camera.fovy = Angle::from_degrees(Q16::from_int(60));
    s.camera.far = q(50);
    const tool::Algo algos[] = {tool::Algo::zbuffer, tool::Algo::painter, tool::Algo::newell, tool::Algo::reverse,
                                tool::Algo::bsp,     tool::Algo::bsp_front, tool::Algo::raycast};
    long frames = 0;
    for (const double near : {1.0 / 256, 1.0 / 64, 0.01, 0.1})
        for (const auto& [w, h] : {std::pair<int, int>{320, 240}, {64, 48}}) {
            s.camera.near = q(near);
            s.width = w;
            s.height = h;
            for (const tool::Algo algo : algos)
                for (const bool cull : {false, true})
                    for (const int bits : {16, 32}) {
                        long edge_on = 0, wall = 0;
                        for (const uint32_t id : tool::decode_ids(test::render_ids(s, algo, cull, bits))) {
                            edge_on += id == 2;
                            wall += id == 1;
                        }
                        INFO("near ", near, " ", w, "x", h, " algo ", int(algo), " cull ", cull, " depth ", bits);
                        CHECK(edge_on == 0);
                        CHECK_MESSAGE(wall == long{w} * h, "edge-on ", edge_on, " wall ", wall);  // and no hole where it was
                        ++frames;
                    }
        }
    CHECK(frames == 4 * 2 * 7 * 2 * 2);
}

// hider's face-id image against the independent double-precision ray caster: >= 99.9% agreement on
// pixels not adjacent to an id edge, for every test model and for generated hard scenes, with and
// without culling; closed meshes show no background pixel inside their silhouette (no cracks).
#include <string>
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

// Ray casting (hider-render --algo raycast) against the z-buffer: the same face-id image on every
// off-edge pixel (README's claim) for every test model and the generated hard scenes (interpenetration,
// cyclic overlap, slivers, triangles through the near plane and behind the eye), culled and not; no cracks inside closed
// meshes; band-by-band output equal to the whole frame; headlight colours equal to the z-buffer's.
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

namespace {

tool::RenderResult run(const tool::Scene& s, tool::Algo algo, bool cull, Shade shade = Shade::id, int band = 0) {
    tool::RenderOptions opt;
    opt.algo = algo;
    opt.cull = cull;
    opt.shade = shade;
    opt.format = tool::PixelFormat::rgb888;
    opt.band_rows = band;
    tool::RenderResult r;
    std::string why;
    const bool ok = tool::render(s, opt, r, why);
    REQUIRE_MESSAGE(ok, why);
    return r;
}

/// Background pixels of the ray cast whose 8 neighbours all show a face in the z-buffer: holes.
long cracks(const std::vector<uint32_t>& ids, const std::vector<uint32_t>& z, int w, int h) {
    long n = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            if (ids[static_cast<size_t>(y) * w + x] != 0) continue;
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) inside = inside && z[static_cast<size_t>(y + dy) * w + x + dx] != 0;
            n += inside;
        }
    return n;
}

void check_against_zbuffer(const tool::Scene& s, const std::string& name, bool closed) {
    for (bool cull : {true, false}) {
        const tool::RenderResult r = run(s, tool::Algo::raycast, cull), z = run(s, tool::Algo::zbuffer, cull);
        const std::vector<uint32_t> ids = tool::decode_ids(r), zids = tool::decode_ids(z);
        const ref::Agreement a = ref::compare_ids(ids, zids, s.width, s.height);
        const long holes = cracks(ids, zids, s.width, s.height);
        MESSAGE(name << std::string(cull ? " cull" : " no-cull") << ": covered " << r.pixels_covered << ", off-edge " << a.off_edge
                     << ", mismatched " << a.off_edge_mismatch << ", rate " << a.rate() << ", cracks " << holes
                     << ", box tests/ray " << double(r.ray.boxes) / double(r.ray.rays) << ", triangle tests/ray "
                     << double(r.ray.triangles) / double(r.ray.rays));
        // 0 on these scenes; surfaces nearer each other than the snapping's depth resolution could differ
        // (README "Depth resolution": ray casting does not snap vertices), none of these has such a pair.
        CHECK(a.off_edge_mismatch == 0);
        CHECK(r.stats.status == Status::ok);
        if (closed) CHECK(holes == 0);
    }
}

std::vector<std::pair<std::string, tool::Scene>> hard_scenes() {
    return test::scenes_from_ref({ref::cyclic_bars(), ref::piercing(), ref::boxes(6, 10), ref::soup(1, 300),
                                  ref::soup(8, 1000), ref::slivers(3, 200), ref::huge_triangles(4), ref::huge_triangles(7)});
}

}  // namespace

TEST_CASE("ray casting matches the z-buffer on the generated hard scenes") {
    for (const auto& [name, s] : hard_scenes()) check_against_zbuffer(s, name, false);
}

TEST_CASE("ray casting matches the z-buffer on every test model, without cracks in closed ones" * doctest::test_suite("slow")) {
    for (const char* name : {"torus.obj", "teapot.obj", "suzanne.obj", "spot.obj", "cow.obj", "fandisk.obj", "beetle.obj",
                             "woody.obj", "stanford-bunny.obj"}) {
        const std::string n = name;
        check_against_zbuffer(test::load_model(name), name, n == "torus.obj" || n == "cow.obj" || n == "spot.obj" || n == "fandisk.obj");
    }
}

TEST_CASE("ray casting: the torus standard view, headlight colours and bands") {
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{0, 0, -2.5};
    cam.target = tool::Vec3d{0, 0, 0};
    cam.fov_deg = 73.7398;
    cam.near = 0.25;
    const tool::Scene s = test::load_model("torus.obj", cam);
    check_against_zbuffer(s, "torus standard", true);
    // Headlight: the colour of a pixel is its face's, so it equals the z-buffer's wherever the ids agree.
    const tool::RenderResult rh = run(s, tool::Algo::raycast, true, Shade::headlight);
    const tool::RenderResult zh = run(s, tool::Algo::zbuffer, true, Shade::headlight);
    const std::vector<uint32_t> ri = tool::decode_ids(run(s, tool::Algo::raycast, true)), zi = tool::decode_ids(run(s, tool::Algo::zbuffer, true));
    long same_id = 0, same_colour = 0;
    for (size_t i = 0; i < ri.size(); ++i) {
        if (ri[i] != zi[i]) continue;
        ++same_id;
        same_colour += rh.rgb[3 * i] == zh.rgb[3 * i] && rh.rgb[3 * i + 1] == zh.rgb[3 * i + 1] && rh.rgb[3 * i + 2] == zh.rgb[3 * i + 2];
    }
    CHECK(same_id > 70000);
    CHECK(same_colour == same_id);
    for (int band : {1, 7, 32}) CHECK(run(s, tool::Algo::raycast, false, Shade::id, band).rgb == run(s, tool::Algo::raycast, false).rgb);
    tool::RenderOptions opt;
    opt.algo = tool::Algo::raycast;
    opt.shade = Shade::depth;
    tool::RenderResult r;
    std::string why;
    CHECK_FALSE(tool::render(s, opt, r, why));
    CHECK(why.find("depth") != std::string::npos);
}

TEST_CASE("a ray through the bunny's BVH does under 1% of the brute-force work" * doctest::test_suite("slow")) {
    const tool::Scene s = test::load_model("stanford-bunny.obj");
    const tool::RenderResult r = run(s, tool::Algo::raycast, true);
    // Brute force tests every triangle per ray; the walk tests boxes and a few triangles (a box test
    // costs less than a triangle test: counting both as one is conservative). Ir figures: hider-bench raycast.
    const double per_ray = double(r.ray.boxes + r.ray.triangles) / double(r.ray.rays);
    MESSAGE("bunny: " << s.tris.size() << " triangles, per ray " << double(r.ray.boxes) / double(r.ray.rays) << " box and "
                      << double(r.ray.triangles) / double(r.ray.rays) << " triangle tests");
    CHECK(per_ray * 100 < double(s.tris.size()));
}

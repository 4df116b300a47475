// Golden frames: hider-render's pipeline on real models at 320x240, compared byte for byte with the
// reviewed PPMs in tests/golden/. A missing golden fails. On a mismatch the frame is written next to
// the golden as <name>_actual.ppm. Goldens are (re)written only with HIDER_UPDATE_GOLDEN=1.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "host/ppm.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

std::vector<uint8_t> read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

void check_golden(const std::string& name, const tool::Scene& scene, const tool::RenderOptions& opt) {
    tool::RenderResult r;
    std::string why;
    REQUIRE_MESSAGE(tool::render(scene, opt, r, why), why);
    const std::vector<uint8_t> bytes = port::ppm_bytes(r.width, r.height, r.rgb);
    const std::string golden = std::string(HIDER_TEST_GOLDEN) + "/" + name + ".ppm";
    const char* update = std::getenv("HIDER_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        REQUIRE(port::write_ppm(golden, r.width, r.height, r.rgb, why));
        MESSAGE("wrote " << golden);
        return;
    }
    const std::vector<uint8_t> expected = read_file(golden);
    REQUIRE_MESSAGE(!expected.empty(), "missing golden " << golden << " (create with HIDER_UPDATE_GOLDEN=1 and review it)");
    const bool same = expected == bytes;
    if (!same) {
        REQUIRE(port::write_ppm(std::string(HIDER_TEST_GOLDEN) + "/" + name + "_actual.ppm", r.width, r.height, r.rgb, why));
    }
    CHECK_MESSAGE(same, name << " differs from its golden; see " << name << "_actual.ppm");
}

tool::CameraArgs torus_standard() {
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{0, 0, -2.5};
    cam.target = tool::Vec3d{0, 0, 0};
    cam.up = tool::Vec3d{0, 1, 0};
    cam.fov_deg = 73.7398;
    cam.near = 0.25;
    return cam;
}

}  // namespace

TEST_CASE("golden: torus standard view, headlight, RGB565") {
    check_golden("torus_headlight_rgb565", test::load_model("torus.obj", torus_standard()), {});
}

TEST_CASE("golden: teapot without culling shows its inside through the lid gap") {
    tool::RenderOptions opt;
    opt.cull = false;
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{2, 4, 5};
    check_golden("teapot_nocull_rgb565", test::load_model("teapot.obj", cam), opt);
}

TEST_CASE("golden: suzanne face ids") {
    tool::RenderOptions opt;
    opt.shade = Shade::id;
    opt.format = tool::PixelFormat::rgb888;
    check_golden("suzanne_id", test::load_model("suzanne.obj"), opt);
}

TEST_CASE("golden: cow depth shading, 32-bit depth, grey8") {
    tool::RenderOptions opt;
    opt.shade = Shade::depth;
    opt.depth_bits = 32;
    opt.format = tool::PixelFormat::grey8;
    check_golden("cow_depth_grey8", test::load_model("cow.obj"), opt);
}

TEST_CASE("golden: bunny headlight rendered in bands of 16 rows") {
    tool::RenderOptions opt;
    opt.band_rows = 16;
    check_golden("bunny_headlight_band16", test::load_model("stanford-bunny.obj"), opt);
}

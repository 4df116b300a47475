// libFuzzer target (clang, ASan, UBSan): arbitrary bytes as a ray-tracing scene file (hider-render
// --scene) through parse_ray_scene() and the tracer at 16x12, whole and in 5-row bands; `mesh cube.obj`
// finds a cube the fuzzer writes to a temporary directory first. Fails on a crash or sanitizer report, a
// failure without a reason, or bands whose bytes differ from the whole frame's (ctest ray_scene_fuzz).
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "common/ray_scene.hpp"
#include "common/render_ray.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

std::string g_dir;

void remove_cube() {
    std::remove((g_dir + "/cube.obj").c_str());
    std::remove(g_dir.c_str());
}

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "ray_scene_fuzz: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const char* tmp = std::getenv("TMPDIR");
    std::string dir = std::string(tmp != nullptr && *tmp != 0 ? tmp : "/tmp") + "/hider-ray-fuzz-XXXXXX";
    if (mkdtemp(dir.data()) == nullptr) fail("cannot make a temporary directory");
    g_dir = dir;
    std::FILE* f = std::fopen((g_dir + "/cube.obj").c_str(), "w");
    if (f == nullptr) fail("cannot write cube.obj");
    std::fputs("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n",
               f);
    std::fclose(f);
    std::atexit(remove_cube);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (text.find('/') != std::string::npos) return 0;  // mesh paths stay in the fuzzer's directory (no /dev/stdin)
    std::istringstream in(text);
    RayScene scene;
    std::string why;
    if (!parse_ray_scene(in, "fuzz.txt", g_dir, scene, why)) {
        if (why.empty()) fail("parse_ray_scene failed without a reason");
        return 0;
    }
    RenderOptions opt;
    opt.format = PixelFormat::rgb888;
    RenderResult whole, banded;
    std::string why_whole, why_banded;
    const bool ok = render_ray_scene(scene, 16, 12, opt, whole, why_whole);
    if (!ok && why_whole.empty()) fail("render_ray_scene failed without a reason");
    opt.band_rows = 5;
    const bool ok_banded = render_ray_scene(scene, 16, 12, opt, banded, why_banded);
    if (ok != ok_banded) fail("whole frame and bands disagree on success");
    if (ok && (whole.rgb.size() != 16 * 12 * 3 || whole.rgb != banded.rgb)) fail("bands differ from the whole frame");
    return 0;
}

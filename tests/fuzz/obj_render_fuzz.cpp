// libFuzzer target (clang, ASan, UBSan): arbitrary bytes as an OBJ file through parse_obj() (small
// limits), build_scene() (the framing camera, culled; an eye inside the model's box, not culled) and every
// algorithm at 24x17, whole and in 3-row bands (the z-buffer also through its centred column window). Fails
// on a crash or sanitizer report, a failure without a reason, bands or a window whose bytes or counts differ
// from the whole frame's, or a pixel written twice by the reverse painter or bsp-front. Run by ctest
// (obj_render_fuzz, host-asan preset) for a bounded time.
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "common/obj.hpp"
#include "common/render.hpp"
#include "common/scene.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

[[noreturn]] void fail(const char* what, const char* algo, int band) {
    std::fprintf(stderr, "obj_render_fuzz: %s (algo %s, band rows %d)\n", what, algo, band);
    std::abort();
}

const char* name_of(Algo a) {
    switch (a) {
        case Algo::zbuffer: return "zbuffer";
        case Algo::painter: return "painter";
        case Algo::newell: return "newell";
        case Algo::reverse: return "reverse";
        case Algo::raycast: return "raycast";
        case Algo::bsp: return "bsp";
        case Algo::bsp_front: return "bsp-front";
    }
    return "?";
}

void exercise(const Scene& scene, bool cull) {
    for (Algo algo : {Algo::zbuffer, Algo::painter, Algo::newell, Algo::reverse, Algo::bsp, Algo::bsp_front, Algo::raycast}) {
        RenderOptions opt;
        opt.algo = algo;
        opt.cull = cull;
        opt.shade = Shade::id;
        opt.format = PixelFormat::rgb888;
        RenderResult whole;
        std::string why;
        const bool ok = render(scene, opt, whole, why);
        if (!ok && why.empty()) fail("render failed without a reason", name_of(algo), 0);
        opt.band_rows = 3;
        RenderResult banded;
        std::string why_banded;
        const bool ok_banded = render(scene, opt, banded, why_banded);
        if (!ok_banded && why_banded.empty()) fail("render failed without a reason", name_of(algo), 3);
        if (ok != ok_banded) fail("whole frame and bands disagree on success", name_of(algo), 3);
        if (!ok) continue;
        const size_t bytes = static_cast<size_t>(scene.width) * scene.height * 3;
        if (whole.rgb.size() != bytes || banded.rgb.size() != bytes) fail("frame of the wrong size", name_of(algo), 0);
        if (whole.rgb != banded.rgb) fail("bands differ from the whole frame", name_of(algo), 3);
        if (algo == Algo::zbuffer) {  // its centred column window, whole and in bands: the same bytes and counts
            for (int rows : {0, 3}) {
                opt.band_rows = rows;
                opt.window = true;
                RenderResult windowed;
                std::string why_windowed;
                if (!render(scene, opt, windowed, why_windowed)) fail("the window failed where the frame did not", name_of(algo), rows);
                if (windowed.rgb != whole.rgb) fail("the window differs from the whole frame", name_of(algo), rows);
                if (windowed.stats.triangles_drawn != whole.stats.triangles_drawn ||
                    windowed.stats.fragments != whole.stats.fragments || windowed.pixels_covered != whole.pixels_covered)
                    fail("the window's counts differ from the whole frame's", name_of(algo), rows);
            }
        }
        if ((algo == Algo::reverse || algo == Algo::bsp_front) && whole.stats.status == Status::ok &&
            whole.stats.pixels_written != whole.pixels_covered)
            fail("a pixel written twice", name_of(algo), 0);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    ObjLimits limits;
    limits.max_line_bytes = 512;
    limits.max_vertices = 64;
    limits.max_faces = 48;
    ObjModel model;
    ObjError err;
    if (!parse_obj(in, "fuzz.obj", model, err, limits)) {
        if (err.what.empty() || err.line < 0) fail("parse_obj failed without a reason", "-", 0);
        return 0;
    }
    size_t triangles = 0;  // a face of n vertices is a fan of n - 2: keep each input to a few milliseconds
    for (const ObjFace& f : model.faces) triangles += f.v.size() - 2;
    if (triangles > 128) return 0;
    for (int camera = 0; camera < 2; ++camera) {
        CameraArgs args;
        args.width = 24;
        args.height = 17;
        if (camera == 1 && !model.vertices.empty()) {
            // The eye inside the model's box, looking at its first vertex: near-plane crossings.
            Vec3d lo = model.vertices[0], hi = lo;
            for (const auto& v : model.vertices)
                for (int k = 0; k < 3; ++k) {
                    lo[k] = v[k] < lo[k] ? v[k] : lo[k];
                    hi[k] = v[k] > hi[k] ? v[k] : hi[k];
                }
            args.eye = Vec3d{lo[0] + (hi[0] - lo[0]) * 0.4, lo[1] + (hi[1] - lo[1]) * 0.55, lo[2] + (hi[2] - lo[2]) * 0.45};
            args.target = model.vertices[0];
        }
        Scene scene;
        std::string why;
        if (!build_scene(model, args, scene, why)) {
            if (why.empty()) fail("build_scene failed without a reason", "-", 0);
            continue;
        }
        exercise(scene, camera == 0);
    }
    return 0;
}

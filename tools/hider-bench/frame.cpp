// hider-bench frame: loads and converts a scene once, allocates every buffer, then calls
// hider_bench_frame N times. Statistics are computed and printed after the last frame, so the
// measured function sees no allocation and no I/O. Output (one line of "key value" pairs after a
// title line) is parsed by the table command; targets calls run_frames() for the covered pixels.
#include <cinttypes>
#include <cstdio>

#include "bench.hpp"
#include "common/obj.hpp"
#include "measured.hpp"

namespace hider::tool::bench {
namespace {

bool same_stats(const FrameStats& a, const FrameStats& b) {
    return a.status == b.status && a.triangles_in == b.triangles_in && a.triangles_drawn == b.triangles_drawn &&
           a.triangles_culled == b.triangles_culled && a.triangles_clipped == b.triangles_clipped &&
           a.triangles_outside == b.triangles_outside && a.fragments == b.fragments &&
           a.pixels_written == b.pixels_written;
}

/// Pixels whose depth is no longer the clear value: exactly those a fragment was written to, since a
/// fragment at the clear depth never passes the test (ties keep). Independent of shading colour.
template <class Depth>
uint32_t covered_pixels(const Depth* depth, size_t n) {
    uint32_t covered = 0;
    for (size_t i = 0; i < n; ++i) covered += depth[i] != DepthTraits<Depth>::kClear ? 1 : 0;
    return covered;
}

}  // namespace

FrameSummary run_frames(const std::string& model_path, const CameraArgs& cam, int depth_bits, long frames) {
    ObjModel model;
    ObjError err;
    if (!load_obj(model_path, model, err)) fail(format(err));
    Scene scene;
    std::string why;
    if (!build_scene(model, cam, scene, why)) fail(model_path + ": " + why);
    const Status ms = validate(scene.mesh());
    if (ms != Status::ok) fail(model_path + ": mesh rejected: " + status_name(ms));

    const size_t pixels = static_cast<size_t>(scene.width) * scene.height;
    AlignedBuffer<ScreenVertex> verts(scene.positions.size());
    AlignedBuffer<uint16_t> color(pixels);
    AlignedBuffer<uint16_t> depth16(depth_bits == 16 ? pixels : 0);
    AlignedBuffer<uint32_t> depth32(depth_bits == 32 ? pixels : 0);
    std::vector<FrameStats> per_frame(static_cast<size_t>(frames));

    FrameJob job;
    job.camera = scene.camera;
    job.width = scene.width;
    job.height = scene.height;
    job.mesh = scene.mesh();
    job.verts = {verts.data(), verts.size()};
    job.color = color.data();
    job.depth16 = depth16.data();
    job.depth32 = depth32.data();
    job.depth_bits = depth_bits;
    for (FrameStats& st : per_frame) {
        hider_bench_frame(&job);
        if (job.status != Status::ok) fail(model_path + ": frame rejected: " + status_name(job.status));
        st = job.stats;
    }

    FrameSummary out;
    out.width = scene.width;
    out.height = scene.height;
    out.stats = per_frame.back();
    out.pixels = pixels;
    if (!out.stats.ok()) fail(model_path + ": draw_zbuffer: " + status_name(out.stats.status));
    for (const FrameStats& st : per_frame)
        if (!same_stats(st, out.stats))
            fail(model_path + ": frames differ in their statistics (nondeterministic lib/?)");
    out.covered = depth_bits == 16 ? covered_pixels(depth16.data(), pixels) : covered_pixels(depth32.data(), pixels);
    return out;
}

int frame_command(const Args& args) {
    std::string model_path;
    CameraArgs cam;
    int depth_bits = 16;
    long frames = 1;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (parse_camera_option(args, i, cam)) continue;
        if (a == "--depth-bits") {
            const std::string& v = option_value(args, i);
            if (v != "16" && v != "32") fail("--depth-bits must be 16 or 32 (got '" + v + "')");
            depth_bits = v == "16" ? 16 : 32;
        } else if (a == "--frames") {
            const std::string& v = option_value(args, i);
            if (!parse_int(v, frames) || frames < 1 || frames > 100000)
                fail("--frames needs a count 1..100000 (got '" + v + "')");
        } else if (!a.empty() && a[0] == '-') {
            fail("frame: unknown option '" + a + "'");
        } else if (model_path.empty()) {
            model_path = a;
        } else {
            fail("frame: more than one model given ('" + model_path + "', '" + a + "')");
        }
    }
    if (model_path.empty()) fail("frame: no model given");

    const FrameSummary f = run_frames(model_path, cam, depth_bits, frames);
    const FrameStats& s = f.stats;
    const uint32_t covered = f.covered;
    const size_t pixels = f.pixels;
    std::printf("frame %s %dx%d depth %d-bit, %ld frame%s, statistics per frame:\n", model_path.c_str(),
                f.width, f.height, depth_bits, frames, frames == 1 ? "" : "s");
    std::printf("triangles %" PRIu32 " drawn %" PRIu32 " culled %" PRIu32 " clipped %" PRIu32 " outside %" PRIu32
                " fragments %" PRIu64 " covered %" PRIu32 " pixels %zu\n",
                s.triangles_in, s.triangles_drawn, s.triangles_culled, s.triangles_clipped, s.triangles_outside,
                s.fragments, covered, pixels);
    return 0;
}

}  // namespace hider::tool::bench

// hider-bench raytrace: instructions per pixel of the ray-traced demo scene (tests/data/scenes/spheres.txt,
// 160x128), mean and worst row, on the host (callgrind, one dump per traced row) and on the chips (the
// raytrace firmware of each cross build tree under QEMU with the insncount plugin: region = the traced
// rows, max = the costliest row). hider-bench raycast: callgrind Ir per primary ray of mesh ray casting
// (torus standard view, bunny default framing, 320x240), and per ray on a grid of sampled pixels through
// the BVH and by brute force over every triangle, which must find the same triangles.
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <map>

#include "bench.hpp"
#include "common/bvh_build.hpp"
#include "common/ray_scene.hpp"
#include "measured_ray.hpp"

namespace hider::tool::bench {
namespace {

namespace fs = std::filesystem;

std::string demo_scene() { return (source_root() / "tests/data/scenes/spheres.txt").string(); }

std::string fixed(double v, int places) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", places, v);
    return buf;
}

/// Total Ir of one callgrind output file ("totals:" or "summary:" line).
uint64_t file_ir(const fs::path& p) {
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("totals:", 0) == 0 || line.rfind("summary:", 0) == 0) return std::strtoull(line.c_str() + line.find(':') + 1, nullptr, 10);
    return 0;
}

/// Per-call Ir of `function` over one run of this executable with `args` (one dump after each call).
std::vector<uint64_t> callgrind_per_call(const std::string& valgrind, const std::string& function, const Args& args) {
    const TempDir tmp;
    const fs::path out = tmp.path() / "cg.out";
    Args argv = {valgrind, "-q", "--tool=callgrind", "--callgrind-out-file=" + out.string(), "--toggle-collect=" + function,
                 "--collect-atstart=no", "--dump-after=" + function, (fs::read_symlink("/proc/self/exe")).string()};
    argv.insert(argv.end(), args.begin(), args.end());
    ProcessResult result;
    std::string error;
    const std::string so = (tmp.path() / "stdout").string(), se = (tmp.path() / "stderr").string();
    if (!run_process(argv, "", {}, so, se, result, error)) fail(error);
    if (!result.exited || result.status != 0) fail("callgrind run failed (" + result.describe() + "):\n" + read_text(se));
    std::vector<uint64_t> counts;
    for (int i = 1;; ++i) {
        const fs::path dump = out.string() + "." + std::to_string(i);
        if (!fs::is_regular_file(dump)) break;
        counts.push_back(file_ir(dump));
    }
    if (counts.empty()) fail("callgrind wrote no per-call dumps for " + function);
    return counts;
}

/// firmware/raytrace/raytrace.elf of build tree `tree` on the small machine.
bool target_count(const fs::path& tree, const std::string& preset, TargetCount& c) {
    return firmware_count(tree, preset, "firmware/raytrace/raytrace.elf", "small", c);
}

RayScene load_demo(const std::string& path) {
    RayScene s;
    std::string why;
    if (!load_ray_scene(path, s, why)) fail(why);
    return s;
}

}  // namespace

int raytrace_run_command(const Args& args) {
    if (args.size() != 1) fail("raytrace-run: needs the scene file");
    const RayScene scene = load_demo(args[0]);
    const ray::Scene s = scene.view();
    ray::PrimaryRays rays;
    if (ray::make_primary_rays(scene.camera, scene.width, scene.height, rays) != Status::ok) fail("raytrace-run: camera rejected");
    std::vector<ray::BvhStackEntry> stack(scene.stack_depth());
    std::vector<ray::SphereRect> rects(std::max<size_t>(1, scene.spheres.size()));
    if (ray::validate_scene(s, {stack.data(), stack.size()}) != Status::ok || ray::sphere_rects(s, rays, {rects.data(), rects.size()}) != Status::ok)
        fail("raytrace-run: scene rejected");
    AlignedBuffer<uint16_t> row(static_cast<size_t>(scene.width));
    RayRowJob job;
    job.scene = &s;
    job.rays = &rays;
    job.stack = {stack.data(), stack.size()};
    job.rects = {rects.data(), rects.size()};
    job.row = row.data();
    ray::TraceStats total;
    for (int32_t y = 0; y < scene.height; ++y) {
        job.y = y;
        hider_bench_ray_row(&job);
        total.merge(job.stats);
    }
    std::printf("rays %u shadow %u\n", total.rays, total.shadow_rays);
    return 0;
}

int raytrace_command(const Args& args) {
    std::string valgrind, scene_path = demo_scene();
    fs::path root = source_root() / "build";
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--valgrind") valgrind = option_value(args, i);
        else if (args[i] == "--build-root") root = fs::absolute(option_value(args, i));  // QEMU runs in a scratch directory
        else if (args[i] == "--scene") scene_path = option_value(args, i);
        else fail("raytrace: unknown argument '" + args[i] + "'");
    }
    valgrind = find_valgrind(valgrind);
    const RayScene scene = load_demo(scene_path);
    const uint64_t pixels = uint64_t(scene.width) * uint64_t(scene.height);
    const std::vector<uint64_t> rows = callgrind_per_call(valgrind, "hider_bench_ray_row", {"raytrace-run", scene_path});
    if (rows.size() != static_cast<size_t>(scene.height)) fail("raytrace: expected one dump per row");
    uint64_t sum = 0, worst = 0;
    for (uint64_t r : rows) { sum += r; worst = std::max(worst, r); }
    std::printf("Ray-traced demo scene (%s, %dx%d, %zu spheres, %zu planes, %zu lights, %d bounces): instructions in\n"
                "trace_row over all rows (host: callgrind Ir, x86-64; chips: QEMU insncount of firmware/raytrace on\n"
                "the small machines, -Os). Worst row = the costliest row / width.\n\n",
                fs::path(scene_path).filename().c_str(), scene.width, scene.height, scene.spheres.size(), scene.planes.size(),
                scene.lights.size(), int(scene.bounces));
    std::printf("| target | instructions/frame | per pixel (mean) | worst row per pixel |\n|---|---:|---:|---:|\n");
    std::printf("| host (x86-64, -O2) | %" PRIu64 " | %s | %s |\n", sum, fixed(double(sum) / double(pixels), 1).c_str(),
                fixed(double(worst) / scene.width, 1).c_str());
    for (const char* preset : {"cm0plus", "cm3", "rv32imac"}) {
        TargetCount c;
        if (!target_count(root / preset, preset, c)) {
            std::printf("| %s | (no build tree with firmware/raytrace) | | |\n", preset);
            continue;
        }
        if (c.pairs != static_cast<uint64_t>(scene.height)) fail(std::string(preset) + ": raytrace ran " + std::to_string(c.pairs) + " rows");
        std::printf("| %s | %" PRIu64 " | %s | %s |\n", preset, c.region, fixed(double(c.region) / double(pixels), 1).c_str(),
                    fixed(double(c.max) / scene.width, 1).c_str());
    }
    return 0;
}

namespace {

/// Loads a model as hider-render frames it (or the torus standard view) and builds its BVH.
struct CastSetup {
    Scene scene;
    BakedBvh bvh;
    ray::PrimaryRays rays;
    std::vector<ray::BvhStackEntry> stack;
};

CastSetup cast_setup(const std::string& model_path, bool torus_view_args) {
    CastSetup c;
    ObjModel model;
    ObjError err;
    if (!load_obj(model_path, model, err)) fail(format(err));
    CameraArgs cam = torus_view_args ? camera_from(torus_view("320x240")) : CameraArgs{};
    std::string why;
    if (!build_scene(model, cam, c.scene, why) || !build_bvh(c.scene.mesh(), c.bvh, why)) fail(model_path + ": " + why);
    c.stack.resize(c.bvh.header.max_depth);
    if (ray::validate_bvh(c.bvh.view(), c.scene.mesh(), {c.stack.data(), c.stack.size()}) != Status::ok) fail("bvh rejected");
    if (ray::make_primary_rays(c.scene.camera, c.scene.width, c.scene.height, c.rays) != Status::ok) fail("camera rejected");
    return c;
}

/// The primary ray queries of a grid of pixels (every `step`-th in x and y), as cast_row makes them.
std::vector<ray::BvhQuery> sample_queries(const CastSetup& c, int step) {
    std::vector<ray::BvhQuery> q;
    for (int y = step / 2; y < c.rays.height; y += step) {
        ray::RowRays rr(c.rays, y);
        for (int x = 0; x < c.rays.width; ++x, rr.next()) {
            ray::BvhQuery one{};
            if (x % step == step / 2 && ray::primary_query(c.rays, rr.direction(), true, one)) q.push_back(one);
        }
    }
    return q;
}

}  // namespace

int raycast_run_command(const Args& args) {
    if (args.size() != 3) fail("raycast-run: needs MODEL torus|default frame|bvh|brute");
    const CastSetup c = cast_setup(args[0], args[1] == "torus");
    AlignedBuffer<uint16_t> row(static_cast<size_t>(c.rays.width));
    if (args[2] == "frame") {
        CastJob job;
        job.rays = &c.rays;
        job.mesh = c.scene.mesh();
        job.bvh = c.bvh.view();
        job.stack = {const_cast<ray::BvhStackEntry*>(c.stack.data()), c.stack.size()};
        job.row = row.data();
        hider_bench_cast(&job);
        std::printf("rays %u hits %u boxes %u triangles %u\n", job.stats.rays, job.stats.hits, job.stats.bvh.boxes, job.stats.bvh.triangles);
        return 0;
    }
    const std::vector<ray::BvhQuery> queries = sample_queries(c, 16);
    std::vector<uint32_t> tri(queries.size()), check(queries.size());
    NearestJob job;
    job.mesh = c.scene.mesh();
    job.bvh = c.bvh.view();
    job.queries = queries.data();
    job.count = queries.size();
    job.stack = {const_cast<ray::BvhStackEntry*>(c.stack.data()), c.stack.size()};
    job.tri = tri.data();
    if (args[2] == "bvh") {
        hider_bench_nearest_bvh(&job);
    } else {
        hider_bench_nearest_brute(&job);
        NearestJob other = job;  // the BVH outside the measured function: both must find the same triangles
        other.tri = check.data();
        hider_bench_nearest_bvh(&other);
        if (tri != check) fail("raycast-run: BVH and brute force found different triangles");
    }
    size_t hits = 0;
    for (uint32_t t : tri) hits += t != UINT32_MAX;
    std::printf("rays %zu hits %zu\n", queries.size(), hits);
    return 0;
}

int raycast_command(const Args& args) {
    std::string valgrind, models = default_models_dir();
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--valgrind") valgrind = option_value(args, i);
        else if (args[i] == "--models") models = option_value(args, i);
        else fail("raycast: unknown argument '" + args[i] + "'");
    }
    valgrind = find_valgrind(valgrind);
    std::printf("Mesh ray casting at 320x240 (hider-render --algo raycast, culling on): callgrind Ir per primary ray\n"
                "for the whole frame (direction, near/far range, BVH walk, shading), and per ray on every 16th pixel in\n"
                "x and y for the nearest-triangle search alone: BVH walk against brute force over every triangle\n"
                "(same exact triangle test; both find the same triangles).\n\n");
    std::printf("| model | view | triangles | BVH nodes / depth | Ir/ray (frame) | sampled rays | Ir/ray BVH | Ir/ray brute force | brute / BVH |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& [name, view] : {std::pair<const char*, const char*>{"torus.obj", "torus"}, {"stanford-bunny.obj", "default"}}) {
        const std::string model = models + "/" + name;
        const CastSetup c = cast_setup(model, std::string(view) == "torus");
        const uint64_t pixels = uint64_t(c.rays.width) * uint64_t(c.rays.height);
        const CallgrindRun frame = run_callgrind(valgrind, "hider_bench_cast", {"raycast-run", model, view, "frame"});
        const CallgrindRun bvh = run_callgrind(valgrind, "hider_bench_nearest_bvh", {"raycast-run", model, view, "bvh"});
        const CallgrindRun brute = run_callgrind(valgrind, "hider_bench_nearest_brute", {"raycast-run", model, view, "brute"});
        unsigned long rays = 0, hits = 0;
        if (std::sscanf(bvh.out.c_str(), "rays %lu hits %lu", &rays, &hits) != 2 || rays == 0) fail("raycast: no sampled rays");
        std::printf("| %s | %s | %zu | %zu / %u | %s | %lu (%lu hit) | %s | %s | %s |\n", name, view, c.scene.tris.size(),
                    c.bvh.nodes.size(), unsigned(c.bvh.header.max_depth), fixed(double(frame.ir) / double(pixels), 1).c_str(), rays,
                    hits, fixed(double(bvh.ir) / double(rays), 1).c_str(), fixed(double(brute.ir) / double(rays), 1).c_str(),
                    fixed(double(brute.ir) / double(bvh.ir), 1).c_str());
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace hider::tool::bench

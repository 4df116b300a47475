// hider-bench sort: callgrind Ir of the painter's sort (painter_order = depth-key fill + 4-pass LSD
// radix sort + order copy, lib/hider/sort/painter.hpp) per polygon, for growing prefixes of one
// polygon list: the bunny's screen polygons built once without culling. Each n is one `sort-run`
// under callgrind with collection only inside hider_bench_sort, so loading and building never count.
// Also the host-side polygon builder shared with the newell command.
#include <algorithm>
#include <cinttypes>
#include <cstdio>

#include "bench.hpp"
#include "common/gen_scenes.hpp"
#include "common/obj.hpp"
#include "common/render.hpp"
#include "measured.hpp"

namespace hider::tool::bench {
namespace {

constexpr const char* kSortModel = "stanford-bunny.obj";
/// The largest frame keeps the most bunny triangles: fewer of them miss every pixel centre.
constexpr const char* kSortSize = "1024x1024";
const std::vector<size_t> kSortCounts = {1000, 2000, 5000, 10000, 20000, 35000, 70000};

/// order[] is painter_order's result for polys: a permutation, farthest zmax first, ties by index.
bool is_painter_order(const ScreenPoly* polys, const uint32_t* order, size_t n) {
    std::vector<uint8_t> seen(n, 0);
    for (size_t k = 0; k < n; ++k) {
        if (order[k] >= n || seen[order[k]] != 0) return false;
        seen[order[k]] = 1;
        if (k == 0) continue;
        const ScreenPoly &a = polys[order[k - 1]], &b = polys[order[k]];
        if (a.zmax < b.zmax || (a.zmax == b.zmax && order[k - 1] > order[k])) return false;
    }
    return true;
}

std::string fixed2(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

}  // namespace

ScreenPolys build_screen_polys(const std::string& model_path, const CameraArgs& cam, bool cull, bool cut_room) {
    ScreenPolys out;
    ObjModel model;
    ObjError err;
    std::string why;
    gen::GenScene generated;
    CameraArgs camera = cam;
    if (model_path.size() < 4 || model_path.compare(model_path.size() - 4, 4, ".obj") != 0) {
        if (!gen::by_name(model_path, generated, why)) fail(why);
        model = gen::obj_model(generated);
        if (!cam.eye) camera = gen::camera_args(generated);
    } else if (!load_obj(model_path, model, err)) {
        fail(format(err));
    }
    if (!build_scene(model, camera, out.scene, why)) fail(model_path + ": " + why);
    const Mesh mesh = out.scene.mesh();
    const Status ms = validate(mesh);
    if (ms != Status::ok) fail(model_path + ": mesh rejected: " + status_name(ms));
    View& view = out.view;
    const Status vs = make_view(out.scene.camera, out.scene.width, out.scene.height, view);
    if (vs != Status::ok) fail(model_path + ": camera rejected: " + status_name(vs));
    std::vector<ScreenVertex> verts(mesh.positions.size());
    const Status ps = project_vertices(view, mesh.positions, {verts.data(), verts.size()});
    if (ps != Status::ok) fail(model_path + ": project_vertices: " + status_name(ps));
    // A clipped triangle gives up to 7 pieces; cuts get hider-render's default room (common/render.cpp).
    const size_t triangles = mesh.tris.size();
    out.store.resize(triangles * 7 + (cut_room ? default_split_pool(triangles) : 0));
    BoundedList<ScreenPoly> polys(out.store.data(), out.store.size());
    build_polys(view, mesh, {verts.data(), verts.size()}, cull, polys, out.stats);
    if (!out.stats.ok()) fail(model_path + ": build_polys: " + status_name(out.stats.status));
    out.built = polys.size();
    return out;
}

int sort_run_command(const Args& args) {
    std::string model_path;
    Args camera;
    long n = 0;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--n") {
            if (!parse_int(option_value(args, i), n) || n < 1) fail("sort-run: --n needs a count >= 1");
        } else if (!args[i].empty() && args[i][0] == '-') {
            camera.push_back(args[i]);
            camera.push_back(option_value(args, i));
        } else {
            model_path = args[i];
        }
    }
    if (model_path.empty() || n == 0) fail("sort-run: needs MODEL and --n N");
    const ScreenPolys p = build_screen_polys(model_path, camera_from(camera), false, false);
    const size_t count = static_cast<size_t>(n);
    if (count > p.built) fail("sort-run: --n " + std::to_string(n) + " > " + std::to_string(p.built) + " polygons");

    AlignedBuffer<SortKey> keys(count), scratch(count);
    AlignedBuffer<uint32_t> order(count);
    SortJob job;
    job.polys = {p.store.data(), count};
    job.keys = {keys.data(), count};
    job.scratch = {scratch.data(), count};
    job.order = {order.data(), count};
    hider_bench_sort(&job);
    if (!is_painter_order(p.store.data(), order.data(), count)) fail("sort-run: painter_order gave a wrong order");
    std::printf("sorted %zu of %zu polygons\n", count, p.built);
    return 0;
}

int sort_command(const Args& args) {
    std::string models = default_models_dir(), valgrind, size = kSortSize;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--models") models = option_value(args, i);
        else if (args[i] == "--valgrind") valgrind = option_value(args, i);
        else if (args[i] == "--size") size = option_value(args, i);
        else fail("sort: unknown argument '" + args[i] + "'");
    }
    valgrind = find_valgrind(valgrind);
    const std::string model = models + "/" + kSortModel;
    const Args camera = {"--size", size};
    const ScreenPolys all = build_screen_polys(model, camera_from(camera), false, false);
    const size_t total = all.built;
    if (total < kSortCounts.front()) fail(model + ": only " + std::to_string(total) + " polygons");

    std::printf("painter_order (farthest-vertex keys, 4-pass LSD radix sort, order copy) on the first n screen\n"
                "polygons of %s at %s, built once without culling: %zu polygons from %" PRIu32 " triangles.\n"
                "callgrind Ir inside hider_bench_sort; n larger than the list is cut to all %zu polygons.\n"
                "Step = (Ir - Ir of the row above) / (n - n of the row above): the cost of one more polygon.\n\n",
                kSortModel, size.c_str(), total, all.stats.triangles_in, total);
    std::printf("| n | Ir | Ir/polygon | step Ir/polygon |\n|---:|---:|---:|---:|\n");
    std::fflush(stdout);
    size_t prev_n = 0;
    uint64_t prev_ir = 0;
    for (size_t n : kSortCounts) {
        n = std::min(n, total);
        if (n == prev_n) continue;
        const Args run_args = {"sort-run", model, "--size", size, "--n", std::to_string(n)};
        const CallgrindRun run = run_callgrind(valgrind, "hider_bench_sort", run_args);
        const std::string expect = "sorted " + std::to_string(n) + " of " + std::to_string(total) + " polygons\n";
        if (run.out != expect) fail("sort: sort-run printed '" + run.out + "', expected '" + expect + "'");
        const std::string step = prev_n == 0 ? "-"
                                             : fixed2((static_cast<double>(run.ir) - static_cast<double>(prev_ir)) /
                                                      static_cast<double>(n - prev_n));
        std::printf("| %zu%s | %" PRIu64 " | %s | %s |\n", n, n == total ? " (all)" : "", run.ir,
                    fixed2(static_cast<double>(run.ir) / static_cast<double>(n)).c_str(), step.c_str());
        std::fflush(stdout);
        prev_n = n;
        prev_ir = run.ir;
    }
    return 0;
}

}  // namespace hider::tool::bench

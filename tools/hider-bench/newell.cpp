// hider-bench newell: for every model in the models directory and for generated interpenetrating soups
// (150, 300 and 1000 triangles), with back faces culled and kept, the statistics of Newell's ordering
// (lib/hider/sort/newell.hpp) and its instructions: callgrind Ir of newell_order alone
// (hider_bench_newell) next to the painter's sort of the same polygons (hider_bench_sort). Each (scene,
// culling) is two `newell-run`s under callgrind, one per measured function. The pool and camera are
// hider-render's defaults, and the statistics are checked against render() (common/render.hpp).
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <sstream>

#include "bench.hpp"
#include "common/gen_scenes.hpp"
#include "common/obj.hpp"
#include "common/render.hpp"
#include "measured.hpp"

namespace hider::tool::bench {
namespace {

/// The generated scenes of the table: random interpenetrating soups (gen_scenes.hpp dense_soup).
const std::vector<std::string> kSoups = {"dense-1-150", "dense-1-300", "dense-1-1000"};

/// The benchmark torus uses its standard view; every other model the framing defaults, a generated
/// scene its own camera.
Args camera_for(const std::string& file) { return file == "torus.obj" ? torus_view("320x240") : Args{}; }

/// "key value" pairs of the line newell-run prints (starting with "newell ").
std::map<std::string, uint64_t> parse_newell_line(const std::string& out) {
    std::map<std::string, uint64_t> v;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("newell ", 0) != 0) continue;
        std::istringstream words(line.substr(7));
        std::string key, value;
        while (words >> key >> value) {
            long parsed = 0;
            if (!parse_int(value, parsed) || parsed < 0) fail("bad line from newell-run: " + line);
            v[key] = static_cast<uint64_t>(parsed);
        }
    }
    for (const char* key : {"polygons", "after", "pair-tests", "moves", "cuts", "cycles", "pixel-ordered", "unresolved", "dropped", "too-deep"})
        if (v.count(key) == 0) fail(std::string("newell-run printed no '") + key + "':\n" + out);
    return v;
}

std::string ratio(double num, double den, int decimals) {
    if (den == 0) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, num / den);
    return buf;
}

/// Newell's statistics from hider-render's own driver, for the same model, camera and culling.
void check_against_render(const std::string& path, const Args& camera, bool cull,
                          const std::map<std::string, uint64_t>& v) {
    const Scene scene = build_screen_polys(path, camera_from(camera), cull, false).scene;
    std::string why;
    RenderOptions opt;
    opt.algo = Algo::newell;
    opt.cull = cull;
    RenderResult r;
    if (!render(scene, opt, r, why)) fail(path + ": render: " + why);
    const NewellStats& n = r.newell;
    if (v.at("after") != r.polygons || v.at("pair-tests") != n.pair_tests || v.at("moves") != n.moves ||
        v.at("cuts") != n.splits || v.at("cycles") != n.cycles || v.at("pixel-ordered") != n.pixel_ordered || v.at("unresolved") != n.unresolved ||
        v.at("dropped") != n.dropped || v.at("too-deep") != n.too_deep)
        fail(path + ": the measured newell_order disagrees with render() (common/render.cpp)");
}

}  // namespace

int newell_run_command(const Args& args) {
    std::string model_path;
    Args camera;
    bool cull = true, sort_only = false;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--no-cull") cull = false;
        else if (args[i] == "--sort-only") sort_only = true;
        else if (!args[i].empty() && args[i][0] == '-') {
            camera.push_back(args[i]);
            camera.push_back(option_value(args, i));
        } else {
            model_path = args[i];
        }
    }
    if (model_path.empty()) fail("newell-run: no model given");
    ScreenPolys p = build_screen_polys(model_path, camera_from(camera), cull, true);
    const size_t built = p.built, cap = built + default_split_pool(p.scene.tris.size());
    BoundedList<ScreenPoly> polys(p.store.data(), cap);
    for (size_t i = 0; i < built; ++i) polys.push_back(p.store[i]);
    if (sort_only) {
        AlignedBuffer<SortKey> keys(built), scratch(built);
        AlignedBuffer<uint32_t> order(built);
        SortJob sort;
        sort.polys = {polys.data(), built};
        sort.keys = {keys.data(), built};
        sort.scratch = {scratch.data(), built};
        sort.order = {order.data(), built};
        hider_bench_sort(&sort);
        std::printf("sorted %zu polygons\n", built);
        return 0;
    }
    AlignedBuffer<PieceCut> cut_store(2 * (cap - built));
    AlignedBuffer<uint32_t> order_store(cap), heap(cap), heap_pos(cap), links(2 * cap), chain(cap), reorders(kNewellReorders);
    AlignedBuffer<uint32_t> cells(grid_cells(p.view.width, p.view.height));
    BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
    BoundedList<uint32_t> order(order_store.data(), cap);
    NewellJob job;
    job.view = p.view;
    job.polys = &polys;
    job.cuts = &cuts;
    AlignedBuffer<SortKey> keys(built), sort_scratch(built);
    job.scratch = {{keys.data(), built}, {sort_scratch.data(), built}, {heap.data(), cap}, {heap_pos.data(), cap},
                   {links.data(), 2 * cap}, {cells.data(), cells.size()}, {chain.data(), cap},
                   {reorders.data(), reorders.size()}};
    job.order = &order;
    const std::vector<uint32_t> faces = flat_faces(p.scene.mesh());  // as render() passes them
    job.options.face_ids = {faces.data(), faces.size()};
    hider_bench_newell(&job);
    if (job.status != Status::ok && job.status != Status::capacity_exceeded)
        fail(model_path + ": newell_order: " + status_name(job.status));
    const NewellStats& s = job.stats;
    std::printf("newell polygons %zu after %zu pair-tests %" PRIu64 " moves %" PRIu32 " cuts %" PRIu32 " cycles %" PRIu32
                " pixel-ordered %" PRIu32 " unresolved %" PRIu32 " dropped %" PRIu32 " too-deep %" PRIu32 "\n",
                built, order.size(), s.pair_tests, s.moves, s.splits, s.cycles, s.pixel_ordered, s.unresolved, s.dropped, s.too_deep);
    return 0;
}

int newell_command(const Args& args) {
    std::string models = default_models_dir(), valgrind;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--models") models = option_value(args, i);
        else if (args[i] == "--valgrind") valgrind = option_value(args, i);
        else fail("newell: unknown argument '" + args[i] + "'");
    }
    valgrind = find_valgrind(valgrind);
    const std::vector<std::string> files = model_files(models);

    std::printf("Newell's ordering per model at 320x240 (torus: its standard view, others: default framing) and\n"
                "for random interpenetrating soups (gen_scenes dense-SEED-N, their own camera), back faces culled or\n"
                "kept; pool: 16 cuts per triangle + 1024. polygons = screen polygons, after = after cuts. callgrind\n"
                "Ir inside hider_bench_sort (painter_order of the same polygons) and hider_bench_newell (newell_order).\n"
                "Statistics checked against render() of common/render.cpp.\n\n");
    std::printf("| scene | back faces | polygons | after | pair tests | moves | cuts | cycles | pixel-ordered | unresolved "
                "| dropped | too deep | painter Ir | Newell Ir | Newell / painter | Newell Ir/polygon |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::fflush(stdout);
    std::vector<std::string> scenes;
    for (const std::string& file : files) scenes.push_back(models + "/" + file);
    scenes.insert(scenes.end(), kSoups.begin(), kSoups.end());
    for (const std::string& path : scenes) {
        const std::string file = std::filesystem::path(path).filename().string();
        const Args camera = camera_for(file);
        for (bool cull : {true, false}) {
            Args run_args = {"newell-run", path};
            run_args.insert(run_args.end(), camera.begin(), camera.end());
            if (!cull) run_args.push_back("--no-cull");
            Args sort_args = run_args;
            sort_args.push_back("--sort-only");
            const CallgrindRun painter = run_callgrind(valgrind, "hider_bench_sort", sort_args);
            const CallgrindRun newell = run_callgrind(valgrind, "hider_bench_newell", run_args);
            const std::map<std::string, uint64_t> v = parse_newell_line(newell.out);
            if (painter.out != "sorted " + std::to_string(v.at("polygons")) + " polygons\n")
                fail(path + ": the two runs sorted different polygon lists");
            check_against_render(path, camera, cull, v);
            const double newell_ir = static_cast<double>(newell.ir), painter_ir = static_cast<double>(painter.ir);
            std::printf("| %s | %s | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64
                        " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %s | %s |\n",
                        file.c_str(), cull ? "culled" : "kept", v.at("polygons"), v.at("after"), v.at("pair-tests"),
                        v.at("moves"), v.at("cuts"), v.at("cycles"), v.at("pixel-ordered"), v.at("unresolved"), v.at("dropped"),
                        v.at("too-deep"), painter.ir,
                        newell.ir, ratio(newell_ir, painter_ir, 1).c_str(),
                        ratio(newell_ir, static_cast<double>(v.at("polygons")), 1).c_str());
            std::fflush(stdout);
        }
    }
    return 0;
}

std::vector<std::string> model_files(const std::string& dir) {
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".obj")
            files.push_back(entry.path().filename().string());
    if (ec) fail(dir + ": cannot list models: " + ec.message());
    std::sort(files.begin(), files.end());
    if (files.empty()) fail(dir + ": no .obj models");
    return files;
}

}  // namespace hider::tool::bench

// hider-bench bsp: the BSP compiler (tools/common/bsp_build, as hider-bsp runs it) on every model of the
// models directory and on the street-level city (tests/data/scenes/city-1-16-16-street.obj) at two
// heuristic settings: polygons, split ratio, triangles, nodes, depth, flash bytes and build time; then
// the walks on the host for the firmware's two views (nodes visited, subtrees skipped, triangles drawn,
// overdraw, and the z-buffer's depth complexity); then the firmware/bsp counts of each cross build tree
// under QEMU (bsp_torus against painter_plain, bsp_city against bsp_city_zbuffer).
#include <chrono>
#include <cinttypes>
#include <cstdio>

#include "bench.hpp"
#include "common/bsp_build.hpp"
#include "common/obj.hpp"
#include "common/render.hpp"
#include "common/render_bsp.hpp"

namespace hider::tool::bench {
namespace {

namespace fs = std::filesystem;

struct Setting {
    const char* name;
    BspOptions opt;
};
const Setting kSettings[] = {{"default (split 8, balance 1, 32 candidates)", {8, 1, 32}},
                             {"balanced (split 2, balance 4, 8 candidates)", {2, 4, 8}}};

/// The firmware's views (tools/hider-bake/scenes.cmake).
const Args kTorusView = {"--size", "160x128", "--eye", "0,0,-2.5", "--target", "0,0,0", "--up", "0,1,0", "--fov", "73.7398", "--near", "0.25"};
const Args kCityView = {"--size", "160x128", "--eye", "12.25,0.3,25.1", "--target", "12.25,0.5,0", "--up", "0,1,0",
                        "--fov", "60", "--near", "0.5", "--far", "200"};

std::string city_path() { return (source_root() / "tests/data/scenes/city-1-16-16-street.obj").string(); }

/// The statistics of one render, failing loudly.
RenderResult render_or_fail(const Scene& scene, const std::vector<uint8_t>& blob, Algo algo, bool cull, const std::string& what) {
    RenderOptions opt;
    opt.algo = algo;
    opt.cull = cull;
    RenderResult r;
    std::string why;
    const bool ok = algo == Algo::zbuffer ? render(scene, opt, r, why) : render_bsp(scene, blob, opt, r, why);
    if (!ok) fail(what + ": " + why);
    return r;
}

/// One view: the z-buffer's depth complexity and both walks' statistics, on the tree hider-bsp makes.
void walk_row(const std::string& label, const std::string& path, const Args& view, bool cull) {
    const CameraArgs cam = camera_from(view);
    ObjModel model;
    ObjError err;
    if (!load_obj(path, model, err)) fail(format(err));
    Scene mesh_scene;
    std::string why;
    if (!build_scene(model, cam, mesh_scene, why)) fail(path + ": " + why);
    std::vector<uint8_t> blob;
    BspStats bs;
    if (!bsp_from_obj(path, BspOptions{}, blob, bs, why)) fail(why);
    const AlignedBlob aligned(blob);
    std::vector<uint32_t> probe(bsp_stack_entries(1u << 16));
    BspTree tree;
    if (bsp_load(aligned.span(), {probe.data(), probe.size()}, tree) != Status::ok) fail(path + ": the built tree does not load");
    Scene tree_scene;
    if (!bsp_scene(tree, cam, tree_scene, why)) fail(path + ": " + why);
    const RenderResult z = render_or_fail(mesh_scene, {}, Algo::zbuffer, cull, label);
    const RenderResult back = render_or_fail(tree_scene, blob, Algo::bsp, cull, label);
    const RenderResult front = render_or_fail(tree_scene, blob, Algo::bsp_front, cull, label);
    auto ratio = [](uint64_t a, uint64_t b) { return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b); };
    std::printf("| %s | %s | %" PRIu64 " / %u = %.2f | %u / %u / %u / %u | %u / %u / %u / %.2f |\n", label.c_str(), cull ? "yes" : "no",
                z.stats.fragments, z.pixels_covered, ratio(z.stats.fragments, z.pixels_covered), back.stats.nodes_visited,
                back.stats.subtrees_skipped, back.stats.triangles_drawn, back.stats.triangles_culled, front.stats.nodes_visited,
                front.stats.subtrees_skipped,
                front.stats.triangles_drawn, ratio(front.stats.pixels_written, front.pixels_covered));
}

}  // namespace

int bsp_command(const Args& args) {
    std::string models = default_models_dir();
    fs::path root = source_root() / "build";
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--models") models = option_value(args, i);
        else if (args[i] == "--build-root") root = fs::absolute(option_value(args, i));  // QEMU runs in a scratch directory
        else fail("bsp: unknown argument '" + args[i] + "'");
    }
    std::vector<std::string> paths;
    for (const std::string& f : model_files(models)) paths.push_back((fs::path(models) / f).string());
    paths.push_back(city_path());

    std::printf("BSP compiler (hider-bsp's code) per model at two heuristic settings: input triangles, polygons after\n"
                "the cuts (split ratio = polygons / input), triangles after closing T-junctions, nodes, depth, the\n"
                "blob's bytes (= flash), build time on this machine (wall clock, one run), and whether its cells are\n"
                "labelled (closed surfaces: the winding numbers; else why not).\n\n");
    std::printf("| model | setting | input | polygons | split ratio | triangles | nodes | depth | flash bytes | build s | cells |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (const std::string& path : paths)
        for (const Setting& s : kSettings) {
            std::vector<uint8_t> blob;
            BspStats st;
            std::string why;
            const auto start = std::chrono::steady_clock::now();
            if (!bsp_from_obj(path, s.opt, blob, st, why)) fail(why);
            const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const std::string cells = st.cells_note.empty()
                                          ? "winding " + std::to_string(st.winding_low) + ".." + std::to_string(st.winding_high)
                                          : st.cells == BspCells::open ? "open surface" : "not labelled: " + st.cells_note;
            std::printf("| %s | %s | %zu | %zu | %.3f | %zu | %zu | %zu | %zu | %.2f | %s |\n", fs::path(path).filename().c_str(), s.name,
                        st.input_triangles, st.polygons,
                        st.input_triangles == 0 ? 0.0 : static_cast<double>(st.polygons) / static_cast<double>(st.input_triangles),
                        st.triangles, st.nodes, st.max_depth, st.bytes, secs, cells.c_str());
            std::fflush(stdout);
        }

    std::printf("\nThe walks on the host, firmware views at 160x128 (default heuristic): the z-buffer's depth complexity\n"
                "(fragments / covered pixels), then nodes visited / subtrees skipped / triangles drawn for bsp (back\n"
                "to front, with the triangles it left out: culled, or hidden by a labelled closed surface) and\n"
                "bsp-front, with bsp-front's overdraw (pixels written / covered).\n\n");
    std::printf("| view | culling | z-buffer depth complexity | bsp nodes / skipped / drawn / left out | bsp-front nodes / skipped / drawn / overdraw |\n");
    std::printf("|---|---|---:|---:|---:|\n");
    walk_row("torus (standard view)", (fs::path(models) / "torus.obj").string(), kTorusView, false);
    walk_row("city-1-16-16 from the street", city_path(), kCityView, true);
    walk_row("city-1-16-16 from the street", city_path(), kCityView, false);

    std::printf("\nfirmware/bsp under QEMU (instructions from bench_begin to bench_end, -Os; the tree loaded once outside):\n"
                "bsp_torus (back to front from one walk's list, 16-row bands, no culling) against painter_plain (same frame), bsp_city\n"
                "(front to back, one band, culled) against bsp_city_zbuffer (the same view's mesh, 16-bit depth).\n\n");
    std::printf("| target | bsp_torus | painter_plain | ratio | bsp_city | bsp_city_zbuffer | ratio |\n|---|---:|---:|---:|---:|---:|---:|\n");
    bool any = false;
    for (const char* preset : {"cm0plus", "cm3", "rv32imac"}) {
        TargetCount t, p, c, z;
        const fs::path tree = root / preset;
        if (!firmware_count(tree, preset, "firmware/bsp/bsp_torus.elf", "big", t) ||
            !firmware_count(tree, preset, "firmware/painter/painter_plain.elf", "big", p) ||
            !firmware_count(tree, preset, "firmware/bsp/bsp_city.elf", "big", c) ||
            !firmware_count(tree, preset, "firmware/bsp/bsp_city_zbuffer.elf", "big", z))
            continue;
        any = true;
        std::printf("| %s | %" PRIu64 " | %" PRIu64 " | %.2f | %" PRIu64 " | %" PRIu64 " | %.2f |\n", preset, t.region, p.region,
                    static_cast<double>(t.region) / static_cast<double>(p.region), c.region, z.region,
                    static_cast<double>(c.region) / static_cast<double>(z.region));
    }
    if (!any) std::printf("(no cross build tree with firmware/bsp under %s)\n", root.c_str());
    return 0;
}

}  // namespace hider::tool::bench

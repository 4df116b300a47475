// hider-bench table: runs `hider-bench frame` under callgrind for each benchmark scene and prints a
// Markdown table of instructions (Ir) per frame. Ir is counted only inside hider_bench_frame, so
// loading, conversion and statistics never count; the numbers repeat exactly from run to run.
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "bench.hpp"

namespace hider::tool::bench {
namespace {

constexpr int kFrames = 2;

struct BenchScene {
    const char* name;
    const char* file;
    Args camera;
    int depth_bits;
};

std::vector<BenchScene> bench_scenes(bool check) {
    std::vector<BenchScene> s = {{"torus 320x240 z16", "torus.obj", torus_view("320x240"), 16}};
    if (check) return s;
    s.push_back({"torus 320x240 z32", "torus.obj", torus_view("320x240"), 32});
    s.push_back({"teapot 320x240 z16", "teapot.obj", {"--size", "320x240"}, 16});
    s.push_back({"bunny 320x240 z16", "stanford-bunny.obj", {"--size", "320x240"}, 16});
    return s;
}

/// "key value" pairs of the statistics line that `frame` prints (the one starting with "triangles").
std::map<std::string, uint64_t> parse_stats(const std::string& out) {
    std::istringstream in(out);
    std::map<std::string, uint64_t> stats;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("triangles ", 0) != 0) continue;
        std::istringstream words(line);
        std::string key, value;
        while (words >> key >> value) {
            long parsed = 0;
            if (!parse_int(value, parsed) || parsed < 0) fail("bad statistics line from frame: " + line);
            stats[key] = static_cast<uint64_t>(parsed);
        }
    }
    for (const char* key : {"triangles", "drawn", "covered", "fragments"})
        if (stats.count(key) == 0) fail(std::string("frame printed no '") + key + "' statistic:\n" + out);
    return stats;
}

std::string ratio(uint64_t num, uint64_t den, int decimals) {
    if (den == 0) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(num) / static_cast<double>(den));
    return buf;
}

/// Ir per frame: exact when the frames divide the total (they do when every frame does the same work).
std::string per_frame(uint64_t total, uint64_t frames) {
    if (total % frames == 0) return std::to_string(total / frames);
    return ratio(total, frames, 1);
}

}  // namespace

Args torus_view(const std::string& size) {
    return {"--size", size,    "--eye", "0,0,-2.5", "--target", "0,0,0",
            "--up",   "0,1,0", "--fov", "73.7398",  "--near",   "0.25"};
}

int table_command(const Args& args) {
    std::string models = default_models_dir(), valgrind;
    bool check = false;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--models") models = option_value(args, i);
        else if (args[i] == "--valgrind") valgrind = option_value(args, i);
        else if (args[i] == "--check") check = true;
        else fail("table: unknown argument '" + args[i] + "'");
    }
    valgrind = find_valgrind(valgrind);
    const std::vector<BenchScene> scenes = bench_scenes(check);
    for (const BenchScene& scene : scenes) {
        const std::string path = models + "/" + scene.file;
        if (!std::ifstream(path)) fail(path + ": cannot open model (set the directory with --models DIR)");
    }

    std::printf("callgrind Ir inside hider_bench_frame (make_view, project_vertices, clear RGB565 + depth,\n"
                "draw_zbuffer<false>, headlight, back faces culled), mean of %d frames; Ir/triangle divides by\n"
                "all mesh triangles; covered px = pixels written at least once.\n\n",
                kFrames);
    std::printf("| scene | triangles | drawn | covered px | Ir/frame | Ir/covered px | Ir/triangle |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    std::fflush(stdout);
    for (const BenchScene& scene : scenes) {
        Args frame_args = {"frame", models + "/" + scene.file};
        frame_args.insert(frame_args.end(), scene.camera.begin(), scene.camera.end());
        frame_args.insert(frame_args.end(), {"--depth-bits", std::to_string(scene.depth_bits), "--frames",
                                             std::to_string(kFrames)});
        const CallgrindRun run = run_callgrind(valgrind, "hider_bench_frame", frame_args);
        const std::map<std::string, uint64_t> st = parse_stats(run.out);
        const uint64_t triangles = st.at("triangles"), drawn = st.at("drawn"), covered = st.at("covered");
        if (check && (drawn == 0 || covered == 0)) fail("check: the torus drew nothing:\n" + run.out);
        const uint64_t ir = run.ir;
        std::printf("| %s | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %s | %s | %s |\n", scene.name, triangles, drawn,
                    covered, per_frame(ir, kFrames).c_str(), ratio(ir, covered * kFrames, 1).c_str(),
                    ratio(ir, triangles * kFrames, 1).c_str());
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace hider::tool::bench

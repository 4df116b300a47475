// hider-bench: deterministic instruction counts of lib/ per frame, per span pixel and per sorted
// polygon, measured with callgrind (Ir = instructions executed) on the host, and on the cross targets
// with QEMU and the insncount plugin (targets). See kUsage; the host-measured code is in measured.cpp.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "bench.hpp"

#ifndef HIDER_BENCH_MODELS_DIR
#define HIDER_BENCH_MODELS_DIR "tests/data/models"
#endif

namespace hider::tool::bench {
namespace {

const char* kUsage =
    "usage: hider-bench frame MODEL.obj [--size WxH] [--eye x,y,z] [--target x,y,z] [--up x,y,z]\n"
    "                         [--fov DEG] [--near N] [--far F] [--depth-bits 16|32] [--frames N]\n"
    "         one frame of lib/ work per call of hider_bench_frame; prints the per-frame statistics\n"
    "       hider-bench table [--models DIR] [--valgrind PATH] [--check]\n"
    "         Markdown table of callgrind Ir per frame for the benchmark scenes (--check: torus row only)\n"
    "       hider-bench span [--valgrind PATH]\n"
    "         callgrind Ir per pixel of the z-buffer span (span_depth_test_paired<false> for 16-bit\n"
    "         depth, span_depth_test<false> for 32-bit) on a 320-pixel row\n"
    "       hider-bench targets [--build-root DIR] [--models DIR]\n"
    "         Markdown table of instructions per frame and per span pixel on cm0plus, cm3 and rv32imac:\n"
    "         firmware of each build tree DIR/<preset> that exists, run in QEMU with the insncount plugin\n"
    "       hider-bench sort [--models DIR] [--size WxH] [--valgrind PATH]\n"
    "         callgrind Ir per polygon of painter_order on 1k..69k polygons of the bunny (no culling)\n"
    "       hider-bench newell [--models DIR] [--valgrind PATH]\n"
    "         Newell statistics and callgrind Ir of newell_order vs painter_order for every model\n"
    "       hider-bench waterfall [--build-root DIR]\n"
    "         Markdown table of instructions per frame and per curve sample of the floating-horizon\n"
    "         waterfall (firmware/waterfall) on cm0plus, cm3 and rv32imac, projection and drawing apart\n"
    "       hider-bench raytrace [--valgrind PATH] [--build-root DIR] [--scene FILE.txt]\n"
    "         instructions per pixel (mean, worst row) of the ray-traced demo scene: host (callgrind) and\n"
    "         firmware/raytrace of each cross build tree under QEMU\n"
    "       hider-bench bsp [--models DIR] [--build-root DIR]\n"
    "         the BSP compiler on every model and the city at two heuristic settings, the walks' statistics,\n"
    "         and firmware/bsp's instruction counts under QEMU for each cross build tree\n"
    "       hider-bench raycast [--models DIR] [--valgrind PATH]\n"
    "         callgrind Ir per ray of mesh ray casting (torus, bunny), BVH against brute force\n"
    "       hider-bench carry [--models DIR]\n"
    "         the torus 320x240's triangles that a band renderer carries, by band height, and those that\n"
    "         reach their middle row in a later band than their first (counted on the host)\n"
    "exit status: 0 ok, 2 error, 77 valgrind (targets: every cross build tree) not found\n";

}  // namespace

[[noreturn]] void fail(const std::string& msg) {
    std::cerr << "hider-bench: " << msg << "\n";
    std::exit(2);
}

const std::string& option_value(const Args& args, size_t& i) {
    if (i + 1 >= args.size()) fail(args[i] + " needs a value\n" + kUsage);
    return args[++i];
}

namespace {

Vec3d parse_vec(const std::string& opt, const std::string& s) {
    Vec3d v{};
    std::string why;
    if (!parse_vec3(opt, s, v, why)) fail(why);
    return v;
}

}  // namespace

std::string default_models_dir() { return HIDER_BENCH_MODELS_DIR; }

std::filesystem::path source_root() {
    const std::filesystem::path models = default_models_dir();
    const std::filesystem::path root = models.parent_path().parent_path().parent_path();  // strip tests/data/models
    return root.empty() ? std::filesystem::path(".") : root;
}

CameraArgs camera_from(const Args& options) {
    CameraArgs cam;
    for (size_t i = 0; i < options.size(); ++i)
        if (!parse_camera_option(options, i, cam)) fail("not a camera option: '" + options[i] + "'");
    return cam;
}

bool parse_camera_option(const Args& args, size_t& i, CameraArgs& cam) {
    const std::string& a = args[i];
    if (a == "--size") {
        const std::string& v = option_value(args, i);
        const size_t x = v.find('x');
        long w = 0, h = 0;
        if (x == std::string::npos || !parse_int(v.substr(0, x), w) || !parse_int(v.substr(x + 1), h))
            fail("--size needs WxH (got '" + v + "')");
        if (w < 1 || h < 1 || w > kMaxFrameSide || h > kMaxFrameSide)
            fail("--size " + v + " out of range (1.." + std::to_string(kMaxFrameSide) + " per side)");
        cam.width = static_cast<int>(w);
        cam.height = static_cast<int>(h);
    } else if (a == "--eye") cam.eye = parse_vec(a, option_value(args, i));
    else if (a == "--target") cam.target = parse_vec(a, option_value(args, i));
    else if (a == "--up") cam.up = parse_vec(a, option_value(args, i));
    else if (a == "--fov") {
        const std::string& v = option_value(args, i);
        if (!parse_double(v, cam.fov_deg)) fail("--fov: bad number '" + v + "'");
    } else if (a == "--near" || a == "--far") {
        const std::string& v = option_value(args, i);
        double d = 0;
        if (!parse_double(v, d)) fail(a + ": bad number '" + v + "'");
        (a == "--near" ? cam.near : cam.far) = d;
    } else {
        return false;
    }
    return true;
}

}  // namespace hider::tool::bench

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-bench");
    using namespace hider::tool::bench;
    if (argc < 2) fail(std::string("no command given\n") + kUsage);
    const std::string command = argv[1];
    const Args args(argv + 2, argv + argc);
    if (command == "frame") return frame_command(args);
    if (command == "table") return table_command(args);
    if (command == "span") return span_command(args);
    if (command == "span-run") return span_run_command(args);
    if (command == "targets") return targets_command(args);
    if (command == "sort") return sort_command(args);
    if (command == "sort-run") return sort_run_command(args);
    if (command == "newell") return newell_command(args);
    if (command == "newell-run") return newell_run_command(args);
    if (command == "waterfall") return waterfall_command(args);
    if (command == "raytrace") return raytrace_command(args);
    if (command == "raytrace-run") return raytrace_run_command(args);
    if (command == "raycast") return raycast_command(args);
    if (command == "raycast-run") return raycast_run_command(args);
    if (command == "bsp") return bsp_command(args);
    if (command == "carry") return carry_command(args);
    if (command == "-h" || command == "--help") {
        std::cout << kUsage;
        return 0;
    }
    fail("unknown command '" + command + "'\n" + kUsage);
}

// hider-bsp: compiles an OBJ model into a BSP tree in the flat format of lib/hider/bsp/format.hpp, as a
// blob (.hbsp) or a C++ header of const data for flash (.hpp, namespace hider::bsp_data::NAME, NAME by
// default the header's file name). Same OBJ reader, fitting and messages as hider-render; errors print
// "file:line: what" or a plain reason and exit 2. Camera options (hider-render's, in model units) add the
// camera mapped into the tree's world to a .hpp (kWidth, kHeight, kCamera), so firmware draws the view
// hider-render shows. Output is deterministic.
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include <hider/bsp/order.hpp>

#include "common/bsp_build.hpp"
#include "host/ppm.hpp"
#include "common/cli.hpp"
#include "common/render_bsp.hpp"
#include "hider-bake/cli.hpp"
#include "hider-bake/emit.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

const char* kUsage =
    "usage: hider-bsp MODEL.obj -o OUT.hbsp|OUT.hpp [--split-weight K] [--balance-weight K] [--candidates N]\n"
    "                 [--max-chain N] [--name NAME] [--stats] [--size WxH] [--eye x,y,z] [--target x,y,z] [--up x,y,z]\n"
    "                 [--fov DEG] [--near N] [--far F]   (camera options: .hpp only)\n";

[[noreturn]] void fail(const std::string& msg) {
    std::cerr << "hider-bsp: " << msg;
    if (msg.empty() || msg.back() != '\n') std::cerr << '\n';
    std::exit(2);
}

int int_option(const std::string& opt, const std::string& v, long lo, long hi) {
    long n = 0;
    if (!parse_int(v, n) || n < lo || n > hi)
        fail(opt + " needs a whole number " + std::to_string(lo) + ".." + std::to_string(hi) + " (got '" + v + "')");
    return static_cast<int>(n);
}

}  // namespace

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-bsp");
    std::string model_path, out_path, name, camera_options, recorded;
    bool named = false;
    BspOptions opt;
    CameraArgs cam;
    bool stats = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (bake::parse_camera_option("hider-bsp", argc, argv, i, cam, camera_options)) continue;
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value\n" + kUsage);
            return argv[++i];
        };
        if (a == "-o") out_path = value();
        else if (a == "--split-weight") opt.split_weight = int_option(a, value(), 0, 1000000);
        else if (a == "--balance-weight") opt.balance_weight = int_option(a, value(), 0, 1000000);
        else if (a == "--candidates") opt.candidates = int_option(a, value(), 1, 100000);
        else if (a == "--max-chain") opt.max_chain = int_option(a, value(), 0, 100000000);
        else if (a == "--name") { name = value(); named = true; }
        else if (a == "--stats") stats = true;
        else if (a == "-h" || a == "--help") { std::cout << kUsage; return 0; }
        else if (!a.empty() && a[0] == '-') fail("unknown option '" + a + "'\n" + kUsage);
        else if (model_path.empty()) model_path = a;
        else fail("more than one model given ('" + model_path + "', '" + a + "')");
    }
    if (model_path.empty()) fail(std::string("no model given\n") + kUsage);
    if (out_path.empty()) fail(std::string("no output given (-o OUT.hbsp)\n") + kUsage);
    if (same_file(model_path, out_path)) fail("output '" + out_path + "' is the model itself: give another -o");
    const bool header = has_extension(out_path, ".hpp");  // in any case, as the other tools
    if (!header && !has_extension(out_path, ".hbsp")) fail("output '" + out_path + "': use .hbsp (a blob) or .hpp (a C++ header)");
    std::string why;
    if (named) {
        if (!bake::valid_name(name, why)) fail("--name '" + name + "' " + why);
    } else if (header) {  // the header's file name: headers of different names never share a namespace
        name = std::filesystem::path(out_path).stem().string();
        if (!bake::valid_name(name, why))
            fail("output '" + out_path + "': its file name '" + name + "' " + why +
                 ", and it names the header's namespace: give --name NAME");
    }
    if (!camera_options.empty() && !header) fail("camera options need a .hpp output (a blob holds no camera)");

    const auto start = std::chrono::steady_clock::now();
    std::vector<uint8_t> blob;
    BspStats st;
    if (!bsp_from_obj(model_path, opt, blob, st, why)) fail(why);
    for (const std::string& w : fan_warnings(model_path, st.badly_fanned)) std::cerr << "hider-bsp: warning: " << w << "\n";
    for (const std::string& w : collapse_warnings(model_path, st.collapsed)) std::cerr << "hider-bsp: warning: " << w << "\n";
    if (st.triangles == 0)
        fail(model_path + ": no face with an area (" + std::to_string(st.degenerate) + " of " +
             std::to_string(st.input_triangles) + " triangles degenerate on the grid): the tree would be empty");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Everything is checked before the output is opened: a failure leaves an existing file as it was.
    const AlignedBlob aligned(blob);
    if (st.max_depth > kToolMaxBspDepth)
        fail(model_path + ": the tree is " + std::to_string(st.max_depth) + " levels deep, more than the " +
             std::to_string(kToolMaxBspDepth) + " hider-bsp and hider-render walk: build it with --max-chain (e.g. 256)");
    std::vector<uint32_t> stack(bsp_stack_entries(kToolMaxBspDepth));
    BspTree tree;
    const Status loaded = bsp_load(aligned.span(), {stack.data(), stack.size()}, tree);
    if (loaded != Status::ok) fail(model_path + ": internal: the built tree does not load (" + status_name(loaded) + ")");
    std::string contents;
    if (header) {
        std::string extra;
        if (!camera_options.empty()) {  // the camera in the tree's world, exactly as hider-render maps it
            Scene scene;
            if (!bsp_scene(tree, cam, scene, why)) fail(model_path + ": " + why);
            extra = bake::camera_source(scene.camera, scene.width, scene.height);
        }
        contents = bsp_header_source(blob, name, bake::comment_text(std::filesystem::path(model_path).filename().string()), camera_options, extra);
    } else {
        contents.assign(reinterpret_cast<const char*>(blob.data()), blob.size());
    }
    if (!port::write_file(out_path, contents, why)) fail(why);
    // Real models split into at most about twice their triangles (2.05 on the shipped ones); far more
    // means planes that cut each other everywhere, and a tree (and a walk) many times the model's size.
    const size_t kept = st.input_triangles - st.degenerate;
    if (kept != 0 && st.polygons > 8 * kept) {
        std::ostringstream w;
        w << "hider-bsp: warning: " << model_path << ": the tree holds " << st.triangles << " triangles for " << kept
          << " in the model (split ratio " << std::fixed << std::setprecision(1)
          << static_cast<double>(st.polygons) / static_cast<double>(kept) << ", " << blob.size()
          << " bytes): its faces' planes cut each other many times\n";
        std::cerr << w.str();
    }
    if (stats) {
        std::printf("input triangles %zu (degenerate %zu) polygons %zu cuts %zu split-ratio %.3f\n", st.input_triangles,
                    st.degenerate, st.polygons, st.cuts,
                    st.input_triangles == st.degenerate ? 0.0 : static_cast<double>(st.polygons) / (st.input_triangles - st.degenerate));
        std::printf("triangles %zu t-junction-points %zu vertices %zu nodes %zu depth %zu largest-node %zu axis-splits %zu\n",
                    st.triangles, st.tjunction_points, st.vertices, st.nodes, st.max_depth, st.largest_node, st.splitters);
        std::printf("bytes %zu (nodes %zu, triangles %zu, vertices %zu) build %.2f s\n", st.bytes, st.nodes * sizeof(BspNode),
                    st.triangles * sizeof(BspTriangle), st.vertices * sizeof(BspVertex), seconds);
        // What a chip walking the tree needs in RAM besides the frame: one ScreenVertex per vertex and the walk stack.
        const size_t stack_entries = bsp_stack_entries(static_cast<uint32_t>(st.max_depth));
        std::printf("walk RAM %zu bytes (vertices %zu x %zu B, stack %zu x 4 B); order_bsp's list: up to %zu x %zu B more\n",
                    st.vertices * sizeof(ScreenVertex) + stack_entries * sizeof(uint32_t), st.vertices, sizeof(ScreenVertex),
                    stack_entries, st.nodes, sizeof(BspDrawEntry));
        if (st.cells_note.empty())
            std::printf("cells labelled %zu (winding numbers %d..%d, triangles stray up to %.1f raw units): only the faces\n"
                        "seen from the eye's cell are drawn\n",
                        st.cells_labelled, st.winding_low, st.winding_high, st.cells_stray_raw);
        else
            std::printf("cells not labelled: %s\n", st.cells_note.c_str());
    }
    return 0;
}

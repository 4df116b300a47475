// hider-bake: fits an OBJ model and camera exactly as hider-render does (build_scene) and writes them
// as a C++ header of constexpr arrays for firmware, so a device renders the very scene hider-render
// renders. Usage: kUsage below and README.md. Errors print "hider-bake: what" and exit 2.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "common/cli.hpp"
#include "common/obj.hpp"
#include "host/ppm.hpp"
#include "common/scene.hpp"
#include "hider-bake/cli.hpp"
#include "hider-bake/emit.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

const char* kProgram = "hider-bake";
const char* kUsage =
    "usage: hider-bake MODEL.obj -o OUT.hpp --name NAME [--size WxH] [--eye x,y,z] [--target x,y,z]\n"
    "                  [--up x,y,z] [--fov DEG] [--near N] [--far F]\n"
    "  writes namespace hider::scenes::NAME { kWidth, kHeight, kCamera, kPositions, kTris, kNormals, mesh() };\n"
    "  camera options and defaults as hider-render's. Exit status: 0 ok, 2 error.\n";

[[noreturn]] void fail(const std::string& msg) { bake::fail(kProgram, msg); }

std::string base_name(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-bake");
    std::string model_path, out_path;
    bake::BakeInfo info;
    CameraArgs cam;
    for (int i = 1; i < argc; ++i) {
        if (bake::parse_camera_option(kProgram, argc, argv, i, cam, info.options)) continue;
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value\n" + kUsage);
            return argv[++i];
        };
        if (a == "-o") out_path = value();
        else if (a == "--name") info.name = value();
        else if (a == "-h" || a == "--help") {
            std::cout << kUsage;
            return 0;
        } else if (!a.empty() && a[0] == '-') fail("unknown option '" + a + "'\n" + kUsage);
        else if (model_path.empty()) model_path = a;
        else fail("more than one model given ('" + model_path + "', '" + a + "')");
    }
    if (model_path.empty()) fail(std::string("no model given\n") + kUsage);
    if (out_path.empty()) fail(std::string("no output given (-o OUT.hpp)\n") + kUsage);
    if (same_file(model_path, out_path)) fail("output '" + out_path + "' is the model itself: give another -o");
    if (info.name.empty()) fail(std::string("no scene name given (--name NAME)\n") + kUsage);
    std::string why;
    if (!bake::valid_name(info.name, why)) fail("--name '" + info.name + "' " + why);

    ObjModel model;
    ObjError err;
    if (!load_obj(model_path, model, err)) fail(format(err));
    for (const std::string& w : fan_warnings(model_path, badly_fanned_faces(model))) std::cerr << "hider-bake: warning: " << w << "\n";
    Scene scene;
    if (!build_scene(model, cam, scene, why)) fail(model_path + ": " + why);
    for (const std::string& w : collapse_warnings(model_path, collapsed_faces(model, scene))) std::cerr << "hider-bake: warning: " << w << "\n";
    if (!any_triangle_with_area(scene))
        std::cerr << "hider-bake: warning: " << model_path << ": no face has an area: the scene draws only the background\n";
    const Status ms = validate(scene.mesh());
    if (ms != Status::ok) fail(model_path + ": mesh rejected: " + status_name(ms));

    info.model = bake::comment_text(base_name(model_path));
    const std::string text = bake::emit_header(scene, info);
    if (!port::write_file(out_path, text, why)) fail(why);
    return 0;
}

// Round trip of the committed baked scenes: compiles firmware/common/scenes/<name>.hpp, rebuilds the
// scene from the OBJ with build_scene and the same options, and checks that lib/ sees identical data
// (frame size, camera, every position, triangle, normal and id) and that validate() accepts it.
// Usage: hider-bake-roundtrip NAME MODEL.obj [camera options]; exit 0 equal, 1 different, 2 error.
#include <iostream>
#include <string>

#include "common/obj.hpp"
#include "common/scene.hpp"
#include "common/scenes/city_street_160x128.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "common/scenes/teapot_320x240.hpp"
#include "common/scenes/torus_320x240.hpp"
#include "hider-bake/cli.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

const char* kProgram = "hider-bake-roundtrip";

struct Baked {
    const char* name;
    int32_t width, height;
    Camera camera;
    Mesh mesh;
};

// Every committed scene, so each can be checked against its source (extend with new scenes).
const Baked kBaked[] = {
    {"torus_160x128", scenes::torus_160x128::kWidth, scenes::torus_160x128::kHeight,
     scenes::torus_160x128::kCamera, scenes::torus_160x128::mesh()},
    {"torus_320x240", scenes::torus_320x240::kWidth, scenes::torus_320x240::kHeight,
     scenes::torus_320x240::kCamera, scenes::torus_320x240::mesh()},
    {"city_street_160x128", scenes::city_street_160x128::kWidth, scenes::city_street_160x128::kHeight,
     scenes::city_street_160x128::kCamera, scenes::city_street_160x128::mesh()},
    {"teapot_320x240", scenes::teapot_320x240::kWidth, scenes::teapot_320x240::kHeight,
     scenes::teapot_320x240::kCamera, scenes::teapot_320x240::mesh()},
};

bool same(const Vec3q16& a, const Vec3q16& b) { return a == b; }
bool same(const Tri& a, const Tri& b) { return a.v[0] == b.v[0] && a.v[1] == b.v[1] && a.v[2] == b.v[2]; }
bool same(const Normal14& a, const Normal14& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

int differences = 0;

void expect(bool ok, const std::string& what) {
    if (!ok) {
        std::cerr << kProgram << ": " << what << " differs\n";
        ++differences;
    }
}

template <class T>
void compare_array(const char* what, Span<const T> baked, const std::vector<T>& source) {
    expect(baked.size() == source.size(), std::string(what) + " count");
    for (size_t i = 0; i < baked.size() && i < source.size(); ++i)
        if (!same(baked[i], source[i])) {
            expect(false, std::string(what) + "[" + std::to_string(i) + "]");
            return;
        }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) bake::fail(kProgram, "usage: hider-bake-roundtrip NAME MODEL.obj [camera options]");
    const std::string name = argv[1], model_path = argv[2];
    CameraArgs cam;
    std::string recorded;
    for (int i = 3; i < argc; ++i)
        if (!bake::parse_camera_option(kProgram, argc, argv, i, cam, recorded))
            bake::fail(kProgram, std::string("unknown option '") + argv[i] + "'");
    const Baked* baked = nullptr;
    for (const Baked& b : kBaked)
        if (name == b.name) baked = &b;
    if (baked == nullptr) bake::fail(kProgram, "no compiled-in baked scene '" + name + "' (add it to kBaked)");

    ObjModel model;
    ObjError err;
    if (!load_obj(model_path, model, err)) bake::fail(kProgram, format(err));
    Scene scene;
    std::string why;
    if (!build_scene(model, cam, scene, why)) bake::fail(kProgram, model_path + ": " + why);

    expect(validate(baked->mesh) == Status::ok, "validate() of the baked mesh");
    expect(baked->width == scene.width && baked->height == scene.height, "frame size");
    const Camera& a = baked->camera;
    const Camera& b = scene.camera;
    expect(a.eye == b.eye && a.target == b.target && a.up == b.up, "camera eye/target/up");
    expect(a.fovy == b.fovy && a.near == b.near && a.far == b.far, "camera fovy/near/far");
    compare_array("positions", baked->mesh.positions, scene.positions);
    compare_array("triangles", baked->mesh.tris, scene.tris);
    compare_array("normals", baked->mesh.normals, scene.normals);
    for (size_t t = 0; t < scene.ids.size(); ++t)
        if (baked->mesh.id(t) != scene.ids[t]) {
            expect(false, "id of triangle " + std::to_string(t));
            break;
        }
    if (differences != 0) return 1;
    std::cout << name << ": baked header matches build_scene (" << scene.positions.size() << " vertices, "
              << scene.tris.size() << " triangles)\n";
    return 0;
}

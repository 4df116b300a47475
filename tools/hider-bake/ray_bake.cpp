// hider-bake-ray: reads a ray-tracing scene file exactly as hider-render --scene does (load_ray_scene)
// and writes it as a C++17 header of constexpr lib/ data for firmware: camera, frame size, surfaces,
// spheres, planes, lights, and each mesh with its baked BVH; scene() lends them as a ray::Scene.
// Usage: hider-bake-ray SCENE.txt -o OUT.hpp --name NAME. Errors print "hider-bake-ray: what", exit 2.
#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "common/cli.hpp"
#include "common/ray_scene.hpp"
#include "host/ppm.hpp"
#include "hider-bake/cli.hpp"
#include "hider-bake/emit.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

const char* kProgram = "hider-bake-ray";
const char* kUsage =
    "usage: hider-bake-ray SCENE.txt -o OUT.hpp --name NAME\n"
    "  writes namespace hider::scenes::NAME { kWidth, kHeight, kCamera, kStackDepth, scene() } for firmware.\n";

[[noreturn]] void fail(const std::string& msg) { bake::fail(kProgram, msg); }

std::string q(int32_t raw, const char* type) { return std::string(type) + "::from_raw(" + std::to_string(raw) + ")"; }
std::string v16(const Vec3q16& v) { return "{" + q(v.x.raw(), "Q16") + ", " + q(v.y.raw(), "Q16") + ", " + q(v.z.raw(), "Q16") + "}"; }
std::string v30(const Vec3q30& v) { return "{" + q(v.x.raw(), "Q30") + ", " + q(v.y.raw(), "Q30") + ", " + q(v.z.raw(), "Q30") + "}"; }
std::string rgb(Rgb c) { return "{" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + "}"; }

/// "inline constexpr T NAME[] = {...};" with one item per line, or nothing for an empty list.
template <class T, class Fn>
void array(std::ostringstream& o, const char* type, const std::string& name, const std::vector<T>& items, Fn&& item) {
    if (items.empty()) return;
    o << "inline constexpr " << type << " " << name << "[] = {\n";
    for (const T& t : items) o << "    " << item(t) << ",\n";
    o << "};\n";
}

std::string span_of(const std::string& name, bool empty) { return empty ? "{}" : "{" + name + "}"; }

void emit_mesh(std::ostringstream& o, const RayScene::MeshData& m, size_t i) {
    const std::string p = "kMesh" + std::to_string(i);
    array(o, "Vec3q16", p + "Positions", m.positions, [](const Vec3q16& v) { return v16(v); });
    array(o, "Tri", p + "Tris", m.tris, [](const Tri& t) {
        return "{{" + std::to_string(t.v[0]) + ", " + std::to_string(t.v[1]) + ", " + std::to_string(t.v[2]) + "}}";
    });
    array(o, "Normal14", p + "Normals", m.normals, [](const Normal14& n) {
        return "{" + std::to_string(n.x) + ", " + std::to_string(n.y) + ", " + std::to_string(n.z) + "}";
    });
    array(o, "uint16_t", p + "Surfaces", m.surfaces, [](uint16_t s) { return std::to_string(s); });
    array(o, "ray::BvhNode", p + "Nodes", m.bvh.nodes, [](const ray::BvhNode& n) {
        std::string s = "{{";
        for (int k = 0; k < 3; ++k) s += std::to_string(n.lo[k]) + (k < 2 ? ", " : "}, {");
        for (int k = 0; k < 3; ++k) s += std::to_string(n.hi[k]) + (k < 2 ? ", " : "}, ");
        return s + std::to_string(n.first) + "u, " + std::to_string(n.count) + "u}";
    });
    array(o, "uint32_t", p + "BvhTriangles", m.bvh.triangles, [](uint32_t t) { return std::to_string(t) + "u"; });
    const ray::BvhHeader& h = m.bvh.header;
    char magic[16];
    std::snprintf(magic, sizeof magic, "0x%08Xu", static_cast<unsigned>(h.magic));
    o << "inline constexpr ray::BvhHeader " << p << "Header{" << magic << ", " << h.version << ", " << h.max_depth << ", "
      << h.node_count << "u, " << h.triangle_count << "u};\n\n";
}

std::string emit(const RayScene& s, const std::string& name, const std::string& source) {
    std::ostringstream o;
    o << "// " << name << ": baked by hider-bake-ray from " << source << "; do not edit, re-bake instead.\n"
      << "// " << s.spheres.size() << " spheres, " << s.planes.size() << " planes, " << s.meshes.size() << " meshes, "
      << s.lights.size() << " lights; values are raw Q16 (positions) and Q30 (unit vectors).\n"
      << "#pragma once\n#include <hider/ray/scene.hpp>\n#include <hider/view.hpp>\n\n"
      << "namespace hider::scenes::" << name << " {\n\n"
      << "inline constexpr int32_t kWidth = " << s.width << ";\n"
      << "inline constexpr int32_t kHeight = " << s.height << ";\n"
      << "/// BVH stack entries the scene's meshes need (validate_scene()).\n"
      << "inline constexpr size_t kStackDepth = " << s.stack_depth() << ";\n"
      << "/// Spheres in the scene (at least 1, for array sizes).\n"
      << "inline constexpr size_t kSphereCount = " << std::max<size_t>(1, s.spheres.size()) << ";\n\n";
    char fov[16];
    std::snprintf(fov, sizeof fov, "0x%08Xu", static_cast<unsigned>(s.camera.fovy.bam()));
    o << "/// gluLookAt + gluPerspective camera (make_primary_rays()).\n"
      << "inline constexpr Camera kCamera{" << v16(s.camera.eye) << ", " << v16(s.camera.target) << ", " << v16(s.camera.up)
      << ", Angle::from_bam(" << fov << "), " << q(s.camera.near.raw(), "Q16") << ", " << q(s.camera.far.raw(), "Q16") << "};\n\n";
    array(o, "ray::Surface", "kSurfaces", s.surfaces, [](const ray::Surface& f) {
        return "{" + rgb(f.color) + ", " + rgb(f.checker_color) + ", " + q(f.checker_size.raw(), "Q16") + ", " +
               std::to_string(f.reflect_q15) + "}";
    });
    array(o, "ray::Sphere", "kSpheres", s.spheres, [](const ray::Sphere& sp) {
        return "{" + v16(sp.centre) + ", " + q(sp.radius.raw(), "Q16") + ", " + std::to_string(sp.surface) + "}";
    });
    array(o, "ray::Plane", "kPlanes", s.planes, [](const ray::Plane& pl) {
        return "{" + v30(pl.normal) + ", " + q(pl.offset.raw(), "Q16") + ", " + std::to_string(pl.surface) + "}";
    });
    array(o, "ray::Light", "kLights", s.lights, [](const ray::Light& l) {
        return std::string("{ray::LightKind::") + (l.kind == ray::LightKind::point ? "point" : "directional") + ", " +
               v16(l.position) + ", " + v30(l.direction) + ", " + rgb(l.color) + "}";
    });
    o << "\n";
    for (size_t i = 0; i < s.meshes.size(); ++i) emit_mesh(o, s.meshes[i], i);
    std::vector<size_t> mesh_index(s.meshes.size());
    for (size_t i = 0; i < mesh_index.size(); ++i) mesh_index[i] = i;
    array(o, "ray::MeshObject", "kMeshes", mesh_index, [&](size_t i) {
        const RayScene::MeshData& m = s.meshes[i];
        const std::string p = "kMesh" + std::to_string(i);
        return "{{{" + p + "Positions}, {" + p + "Tris}, " + span_of(p + "Normals", m.normals.empty()) + ", {}}, {" + p +
               "Header, {" + p + "Nodes}, {" + p + "BvhTriangles}}, " + std::to_string(m.surface) + ", " +
               span_of(p + "Surfaces", m.surfaces.empty()) + "}";
    });
    o << "\n/// The scene for lib/ (validate_scene() once, with a stack of kStackDepth entries).\n"
      << "constexpr ray::Scene scene() {\n    ray::Scene s;\n";
    auto field = [&](const char* member, const char* array_name, bool empty) {
        if (!empty) o << "    s." << member << " = {" << array_name << "};\n";
    };
    field("spheres", "kSpheres", s.spheres.empty());
    field("planes", "kPlanes", s.planes.empty());
    field("meshes", "kMeshes", s.meshes.empty());
    field("lights", "kLights", s.lights.empty());
    field("surfaces", "kSurfaces", s.surfaces.empty());
    o << "    s.ambient = " << rgb(s.ambient) << ";\n    s.background = " << rgb(s.background) << ";\n"
      << "    s.max_bounces = " << int(s.bounces) << ";\n    s.max_distance = " << q(s.max_distance.raw(), "Q16") << ";\n"
      << "    s.sphere_bound = {" << v16(s.sphere_bound.centre) << ", " << q(s.sphere_bound.radius.raw(), "Q16") << ", 0};\n"
      << "    return s;\n}\n\n}  // namespace hider::scenes::" << name << "\n";
    return o.str();
}

}  // namespace

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-bake-ray");
    std::string scene_path, out_path, name;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value\n" + kUsage);
            return argv[++i];
        };
        if (a == "-o") out_path = value();
        else if (a == "--name") name = value();
        else if (a == "-h" || a == "--help") { std::cout << kUsage; return 0; }
        else if (!a.empty() && a[0] == '-') fail("unknown option '" + a + "'\n" + kUsage);
        else if (scene_path.empty()) scene_path = a;
        else fail("more than one scene given ('" + scene_path + "', '" + a + "')");
    }
    if (scene_path.empty()) fail(std::string("no scene given\n") + kUsage);
    if (out_path.empty()) fail(std::string("no output given (-o OUT.hpp)\n") + kUsage);
    if (same_file(scene_path, out_path)) fail("output '" + out_path + "' is the scene itself: give another -o");
    if (name.empty()) fail(std::string("no scene name given (--name NAME)\n") + kUsage);
    std::string why;
    if (!bake::valid_name(name, why)) fail("--name '" + name + "' " + why);
    RayScene scene;
    if (!load_ray_scene(scene_path, scene, why)) fail(why);
    // The same approximation warnings as hider-render --scene: the baked scene draws what it draws.
    for (const std::string& w : grid_warnings(scene)) std::cerr << kProgram << ": warning: " << scene_path << ": " << w << "\n";
    const size_t slash = scene_path.find_last_of('/');
    const std::string text = emit(scene, name, bake::comment_text(slash == std::string::npos ? scene_path : scene_path.substr(slash + 1)));
    if (!port::write_file(out_path, text, why)) fail(why);
    return 0;
}

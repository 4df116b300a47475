// Ray-tracing scenes for hider-render --scene: a small line-based text format (README.md, "Ray-traced
// scenes") read into lib/'s fixed-point ray::Scene once, with every value range-checked. Errors name the
// file and line: "scene.txt:12: sphere: radius must be > 0 (got -1)".
#pragma once
#include <hider/ray/trace.hpp>

#include <istream>
#include <string>
#include <vector>

#include "common/bvh_build.hpp"

namespace hider::tool {

/// A parsed scene: host-owned arrays; view() lends them to lib/ (valid while this object lives).
struct RayScene {
    struct MeshData {
        std::vector<Vec3q16> positions;
        std::vector<Tri> tris;
        std::vector<Normal14> normals;
        std::vector<uint16_t> surfaces;  ///< per triangle (loose triangles), or empty
        BakedBvh bvh;
        uint16_t surface = 0;
    };
    std::vector<ray::Sphere> spheres;
    std::vector<ray::Plane> planes;
    std::vector<ray::Light> lights;
    std::vector<ray::Surface> surfaces;
    std::vector<MeshData> meshes;
    Camera camera{};
    int width = 320, height = 240;  ///< from `size`, else 320x240
    Rgb ambient{0, 0, 0};
    Rgb background{0, 0, 0};
    uint8_t bounces = 0;
    Q16 max_distance = Q16::max();
    ray::Sphere sphere_bound{};  ///< ray::enclosing_sphere() of the spheres

    /// The scene for lib/ (spans into this object's arrays).
    ray::Scene view() const;
    /// Stack entries the deepest BVH needs (at least 1).
    size_t stack_depth() const;

private:
    mutable std::vector<ray::MeshObject> objects_;
};

/// Most reflections a scene file may ask for (`bounces`).
constexpr int kMaxSceneBounces = 16;

/// Reads the scene file at `path`; OBJ meshes are found relative to its directory. On failure returns
/// false with `error` = "file:line: what" (or "file: what").
bool load_ray_scene(const std::string& path, RayScene& out, std::string& error);

/// Reads scene text from `in` (named `name` in errors; meshes relative to `base_dir`).
bool parse_ray_scene(std::istream& in, const std::string& name, const std::string& base_dir, RayScene& out,
                     std::string& error);

/// Warnings for meshes whose triangles collapse or turn over on the vertex grid the triangle test uses for
/// rays from the camera's eye (coarser than 1 raw once a mesh's box reaches 16 units from the eye): such
/// triangles may leave holes. One line per such mesh, empty when none.
std::vector<std::string> grid_warnings(const RayScene& s);

}  // namespace hider::tool

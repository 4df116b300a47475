// Host boundary between doubles and lib/: fits an OBJ model and its camera into the fixed-point world
// (by the bounding box of the model, eye and target, so units do not matter) and builds lib/ arrays.
#pragma once
#include <hider/mesh.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/obj.hpp"

namespace hider::tool {

using Vec3d = std::array<double, 3>;

/// Camera as the user gives it, in model units; unset values get framing defaults.
struct CameraArgs {
    std::optional<Vec3d> eye, target, up;
    double fov_deg = 60.0;  ///< vertical
    std::optional<double> near, far;
    int width = 320, height = 240;
    /// World = (model - fit_centre) * fit_scale instead of fitting model + eye + target into the world
    /// cube (a BSP's world is fixed when it is built, before any camera).
    std::optional<Vec3d> fit_centre;
    std::optional<double> fit_scale;
};

/// Half the side of the cube the scene's bounding box is scaled into, in world units.
constexpr double kFitHalfExtent = 512.0;

/// A model and camera in lib/ form (fixed point), plus how model units map to world units.
struct Scene {
    std::vector<Vec3q16> positions;
    std::vector<Tri> tris;
    std::vector<Normal14> normals;
    std::vector<uint32_t> ids;
    Camera camera{};
    int width = 320, height = 240;
    Vec3d centre{};     ///< world = (model - centre) * scale
    double scale = 1.0;

    Mesh mesh() const {
        return {{positions.data(), positions.size()}, {tris.data(), tris.size()}, {normals.data(), normals.size()},
                {ids.data(), ids.size()}};
    }
};

/// Converts a loaded OBJ model and camera arguments to a Scene. On failure returns false and sets
/// `error` to a plain reason (the caller prefixes the file name). `max_vertices`: a Mesh's limit by
/// default; a BSP tree's vertices (32-bit indices, drawn without a Mesh) pass their own.
bool build_scene(const ObjModel& model, const CameraArgs& args, Scene& out, std::string& error,
                 size_t max_vertices = kMaxMeshVertices);

/// `f` lines of faces that have an area in the model but whose every fan triangle has none on the
/// scene's Q16 grid (build_scene() of that model): they draw nothing. A model fitted into +-512 world
/// units keeps detail down to about its extent / 2^26; finer faces collapse.
std::vector<int> collapsed_faces(const ObjModel& model, const Scene& scene);

/// False when no triangle of the scene has an area on its grid (a model of faces on lines or points, in
/// the model or after collapsed_faces()): every algorithm draws only the background.
bool any_triangle_with_area(const Scene& scene);

/// True when triangle (a, b, c) of grid points inside the world cube (|raw| < 2^29: edges below 2^30,
/// cross_raw()'s range) has an area: its exact cross product is not zero.
bool area_on_grid(const Vec3q16& a, const Vec3q16& b, const Vec3q16& c);

/// Warnings for collapsed_faces(): the first five by line, then how many more.
std::vector<std::string> collapse_warnings(const std::string& path, const std::vector<int>& lines);

/// Exact double value of a Q16 world coordinate (for references that must see hider's own scene).
inline double to_double(Q16 v) { return v.raw() / 65536.0; }

}  // namespace hider::tool

// A ray-traced scene as lib/ reads it: spheres, planes and meshes (each with its BVH) referring to
// surfaces (colour, checker, reflectivity), point and directional lights, ambient and background
// colours, the bounce depth and the longest ray. All arrays are borrowed (const data in flash on a
// device); validate_scene() checks them once against the ranges in CONVENTIONS.md ("Ray tracing").
#pragma once
#include <hider/frame.hpp>
#include <hider/ray/bvh.hpp>
#include <hider/ray/shapes.hpp>

namespace hider::ray {

/// 1.0 of a reflectivity.
constexpr uint16_t kReflectOne = uint16_t{1} << 15;

/// How a surface looks: a colour or a checker of two, and how much it mirrors.
struct Surface {
    Rgb color{255, 255, 255};
    Rgb checker_color{0, 0, 0};  ///< the odd squares of the checker
    Q16 checker_size{};          ///< side of a checker square; 0 = plain colour
    uint16_t reflect_q15 = 0;    ///< reflectivity in [0, kReflectOne]
};

enum class LightKind : uint8_t { point, directional };

struct Light {
    LightKind kind = LightKind::point;
    Vec3q16 position{};   ///< point light: where it is (inside the world cube)
    Vec3q30 direction{};  ///< directional light: unit vector toward the light
    Rgb color{255, 255, 255};
};

/// A triangle mesh in world coordinates with its hierarchy (validated together).
struct MeshObject {
    Mesh mesh;
    Bvh bvh;
    uint16_t surface = 0;                 ///< surface of every triangle, unless per-triangle ones are given
    Span<const uint16_t> triangle_surfaces;  ///< empty, or one surface index per triangle
};

struct Scene {
    Span<const Sphere> spheres;
    Span<const Plane> planes;
    Span<const MeshObject> meshes;
    Span<const Light> lights;
    Span<const Surface> surfaces;
    Rgb ambient{0, 0, 0};         ///< light reaching every surface (unshadowed)
    Rgb background{0, 0, 0};      ///< colour of a ray that meets nothing
    uint8_t max_bounces = 0;      ///< reflections followed (0: none)
    Q16 max_distance = Q16::max();  ///< a primary or mirror ray meets nothing farther (shadow rays: to the light)
    /// A sphere holding every sphere (radius 0: none): a ray that misses it skips all sphere tests.
    /// enclosing_sphere() makes one; validate_scene() checks that it holds them all.
    Sphere sphere_bound{};
};

/// A sphere holding all of `spheres` (radius 0 for none): centred on their bounding box, radius rounded
/// up. Precondition: the spheres lie in the world cube. Cost: one square root per sphere.
constexpr Sphere enclosing_sphere(Span<const Sphere> spheres) {
    if (spheres.empty()) return {};
    int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
    for (const Sphere& s : spheres) {
        const int32_t c[3] = {s.centre.x.raw(), s.centre.y.raw(), s.centre.z.raw()};
        for (int i = 0; i < 3; ++i) {
            lo[i] = min(lo[i], c[i] - s.radius.raw());
            hi[i] = max(hi[i], c[i] + s.radius.raw());
        }
    }
    const Vec3q16 centre{Q16::from_raw(lo[0] + (hi[0] - lo[0]) / 2), Q16::from_raw(lo[1] + (hi[1] - lo[1]) / 2),
                         Q16::from_raw(lo[2] + (hi[2] - lo[2]) / 2)};
    int64_t radius = 0;
    for (const Sphere& s : spheres) {
        const Vec3q16 d = s.centre - centre;
        const uint64_t d2 = static_cast<uint64_t>(mul_wide(d.x.raw(), d.x.raw())) + static_cast<uint64_t>(mul_wide(d.y.raw(), d.y.raw())) +
                            static_cast<uint64_t>(mul_wide(d.z.raw(), d.z.raw()));
        const uint64_t root = isqrt64(d2);
        radius = max(radius, static_cast<int64_t>(root + (root * root < d2 ? 1 : 0)) + s.radius.raw());
    }
    return {centre, Q16::from_raw(static_cast<int32_t>(min<int64_t>(radius, INT32_MAX))), 0};
}

/// Most spheres, planes, meshes, lights or surfaces a scene may have (16-bit object indices).
constexpr size_t kMaxSceneObjects = 65535;
/// A plane's |offset| must stay below this (2^14 units: beyond, it cannot cross the world cube).
constexpr int32_t kMaxPlaneOffsetRaw = int32_t{1} << 30;
/// A unit vector's squared length may differ from 1 by at most this, in Q60 (2^-20).
constexpr int64_t kUnitTolerance = int64_t{1} << 40;
/// A mesh normal's (Normal14, Q14) squared length may differ from 1 by at most this, in Q28 (2^-10:
/// face_normal()'s rounding stays below 2^-13).
constexpr int64_t kNormal14Tolerance = int64_t{1} << 18;

namespace detail {
constexpr bool is_unit(const Vec3q30& v) { return abs_value(dot_q60(v, v) - (int64_t{1} << 60)) <= kUnitTolerance; }

inline Status validate_meshes(const Scene& s, Span<BvhStackEntry> stack) {
    for (const MeshObject& m : s.meshes) {
        if (m.surface >= s.surfaces.size()) return Status::bad_data;
        if (!m.mesh.normals.empty() && m.mesh.normals.size() != m.mesh.tris.size()) return Status::bad_data;
        for (const Normal14& n : m.mesh.normals) {  // unit, or zero (face_normal() of a degenerate face)
            const int64_t len2 = int64_t{n.x} * n.x + int64_t{n.y} * n.y + int64_t{n.z} * n.z;
            if (len2 != 0 && abs_value(len2 - (int64_t{1} << 28)) > kNormal14Tolerance) return Status::invalid_argument;
        }
        if (!m.triangle_surfaces.empty()) {
            if (m.triangle_surfaces.size() != m.mesh.tris.size()) return Status::bad_data;
            for (uint16_t i : m.triangle_surfaces)
                if (i >= s.surfaces.size()) return Status::bad_data;
        }
        const Status st = validate_bvh(m.bvh, m.mesh, stack);
        if (st != Status::ok) return st;
    }
    return Status::ok;
}
}  // namespace detail

/// Checks a scene once. invalid_argument: a reflectivity above 1, a negative checker size, a radius
/// <= 0, a plane normal or light direction that is not unit length (within 2^-20), a mesh normal neither
/// zero nor unit (within 2^-10: the tracer negates and reflects about it), max_distance
/// <= 0, too many objects, a sphere bound that does not hold every sphere. out_of_range: a sphere not
/// wholly inside the world cube, a point light outside it, a plane offset of 2^14 units or more, a mesh
/// box outside it. bad_data: a surface index or a mesh/BVH fault (validate_bvh). capacity_exceeded:
/// `stack` is shallower than a BVH needs. Cost O(scene size).
inline Status validate_scene(const Scene& s, Span<BvhStackEntry> stack) {
    if (s.spheres.size() > kMaxSceneObjects || s.planes.size() > kMaxSceneObjects || s.meshes.size() > kMaxSceneObjects ||
        s.lights.size() > kMaxSceneObjects || s.surfaces.size() > kMaxSceneObjects || s.max_distance.raw() <= 0)
        return Status::invalid_argument;
    for (const Surface& f : s.surfaces)
        if (f.reflect_q15 > kReflectOne || f.checker_size.raw() < 0) return Status::invalid_argument;
    for (const Sphere& sp : s.spheres) {
        if (sp.radius.raw() <= 0) return Status::invalid_argument;
        const int32_t c[3] = {sp.centre.x.raw(), sp.centre.y.raw(), sp.centre.z.raw()};
        for (int32_t e : c)
            if (abs_value(int64_t{e}) + sp.radius.raw() >= kRayWorldLimitRaw) return Status::out_of_range;
        if (sp.surface >= s.surfaces.size()) return Status::bad_data;
    }
    for (const Plane& pl : s.planes) {
        if (!detail::is_unit(pl.normal)) return Status::invalid_argument;
        if (abs_value(int64_t{pl.offset.raw()}) >= kMaxPlaneOffsetRaw) return Status::out_of_range;
        if (pl.surface >= s.surfaces.size()) return Status::bad_data;
    }
    if (s.sphere_bound.radius.raw() < 0) return Status::invalid_argument;
    if (s.sphere_bound.radius.raw() > 0) {  // holds every sphere: |c - C| + r <= R, exactly
        if (!in_world(s.sphere_bound.centre)) return Status::out_of_range;
        for (const Sphere& sp : s.spheres) {
            const Vec3q16 d = sp.centre - s.sphere_bound.centre;
            const int64_t room = int64_t{s.sphere_bound.radius.raw()} - sp.radius.raw();
            const uint64_t d2 = static_cast<uint64_t>(mul_wide(d.x.raw(), d.x.raw())) + static_cast<uint64_t>(mul_wide(d.y.raw(), d.y.raw())) +
                                static_cast<uint64_t>(mul_wide(d.z.raw(), d.z.raw()));
            if (room < 0 || d2 > static_cast<uint64_t>(room) * static_cast<uint64_t>(room)) return Status::invalid_argument;
        }
    }
    for (const Light& l : s.lights) {
        if (l.kind == LightKind::point && !in_world(l.position)) return Status::out_of_range;
        if (l.kind == LightKind::directional && !detail::is_unit(l.direction)) return Status::invalid_argument;
    }
    return detail::validate_meshes(s, stack);
}

}  // namespace hider::ray

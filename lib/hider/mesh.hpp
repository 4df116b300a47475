// A triangle mesh as lib/ draws it: world-space Q16 positions, triangles of uint16 indices, and per
// triangle an optional unit normal (Q14, for headlight shading) and face id. Baked data is checked
// once by validate(); the drawing code then trusts indices (raster/vertices.hpp projects the positions).
#pragma once
#include <hider/view.hpp>

namespace hider {

struct Tri {
    uint16_t v[3];
};

/// Borrowed views of the mesh arrays (const data in flash on a device).
struct Mesh {
    Span<const Vec3q16> positions;
    Span<const Tri> tris;
    Span<const Normal14> normals;  ///< one per triangle, or empty (faces then shade at full brightness)
    Span<const uint32_t> ids;      ///< one per triangle, or empty (id = triangle index + 1)

    uint32_t id(size_t tri) const { return ids.empty() ? static_cast<uint32_t>(tri + 1) : ids[tri]; }
};

/// Most vertices a mesh may index with uint16_t.
constexpr size_t kMaxMeshVertices = 65536;

/// Whether normals and ids, each either empty or one per triangle, fit the triangles.
inline bool triangle_arrays_fit(const Mesh& m) {
    return (m.normals.empty() || m.normals.size() == m.tris.size()) && (m.ids.empty() || m.ids.size() == m.tris.size());
}

/// Checks a mesh once (sizes, every index, every coordinate inside the world range).
/// Returns bad_data for a wrong size or index, out_of_range for a coordinate. Cost: O(vertices + triangles).
inline Status validate(const Mesh& m) {
    if (m.positions.size() > kMaxMeshVertices || !triangle_arrays_fit(m)) return Status::bad_data;
    for (const Tri& t : m.tris)
        for (uint16_t i : t.v)
            if (i >= m.positions.size()) return Status::bad_data;
    for (const Vec3q16& p : m.positions) {
        const int32_t c[3] = {p.x.raw(), p.y.raw(), p.z.raw()};
        for (int32_t e : c)
            if (e <= -kWorldLimitRaw || e >= kWorldLimitRaw) return Status::out_of_range;
    }
    return Status::ok;
}

/// validate() for a mesh drawn through with_model(view, model): also checks the placed mesh. A rigid
/// model transform can carry a mesh that validate() accepts out of the world range (half a turn about
/// the y axis through (-8000, 0, -8000) takes (8000, 0, 8000) to (-24000, 0, -24000)). Past the world
/// range only placements whose view coordinates wrap are refused by project_vertices() (view.hpp,
/// check_view_range()); this check keeps scenes inside the range every part of hider is tested for.
/// Returns validate(m)'s errors, invalid_argument for a matrix entry beyond +-1 (the 32-bit transforms,
/// the ARMv6-M one among them, rely on it; whether the matrix is a rotation is not checked), out_of_range
/// for a placed position outside the world range (computed exactly, without wrapping). Cost:
/// O(vertices + triangles), as validate().
inline Status validate(const Mesh& m, const Transform& model) {
    const Status s = validate(m);
    if (s != Status::ok) return s;
    for (const auto& row : model.rot.m)
        for (const Q30& e : row)
            if (e.raw() < -Q30::kOne || e.raw() > Q30::kOne) return Status::invalid_argument;
    for (const Vec3q16& p : m.positions) {
        const Vec3i64 w = apply_wide(model, p);  // apply() would wrap
        const int64_t placed[3] = {w.x, w.y, w.z};
        for (const int64_t c : placed)
            if (c <= -kWorldLimitRaw || c >= kWorldLimitRaw) return Status::out_of_range;
    }
    return Status::ok;
}

}  // namespace hider

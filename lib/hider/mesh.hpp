// A triangle mesh as lib/ draws it: world-space Q16 positions, triangles of uint16 indices, and per
// triangle an optional unit normal (Q14, for headlight shading) and face id. Baked data is checked
// once by validate(); the drawing code then trusts indices. Vertex projection fills a caller array.
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

/// Checks a mesh once (sizes, every index, every coordinate inside the world range).
/// Returns bad_data for a wrong size or index, out_of_range for a coordinate. Cost: O(vertices + triangles).
inline Status validate(const Mesh& m) {
    if (m.positions.size() > kMaxMeshVertices) return Status::bad_data;
    if (!m.normals.empty() && m.normals.size() != m.tris.size()) return Status::bad_data;
    if (!m.ids.empty() && m.ids.size() != m.tris.size()) return Status::bad_data;
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

/// Smallest and largest depth among drawable projected vertices (for depth shading).
struct DepthRange {
    uint32_t min = kDepthFar, max = kDepthNear;
};

/// Transforms and projects every position into `out` (same index); vertices outside a clip plane are
/// marked (ScreenVertex::outside()) and clipped per triangle later. Returns invalid_argument if out is
/// too small. Precondition: validate(mesh) == ok. Cost per vertex: the transform (nine 32x32->64
/// products, or 36 32-bit multiplies on ARMv6-M), clip codes, and three quotients by w (one reciprocal
/// on ARMv6-M, one 32-bit division for each screen coordinate where the CPU divides).
inline Status project_vertices(const View& view, Span<const Vec3q16> positions, Span<ScreenVertex> out,
                               DepthRange* range = nullptr) {
    if (out.size() < positions.size()) return Status::invalid_argument;
    const PreparedTransform to_view(view.to_view);
    for (size_t i = 0; i < positions.size(); ++i) {
        const ViewPoint p = to_view_point(to_view, positions[i]);
        const ScaledXY xy = scaled_xy(view, p);
        const uint8_t code = outcode(view, p, xy);
        if (code != 0) {
            out[i].mark_outside(code);
            continue;
        }
        const ScreenVertex s = project(view, p, xy);
        ScreenVertex& o = out[i];  // field by field: a whole-struct copy became a 9-byte memcpy call on ARMv6-M
        o.x = s.x;
        o.y = s.y;
        o.z = s.z;
    }
    if (range != nullptr) {  // a second pass, so frames without depth shading do not pay for it
        DepthRange r;
        for (size_t i = 0; i < positions.size(); ++i) {
            const uint32_t z = out[i].z;
            if (z == 0) continue;  // outside a clip plane
            r.min = min(r.min, z);
            r.max = max(r.max, z);
        }
        *range = r;
    }
    return Status::ok;
}

}  // namespace hider

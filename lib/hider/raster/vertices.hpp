// Per-frame vertex projection of a mesh: each position to view space, its clip code, and the projected
// ScreenVertex (or the planes it lies outside of), into a caller array indexed like the positions.
#pragma once
#include <hider/raster/clip.hpp>

namespace hider {

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

/// project_vertices() for one position, with the view transform prepared once by the caller: the same
/// ScreenVertex (or outside mark) for the same view. For walks that project only what they draw.
inline void project_vertex(const View& view, const PreparedTransform& to_view, const Vec3q16& position, ScreenVertex& out) {
    const ViewPoint p = to_view_point(to_view, position);
    const ScaledXY xy = scaled_xy(view, p);
    const uint8_t code = outcode(view, p, xy);
    if (code != 0) {
        out.mark_outside(code);
        return;
    }
    const ScreenVertex s = project(view, p, xy);
    out.x = s.x;
    out.y = s.y;
    out.z = s.z;
}

/// Marks every vertex as not projected yet (x = y = z = 0, which project_vertex() never gives), for a
/// walk that projects on first use (draw_bsp()): once per frame, before the first band.
inline void mark_unprojected(Span<ScreenVertex> verts) {
    for (ScreenVertex& v : verts) {
        v.x = 0;
        v.y = 0;
        v.z = 0;
    }
}

/// True for a vertex mark_unprojected() left alone.
constexpr bool unprojected(const ScreenVertex& v) { return v.z == 0 && v.x == 0; }

}  // namespace hider

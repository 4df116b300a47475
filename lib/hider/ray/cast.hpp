// Ray casting of one mesh as a hidden-surface method beside the z-buffer: a primary ray per pixel
// centre, the nearest triangle through the mesh's BVH, coloured by face shading (headlight or id, as
// FaceShading colours the z-buffer's triangles). Visibility is the z-buffer's: near <= w <= far with
// w = t (d . f) the view depth, back faces culled on request, ties to the smaller triangle index.
#pragma once
#include <hider/ray/trace.hpp>
#include <hider/shade.hpp>

namespace hider::ray {

namespace detail {
/// floor(n / d) or, round_up, ceil(n / d), for n >= 0 and d > 0, saturated to INT32_MAX (one 64/32 division).
constexpr int32_t quotient_sat(uint64_t n, uint32_t d, bool round_up) {
    if ((n >> 32) >= d) return INT32_MAX;
    uint32_t rem = 0;
    const uint64_t q = uint64_t{udiv64_32(n, d, rem)} + (round_up && rem != 0 ? 1 : 0);
    return q > static_cast<uint64_t>(INT32_MAX) ? INT32_MAX : static_cast<int32_t>(q);
}
}  // namespace detail

/// The walk of primary ray `d` that keeps the z-buffer's near <= w <= far: w = t (d . f), so the BVH query
/// covers t in (near / cos - 1, far / cos] (rounded outward), cull as asked, nothing skipped. False when
/// the ray does not point forward (cos <= 0: never for a pixel's ray).
inline bool primary_query(const PrimaryRays& rays, const Vec3q30& d, bool cull, BvhQuery& q) {
    const int64_t cos_q30 = dot_q60(d, rays.forward) >> 30;
    if (cos_q30 <= 0) return false;
    const uint64_t near_q46 = static_cast<uint64_t>(rays.view.near_raw) << 30, far_q46 = static_cast<uint64_t>(rays.view.far_raw) << 30;
    set_ray(q.ray, rays.eye, d);
    q.t_min = detail::quotient_sat(near_q46, static_cast<uint32_t>(cos_q30), false) - 1;
    q.t_max = detail::quotient_sat(far_q46, static_cast<uint32_t>(cos_q30), true);
    q.cull = cull;
    q.skip = UINT32_MAX;
    return true;
}

/// Casts row y of the frame of `rays` against `mesh` and writes width pixels of Format to `row`:
/// opt.shade headlight or id (Shade::depth is not a ray-casting mode: the caller rejects it), pixels
/// that meet nothing get `background`. Counts rays and hits and the BVH's work. Preconditions:
/// validate_bvh(bvh, mesh, stack) == ok with this stack (or one no shorter), 0 <= y < rays.height.
template <class Format>
TraceStats cast_row(const PrimaryRays& rays, const Mesh& mesh, const Bvh& bvh, const DrawOptions& opt, Rgb background,
                    int32_t y, typename Format::Pixel* row, Span<BvhStackEntry> stack) {
    TraceStats stats;
    const FaceShading shading(rays.view, opt);
    const typename Format::Pixel empty = Format::pack(background);
    RowRays rr(rays, y);
    for (int32_t x = 0; x < rays.width; ++x, rr.next()) {
        ++stats.rays;
        row[x] = empty;
        BvhQuery q;
        if (!primary_query(rays, rr.direction(), opt.cull, q)) continue;
        uint32_t tri = 0;
        TriangleHit hit{};
        if (!bvh_walk(bvh, mesh, q, stack, tri, hit, &stats.bvh)) continue;
        ++stats.hits;
        row[x] = Format::pack(shading.color(mesh, tri, hit.front));
    }
    return stats;
}

}  // namespace hider::ray

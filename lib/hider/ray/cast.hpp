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

/// Casts row y of the frame of `rays` against `mesh` and writes width pixels of Format to `row`:
/// opt.shade headlight or id (Shade::depth is not a ray-casting mode: the caller rejects it), pixels
/// that meet nothing get `background`. Counts rays and hits and the BVH's work. Preconditions:
/// validate_bvh(bvh, mesh, stack) == ok, 0 <= y < rays.height.
template <class Format>
TraceStats cast_row(const PrimaryRays& rays, const Mesh& mesh, const Bvh& bvh, const DrawOptions& opt, Rgb background,
                    int32_t y, typename Format::Pixel* row, Span<BvhStackEntry> stack) {
    TraceStats stats;
    const FaceShading shading(rays.view, opt);
    const typename Format::Pixel empty = Format::pack(background);
    const uint64_t near_q46 = static_cast<uint64_t>(rays.view.near_raw) << 30, far_q46 = static_cast<uint64_t>(rays.view.far_raw) << 30;
    RowRays rr(rays, y);
    for (int32_t x = 0; x < rays.width; ++x, rr.next()) {
        const Vec3q30 d = rr.direction();
        ++stats.rays;
        // t where the ray crosses the near and far planes: w / cos, cos = d . f (> 0 for every pixel).
        const int64_t cos_q30 = dot_q60(d, rays.forward) >> 30;
        row[x] = empty;
        if (cos_q30 <= 0) continue;
        const int32_t t_near = detail::quotient_sat(near_q46, static_cast<uint32_t>(cos_q30), false);
        const int32_t t_far = detail::quotient_sat(far_q46, static_cast<uint32_t>(cos_q30), true);
        const BvhQuery q{{rays.eye, d}, t_near - 1, t_far, opt.cull, UINT32_MAX};
        uint32_t tri = 0;
        TriangleHit hit{};
        if (!bvh_walk(bvh, mesh, q, stack, tri, hit, &stats.bvh)) continue;
        ++stats.hits;
        row[x] = Format::pack(shading.color(mesh, tri, hit.front));
    }
    return stats;
}

}  // namespace hider::ray

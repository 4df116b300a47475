// The code callgrind counts for hider-bench raytrace and raycast: lib/ calls only.
#include "measured_ray.hpp"

using hider::tool::bench::CastJob;
using hider::tool::bench::NearestJob;
using hider::tool::bench::RayRowJob;

extern "C" __attribute__((noinline)) void hider_bench_ray_row(RayRowJob* job) {
    job->stats = hider::ray::trace_row<hider::Rgb565Format>(*job->scene, *job->rays, job->y, job->row, job->stack, job->rects);
}

extern "C" __attribute__((noinline)) void hider_bench_cast(CastJob* job) {
    for (int32_t y = 0; y < job->rays->height; ++y)
        job->stats.merge(hider::ray::cast_row<hider::Rgb565Format>(*job->rays, job->mesh, job->bvh, job->draw, {0, 0, 0}, y,
                                                                   job->row, job->stack));
}

extern "C" __attribute__((noinline)) void hider_bench_nearest_bvh(const NearestJob* job) {
    for (size_t i = 0; i < job->count; ++i) {
        uint32_t tri = UINT32_MAX;
        hider::ray::TriangleHit hit{};
        if (!hider::ray::bvh_walk(job->bvh, job->mesh, job->queries[i], job->stack, tri, hit)) tri = UINT32_MAX;
        job->tri[i] = tri;
    }
}

/// The loop a ray caster without a hierarchy runs: every triangle, nearest t, ties to the smaller index.
extern "C" __attribute__((noinline)) void hider_bench_nearest_brute(const NearestJob* job) {
    const hider::Mesh& m = job->mesh;
    for (size_t i = 0; i < job->count; ++i) {
        const hider::ray::BvhQuery& q = job->queries[i];
        const hider::ray::TriangleRay tr = hider::ray::bvh_triangle_ray(job->bvh, q.ray);
        uint32_t best = UINT32_MAX;
        int32_t t_max = q.t_max;
        for (uint32_t t = 0; t < m.tris.size(); ++t) {
            const hider::Tri& v = m.tris[t];
            hider::ray::TriangleHit hit{};
            if (!hider::ray::intersect_triangle(tr, m.positions[v.v[0]], m.positions[v.v[1]], m.positions[v.v[2]], q.t_min, t_max,
                                                q.cull, hit))
                continue;
            if (best != UINT32_MAX && hit.t_q16 == t_max) continue;  // tie: the earlier (smaller) index stays
            best = t;
            t_max = hit.t_q16;
        }
        job->tri[i] = best;
    }
}

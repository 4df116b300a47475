// The measured regions of hider-bench raytrace and raycast: extern "C" noinline functions that callgrind
// toggles on. They run lib/ code only (no allocation, no I/O) on inputs the caller prepared.
#pragma once
#include <hider/ray/cast.hpp>

namespace hider::tool::bench {

/// One row of the ray tracer: trace_row<Rgb565Format> of row y into `row`.
struct RayRowJob {
    const ray::Scene* scene = nullptr;
    const ray::PrimaryRays* rays = nullptr;
    Span<ray::BvhStackEntry> stack;
    Span<const ray::SphereRect> rects;
    uint16_t* row = nullptr;
    int32_t y = 0;
    ray::TraceStats stats{};  ///< out
};

/// A whole frame of mesh ray casting (cast_row<Rgb565Format> for every row).
struct CastJob {
    const ray::PrimaryRays* rays = nullptr;
    Mesh mesh{};
    ray::Bvh bvh{};
    DrawOptions draw{};
    Span<ray::BvhStackEntry> stack;
    uint16_t* row = nullptr;
    ray::TraceStats stats{};  ///< out
};

/// Nearest triangles of prepared rays, through the BVH or by testing every triangle (brute force).
struct NearestJob {
    Mesh mesh{};
    ray::Bvh bvh{};  ///< also sets the triangle test's grid for the brute force
    const ray::BvhQuery* queries = nullptr;
    size_t count = 0;
    Span<ray::BvhStackEntry> stack;
    uint32_t* tri = nullptr;  ///< out: nearest triangle per query, UINT32_MAX for none
};

}  // namespace hider::tool::bench

extern "C" __attribute__((noinline)) void hider_bench_ray_row(hider::tool::bench::RayRowJob* job);
extern "C" __attribute__((noinline)) void hider_bench_cast(hider::tool::bench::CastJob* job);
extern "C" __attribute__((noinline)) void hider_bench_nearest_bvh(const hider::tool::bench::NearestJob* job);
extern "C" __attribute__((noinline)) void hider_bench_nearest_brute(const hider::tool::bench::NearestJob* job);

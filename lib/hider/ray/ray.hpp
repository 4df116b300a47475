// Rays and hits: a Q16 origin and a unit Q30 direction; distances t along a ray are Q16 world units.
// The ray tracer's ranges (CONVENTIONS.md, "Ray tracing"): every origin and every object lies inside the
// world cube |coordinate| < 2^13 units, so any two points differ by less than 2^30 raw per component
// and any t is below 2^15 units (the cube's diagonal), which keeps every product below in int64.
#pragma once
#include <hider/ray/math.hpp>

namespace hider::ray {

struct Ray {
    Vec3q16 origin;
    Vec3q30 dir;  ///< unit length (within a few LSB)
};

/// Sets r to (o, d) field by field: a whole-struct copy becomes a memcpy call at -Os on RV32 and ARMv6-M.
__attribute__((always_inline)) inline void set_ray(Ray& r, const Vec3q16& o, const Vec3q30& d) {
    r.origin.x = o.x;
    r.origin.y = o.y;
    r.origin.z = o.z;
    r.dir.x = d.x;
    r.dir.y = d.y;
    r.dir.z = d.z;
}

/// Kinds of object a hit can be on, in the order the tie rule ranks them.
enum class ObjectKind : uint8_t { none, sphere, plane, triangle };

/// The nearest hit of a ray: distance, object and (triangles) which side faces the ray.
struct Hit {
    int32_t t_q16 = 0;
    ObjectKind kind = ObjectKind::none;
    uint16_t object = 0;    ///< sphere, plane or mesh index
    uint32_t triangle = 0;  ///< triangle index in the mesh (kind == triangle)
    bool front = true;      ///< the ray meets the outside (sphere) or the counter-clockwise side (triangle)
};

/// |coordinate| of every ray origin and object must stay below this (2^13 units, as kWorldLimitRaw).
constexpr int32_t kRayWorldLimitRaw = int32_t{1} << 29;

/// Whether p lies inside the world cube |coordinate| < 2^13 units.
constexpr bool in_world(const Vec3q16& p) {
    constexpr int32_t lim = kRayWorldLimitRaw;
    return p.x.raw() > -lim && p.x.raw() < lim && p.y.raw() > -lim && p.y.raw() < lim && p.z.raw() > -lim &&
           p.z.raw() < lim;
}

/// Whether point_along(p, t, d) lies inside the world cube, for any t: each coordinate is summed in 64
/// bits, so a far hit (a grazing ray meeting a plane thousands of units out) is a miss, not an overflow.
constexpr bool along_in_world(const Vec3q16& p, int32_t t_q16, const Vec3q30& d) {
    constexpr int64_t one = int64_t{1} << 30;
    constexpr int64_t lo = (1 - int64_t{kRayWorldLimitRaw}) * one, span = (2 * int64_t{kRayWorldLimitRaw} - 1) * one;
    const int32_t pc[3] = {p.x.raw(), p.y.raw(), p.z.raw()}, dc[3] = {d.x.raw(), d.y.raw(), d.z.raw()};
    for (int k = 0; k < 3; ++k) {  // v = p + round(t d) in Q46 (below 2^62): inside when -lim < v >> 30 < lim
        const int64_t v = int64_t{pc[k]} * one + mul_wide(t_q16, dc[k]) + one / 2;
        if (static_cast<uint64_t>(v - lo) >= static_cast<uint64_t>(span)) return false;
    }
    return true;
}

}  // namespace hider::ray

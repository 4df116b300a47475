// Ray-sphere and ray-plane intersection in fixed point (Appel 1968, Whitted 1980). Rays have a unit Q30
// direction, so the sphere's quadratic is t^2 + 2 b t + c = 0 with b = d.(o - centre); its discriminant
// is taken in the stable form r^2 - |q|^2 with q = (o - centre) - b d, the ray's offset from the centre
// at its closest approach (Haines et al., "Precision Improvements for Ray/Sphere Intersection", Ray
// Tracing Gems 2019): its error does not grow with the distance to the sphere. Rounding: b, q and t
// round to the nearest Q16, sqrt floors; the hit decision is exact for those rounded values.
#pragma once
#include <hider/ray/ray.hpp>

namespace hider::ray {

/// A sphere; validate_scene() keeps it inside the world cube (|centre| + radius < 2^13 per axis).
struct Sphere {
    Vec3q16 centre;
    Q16 radius;        ///< > 0
    uint16_t surface;  ///< index into Scene::surfaces
};

/// The infinite plane normal . p = offset, clipped to the world cube (a hit outside it is a miss).
struct Plane {
    Vec3q30 normal;    ///< unit; its side is the front
    Q16 offset;
    uint16_t surface;
};

/// Nearest root t of `ray` and `s` with t_min < t < t_max (an open segment: the tie rule's strict
/// comparison), in Q16. A ray starting inside the sphere meets it at the far root; a tangent ray
/// hits (one root). `front` is false when the hit is on the inside. Cost: 9 products and one sqrt.
inline bool intersect_sphere(const Ray& ray, const Sphere& s, int32_t t_min, int32_t t_max, int32_t& t_out,
                             bool& front) {
    const Vec3q16 oc = ray.origin - s.centre;  // |components| < 2^30 raw (world cube)
    const int32_t b = round_q46_to_q16(dot_q46(ray.dir, oc));
    const int64_t r = s.radius.raw();
    // Both roots lie in [-b - r, -b + r]: reject without the square root when that misses the segment.
    if (int64_t{-b} + r <= t_min || int64_t{-b} - r >= t_max) return false;
    const int32_t qx = oc.x.raw() - round_q46_to_q16(mul_wide(b, ray.dir.x.raw()));
    const int32_t qy = oc.y.raw() - round_q46_to_q16(mul_wide(b, ray.dir.y.raw()));
    const int32_t qz = oc.z.raw() - round_q46_to_q16(mul_wide(b, ray.dir.z.raw()));
    const int64_t disc = mul_wide(s.radius.raw(), s.radius.raw()) - mul_wide(qx, qx) - mul_wide(qy, qy) - mul_wide(qz, qz);
    if (disc < 0) return false;
    const int64_t h = isqrt64(static_cast<uint64_t>(disc));
    const int64_t t0 = int64_t{-b} - h, t1 = int64_t{-b} + h;
    if (t0 > t_min) {
        if (t0 >= t_max) return false;
        t_out = static_cast<int32_t>(t0);
        front = true;
        return true;
    }
    if (t1 <= t_min || t1 >= t_max) return false;
    t_out = static_cast<int32_t>(t1);
    front = false;
    return true;
}

/// Whether the open segment t_min < t < t_max of `ray` may meet sphere `s`: the cheap test of a
/// bounding sphere. Conservative (never false when the segment meets the ball): the line must pass
/// within r of the centre and [-b - r, -b + r], which holds the chord, must overlap the segment. No
/// square root; the same b and q as intersect_sphere().
inline bool segment_meets_sphere(const Ray& ray, const Sphere& s, int32_t t_min, int32_t t_max) {
    const Vec3q16 oc = ray.origin - s.centre;
    const int32_t b = round_q46_to_q16(dot_q46(ray.dir, oc));
    const int64_t r = s.radius.raw();
    if (int64_t{-b} + r <= t_min || int64_t{-b} - r >= t_max) return false;
    const int32_t qx = oc.x.raw() - round_q46_to_q16(mul_wide(b, ray.dir.x.raw()));
    const int32_t qy = oc.y.raw() - round_q46_to_q16(mul_wide(b, ray.dir.y.raw()));
    const int32_t qz = oc.z.raw() - round_q46_to_q16(mul_wide(b, ray.dir.z.raw()));
    return mul_wide(s.radius.raw(), s.radius.raw()) - mul_wide(qx, qx) - mul_wide(qy, qy) - mul_wide(qz, qz) >= 0;
}

/// Signed distance of p from the plane (positive on the normal's side), Q16 rounded to nearest.
constexpr int32_t plane_distance(const Plane& pl, const Vec3q16& p) {
    return round_q46_to_q16(dot_q46(pl.normal, p)) - pl.offset.raw();
}

/// Root t of `ray` and `pl` with t_min < t < t_max (Q16), rounded to nearest; false when the ray is
/// parallel to the plane (d.n rounds to 0 in Q30), the root is outside the segment, or the hit point
/// lies outside the world cube. `front` is true when the ray arrives on the normal's side.
inline bool intersect_plane(const Ray& ray, const Plane& pl, int32_t t_min, int32_t t_max, int32_t& t_out, bool& front) {
    const int32_t den = static_cast<int32_t>((dot_q60(pl.normal, ray.dir) + (int64_t{1} << 29)) >> 30);  // n.d, Q30
    if (den == 0) return false;
    const int64_t num = -int64_t{plane_distance(pl, ray.origin)};  // t = num / den
    if (num == 0 || (num < 0) != (den < 0)) return false;          // behind the origin, or on the plane
    const int64_t anum = abs_value(num) * Q30::kOne, aden = abs_value(int64_t{den});
    // t >= t_max <=> |num| 2^30 >= t_max |den|: no division for hits beyond the segment.
    if (t_max <= 0 || anum >= int64_t{t_max} * aden) return false;
    const int64_t t = div_round(anum, aden);
    if (t <= t_min || t >= t_max) return false;
    if (!along_in_world(ray.origin, static_cast<int32_t>(t), ray.dir)) return false;
    t_out = static_cast<int32_t>(t);
    front = den < 0;
    return true;
}

}  // namespace hider::ray

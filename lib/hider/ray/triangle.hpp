// Ray-triangle and ray-box tests for mesh ray casting.
// Triangles: exact signed volumes (Plucker tests) det(d, a, b) of the ray direction and each edge, with
// the vertices taken relative to the ray origin and floored to a per-ray grid of 2^shift raw units
// chosen so every product fits int64 (vertices within 2^20 grid steps of the origin), and the direction
// rounded to Q18 (volumes below 3 2^59, their sum below 2^62.2, det(a, b, c) below 2^62.6). The tests are exact on those rounded values, so two triangles sharing an edge compute
// the same volume with opposite signs: rays never slip between them (watertight). A zero volume (the ray
// exactly on an edge's line) counts for exactly one of the triangles sharing the edge or vertex: its sign
// is taken from the edge's direction across the ray, a fixed 2-D "top-left" rule in the plane normal to d. t is the quotient
// det(a, b, c) / d.n to about 2^-30; the Q18 direction moves it by up to about t 2^-18 / |cos| (cos of the
// angle between ray and normal), the grid by about 2^shift raw / |cos|.
// Boxes: slab test with t rounded outward (never misses a box the ray meets; may accept a near miss).
#pragma once
#include <hider/ray/ray.hpp>

namespace hider::ray {

/// Per-ray constants of the triangle test.
struct TriangleRay {
    Vec3q16 origin;
    int32_t d18[3];  ///< direction in Q18, rounded
    int shift;       ///< vertex grid: (v - origin) >> shift
    int32_t u[3];    ///< tie rule: w x d for the axis w least aligned with d (perpendicular to d)
    int64_t u2[3];   ///< tie rule, second: d x u
};

/// The vertex grid's shift for vertices no farther than `reach_raw` from the ray's origin on any axis.
constexpr int triangle_grid_shift(uint32_t reach_raw) {
    const int bits = reach_raw == 0 ? 0 : 32 - clz32(reach_raw);  // reach < 2^bits
    return bits > 20 ? bits - 20 : 0;                              // |(v - o) >> shift| <= 2^20
}

/// The part of make_triangle_ray() that box tests need: the direction as the test takes it and the grid.
constexpr TriangleRay triangle_ray_grid(const Ray& ray, uint32_t reach_raw) {
    TriangleRay tr{ray.origin, {}, 0, {}, {}};
    const int32_t d[3] = {ray.dir.x.raw(), ray.dir.y.raw(), ray.dir.z.raw()};
    for (int i = 0; i < 3; ++i) tr.d18[i] = (d[i] + (1 << 11)) >> 12;
    tr.shift = triangle_grid_shift(reach_raw);
    return tr;
}

/// Completes triangle_ray_grid()'s result with the tie rule.
constexpr void complete_triangle_ray(TriangleRay& tr) {
    int w = 0;  // the axis least aligned with d (ties: x, then y)
    for (int i = 1; i < 3; ++i)
        if (abs_value(tr.d18[i]) < abs_value(tr.d18[w])) w = i;
    const int w1 = w == 2 ? 0 : w + 1, w2 = w1 == 2 ? 0 : w1 + 1;  // e_w x d = (.., -d[w2] at w1, d[w1] at w2)
    tr.u[w] = 0;
    tr.u[w1] = -tr.d18[w2];
    tr.u[w2] = tr.d18[w1];
    tr.u2[0] = int64_t{tr.d18[1]} * tr.u[2] - int64_t{tr.d18[2]} * tr.u[1];
    tr.u2[1] = int64_t{tr.d18[2]} * tr.u[0] - int64_t{tr.d18[0]} * tr.u[2];
    tr.u2[2] = int64_t{tr.d18[0]} * tr.u[1] - int64_t{tr.d18[1]} * tr.u[0];
}

/// Prepares the triangle test for `ray` and vertices no farther than `reach_raw` from its origin on
/// any axis (mesh ray casting takes the reach from the BVH's root box).
constexpr TriangleRay make_triangle_ray(const Ray& ray, uint32_t reach_raw) {
    TriangleRay tr = triangle_ray_grid(ray, reach_raw);
    complete_triangle_ray(tr);
    return tr;
}

/// A triangle hit: distance and whether the ray meets the counter-clockwise (front) side.
struct TriangleHit {
    int32_t t_q16;
    bool front;
};

namespace detail {
struct GridVec {
    int32_t x, y, z;
};

/// Volume det(d, a, b) = (d x a) . b with d x a precomputed: |d x a| <= 2^39, |b| <= 2^20.
constexpr int64_t volume(const int64_t (&da)[3], const GridVec& b) { return da[0] * b.x + da[1] * b.y + da[2] * b.z; }

/// d x a for |d| <= 2^18, |a| <= 2^20.
constexpr void cross_d(const int32_t (&d)[3], const GridVec& a, int64_t (&out)[3]) {
    out[0] = mul_wide(d[1], a.z) - mul_wide(d[2], a.y);
    out[1] = mul_wide(d[2], a.x) - mul_wide(d[0], a.z);
    out[2] = mul_wide(d[0], a.y) - mul_wide(d[1], a.x);
}

/// Sign of an edge volume with the tie rule: a zero volume takes the sign of (b - a) . u, or if that is
/// zero of (b - a) . u2; u and u2 span the plane normal to d, so this is a fixed 2-D order of the edge's
/// projected direction (antisymmetric: the edge's neighbour runs it the other way and gets the other
/// sign). An edge parallel to d (both zero) belongs to a triangle seen edge-on, which is never hit.
constexpr int edge_sign(int64_t v, const TriangleRay& r, const GridVec& a, const GridVec& b) {
    if (v != 0) return v > 0 ? 1 : -1;
    const int64_t ex = int64_t{b.x} - a.x, ey = int64_t{b.y} - a.y, ez = int64_t{b.z} - a.z;  // |e| <= 2^21
    const int64_t s1 = ex * r.u[0] + ey * r.u[1] + ez * r.u[2];
    if (s1 != 0) return s1 > 0 ? 1 : -1;
    return ex * r.u2[0] + ey * r.u2[1] + ez * r.u2[2] >= 0 ? 1 : -1;  // |u2| <= 2^37
}

/// round(|num| 2^e / |den|) for den != 0 and e >= -32, saturated to INT32_MAX: the divisor is cut to
/// 31 significant bits first, so the result has about 2^-30 relative error and every step fits 64 bits.
constexpr int32_t scaled_quotient(int64_t num, int64_t den, int e) {
    uint64_t n = static_cast<uint64_t>(abs_value(num)), d = static_cast<uint64_t>(abs_value(den));
    const int cut = bit_length64(d) - 31;
    if (cut > 0) { d >>= cut; e -= cut; }  // num 2^e / den ~ num 2^(e - cut) / (den >> cut)
    if (e >= 0) {
        if (bit_length64(n) + e > bit_length64(d) + 32) return INT32_MAX;  // quotient >= 2^31
        n <<= e;
    } else {
        d <<= -e;
    }
    const uint64_t q = (n + d / 2) / d;
    return q > static_cast<uint64_t>(INT32_MAX) ? INT32_MAX : static_cast<int32_t>(q);
}
}  // namespace detail

/// Tests triangle (p0, p1, p2) against the prepared ray: true with the hit when the ray meets it at
/// t_min < t <= t_max (Q16); back faces (the ray meets the clockwise side) are skipped when `cull`.
/// Precondition: the vertices lie within the reach given to make_triangle_ray().
constexpr bool intersect_triangle(const TriangleRay& r, const Vec3q16& p0, const Vec3q16& p1, const Vec3q16& p2,
                                  int32_t t_min, int32_t t_max, bool cull, TriangleHit& hit) {
    const int s = r.shift;
    auto grid = [&](const Vec3q16& p) {
        return detail::GridVec{(p.x.raw() - r.origin.x.raw()) >> s, (p.y.raw() - r.origin.y.raw()) >> s,
                               (p.z.raw() - r.origin.z.raw()) >> s};
    };
    const detail::GridVec a = grid(p0), b = grid(p1), c = grid(p2);
    int64_t da[3] = {}, db[3] = {};
    detail::cross_d(r.d18, a, da);
    const int64_t v_ab = detail::volume(da, b);   // det(d, a, b)
    const int64_t v_ca = -detail::volume(da, c);  // det(d, c, a) = -(d x a) . c
    const int s_ab = detail::edge_sign(v_ab, r, a, b), s_ca = detail::edge_sign(v_ca, r, c, a);
    if (s_ab != s_ca) return false;
    detail::cross_d(r.d18, b, db);
    const int64_t v_bc = detail::volume(db, c);  // det(d, b, c)
    if (detail::edge_sign(v_bc, r, b, c) != s_ab) return false;
    const int64_t v_sum = v_ab + v_bc + v_ca;  // d . n for n = (b - a) x (c - a); < 0: front face
    if (v_sum == 0 || (cull && v_sum > 0)) return false;
    // det(a, b, c) = a . (b x c): t = det / (d . n) in grid units, times 2^(shift + 18) for Q16 world units.
    const int64_t bc0 = mul_wide(b.y, c.z) - mul_wide(b.z, c.y), bc1 = mul_wide(b.z, c.x) - mul_wide(b.x, c.z),
                  bc2 = mul_wide(b.x, c.y) - mul_wide(b.y, c.x);
    const int64_t det = bc0 * a.x + bc1 * a.y + bc2 * a.z;
    if (det == 0 || (det < 0) != (v_sum < 0)) return false;  // behind the origin or through it
    const int32_t t = detail::scaled_quotient(det, v_sum, s + 18);
    if (t <= t_min || t > t_max) return false;
    hit = {t, v_sum < 0};
    return true;
}

/// Per-ray constants of the slab test.
struct BoxRay {
    int32_t origin[3];
    int64_t inv[3];     ///< 1 / d in Q16 (|d| >= 2^-15); 0 on an axis the ray (nearly) parallels
    int32_t reach[3];   ///< on such an axis, how far the ray can drift within t_max, raw, rounded up
    /// How far below its raw value the triangle test may see a vertex (its grid floors v - origin to
    /// 2^shift raw: 2^shift - 1); each box reaches this much lower so that it holds its triangles as
    /// tested (else a ray slips between two neighbours' boxes). 0 for boxes of exact geometry.
    int32_t grid_slack;
};

/// Prepares the slab test for `ray` up to distance t_max (Q16, > 0).
constexpr BoxRay make_box_ray(const Ray& ray, int32_t t_max) {
    BoxRay br{{ray.origin.x.raw(), ray.origin.y.raw(), ray.origin.z.raw()}, {}, {}, 0};
    const int32_t d[3] = {ray.dir.x.raw(), ray.dir.y.raw(), ray.dir.z.raw()};
    for (int i = 0; i < 3; ++i) {
        if (abs_value(d[i]) >= (int32_t{1} << 15)) {
            br.inv[i] = div_round(int64_t{1} << 46, d[i]);
        } else {
            br.inv[i] = 0;
            br.reach[i] = static_cast<int32_t>((mul_wide(t_max, abs_value(d[i])) >> 30) + 1);
        }
    }
    return br;
}

/// Whether the ray may meet box [lo - grid_slack, hi] (raw Q16) between t_min and t_max; on true, t_enter
/// is a lower bound of where it enters (Q16). Conservative: t is widened by |t| 2^-16 + 2 LSB on each axis.
constexpr bool intersect_box(const BoxRay& r, const int32_t (&lo)[3], const int32_t (&hi)[3], int32_t t_min,
                             int32_t t_max, int32_t& t_enter) {
    int64_t enter = t_min, exit = t_max;
    for (int i = 0; i < 3; ++i) {
        const int64_t low = int64_t{lo[i]} - r.grid_slack;
        if (r.inv[i] == 0) {
            if (low > int64_t{r.origin[i]} + r.reach[i] || int64_t{hi[i]} < int64_t{r.origin[i]} - r.reach[i])
                return false;
            continue;
        }
        int64_t t0 = ((low - r.origin[i]) * r.inv[i]) >> 16;
        int64_t t1 = ((int64_t{hi[i]} - r.origin[i]) * r.inv[i]) >> 16;
        if (t0 > t1) swap_values(t0, t1);
        t0 -= (abs_value(t0) >> 16) + 2;
        t1 += (abs_value(t1) >> 16) + 2;
        enter = max(enter, t0);
        exit = min(exit, t1);
        if (enter > exit) return false;
    }
    t_enter = static_cast<int32_t>(enter);
    return true;
}

}  // namespace hider::ray

// Ray-sphere and ray-plane intersection (lib/hider/ray/shapes.hpp) against double-precision roots of
// the same fixed-point inputs. Tolerances, in Q16 LSB (2^-16 units):
//   sphere: |t - t_ref| <= 2 + 2 |q| / h_ref, and <= 2 + 2 sqrt(|q|) near tangency, with |q| the ray's
//           distance from the centre in raw Q16 and h_ref the half chord: the discriminant r^2 - |q|^2 is
//           exact for q rounded to Q16 (error about 2 |q| raw in Q32), and the root amplifies it by 1/(2h).
//           Hit and miss agree except where |r^2 - |q|^2| is within that error band.
//   plane:  |t - t_ref| <= 1 + (1 + t 2^-30) / |n.d| (the signed distance rounds to Q16, n.d to Q30).
#include <hider/ray/shapes.hpp>

#include <cmath>
#include <random>

#include <doctest/doctest.h>

#include "support/fixed_print.hpp"

using namespace hider;
using namespace hider::ray;

namespace {

struct V3 {
    double x, y, z;
};
V3 d3(const Vec3q16& v) { return {v.x.raw() / 65536.0, v.y.raw() / 65536.0, v.z.raw() / 65536.0}; }
V3 d3(const Vec3q30& v) { return {v.x.raw() / 1073741824.0, v.y.raw() / 1073741824.0, v.z.raw() / 1073741824.0}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

Vec3q16 q16(double x, double y, double z) {
    return {Q16::from_raw(int32_t(std::lround(x * 65536))), Q16::from_raw(int32_t(std::lround(y * 65536))),
            Q16::from_raw(int32_t(std::lround(z * 65536)))};
}

Vec3q30 unit(double x, double y, double z) {
    Vec3q30 u{};
    const double m = std::fmax(std::fabs(x), std::fmax(std::fabs(y), std::fabs(z)));
    REQUIRE(unit_q30(int32_t(std::lround(x / m * 1e9)), int32_t(std::lround(y / m * 1e9)), int32_t(std::lround(z / m * 1e9)), u));
    return u;
}

/// Roots of |o + t d - c|^2 = r^2 for the exact values lib/ works with (d as stored, not renormalised).
struct SphereRef {
    bool real = false;
    double t0 = 0, t1 = 0, q_raw = 0, h = 0;
};
SphereRef sphere_ref(const Ray& ray, const Sphere& s) {
    const V3 o = d3(ray.origin), d = d3(ray.dir), c = d3(s.centre), oc = sub(o, c);
    const double r = s.radius.raw() / 65536.0, a = dot(d, d), b = dot(oc, d);
    const V3 q = sub(oc, {d.x * b / a, d.y * b / a, d.z * b / a});
    SphereRef ref;
    ref.q_raw = std::sqrt(dot(q, q)) * 65536;
    const double disc = r * r - dot(q, q);
    if (disc < 0) return ref;
    ref.real = true;
    ref.h = std::sqrt(disc / a);
    ref.t0 = (-b / a - ref.h) * 65536;
    ref.t1 = (-b / a + ref.h) * 65536;
    ref.h *= 65536;
    return ref;
}

/// The root lib/ should report for t_min < t < t_max, or NAN.
double expected_root(const SphereRef& ref, double t_min, double t_max) {
    if (!ref.real) return std::nan("");
    if (ref.t0 > t_min) return ref.t0 < t_max ? ref.t0 : std::nan("");
    return ref.t1 > t_min && ref.t1 < t_max ? ref.t1 : std::nan("");
}

double sphere_tolerance(const SphereRef& ref, double t) {
    const double amplified = ref.h > 0 ? 2 * ref.q_raw / ref.h : HUGE_VAL;
    return 2 + std::fabs(t) * std::ldexp(1.0, -28) + std::fmin(amplified, 2 * std::sqrt(ref.q_raw));
}

/// Runs one sphere case; returns false on a disagreement outside the stated band.
struct SphereTally {
    long hits = 0, misses = 0, band_disagreements = 0;
    double worst_ratio = 0;  // |t - t_ref| / tolerance
};
void check_sphere(const Ray& ray, const Sphere& s, int32_t t_min, int32_t t_max, SphereTally& tally) {
    const SphereRef ref = sphere_ref(ray, s);
    int32_t t = 0;
    bool front = true;
    const bool hit = intersect_sphere(ray, s, t_min, t_max, t, front);
    const double want = expected_root(ref, t_min, t_max);
    const double r_raw = s.radius.raw();
    // The decision may differ only within the discriminant's error band (or at the segment's ends).
    const double disc_raw = r_raw * r_raw - ref.q_raw * ref.q_raw;
    const bool near_tangent = std::fabs(disc_raw) <= 4 * ref.q_raw + 4 * r_raw;
    const double tol = sphere_tolerance(ref, std::isnan(want) ? ref.t1 : want);
    const bool near_ends = !std::isnan(want) && (std::fabs(want - t_min) <= tol || std::fabs(want - t_max) <= tol);
    const bool ends_any = ref.real && (std::fabs(ref.t0 - t_min) <= tol || std::fabs(ref.t1 - t_min) <= tol ||
                                       std::fabs(ref.t0 - t_max) <= tol || std::fabs(ref.t1 - t_max) <= tol);
    if (hit != !std::isnan(want)) {
        ++tally.band_disagreements;
        INFO("t_ref0 ", ref.t0, " t_ref1 ", ref.t1, " disc_raw ", disc_raw, " q_raw ", ref.q_raw, " lib t ", t);
        CHECK((near_tangent || near_ends || ends_any));
        return;
    }
    if (!hit) { ++tally.misses; return; }
    ++tally.hits;
    tally.worst_ratio = std::fmax(tally.worst_ratio, std::fabs(t - want) / tol);
    INFO("t ", t, " t_ref ", want, " tolerance ", tol, " q_raw ", ref.q_raw, " h ", ref.h);
    CHECK(std::fabs(t - want) <= tol);
    CHECK(front == (want == ref.t0));
}

}  // namespace

TEST_CASE("ray-sphere roots agree with double within the stated LSB tolerance") {
    std::mt19937 rng(21);
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    SphereTally tally;
    SUBCASE("random rays and spheres, from outside and inside") {
        for (int i = 0; i < 20000; ++i) {
            const double r = uni(0.05, 20);
            const Sphere s{q16(uni(-50, 50), uni(-50, 50), uni(-50, 50)), Q16::from_raw(int32_t(r * 65536)), 0};
            const V3 o{uni(-60, 60), uni(-60, 60), uni(-60, 60)}, c = d3(s.centre);
            // Aim near the sphere: about half the rays hit.
            const V3 aim{c.x + uni(-2, 2) * r - o.x, c.y + uni(-2, 2) * r - o.y, c.z + uni(-2, 2) * r - o.z};
            const Ray ray{q16(o.x, o.y, o.z), unit(aim.x, aim.y, aim.z)};
            check_sphere(ray, s, 16, INT32_MAX, tally);
        }
        MESSAGE("random: hits " << tally.hits << ", misses " << tally.misses << ", in-band disagreements "
                                << tally.band_disagreements << ", worst |t - t_ref| / tolerance " << tally.worst_ratio);
        CHECK(tally.hits > 1000);
    }
    SUBCASE("rays aimed at the sphere's centre from far away hit within 2 LSB + t 2^-28") {
        for (int i = 0; i < 2000; ++i) {
            const Vec3q16 c = q16(uni(-10, 10), uni(-10, 10), uni(-10, 10));
            const Vec3q16 o = q16(uni(-4000, 4000), uni(-4000, 4000), uni(-4000, 4000));
            const V3 oc = sub(d3(c), d3(o));
            const Ray ray{o, unit(oc.x, oc.y, oc.z)};
            const Sphere s{c, Q16::from_ratio(3, 2), 0};
            check_sphere(ray, s, 16, INT32_MAX, tally);
            const SphereRef ref = sphere_ref(ray, s);
            int32_t t = 0;
            bool front = false;
            REQUIRE(intersect_sphere(ray, s, 16, INT32_MAX, t, front));
            CHECK(std::fabs(t - ref.t0) <= 2 + ref.t0 * std::ldexp(1.0, -28) + 2 * ref.q_raw / ref.h);
        }
    }
    SUBCASE("grazing rays: tangent, just inside and just outside the rim") {
        for (int i = 0; i < 20000; ++i) {
            const double r = uni(0.2, 30);
            const Vec3q16 c = q16(uni(-20, 20), uni(-20, 20), uni(-20, 20));
            const Vec3q30 d = unit(uni(-1, 1), uni(-1, 1), uni(-1, 1));
            // Origin: the centre moved back along d and sideways by r (1 + e), e within a few 2^-16 / r.
            const V3 dd = d3(d);
            V3 side{dd.y, -dd.x, 0};
            if (std::fabs(dot(side, side)) < 1e-6) side = {0, dd.z, -dd.y};
            const double sl = std::sqrt(dot(side, side));
            const double off = r * (1 + uni(-4, 4) / (65536.0 * r));
            const double back = uni(r + 1, 80);
            const V3 cc = d3(c);
            const Ray ray{q16(cc.x - dd.x * back + side.x / sl * off, cc.y - dd.y * back + side.y / sl * off,
                              cc.z - dd.z * back + side.z / sl * off),
                          d};
            check_sphere(ray, {c, Q16::from_raw(int32_t(r * 65536)), 0}, 16, INT32_MAX, tally);
        }
        MESSAGE("grazing: hits " << tally.hits << ", misses " << tally.misses << ", in-band disagreements "
                                 << tally.band_disagreements << ", worst ratio " << tally.worst_ratio);
        CHECK(tally.hits > 100);
        CHECK(tally.misses > 100);
    }
    SUBCASE("rays starting inside meet the far side, from the back") {
        for (int i = 0; i < 5000; ++i) {
            const double r = uni(0.5, 40);
            const Vec3q16 c = q16(uni(-20, 20), uni(-20, 20), uni(-20, 20));
            const V3 cc = d3(c);
            const Ray ray{q16(cc.x + uni(-0.5, 0.5) * r, cc.y + uni(-0.5, 0.5) * r, cc.z + uni(-0.5, 0.5) * r),
                          unit(uni(-1, 1), uni(-1, 1), uni(-1, 1))};
            const Sphere s{c, Q16::from_raw(int32_t(r * 65536)), 0};
            int32_t t = 0;
            bool front = true;
            REQUIRE(intersect_sphere(ray, s, 16, INT32_MAX, t, front));
            CHECK_FALSE(front);
            check_sphere(ray, s, 16, INT32_MAX, tally);
        }
    }
}

TEST_CASE("ray-sphere: the segment bounds, spheres behind the origin and the epsilon") {
    const Sphere s{{Q16::from_int(0), Q16::from_int(0), Q16::from_int(-10)}, Q16::from_int(2), 0};
    const Vec3q30 fwd{Q30::from_raw(0), Q30::from_raw(0), Q30::from_raw(-Q30::kOne)};
    const Vec3q30 back{Q30::from_raw(0), Q30::from_raw(0), Q30::from_raw(Q30::kOne)};
    const Ray ray{{Q16::from_int(0), Q16::from_int(0), Q16::from_int(0)}, fwd};
    int32_t t = 0;
    bool front = false;
    REQUIRE(intersect_sphere(ray, s, 16, INT32_MAX, t, front));
    CHECK(t == Q16::from_int(8).raw());  // exact on the axis
    CHECK(front);
    CHECK_FALSE(intersect_sphere(ray, s, 16, Q16::from_int(8).raw(), t, front));  // open at t_max
    REQUIRE(intersect_sphere(ray, s, Q16::from_int(8).raw(), INT32_MAX, t, front));  // open at t_min: far root
    CHECK(t == Q16::from_int(12).raw());
    CHECK_FALSE(front);
    CHECK_FALSE(intersect_sphere({ray.origin, back}, s, 16, INT32_MAX, t, front));  // behind the origin
    // From a point on the surface going outward nothing is met beyond the epsilon.
    const Ray leaving{{Q16::from_int(0), Q16::from_int(0), Q16::from_int(-8)}, back};
    CHECK_FALSE(intersect_sphere(leaving, s, 16, INT32_MAX, t, front));
    // Tangent at exactly the radius: one root (a hit).
    const Ray tangent{{Q16::from_int(2), Q16::from_int(0), Q16::from_int(0)}, fwd};
    REQUIRE(intersect_sphere(tangent, s, 16, INT32_MAX, t, front));
    CHECK(t == Q16::from_int(10).raw());
    const Ray outside{{Q16::from_raw(Q16::from_int(2).raw() + 1), Q16::from_int(0), Q16::from_int(0)}, fwd};
    CHECK_FALSE(intersect_sphere(outside, s, 16, INT32_MAX, t, front));
}

TEST_CASE("ray-plane roots agree with double within 1 + (1 + t 2^-30) / |n.d| LSB; parallel rays miss") {
    std::mt19937 rng(33);
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    long hits = 0;
    double worst = 0;
    for (int i = 0; i < 50000; ++i) {
        const Plane pl{unit(uni(-1, 1), uni(-1, 1), uni(-1, 1)), Q16::from_raw(int32_t(uni(-100, 100) * 65536)), 0};
        const Ray ray{q16(uni(-100, 100), uni(-100, 100), uni(-100, 100)), unit(uni(-1, 1), uni(-1, 1), uni(-1, 1))};
        const V3 n = d3(pl.normal), o = d3(ray.origin), d = d3(ray.dir);
        const double nd = dot(n, d), t_ref = (pl.offset.raw() / 65536.0 - dot(n, o)) / nd * 65536;
        int32_t t = 0;
        bool front = false;
        const bool hit = intersect_plane(ray, pl, 16, INT32_MAX, t, front);
        const double tol = 1 + (1 + std::fabs(t_ref) * std::ldexp(1.0, -30)) / std::fabs(nd);
        if (!hit) {
            INFO("t_ref ", t_ref, " n.d ", nd);
            CHECK((t_ref <= 16 + tol || t_ref > 8191 * 65536.0));  // behind, at the origin, or past the world
            continue;
        }
        ++hits;
        CHECK(front == (nd < 0));
        worst = std::fmax(worst, std::fabs(t - t_ref) / tol);
        CHECK(std::fabs(t - t_ref) <= tol);
    }
    MESSAGE("plane: hits " << hits << ", worst |t - t_ref| / tolerance " << worst);
    CHECK(hits > 10000);
    SUBCASE("parallel rays, rays in the plane and rays from behind") {
        const Plane ground{{Q30::from_raw(0), Q30::from_raw(Q30::kOne), Q30::from_raw(0)}, Q16::from_int(-1), 0};
        const Vec3q30 along{Q30::from_raw(Q30::kOne), Q30::from_raw(0), Q30::from_raw(0)};
        int32_t t = 0;
        bool front = false;
        CHECK_FALSE(intersect_plane({{Q16::from_int(0), Q16::from_int(0), Q16::from_int(0)}, along}, ground, 16, INT32_MAX, t, front));
        CHECK_FALSE(intersect_plane({{Q16::from_int(0), Q16::from_int(-1), Q16::from_int(0)}, along}, ground, 16, INT32_MAX, t, front));
        // n.d of 2^-32: rounds to 0 in Q30, so the ray counts as parallel.
        const Vec3q30 almost{Q30::from_raw(Q30::kOne), Q30::from_raw(-1), Q30::from_raw(0)};
        CHECK_FALSE(intersect_plane({{Q16::from_int(0), Q16::from_int(0), Q16::from_int(0)}, almost}, ground, 16, INT32_MAX, t, front));
        const Vec3q30 down{Q30::from_raw(0), Q30::from_raw(-Q30::kOne), Q30::from_raw(0)};
        REQUIRE(intersect_plane({{Q16::from_int(3), Q16::from_int(4), Q16::from_int(5)}, down}, ground, 16, INT32_MAX, t, front));
        CHECK(t == Q16::from_int(5).raw());
        CHECK(front);
        const Vec3q30 up{Q30::from_raw(0), Q30::from_raw(Q30::kOne), Q30::from_raw(0)};
        REQUIRE(intersect_plane({{Q16::from_int(3), Q16::from_int(-4), Q16::from_int(5)}, up}, ground, 16, INT32_MAX, t, front));
        CHECK(t == Q16::from_int(3).raw());
        CHECK_FALSE(front);  // from below: the back side
        // A hit outside the world cube is a miss (the plane is clipped to |coordinate| < 2^13).
        const Vec3q30 shallow = unit(1, -1.0 / 10000, 0);
        CHECK_FALSE(intersect_plane({{Q16::from_int(0), Q16::from_int(0), Q16::from_int(0)}, shallow}, ground, 16, INT32_MAX, t, front));
        // ... also when the hit lies so far out that p + t d leaves int32 (t = 25,000 units from z = -8,000:
        // z about -33,000 units, beyond Q16). It summed in int32 before (UBSan: signed overflow).
        const Vec3q30 grazing = unit(0, -1.0 / 25000, -1);
        const Vec3q16 far_origin{Q16::from_int(0), Q16::from_int(0), Q16::from_int(-8000)};
        CHECK_FALSE(intersect_plane({far_origin, grazing}, ground, 16, INT32_MAX, t, front));
        const Vec3q30 steeper = unit(0, -1.0 / 100, -1);  // meets the ground 100 units on: a hit
        REQUIRE(intersect_plane({far_origin, steeper}, ground, 16, INT32_MAX, t, front));
        CHECK(std::abs(t - Q16::from_int(100).raw()) <= Q16::from_int(1).raw());
    }
}

TEST_CASE("along_in_world equals in_world(point_along) wherever point_along fits, and is false past int32") {
    std::mt19937 rng(11);
    auto raw = [&](int32_t lim) { return static_cast<int32_t>(rng() % (2u * static_cast<uint32_t>(lim) + 1u)) - lim; };
    long inside = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3q16 p{Q16::from_raw(raw(kRayWorldLimitRaw - 1)), Q16::from_raw(raw(kRayWorldLimitRaw - 1)),
                        Q16::from_raw(raw(kRayWorldLimitRaw - 1))};
        Vec3q30 d{};
        if (!unit_q30(raw(1000000), raw(1000000), raw(1000000), d)) continue;
        const int32_t t = static_cast<int32_t>(rng() % (uint32_t{1} << 30));  // |t d| < 2^30: p + t d fits int32
        const bool expect = in_world(point_along(p, t, d));
        CHECK(along_in_world(p, t, d) == expect);
        inside += expect;
    }
    MESSAGE(inside << " of 100000 points inside");
    CHECK(inside > 1000);
    CHECK(inside < 99000);
    const Vec3q30 axis{Q30::from_raw(0), Q30::from_raw(0), Q30::from_raw(-Q30::kOne - 1)};
    const Vec3q16 edge{Q16::from_int(0), Q16::from_int(0), Q16::from_raw(-kRayWorldLimitRaw + 1)};
    CHECK_FALSE(along_in_world(edge, INT32_MAX, axis));
    CHECK_FALSE(along_in_world(edge, 1, axis));
    CHECK(along_in_world(edge, 0, axis));
}

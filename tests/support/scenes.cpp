// Hard-scene generators. Only +, -, *, / and sqrt (correctly rounded in IEEE 754) touch the random numbers, so a
// seed gives the same scene with any standard library (unless the compiler contracts a * b + c into FMA).
#include "support/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace hider::ref {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kFovyDeg = 60.0;

Vec3d add(const Vec3d& a, const Vec3d& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d mul(const Vec3d& a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(const Vec3d& a, const Vec3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3d unit(const Vec3d& a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

// Uniform double in [0, 1) from 53 random bits: two draws, the first supplies the high 27 bits.
double uniform01(std::mt19937& rng) {
    const uint64_t hi = static_cast<uint64_t>(rng()) >> 5;
    const uint64_t lo = static_cast<uint64_t>(rng()) >> 6;
    return static_cast<double>(hi * 67108864u + lo) / 9007199254740992.0;  // 2^26, 2^53
}

double uniform(std::mt19937& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }

// Each coordinate uniform in [lo, hi), drawn x, then y, then z.
Vec3d uniform_vec(std::mt19937& rng, double lo, double hi) {
    const double x = uniform(rng, lo, hi);
    const double y = uniform(rng, lo, hi);
    const double z = uniform(rng, lo, hi);
    return {x, y, z};
}

// Uniformly distributed unit vector: rejection sampling in the unit ball.
Vec3d random_direction(std::mt19937& rng) {
    for (;;) {
        const Vec3d p = uniform_vec(rng, -1.0, 1.0);
        const double len2 = dot(p, p);
        if (len2 > 0.01 && len2 <= 1.0) return unit(p);
    }
}

// Random unit vector orthogonal to the unit vector `axis`.
Vec3d random_perpendicular(std::mt19937& rng, const Vec3d& axis) {
    for (;;) {
        const Vec3d c = cross(axis, random_direction(rng));
        if (dot(c, c) > 0.01) return unit(c);
    }
}

RefCamera make_camera(const Vec3d& eye, const Vec3d& target, double near, double far) {
    return RefCamera{eye, target, {0.0, 1.0, 0.0}, kFovyDeg, near, far, kWidth, kHeight};
}

void add_tri(RefScene& scene, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    scene.tris.push_back(RefTriangle{{a, b, c}, static_cast<uint32_t>(scene.tris.size() + 1)});
}

// Adds the two triangles of quad a, b, c, d (in that order around it; the winding of a, b, c is kept).
void add_quad(RefScene& scene, const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
    add_tri(scene, a, b, c);
    add_tri(scene, a, c, d);
}

// Closed box, 12 triangles, CCW from outside, corners shared exactly between faces. u, v, w: right-handed
// orthogonal axes (w along u x v) scaled by the half extents. Corner bit 0/1/2 set means +u/+v/+w.
void add_box(RefScene& scene, const Vec3d& centre, const Vec3d& u, const Vec3d& v, const Vec3d& w) {
    Vec3d corner[8];
    for (int i = 0; i < 8; ++i) {
        const Vec3d pu = (i & 1) ? u : mul(u, -1.0);
        const Vec3d pv = (i & 2) ? v : mul(v, -1.0);
        const Vec3d pw = (i & 4) ? w : mul(w, -1.0);
        corner[i] = add(add(add(centre, pu), pv), pw);
    }
    // Per face with outward normal n and in-face axes a x b = n: corners (-a-b, +a-b, +a+b, -a+b).
    constexpr int kFaces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (const auto& f : kFaces) add_quad(scene, corner[f[0]], corner[f[1]], corner[f[2]], corner[f[3]]);
}

std::string name_of(const char* kind, uint32_t seed, int count) {
    return std::string(kind) + "-" + std::to_string(seed) + "-" + std::to_string(count);
}

}  // namespace

RefScene soup(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    RefScene scene;
    scene.name = name_of("soup", seed, count);
    scene.cam = make_camera({2.5, 2.0, 3.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);  // cube spans d in [3.0, 6.5]
    for (int i = 0; i < count; ++i) {
        const Vec3d centre = uniform_vec(rng, -1.0, 1.0);
        const double t = uniform01(rng);
        const double size = 0.02 + 0.78 * t * t * t;  // mostly small, a few large
        Vec3d v[3];
        for (Vec3d& p : v) {
            p = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
            p = {std::clamp(p.x, -1.0, 1.0), std::clamp(p.y, -1.0, 1.0), std::clamp(p.z, -1.0, 1.0)};
        }
        add_tri(scene, v[0], v[1], v[2]);
    }
    return scene;
}

RefScene slivers(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    RefScene scene;
    scene.name = name_of("slivers", seed, count);
    scene.cam = make_camera({2.5, 2.0, 3.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);  // all within 1.8 of the origin
    for (int i = 0; i < count; ++i) {
        const Vec3d centre = uniform_vec(rng, -0.35, 0.35);
        const Vec3d dir = random_direction(rng);
        const Vec3d perp = random_perpendicular(rng, dir);
        const double length = uniform(rng, 1.2, 2.2);
        const double altitude = length / uniform(rng, 200.0, 1000.0);
        const double apex_along = uniform(rng, -0.4, 0.4) * length;
        const Vec3d half = mul(dir, length / 2.0);
        const Vec3d apex = add(add(centre, mul(dir, apex_along)), mul(perp, altitude));
        add_tri(scene, sub(centre, half), add(centre, half), apex);
    }
    return scene;
}

RefScene huge_triangles(uint32_t seed) {
    std::mt19937 rng(seed);
    RefScene scene;
    scene.name = name_of("huge_triangles", seed, 32);
    scene.cam = make_camera({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 0.5, 200.0);  // view space == world space
    for (int i = 0; i < 6; ++i) {
        Vec3d v[3];
        for (Vec3d& p : v) {
            const double x = uniform(rng, -150.0, 150.0);
            const double y = uniform(rng, -150.0, 150.0);
            const double z = uniform(rng, -150.0, 40.0);  // some vertices behind the eye
            p = {x, y, z};
        }
        add_tri(scene, v[0], v[1], v[2]);
    }
    add_tri(scene, {-400.0, -1.5, 300.0}, {400.0, -1.5, 300.0}, {0.0, -1.5, -150.0});  // floor under the eye, faces up
    // Wall in the plane z = -0.45 - y: d < near = 0.5 below the view ray y/d = 0.1, so its lower part is clipped.
    add_tri(scene, {-40.0, -30.0, 29.55}, {40.0, -30.0, 29.55}, {0.0, 30.0, -30.45});
    for (int i = 0; i < 24; ++i) {
        const double d = uniform(rng, 2.0, 8.0);
        const Vec3d centre = {uniform(rng, -0.45, 0.45) * d, uniform(rng, -0.35, 0.35) * d, -d};
        const double size = uniform(rng, 0.1, 0.5) * d / 4.0;
        Vec3d v[3];
        for (Vec3d& p : v) p = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
        add_tri(scene, v[0], v[1], v[2]);
    }
    return scene;
}

RefScene cyclic_bars() {
    RefScene scene;
    scene.name = "cyclic_bars";
    scene.cam = make_camera({0.0, 0.0, 4.5}, {0.0, 0.0, 0.0}, 1.0, 20.0);
    // Bar i runs along the triangle side corner[i] -> corner[i+1] (extended by kExtend at both ends), rising from
    // z = -kRise at corner[i] to +kRise at corner[i+1]; at every corner the arriving bar lies over the leaving one.
    constexpr double kRise = 0.3;
    constexpr double kExtend = 0.6;
    const double half_sqrt3 = std::sqrt(3.0) / 2.0;
    const Vec3d corner[3] = {{0.0, 1.0, 0.0}, {-half_sqrt3, -0.5, 0.0}, {half_sqrt3, -0.5, 0.0}};
    for (int i = 0; i < 3; ++i) {
        const Vec3d from = add(corner[i], {0.0, 0.0, -kRise});
        const Vec3d to = add(corner[(i + 1) % 3], {0.0, 0.0, kRise});
        const Vec3d along = unit(sub(to, from));
        const Vec3d side = unit(Vec3d{-along.y, along.x, 0.0});
        const double half_length = std::sqrt(dot(sub(to, from), sub(to, from))) / 2.0 + kExtend;
        const Vec3d centre = mul(add(from, to), 0.5);
        add_box(scene, centre, mul(along, half_length), mul(side, 0.2), mul(cross(along, side), 0.05));
    }
    return scene;
}

RefScene piercing() {
    RefScene scene;
    scene.name = "piercing";
    scene.cam = make_camera({0.0, 0.0, 8.0}, {0.0, 0.0, 0.0}, 1.0, 20.0);
    // Left: id 1 lies in z = 0, id 2 in z = -(x + 2.5) / 1.8; they cross along x = -2.5 (id 2 nearer on the left).
    add_tri(scene, {-4.5, -1.5, 0.0}, {-0.5, -1.5, 0.0}, {-2.5, 1.5, 0.0});
    add_tri(scene, {-4.3, -1.0, 1.0}, {-0.7, -1.0, -1.0}, {-2.5, 1.6, 0.0});
    // Right: a quad in z = 0 and a triangle through it along y = 0 (its upper half is behind the quad).
    add_quad(scene, {1.0, -1.5, 0.0}, {4.0, -1.5, 0.0}, {4.0, 1.5, 0.0}, {1.0, 1.5, 0.0});
    add_tri(scene, {1.8, -0.8, 1.5}, {3.2, -0.8, 1.5}, {2.5, 0.8, -1.5});
    return scene;
}

RefScene boxes(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    RefScene scene;
    scene.name = name_of("boxes", seed, count);
    scene.cam = make_camera({4.0, 3.0, 5.5}, {0.0, 0.0, 0.0}, 1.0, 20.0);  // boxes stay within 2.8 of the origin
    for (int i = 0; i < count; ++i) {
        const Vec3d centre = uniform_vec(rng, -1.0, 1.0);
        const Vec3d u = random_direction(rng);
        const Vec3d v = random_perpendicular(rng, u);
        const Vec3d w = cross(u, v);
        const double hu = uniform(rng, 0.2, 0.6);
        const double hv = uniform(rng, 0.2, 0.6);
        const double hw = uniform(rng, 0.2, 0.6);
        add_box(scene, centre, mul(u, hu), mul(v, hv), mul(w, hw));
    }
    return scene;
}

}  // namespace hider::ref

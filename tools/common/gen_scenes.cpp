// Scene generators (see gen_scenes.hpp). Each draws from its own std::mt19937 in a fixed order.
#include "common/gen_scenes.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <map>
#include <ostream>
#include <random>
#include <sstream>
#include <tuple>

namespace hider::tool::gen {
namespace {

P3 add(const P3& a, const P3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
P3 sub(const P3& a, const P3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P3 mul(const P3& a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(const P3& a, const P3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
P3 cross(const P3& a, const P3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
P3 unit(const P3& a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

// Uniform double in [0, 1) from 53 random bits: two draws, the first supplies the high 27 bits.
double uniform01(std::mt19937& rng) {
    const uint64_t hi = static_cast<uint64_t>(rng()) >> 5;
    const uint64_t lo = static_cast<uint64_t>(rng()) >> 6;
    return static_cast<double>(hi * 67108864u + lo) / 9007199254740992.0;  // 2^26, 2^53
}

double uniform(std::mt19937& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }

// Each coordinate uniform in [lo, hi), drawn x, then y, then z.
P3 uniform_vec(std::mt19937& rng, double lo, double hi) {
    const double x = uniform(rng, lo, hi);
    const double y = uniform(rng, lo, hi);
    const double z = uniform(rng, lo, hi);
    return {x, y, z};
}

// Uniformly distributed unit vector: rejection sampling in the unit ball.
P3 random_direction(std::mt19937& rng) {
    for (;;) {
        const P3 p = uniform_vec(rng, -1.0, 1.0);
        const double len2 = dot(p, p);
        if (len2 > 0.01 && len2 <= 1.0) return unit(p);
    }
}

// Random unit vector orthogonal to the unit vector `axis`.
P3 random_perpendicular(std::mt19937& rng, const P3& axis) {
    for (;;) {
        const P3 c = cross(axis, random_direction(rng));
        if (dot(c, c) > 0.01) return unit(c);
    }
}

GenScene make(const std::string& name, const P3& eye, const P3& target, double near, double far) {
    GenScene s;
    s.name = name;
    s.eye = eye;
    s.target = target;
    s.up = {0.0, 1.0, 0.0};
    s.near = near;
    s.far = far;
    return s;
}

void add_face(GenScene& s, std::vector<P3> v) { s.faces.push_back(Face{std::move(v), static_cast<uint32_t>(s.faces.size() + 1)}); }
void add_tri(GenScene& s, const P3& a, const P3& b, const P3& c) { add_face(s, {a, b, c}); }

// Adds the two triangles of quad a, b, c, d (in that order around it; the winding of a, b, c is kept).
void add_quad(GenScene& s, const P3& a, const P3& b, const P3& c, const P3& d) {
    add_tri(s, a, b, c);
    add_tri(s, a, c, d);
}

// Closed box, 12 triangles, CCW from outside, corners shared exactly between faces. u, v, w: right-handed
// orthogonal axes (w along u x v) scaled by the half extents. Corner bit 0/1/2 set means +u/+v/+w.
void add_box(GenScene& s, const P3& centre, const P3& u, const P3& v, const P3& w) {
    P3 corner[8];
    for (int i = 0; i < 8; ++i) {
        const P3 pu = (i & 1) ? u : mul(u, -1.0);
        const P3 pv = (i & 2) ? v : mul(v, -1.0);
        const P3 pw = (i & 4) ? w : mul(w, -1.0);
        corner[i] = add(add(add(centre, pu), pv), pw);
    }
    // Per face with outward normal n and in-face axes a x b = n: corners (-a-b, +a-b, +a+b, -a+b).
    constexpr int kFaces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (const auto& f : kFaces) add_quad(s, corner[f[0]], corner[f[1]], corner[f[2]], corner[f[3]]);
}

// An axis-aligned box from (x0, y0, z0) to (x1, y1, z1).
void add_aabb(GenScene& s, const P3& lo, const P3& hi) {
    const P3 c = mul(add(lo, hi), 0.5);
    add_box(s, c, {(hi.x - lo.x) / 2, 0, 0}, {0, (hi.y - lo.y) / 2, 0}, {0, 0, (hi.z - lo.z) / 2});
}

std::string name_of(const char* kind, uint32_t seed, int count) {
    return std::string(kind) + "-" + std::to_string(seed) + "-" + std::to_string(count);
}

}  // namespace

GenScene soup(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("soup", seed, count), {2.5, 2.0, 3.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);  // d in [3.0, 6.5]
    for (int i = 0; i < count; ++i) {
        const P3 centre = uniform_vec(rng, -1.0, 1.0);
        const double t = uniform01(rng);
        const double size = 0.02 + 0.78 * t * t * t;  // mostly small, a few large
        P3 v[3];
        for (P3& p : v) {
            p = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
            p = {std::clamp(p.x, -1.0, 1.0), std::clamp(p.y, -1.0, 1.0), std::clamp(p.z, -1.0, 1.0)};
        }
        add_tri(s, v[0], v[1], v[2]);
    }
    return s;
}

GenScene dense_soup(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("dense", seed, count), {2.5, 2.0, 3.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);
    for (int i = 0; i < count; ++i) {
        const P3 centre = uniform_vec(rng, -0.7, 0.7);
        const double size = uniform(rng, 0.25, 0.6);
        const P3 a = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
        const P3 b = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
        const P3 c = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
        add_tri(s, a, b, c);
    }
    return s;
}

GenScene slivers(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("slivers", seed, count), {2.5, 2.0, 3.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);
    for (int i = 0; i < count; ++i) {
        const P3 centre = uniform_vec(rng, -0.35, 0.35);
        const P3 dir = random_direction(rng);
        const P3 perp = random_perpendicular(rng, dir);
        const double length = uniform(rng, 1.2, 2.2);
        const double altitude = length / uniform(rng, 200.0, 1000.0);
        const double apex_along = uniform(rng, -0.4, 0.4) * length;
        const P3 half = mul(dir, length / 2.0);
        const P3 apex = add(add(centre, mul(dir, apex_along)), mul(perp, altitude));
        add_tri(s, sub(centre, half), add(centre, half), apex);
    }
    return s;
}

GenScene huge_triangles(uint32_t seed) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("huge_triangles", seed, 32), {0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 0.5, 200.0);
    for (int i = 0; i < 6; ++i) {
        P3 v[3];
        for (P3& p : v) {
            const double x = uniform(rng, -150.0, 150.0);
            const double y = uniform(rng, -150.0, 150.0);
            const double z = uniform(rng, -150.0, 40.0);  // some vertices behind the eye
            p = {x, y, z};
        }
        add_tri(s, v[0], v[1], v[2]);
    }
    add_tri(s, {-400.0, -1.5, 300.0}, {400.0, -1.5, 300.0}, {0.0, -1.5, -150.0});  // floor under the eye, faces up
    // Wall in the plane z = -0.45 - y: d < near = 0.5 below the view ray y/d = 0.1, so its lower part is clipped.
    add_tri(s, {-40.0, -30.0, 29.55}, {40.0, -30.0, 29.55}, {0.0, 30.0, -30.45});
    for (int i = 0; i < 24; ++i) {
        const double d = uniform(rng, 2.0, 8.0);
        const P3 centre = {uniform(rng, -0.45, 0.45) * d, uniform(rng, -0.35, 0.35) * d, -d};
        const double size = uniform(rng, 0.1, 0.5) * d / 4.0;
        P3 v[3];
        for (P3& p : v) p = add(centre, mul(uniform_vec(rng, -1.0, 1.0), size));
        add_tri(s, v[0], v[1], v[2]);
    }
    return s;
}

GenScene cyclic_bars() {
    GenScene s = make("cyclic_bars", {0.0, 0.0, 4.5}, {0.0, 0.0, 0.0}, 1.0, 20.0);
    // Bar i runs along the triangle side corner[i] -> corner[i+1] (extended by kExtend at both ends), rising from
    // z = -kRise at corner[i] to +kRise at corner[i+1]; at every corner the arriving bar lies over the leaving one.
    constexpr double kRise = 0.3;
    constexpr double kExtend = 0.6;
    const double half_sqrt3 = std::sqrt(3.0) / 2.0;
    const P3 corner[3] = {{0.0, 1.0, 0.0}, {-half_sqrt3, -0.5, 0.0}, {half_sqrt3, -0.5, 0.0}};
    for (int i = 0; i < 3; ++i) {
        const P3 from = add(corner[i], {0.0, 0.0, -kRise});
        const P3 to = add(corner[(i + 1) % 3], {0.0, 0.0, kRise});
        const P3 along = unit(sub(to, from));
        const P3 side = unit(P3{-along.y, along.x, 0.0});
        const double half_length = std::sqrt(dot(sub(to, from), sub(to, from))) / 2.0 + kExtend;
        const P3 centre = mul(add(from, to), 0.5);
        add_box(s, centre, mul(along, half_length), mul(side, 0.2), mul(cross(along, side), 0.05));
    }
    return s;
}

GenScene piercing() {
    GenScene s = make("piercing", {0.0, 0.0, 8.0}, {0.0, 0.0, 0.0}, 1.0, 20.0);
    // Left: id 1 lies in z = 0, id 2 in z = -(x + 2.5) / 1.8; they cross along x = -2.5 (id 2 nearer on the left).
    add_tri(s, {-4.5, -1.5, 0.0}, {-0.5, -1.5, 0.0}, {-2.5, 1.5, 0.0});
    add_tri(s, {-4.3, -1.0, 1.0}, {-0.7, -1.0, -1.0}, {-2.5, 1.6, 0.0});
    // Right: a quad in z = 0 and a triangle through it along y = 0 (its upper half is behind the quad).
    add_quad(s, {1.0, -1.5, 0.0}, {4.0, -1.5, 0.0}, {4.0, 1.5, 0.0}, {1.0, 1.5, 0.0});
    add_tri(s, {1.8, -0.8, 1.5}, {3.2, -0.8, 1.5}, {2.5, 0.8, -1.5});
    return s;
}

GenScene boxes(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("boxes", seed, count), {4.0, 3.0, 5.5}, {0.0, 0.0, 0.0}, 1.0, 20.0);
    for (int i = 0; i < count; ++i) {
        const P3 centre = uniform_vec(rng, -1.0, 1.0);
        const P3 u = random_direction(rng);
        const P3 v = random_perpendicular(rng, u);
        const P3 w = cross(u, v);
        const double hu = uniform(rng, 0.2, 0.6);
        const double hv = uniform(rng, 0.2, 0.6);
        const double hw = uniform(rng, 0.2, 0.6);
        add_box(s, centre, mul(u, hu), mul(v, hv), mul(w, hw));
    }
    return s;
}

GenScene mikado(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("mikado", seed, count), {2.5, 2.0, 3.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);
    for (int i = 0; i < count; ++i) {
        const P3 centre = uniform_vec(rng, -0.4, 0.4);
        const P3 dir = random_direction(rng);
        const P3 across = random_perpendicular(rng, dir);
        const P3 half = mul(dir, uniform(rng, 1.0, 1.5));
        const P3 side = mul(across, uniform(rng, 0.02, 0.05));
        const P3 a = sub(centre, half), b = add(centre, half);
        add_face(s, {sub(a, side), sub(b, side), add(b, side), add(a, side)});
    }
    return s;
}

GenScene stacked_boxes(uint32_t seed, int count) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("stacked", seed, count), {3.0, 2.5, 4.0}, {0.0, 0.0, 0.0}, 0.5, 20.0);
    double base = -1.5;
    for (int i = 0; i < count; ++i) {
        const double angle = uniform(rng, 0.0, 6.283185307179586);
        const double hx = uniform(rng, 0.3, 0.7), hy = uniform(rng, 0.15, 0.35), hz = uniform(rng, 0.3, 0.7);
        const double sink = uniform(rng, 0.2, 0.6) * hy;  // how deep it sits in the box below
        const P3 u = {std::cos(angle), 0.0, std::sin(angle)};
        const P3 w = {-std::sin(angle), 0.0, std::cos(angle)};
        const P3 centre = {uniform(rng, -0.15, 0.15), base + hy - (i == 0 ? 0.0 : sink), uniform(rng, -0.15, 0.15)};
        add_box(s, centre, mul(u, hx), {0.0, hy, 0.0}, mul(w, hz));  // w = u x up: right-handed
        base = centre.y + hy;
    }
    s.target = {0.0, base / 2 - 0.75, 0.0};
    return s;
}

GenScene ground_grid(uint32_t seed, int n, int posts) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("grid", seed, n) + "-" + std::to_string(posts), {0.0, 1.0, 0.0}, {0.0, 0.6, -4.0}, 0.5, 60.0);
    // Tiles from x in [-20, 20], z in [-40, 10]: under the eye and behind it, so the near plane cuts them.
    const double x0 = -20.0, x1 = 20.0, z0 = 10.0, z1 = -40.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
            const double za = z0 + (z1 - z0) * j / n, zb = z0 + (z1 - z0) * (j + 1) / n;
            add_face(s, {{xa, 0.0, za}, {xb, 0.0, za}, {xb, 0.0, zb}, {xa, 0.0, zb}});  // CCW from above
        }
    for (int k = 0; k < posts; ++k) {
        const P3 c = {uniform(rng, -6.0, 6.0), 0.0, uniform(rng, -30.0, -2.0)};
        const double h = uniform(rng, 0.3, 3.0), r = uniform(rng, 0.2, 0.8);
        add_aabb(s, {c.x - r, -0.2, c.z - r}, {c.x + r, h, c.z + r});  // sunk into the ground a little
    }
    return s;
}

GenScene city(uint32_t seed, int nx, int nz, CityView view) {
    std::mt19937 rng(seed);
    const double block = 1.0, street = 0.5, pitch = block + street;
    const double width = nx * pitch + street, depth = nz * pitch + street;
    GenScene s = make(name_of("city", seed, nx) + "-" + std::to_string(nz) + (view == CityView::above ? "-above" : "-street"),
                      {0, 0, 0}, {0, 0, 0}, 0.5, 200.0);
    // Ground: one tile per block cell (two triangles each), from (0, 0) to (width, depth) in x and z.
    const int gx = nx + 1, gz = nz + 1;
    for (int j = 0; j < gz; ++j)
        for (int i = 0; i < gx; ++i) {
            const double xa = width * i / gx, xb = width * (i + 1) / gx, za = depth * j / gz, zb = depth * (j + 1) / gz;
            add_quad(s, {xa, 0.0, zb}, {xb, 0.0, zb}, {xb, 0.0, za}, {xa, 0.0, za});  // CCW from above
        }
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = street + i * pitch, z = street + j * pitch;
            const double h = uniform(rng, 1.0, 6.0), inset = uniform(rng, 0.0, 0.15);
            add_aabb(s, {x + inset, -0.1, z + inset}, {x + block - inset, h, z + block - inset});
        }
    if (view == CityView::above) {
        s.eye = {width * 0.5, std::max(width, depth) * 0.9, depth * 1.25};
        s.target = {width * 0.5, 0.0, depth * 0.5};
    } else {
        // Street level in the middle street (between block columns nx/2 - 1 and nx/2), looking along it:
        // blocks on both sides hide those behind them.
        const int col = nx / 2;
        const double sx = col * pitch + street * 0.5;
        s.eye = {sx, 0.3, depth + 0.6};
        s.target = {sx, 0.5, 0.0};
    }
    return s;
}

GenScene big_face(int n) {
    GenScene s = make("bigface-" + std::to_string(n), {0.3, 1.5, 2.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);
    std::vector<P3> v;
    for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / n;
        const double x = std::cos(a), z = std::sin(a);
        v.push_back({x, 0.3 * x, -z});  // tilted circle, CCW seen from above
    }
    add_face(s, std::move(v));
    return s;
}

GenScene star_face(uint32_t seed, int n) {
    std::mt19937 rng(seed);
    GenScene s = make(name_of("star", seed, n), {0.3, 1.5, 2.5}, {0.0, 0.0, 0.0}, 0.5, 10.0);
    std::vector<P3> v;
    for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / n, r = uniform(rng, 0.3, 1.0);
        const double x = r * std::cos(a), z = r * std::sin(a);
        v.push_back({x, 0.3 * x, -z});
    }
    add_face(s, std::move(v));
    return s;
}

bool by_name(const std::string& name, GenScene& out, std::string& why) {
    std::vector<std::string> parts;
    std::istringstream in(name);
    for (std::string p; std::getline(in, p, '-');) parts.push_back(p);
    std::string bad;  // the first number of a known kind that is malformed or out of its range
    auto num = [&](size_t i, long lo, long hi, long& v) {
        if (i >= parts.size()) return false;
        char* end = nullptr;
        errno = 0;
        v = std::strtol(parts[i].c_str(), &end, 10);
        const bool ok = !parts[i].empty() && *end == '\0' && errno == 0 && v >= lo && v <= hi;
        if (!ok && bad.empty())
            bad = "'" + parts[i] + "' (field " + std::to_string(i) + ") is not a whole number in " + std::to_string(lo) +
                  ".." + std::to_string(hi);
        return ok;
    };
    long a = 0, b = 0, c = 0;
    const std::string& k = parts.empty() ? name : parts[0];
    const size_t n = parts.size();
    if (k == "soup" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 1, 100000, b)) out = soup(uint32_t(a), int(b));
    else if (k == "dense" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 1, 100000, b)) out = dense_soup(uint32_t(a), int(b));
    else if (k == "slivers" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 1, 100000, b)) out = slivers(uint32_t(a), int(b));
    else if (k == "huge" && n == 2 && num(1, 0, 1L << 31, a)) out = huge_triangles(uint32_t(a));
    else if (name == "cyclic-bars") out = cyclic_bars();
    else if (name == "piercing") out = piercing();
    else if (k == "boxes" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 1, 10000, b)) out = boxes(uint32_t(a), int(b));
    else if (k == "mikado" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 1, 10000, b)) out = mikado(uint32_t(a), int(b));
    else if (k == "stacked" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 1, 1000, b)) out = stacked_boxes(uint32_t(a), int(b));
    else if (k == "grid" && n == 4 && num(1, 0, 1L << 31, a) && num(2, 1, 200, b) && num(3, 0, 1000, c))
        out = ground_grid(uint32_t(a), int(b), int(c));
    else if (k == "city" && n == 5 && num(1, 0, 1L << 31, a) && num(2, 1, 100, b) && num(3, 1, 100, c) &&
             (parts[4] == "above" || parts[4] == "street"))
        out = city(uint32_t(a), int(b), int(c), parts[4] == "above" ? CityView::above : CityView::street);
    else if (k == "bigface" && n == 2 && num(1, 3, 60000, a)) out = big_face(int(a));
    else if (k == "star" && n == 3 && num(1, 0, 1L << 31, a) && num(2, 3, 60000, b)) out = star_face(uint32_t(a), int(b));
    else {
        why = bad.empty() ? "unknown scene '" + name + "' (known: " + name_patterns() + ")"
                          : "scene '" + name + "': " + bad;
        return false;
    }
    return true;
}

std::string name_patterns() {
    return "soup-SEED-N, dense-SEED-N, slivers-SEED-N, huge-SEED, cyclic-bars, piercing, boxes-SEED-N, mikado-SEED-N, stacked-SEED-N, "
           "grid-SEED-N-POSTS, city-SEED-NX-NZ-above|street, bigface-N, star-SEED-N";
}

void write_obj(const GenScene& s, std::ostream& out) {
    std::map<std::tuple<double, double, double>, size_t> index;
    std::vector<P3> verts;
    std::vector<std::vector<size_t>> faces;
    for (const Face& f : s.faces) {
        std::vector<size_t> idx;
        for (const P3& p : f.v) {
            const auto key = std::make_tuple(p.x, p.y, p.z);
            auto it = index.find(key);
            if (it == index.end()) {
                it = index.emplace(key, verts.size()).first;
                verts.push_back(p);
            }
            idx.push_back(it->second + 1);
        }
        faces.push_back(idx);
    }
    out << "# " << s.name << " (generated by tools/common/gen_scenes.cpp)\n";
    out.precision(17);
    for (const P3& p : verts) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& f : faces) {
        out << 'f';
        for (size_t i : f) out << ' ' << i;
        out << '\n';
    }
}

std::string camera_flags(const GenScene& s) {
    std::ostringstream o;
    o.precision(17);
    o << "--eye " << s.eye.x << ',' << s.eye.y << ',' << s.eye.z << " --target " << s.target.x << ',' << s.target.y << ','
      << s.target.z << " --up " << s.up.x << ',' << s.up.y << ',' << s.up.z << " --fov " << s.fovy_deg << " --near " << s.near
      << " --far " << s.far << " --size " << s.width << 'x' << s.height;
    return o.str();
}

ObjModel obj_model(const GenScene& s) {
    ObjModel m;
    std::map<std::tuple<double, double, double>, int32_t> index;
    int line = 2;  // after write_obj's comment line; vertices come first there, so only ids and order matter
    for (const Face& f : s.faces) {
        ObjFace face;
        for (const P3& p : f.v) {
            const auto key = std::make_tuple(p.x, p.y, p.z);
            auto it = index.find(key);
            if (it == index.end()) {
                it = index.emplace(key, static_cast<int32_t>(m.vertices.size())).first;
                m.vertices.push_back({p.x, p.y, p.z});
            }
            face.v.push_back(it->second);
        }
        face.id = f.id;
        face.line = line++;
        m.faces.push_back(std::move(face));
    }
    return m;
}

CameraArgs camera_args(const GenScene& s) {
    CameraArgs c;
    c.eye = Vec3d{s.eye.x, s.eye.y, s.eye.z};
    c.target = Vec3d{s.target.x, s.target.y, s.target.z};
    c.up = Vec3d{s.up.x, s.up.y, s.up.z};
    c.fov_deg = s.fovy_deg;
    c.near = s.near;
    c.far = s.far;
    c.width = s.width;
    c.height = s.height;
    return c;
}

}  // namespace hider::tool::gen

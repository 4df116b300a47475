// Ray-triangle tests and the BVH (lib/hider/ray/triangle.hpp, bvh.hpp, tools/common/bvh_build.*):
// the walk equals a brute-force loop over every triangle (nearest and any hit, culling, skip), rays never
// slip through a closed mesh (exact parity of crossings, also for rays exactly through vertices), t
// agrees with double, the slab test never misses a box, and validate_bvh rejects each kind of damage.
#include <hider/ray/bvh.hpp>
#include <hider/ray/scene.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/bvh_build.hpp"
#include "support/fixed_print.hpp"
#include "support/scene_util.hpp"

using namespace hider;
using namespace hider::ray;

namespace {

struct Built {
    tool::Scene scene;
    tool::BakedBvh bvh;
    std::vector<BvhStackEntry> stack;
    Mesh mesh() const { return scene.mesh(); }
};

Built build(const tool::Scene& s) {
    Built b;
    b.scene = s;
    std::string why;
    REQUIRE_MESSAGE(tool::build_bvh(b.scene.mesh(), b.bvh, why), why);
    b.stack.resize(b.bvh.header.max_depth);
    REQUIRE(validate_bvh(b.bvh.view(), b.scene.mesh(), {b.stack.data(), b.stack.size()}) == Status::ok);
    return b;
}

Built soup(uint32_t seed, int n) {
    tool::Scene s;
    std::string why;
    REQUIRE_MESSAGE(test::scene_from_ref(ref::soup(seed, n), s, why), why);
    return build(s);
}

/// Brute force: every triangle with the walk's per-ray constants; nearest t, ties to the smaller index.
bool brute(const Built& b, const BvhQuery& q, uint32_t& tri, TriangleHit& hit, bool any) {
    const Mesh m = b.mesh();
    const TriangleRay tr = bvh_triangle_ray(b.bvh.view(), q.ray);
    bool found = false;
    for (uint32_t t = 0; t < m.tris.size(); ++t) {
        if (t == q.skip) continue;
        TriangleHit h{};
        const Tri& v = m.tris[t];
        if (!intersect_triangle(tr, m.positions[v.v[0]], m.positions[v.v[1]], m.positions[v.v[2]], q.t_min, q.t_max, q.cull, h))
            continue;
        if (any) { tri = t; hit = h; return true; }
        if (!found || h.t_q16 < hit.t_q16) { found = true; tri = t; hit = h; }
    }
    return found;
}

Vec3q30 unit_of(double x, double y, double z) {
    Vec3q30 u{};
    const double m = std::fmax(std::fabs(x), std::fmax(std::fabs(y), std::fabs(z)));
    REQUIRE(unit_q30(int32_t(std::lround(x / m * 1e9)), int32_t(std::lround(y / m * 1e9)), int32_t(std::lround(z / m * 1e9)), u));
    return u;
}

/// A ray from a random point in the cube of half side `spread` (raw) toward a random point of the box.
Ray random_ray(std::mt19937& rng, const ray::BvhNode& root, double spread) {
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    const double o[3] = {uni(-spread, spread), uni(-spread, spread), uni(-spread, spread)};
    double aim[3];
    for (int i = 0; i < 3; ++i) aim[i] = uni(root.lo[i], root.hi[i]) - o[i];
    return {{Q16::from_raw(int32_t(o[0])), Q16::from_raw(int32_t(o[1])), Q16::from_raw(int32_t(o[2]))}, unit_of(aim[0], aim[1], aim[2])};
}

}  // namespace

TEST_CASE("the BVH walk finds exactly the brute-force nearest and any hit") {
    std::vector<Built> meshes;
    meshes.push_back(build(test::load_model("torus.obj")));
    meshes.push_back(soup(2, 400));
    meshes.push_back(soup(9, 150));
    for (const Built& b : meshes) {
        std::mt19937 rng(17);
        const Bvh bvh = b.bvh.view();
        long hits = 0;
        for (int i = 0; i < 1500; ++i) {
            const Ray ray = random_ray(rng, bvh.nodes[0], (i % 2 == 0 ? 400.0 : 1500.0) * 65536);
            for (bool cull : {false, true}) {
                BvhQuery q{ray, 16, INT32_MAX, cull, UINT32_MAX};
                uint32_t tri = 0, tri_ref = 0;
                TriangleHit hit{}, ref{};
                const bool found = bvh_walk(bvh, b.mesh(), q, {const_cast<BvhStackEntry*>(b.stack.data()), b.stack.size()}, tri, hit);
                const bool found_ref = brute(b, q, tri_ref, ref, false);
                REQUIRE(found == found_ref);
                if (!found) continue;
                ++hits;
                CHECK(tri == tri_ref);
                CHECK(hit.t_q16 == ref.t_q16);
                CHECK(hit.front == ref.front);
                // Skipping the hit triangle finds the next one, as brute force does.
                q.skip = tri;
                const bool again = bvh_walk(bvh, b.mesh(), q, {const_cast<BvhStackEntry*>(b.stack.data()), b.stack.size()}, tri, hit);
                CHECK(again == brute(b, q, tri_ref, ref, false));
                if (again) CHECK(tri == tri_ref);
                // Any hit: found exactly when a nearest hit exists, and it is a real hit.
                q.skip = UINT32_MAX;
                CHECK(bvh_walk<true>(bvh, b.mesh(), q, {const_cast<BvhStackEntry*>(b.stack.data()), b.stack.size()}, tri, hit));
                CHECK(brute(b, {ray, 16, hit.t_q16, cull, UINT32_MAX}, tri_ref, ref, false));
            }
        }
        MESSAGE(b.scene.tris.size() << " triangles, depth " << b.bvh.header.max_depth << ", nodes " << b.bvh.nodes.size()
                                    << ": " << hits << " hits of 3000 rays");
        CHECK(hits > 500);
    }
}

TEST_CASE("no ray slips between the boxes of a large mesh: a floor of +-8000 units at grazing angles") {
    // The triangle test floors vertices to a grid of 2^shift raw set by the mesh's reach (2^9 here): the
    // boxes must hold the triangles as floored, or a ray along a cell edge misses both neighbours'
    // boxes. Independent reference: the plane y = 0, which every ray below the horizon meets inside the
    // floor; and brute force over every triangle for the nearest one.
    for (int cells : {40, 64}) {
        tool::Scene s;
        const double half = 8000.0, step = 2 * half / cells;
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i)
                s.positions.push_back({Q16::from_raw(int32_t(std::lround((-half + i * step) * 65536))), Q16::from_raw(0),
                                       Q16::from_raw(int32_t(std::lround((-half + j * step) * 65536)))});
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i) {
                const auto v = [&](int di, int dj) { return uint16_t((j + dj) * (cells + 1) + i + di); };
                s.tris.push_back({{v(0, 0), v(0, 1), v(1, 1)}});  // counter-clockwise seen from +y
                s.tris.push_back({{v(0, 0), v(1, 1), v(1, 0)}});
            }
        const Built b = build(s);
        const Bvh bvh = b.bvh.view();
        Span<BvhStackEntry> stack{const_cast<BvhStackEntry*>(b.stack.data()), b.stack.size()};
        CHECK(bvh_triangle_ray(bvh, {{Q16::from_raw(0), Q16::from_raw(0), Q16::from_raw(0)}, unit_of(0, -1, 0)}).shift >= 9);
        std::mt19937 rng(31 + static_cast<uint32_t>(cells));
        auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
        long rays = 0, holes = 0, differ = 0;
        for (int k = 0; k < 3000; ++k) {
            // From just above the floor toward a point on it (every other one on a cell edge line).
            const double o[3] = {uni(-2, 2), uni(0.05, 3), uni(-2, 2)};
            double aim[3] = {uni(-half, half) * 0.9, 0, uni(-half, half) * 0.9};
            if (k % 2 == 0) aim[k % 4 == 0 ? 0 : 2] = std::round(aim[k % 4 == 0 ? 0 : 2] / step) * step;
            const Ray ray{{Q16::from_raw(int32_t(std::lround(o[0] * 65536))), Q16::from_raw(int32_t(std::lround(o[1] * 65536))),
                           Q16::from_raw(int32_t(std::lround(o[2] * 65536)))},
                          unit_of(aim[0] - o[0], aim[1] - o[1], aim[2] - o[2])};
            // Where the ray meets y = 0, in double, along the direction rounded to Q18 as the triangle
            // test takes it (README: at grazing angles that rounding moves the hit by t 2^-18 / |cos|).
            auto q18 = [](int32_t raw) { return std::floor((raw + 2048.0) / 4096.0) / 262144.0; };
            const double d[3] = {q18(ray.dir.x.raw()), q18(ray.dir.y.raw()), q18(ray.dir.z.raw())};
            if (d[1] >= 0) continue;
            // The vertex grid may lower the floor by up to one step (2^9 raw): the hit lies between t and t_low.
            const double oy = ray.origin.y.raw() / 65536.0, t = -oy / d[1], t_low = -(oy + 512 / 65536.0) / d[1];
            const double px = ray.origin.x.raw() / 65536.0 + t_low * d[0], pz = ray.origin.z.raw() / 65536.0 + t_low * d[2];
            const double qx = ray.origin.x.raw() / 65536.0 + t * d[0], qz = ray.origin.z.raw() / 65536.0 + t * d[2];
            if (std::fmax(std::fabs(px), std::fabs(qx)) > half - 1 || std::fmax(std::fabs(pz), std::fabs(qz)) > half - 1) continue;
            ++rays;
            const BvhQuery q{ray, 16, INT32_MAX, false, UINT32_MAX};
            uint32_t tri = 0, tri_ref = 0;
            TriangleHit hit{}, ref{};
            const bool found = bvh_walk(bvh, b.mesh(), q, stack, tri, hit);
            const bool found_ref = brute(b, q, tri_ref, ref, false);
            holes += !found;
            differ += found != found_ref || (found && (tri != tri_ref || hit.t_q16 != ref.t_q16));
        }
        MESSAGE(cells << "x" << cells << " cells: " << rays << " rays onto the floor, " << holes << " holes, " << differ
                      << " differ from brute force");
        CHECK(rays > 2000);
        CHECK(holes == 0);
        CHECK(differ == 0);
    }
}

TEST_CASE("rays never slip through a closed mesh: crossings come in pairs, also exactly through vertices") {
    const Built b = build(test::load_model("torus.obj"));
    const Mesh m = b.mesh();
    const Bvh bvh = b.bvh.view();
    const ray::BvhNode& root = bvh.nodes[0];
    auto crossings = [&](const Ray& ray) {
        const TriangleRay tr = bvh_triangle_ray(bvh, ray);
        int n = 0;
        for (const Tri& v : m.tris) {
            TriangleHit h{};
            n += intersect_triangle(tr, m.positions[v.v[0]], m.positions[v.v[1]], m.positions[v.v[2]], 0, INT32_MAX, false, h);
        }
        return n;
    };
    const int32_t far_z = root.hi[2] + 100 * 65536;
    const Vec3q30 down{Q30::from_raw(0), Q30::from_raw(0), Q30::from_raw(-Q30::kOne)};
    long odd = 0, through = 0;
    for (const Vec3q16& v : m.positions) {  // along -z exactly through every vertex
        const int n = crossings({{v.x, v.y, Q16::from_raw(far_z)}, down});
        if (n % 2 != 0) MESSAGE("vertex ray odd " << n << " at " << v.x.raw() << "," << v.y.raw());
        odd += n % 2;
        through += n > 0;
    }
    std::mt19937 rng(23);
    for (int i = 0; i < 4000; ++i) {
        const Ray ray = random_ray(rng, root, 1500.0 * 65536);
        const int32_t o[3] = {ray.origin.x.raw(), ray.origin.y.raw(), ray.origin.z.raw()};
        bool outside = false;
        for (int k = 0; k < 3; ++k) outside = outside || o[k] < root.lo[k] || o[k] > root.hi[k];
        if (!outside) continue;  // an origin inside the solid would see an odd count
        const int n = crossings(ray);
        if (n % 2 != 0) MESSAGE("random ray odd " << n);
        odd += n % 2;
    }
    // A vertex on the silhouette may be touched without a crossing; all others are crossed.
    MESSAGE("rays through vertices meeting the torus: " << through << " of " << m.positions.size());
    CHECK(through >= static_cast<long>(m.positions.size()) * 9 / 10);
    CHECK(odd == 0);
}

TEST_CASE("ray-triangle t agrees with double within 2 + t (2^-18 / |cos| + 2^-28) LSB") {
    std::mt19937 rng(29);
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    long hits = 0;
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        Vec3q16 p[3];
        double pd[3][3];
        for (auto& q : p) q = {Q16::from_raw(int32_t(uni(-7, 7) * 65536)), Q16::from_raw(int32_t(uni(-7, 7) * 65536)),
                               Q16::from_raw(int32_t(uni(-7, 7) * 65536))};
        for (int k = 0; k < 3; ++k) pd[k][0] = p[k].x.raw(), pd[k][1] = p[k].y.raw(), pd[k][2] = p[k].z.raw();
        const Vec3q16 o{Q16::from_raw(int32_t(uni(-7, 7) * 65536)), Q16::from_raw(int32_t(uni(-7, 7) * 65536)),
                        Q16::from_raw(int32_t(uni(-7, 7) * 65536))};
        // Aim at a random point of the triangle (barycentric), so most rays hit.
        double w0 = uni(0, 1), w1 = uni(0, 1);
        if (w0 + w1 > 1) { w0 = 1 - w0; w1 = 1 - w1; }
        double aim[3];
        for (int k = 0; k < 3; ++k) aim[k] = pd[0][k] + w0 * (pd[1][k] - pd[0][k]) + w1 * (pd[2][k] - pd[0][k]);
        const Ray ray{o, unit_of(aim[0] - o.x.raw(), aim[1] - o.y.raw(), aim[2] - o.z.raw())};
        const TriangleRay tr = make_triangle_ray(ray, 15u << 16);  // reach below 2^20: grid shift 0
        REQUIRE(tr.shift == 0);
        TriangleHit h{};
        if (!intersect_triangle(tr, p[0], p[1], p[2], 0, INT32_MAX, false, h)) continue;
        ++hits;
        const double d[3] = {ray.dir.x.raw() / 1073741824.0, ray.dir.y.raw() / 1073741824.0, ray.dir.z.raw() / 1073741824.0};
        double e1[3], e2[3], n[3], ao[3];
        for (int k = 0; k < 3; ++k) { e1[k] = pd[1][k] - pd[0][k]; e2[k] = pd[2][k] - pd[0][k]; ao[k] = pd[0][k] - (k == 0 ? o.x.raw() : k == 1 ? o.y.raw() : o.z.raw()); }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        const double dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
        const double t_ref = (ao[0] * n[0] + ao[1] * n[1] + ao[2] * n[2]) / dn;
        const double cos = std::fabs(dn) / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        // The direction is rounded to Q18 (|error| <= sqrt(3) 2^-19 per ray), t to about 2^-30.
        const double tol = 2 + std::fabs(t_ref) * (std::ldexp(1.0, -18) / cos + std::ldexp(1.0, -28));
        worst = std::fmax(worst, std::fabs(h.t_q16 - t_ref) / tol);
        CHECK(std::fabs(h.t_q16 - t_ref) <= tol);
        CHECK(h.front == (dn < 0));
    }
    MESSAGE("triangle t: " << hits << " hits, worst |t - t_ref| / tolerance " << worst);
    CHECK(hits > 15000);
}

TEST_CASE("the slab test never misses a box the ray crosses") {
    std::mt19937 rng(31);
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    long crossed = 0;
    for (int i = 0; i < 100000; ++i) {
        int32_t lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            const double a = uni(-100, 100) * 65536, w = uni(0, 3) * 65536 * (i % 7 == 0 ? 0 : 1);  // some flat boxes
            lo[k] = int32_t(a);
            hi[k] = int32_t(a + w);
        }
        // A ray through a point inside the box, from far away; often nearly parallel to an axis.
        double p[3], o[3], d[3];
        for (int k = 0; k < 3; ++k) p[k] = uni(lo[k], hi[k]);
        for (int k = 0; k < 3; ++k) d[k] = uni(-1, 1) * (rng() % 3 == 0 ? 1e-6 : 1);
        const Vec3q30 dir = unit_of(d[0], d[1], d[2]);
        const double back = uni(1, 3000) * 65536;
        for (int k = 0; k < 3; ++k) o[k] = p[k] - back * (k == 0 ? dir.x.raw() : k == 1 ? dir.y.raw() : dir.z.raw()) / 1073741824.0;
        const Ray ray{{Q16::from_raw(int32_t(std::lround(o[0]))), Q16::from_raw(int32_t(std::lround(o[1]))),
                       Q16::from_raw(int32_t(std::lround(o[2])))}, dir};
        // The rounded origin moves the line by up to one LSB: widen the box by 2 LSB for the check.
        for (int k = 0; k < 3; ++k) { lo[k] -= 2; hi[k] += 2; }
        const BoxRay br = make_box_ray(ray, INT32_MAX);
        int32_t te = 0;
        CHECK(intersect_box(br, lo, hi, 0, INT32_MAX, te));
        CHECK(te <= back + 4);
        ++crossed;
    }
    CHECK(crossed == 100000);
}

TEST_CASE("validate_bvh accepts the built tree and rejects every kind of damage") {
    Built b = soup(5, 200);
    const Mesh m = b.mesh();
    const uint16_t depth = b.bvh.header.max_depth;
    auto check = [&](const tool::BakedBvh& t, size_t stack) {
        std::vector<BvhStackEntry> s(stack);
        return validate_bvh(t.view(), m, {s.data(), s.size()});
    };
    CHECK(check(b.bvh, depth) == Status::ok);
    CHECK(check(b.bvh, depth + 1) == Status::ok);
    CHECK(check(b.bvh, depth - 1) == Status::capacity_exceeded);  // stack one short of max_depth
    auto damaged = [&](auto&& change) {
        tool::BakedBvh t = b.bvh;
        change(t);
        return check(t, std::max<size_t>(depth, t.header.max_depth));
    };
    size_t inner = 0, leaf = 0;
    while (b.bvh.nodes[inner].count != 0) ++inner;
    while (b.bvh.nodes[leaf].count == 0) ++leaf;
    CHECK(damaged([](tool::BakedBvh& t) { t.header.magic ^= 1; }) == Status::bad_data);
    CHECK(damaged([](tool::BakedBvh& t) { ++t.header.version; }) == Status::bad_data);
    CHECK(damaged([](tool::BakedBvh& t) { t.nodes.pop_back(); }) == Status::bad_data);
    CHECK(damaged([](tool::BakedBvh& t) { t.triangles.pop_back(); --t.header.triangle_count; }) == Status::bad_data);
    CHECK(damaged([](tool::BakedBvh& t) { t.header.max_depth = 1; }) == Status::bad_data);  // deeper than recorded
    CHECK(damaged([&](tool::BakedBvh& t) { t.nodes[inner].first = static_cast<uint32_t>(inner); }) == Status::bad_data);  // cycle
    CHECK(damaged([&](tool::BakedBvh& t) { t.nodes[inner].first = t.header.node_count; }) == Status::bad_data);
    CHECK(damaged([&](tool::BakedBvh& t) { t.nodes[inner + 1].hi[0] = t.nodes[inner].hi[0] + 1; }) == Status::bad_data);
    CHECK(damaged([&](tool::BakedBvh& t) { t.triangles[t.nodes[leaf].first] = 1u << 30; }) == Status::bad_data);
    CHECK(damaged([&](tool::BakedBvh& t) { t.nodes[leaf].lo[1] = t.nodes[leaf].hi[1]; }) == Status::bad_data);  // vertex outside
    CHECK(damaged([&](tool::BakedBvh& t) { ++t.nodes[leaf].first; }) == Status::bad_data);  // leaves not consecutive
    CHECK(damaged([&](tool::BakedBvh& t) { t.nodes[leaf].lo[2] = t.nodes[leaf].hi[2] + 1; }) == Status::bad_data);  // lo > hi
    CHECK(damaged([](tool::BakedBvh& t) { t.nodes[0].lo[0] = -(1 << 29); }) == Status::out_of_range);
    // Entries listing a triangle twice and another never (a red team's tree: every index and box passed,
    // and no ray could hit the missing one). In a tree of one leaf the root's box holds every triangle,
    // so only the entries' power sums can tell: a duplicate; two changed keeping the sum; three keeping
    // the sum and the sum of squares (0..7 as 0 2 2 3 4 3 7 7: 28 and 140 as 0..7's, cubes 820 against
    // 784). A swap keeps the set.
    const Built eight = soup(12, 8);
    REQUIRE(eight.mesh().tris.size() == 8);
    tool::BakedBvh one = eight.bvh;
    BvhNode root = one.nodes[0];
    root.first = 0;
    root.count = 8;
    one.nodes.assign(1, root);
    one.header.node_count = 1;
    one.header.max_depth = 1;
    std::vector<BvhStackEntry> one_stack(1);
    auto listing = [&](std::vector<uint32_t> entries) {
        one.triangles = std::move(entries);
        return validate_bvh(one.view(), eight.mesh(), {one_stack.data(), one_stack.size()});
    };
    CHECK(listing({0, 1, 2, 3, 4, 5, 6, 7}) == Status::ok);
    CHECK(listing({7, 1, 2, 3, 4, 5, 6, 0}) == Status::ok);
    CHECK(listing({0, 0, 2, 3, 4, 5, 6, 7}) == Status::bad_data);
    CHECK(listing({0, 2, 2, 3, 4, 4, 6, 7}) == Status::bad_data);
    CHECK(listing({0, 2, 2, 3, 4, 3, 7, 7}) == Status::bad_data);
    // A mesh with a different triangle count is not this tree's mesh.
    std::vector<BvhStackEntry> s(depth);
    Mesh fewer = m;
    fewer.tris = {m.tris.data(), m.tris.size() - 1};
    CHECK(validate_bvh(b.bvh.view(), fewer, {s.data(), s.size()}) == Status::bad_data);
    // Normals or ids short of the triangles: cast_row() would read past them (a red-team pass).
    REQUIRE(m.normals.size() == m.tris.size());
    Mesh short_normals = m;
    short_normals.normals = {m.normals.data(), m.normals.size() - 1};
    CHECK(validate_bvh(b.bvh.view(), short_normals, {s.data(), s.size()}) == Status::bad_data);
    std::vector<uint32_t> ids(m.tris.size() - 1, 7);
    Mesh short_ids = m;
    short_ids.ids = {ids.data(), ids.size()};
    CHECK(validate_bvh(b.bvh.view(), short_ids, {s.data(), s.size()}) == Status::bad_data);
    CHECK(validate_bvh(b.bvh.view(), m, {s.data(), s.size()}) == Status::ok);
}

TEST_CASE("validate_scene refuses a mesh normal that is neither unit nor zero") {
    // A red team's normal of -32768 (Q14) passed, and the tracer's turn of it toward the ray overflowed
    // (-INT32_MIN); any non-unit normal made reflections wrap while the status was ok.
    Built b = soup(5, 40);
    std::vector<Normal14> normals(b.scene.normals.begin(), b.scene.normals.end());
    Mesh m = b.mesh();
    m.normals = {normals.data(), normals.size()};
    const ray::Surface surface{};
    const ray::MeshObject object{m, b.bvh.view(), 0, {}};
    ray::Scene s;
    s.meshes = {&object, 1};
    s.surfaces = {&surface, 1};
    auto status = [&] { return ray::validate_scene(s, {b.stack.data(), b.stack.size()}); };
    CHECK(status() == Status::ok);
    const Normal14 kept = normals[3];
    for (const Normal14 bad : {Normal14{-32768, 0, 0}, Normal14{32767, 32767, 32767}, Normal14{0, 0, 16384 - 200},
                               Normal14{0, 16384 + 200, 0}}) {
        normals[3] = bad;
        CHECK(status() == Status::invalid_argument);
    }
    normals[3] = Normal14{0, 0, 0};  // face_normal() of a degenerate face
    CHECK(status() == Status::ok);
    normals[3] = Normal14{0, -16384, 0};
    CHECK(status() == Status::ok);
    normals[3] = kept;
    CHECK(status() == Status::ok);
}

TEST_CASE("the builder keeps depth within its limit and leaves small") {
    const Built b = build(test::load_model("torus.obj"));
    size_t most = 0;
    for (const auto& n : b.bvh.nodes) most = std::max<size_t>(most, n.count);
    CHECK(most <= 4);
    tool::BakedBvh shallow;
    std::string why;
    tool::BvhBuildOptions opt;
    opt.max_depth = 5;
    REQUIRE(tool::build_bvh(b.scene.mesh(), shallow, why, opt));
    CHECK(shallow.header.max_depth <= 5);
    std::vector<BvhStackEntry> s(5);
    CHECK(validate_bvh(shallow.view(), b.scene.mesh(), {s.data(), s.size()}) == Status::ok);
    tool::Scene empty = b.scene;
    empty.tris.clear();
    CHECK_FALSE(tool::build_bvh(empty.mesh(), shallow, why));
}

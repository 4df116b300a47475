// Whitted ray tracing of a Scene: nearest hit over spheres, planes and meshes, Lambert shading from
// point and directional lights with one shadow ray each, plus ambient, and mirror reflection followed
// in a loop (no recursion) up to Scene::max_bounces. Colour arithmetic (CONVENTIONS.md, "Ray tracing"):
// light per channel in Q16 (255 -> 65535), weights in Q15, the pixel accumulated in Q23; all floors.
// Tie rule: equal t goes to spheres, then planes, then meshes, each in array order, and within a mesh
// to the smaller triangle index. A secondary ray ignores the flat or convex object it leaves, and leaves
// a mesh or a sphere's inside lifted off the surface (ray_start()).
#pragma once
#include <hider/ray/cull.hpp>

namespace hider::ray {

/// Smallest t a ray accepts (2^-12 units): keeps rays from meeting the surface they start on again.
constexpr int32_t kRayEpsilonRaw = 16;

/// What tracing did: rays by kind, plus the BVH's work.
struct TraceStats {
    uint32_t rays = 0;         ///< primary and reflected rays
    uint32_t shadow_rays = 0;
    uint32_t hits = 0;
    BvhCounters bvh{};

    void merge(const TraceStats& o) {
        rays += o.rays;
        shadow_rays += o.shadow_rays;
        hits += o.hits;
        bvh.boxes += o.bvh.boxes;
        bvh.triangles += o.bvh.triangles;
    }
};

namespace detail {
/// The object a secondary ray starts on (kind none: nothing is skipped).
struct Skip {
    ObjectKind kind = ObjectKind::none;
    uint16_t object = 0;
    uint32_t triangle = 0;
};

/// A primary ray's pixel and the frame's sphere rectangles (sphere_rects()); null: no culling.
struct PixelCull {
    const SphereRect* rects;
    int32_t x, y;
};

/// Nearest hit (or, kAnyHit, any hit) of `ray` on t_min < t < t_max over the whole scene. Spheres are
/// skipped by the pixel's rectangles (primary rays) or else all at once by the scene's sphere bound.
template <bool kAnyHit>
bool scene_hit(const Scene& s, const Ray& ray, int32_t t_min, int32_t t_max, const Skip& skip,
               Span<BvhStackEntry> stack, Hit& hit, TraceStats& stats, const PixelCull* cull = nullptr) {
    bool found = false;
    int32_t best = t_max, t = 0;
    bool front = true;
    const bool spheres = cull != nullptr || s.sphere_bound.radius.raw() == 0 ||
                         segment_meets_sphere(ray, s.sphere_bound, t_min, t_max);
    for (size_t i = 0; spheres && i < s.spheres.size(); ++i) {
        if (skip.kind == ObjectKind::sphere && skip.object == i) continue;
        if (cull != nullptr && !cull->rects[i].contains(cull->x, cull->y)) continue;
        if (!intersect_sphere(ray, s.spheres[i], t_min, best, t, front)) continue;
        hit = {t, ObjectKind::sphere, static_cast<uint16_t>(i), 0, front};
        if (kAnyHit) return true;
        found = true;
        best = t;
    }
    for (size_t i = 0; i < s.planes.size(); ++i) {
        if (skip.kind == ObjectKind::plane && skip.object == i) continue;
        if (!intersect_plane(ray, s.planes[i], t_min, best, t, front)) continue;
        hit = {t, ObjectKind::plane, static_cast<uint16_t>(i), 0, front};
        if (kAnyHit) return true;
        found = true;
        best = t;
    }
    for (size_t i = 0; i < s.meshes.size(); ++i) {
        const MeshObject& m = s.meshes[i];
        const uint32_t skip_tri = skip.kind == ObjectKind::triangle && skip.object == i ? skip.triangle : UINT32_MAX;
        uint32_t tri = 0;
        TriangleHit th{};
        const BvhQuery q{ray, t_min, best - 1, false, skip_tri};  // t < best: earlier objects win ties
        if (!bvh_walk<kAnyHit>(m.bvh, m.mesh, q, stack, tri, th, &stats.bvh)) continue;
        hit = {th.t_q16, ObjectKind::triangle, static_cast<uint16_t>(i), tri, th.front};
        if (kAnyHit) return true;
        found = true;
        best = th.t_q16;
    }
    return found;
}

/// Unit normal at hit point p, turned to face the incoming direction d.
inline Vec3q30 facing_normal(const Scene& s, const Hit& h, const Vec3q16& p, const Vec3q30& d) {
    Vec3q30 n{};
    if (h.kind == ObjectKind::sphere) {
        const Vec3q16 r = p - s.spheres[h.object].centre;
        if (!unit_q30(r.x.raw(), r.y.raw(), r.z.raw(), n)) n = {Q30::from_raw(0), Q30::from_raw(Q30::kOne), Q30::from_raw(0)};
    } else if (h.kind == ObjectKind::plane) {
        n = s.planes[h.object].normal;
    } else {
        const Mesh& m = s.meshes[h.object].mesh;
        if (!m.normals.empty()) {
            const Normal14& q = m.normals[h.triangle];
            n = {Q30::from_raw(q.x * 65536), Q30::from_raw(q.y * 65536), Q30::from_raw(q.z * 65536)};
        } else {
            const Tri& t = m.tris[h.triangle];
            const Vec3q16 a = m.positions[t.v[0]];
            (void)normalize(cross_raw(m.positions[t.v[1]] - a, m.positions[t.v[2]] - a), n);
        }
    }
    if (dot_q60(n, d) > 0) n = {-n.x, -n.y, -n.z};
    return n;
}

/// The normal a ray is mirrored about: facing_normal()'s, made unit again where it is a mesh's Normal14,
/// which is unit only within validate_scene()'s tolerance: reflect() keeps a ray's length only about a
/// unit normal, and the sphere test takes every ray as unit. A zero normal stays zero (the ray goes on).
inline Vec3q30 mirror_normal(const Scene& s, const Hit& h, const Vec3q30& n) {
    Vec3q30 u = n;
    if (h.kind == ObjectKind::triangle && !s.meshes[h.object].mesh.normals.empty())
        (void)unit_q30(n.x.raw(), n.y.raw(), n.z.raw(), u);
    return u;
}

/// The triangle test's vertex grid step (raw) for rays of `bvh` from `origin` (bvh_triangle_ray_grid()).
inline int64_t mesh_grid_step(const Bvh& bvh, const Vec3q16& origin) {
    return int64_t{1} << triangle_grid_shift(bvh_reach(bvh, origin));
}

/// Where the secondary rays of hit h at p (normal n facing the viewer; `incoming` the ray that found it)
/// start. A flat object or a sphere seen from outside is skipped by them, so p serves. A mesh's other
/// triangles and a sphere left from inside are not: p is off the surface by up to about t 2^-18 (the
/// triangle test's rounded direction) plus sqrt(3) grid steps of the incoming ray's vertex grid, and the
/// secondary ray's own grid moves the neighbouring triangles (and coincident twins) by up to sqrt(3) of
/// its steps; its shadow rays would meet them at once (acne). So p is lifted towards the viewer by
/// kRayEpsilonRaw + t 2^-17, plus, from a mesh, twice both grid steps (clamped to the world). The grid
/// step is 1 raw unless the mesh's box reaches past 2^20 raw (16 units) from the ray's origin.
inline Vec3q16 ray_start(const Scene& s, const Ray& incoming, const Hit& h, const Vec3q16& p, const Vec3q30& n) {
    if (h.kind != ObjectKind::triangle && (h.kind != ObjectKind::sphere || h.front)) return p;
    int64_t lift = kRayEpsilonRaw + (h.t_q16 >> 17);
    if (h.kind == ObjectKind::triangle) {
        const Bvh& bvh = s.meshes[h.object].bvh;
        const int64_t grids = mesh_grid_step(bvh, incoming.origin) + mesh_grid_step(bvh, p);
        if (grids > 2) lift += 2 * grids;  // both 1 raw: within kRayEpsilonRaw, as before
    }
    auto comp = [lift](Q16 c, Q30 nc) {
        const int64_t v = c.raw() + ((nc.raw() * lift + (int64_t{1} << 29)) >> 30);
        return Q16::from_raw(static_cast<int32_t>(clamp<int64_t>(v, 1 - kRayWorldLimitRaw, kRayWorldLimitRaw - 1)));
    };
    return {comp(p.x, n.x), comp(p.y, n.y), comp(p.z, n.z)};
}

inline const Surface& hit_surface(const Scene& s, const Hit& h) {
    if (h.kind == ObjectKind::sphere) return s.surfaces[s.spheres[h.object].surface];
    if (h.kind == ObjectKind::plane) return s.surfaces[s.planes[h.object].surface];
    const MeshObject& m = s.meshes[h.object];
    return s.surfaces[m.triangle_surfaces.empty() ? m.surface : m.triangle_surfaces[h.triangle]];
}

/// Surface colour at p: checker squares of side checker_size in the two world axes other than the
/// normal's largest component (ties: x before y before z); (floor(u/size) + floor(v/size)) odd -> checker_color.
inline Rgb surface_color(const Surface& f, const Vec3q16& p, const Vec3q30& n) {
    if (f.checker_size.raw() == 0) return f.color;
    const int32_t ax = abs_value(n.x.raw()), ay = abs_value(n.y.raw()), az = abs_value(n.z.raw());
    int32_t u = p.y.raw(), v = p.z.raw();                        // x dominant
    if (ay > ax && ay >= az) { u = p.x.raw(); v = p.z.raw(); }   // y dominant
    else if (az > ax && az > ay) { u = p.x.raw(); v = p.y.raw(); }
    const int32_t size = f.checker_size.raw();
    return ((div_floor32(u, size) + div_floor32(v, size)) & 1) != 0 ? f.checker_color : f.color;
}

/// Light arriving at p (normal n facing the viewer) per channel, Q16: ambient plus, for each light on
/// n's side that no object blocks, max(n.l, 0) times its colour.
inline void irradiance(const Scene& s, const Vec3q16& p, const Vec3q30& n, const Skip& skip, Span<BvhStackEntry> stack,
                       TraceStats& stats, uint32_t (&e)[3]) {
    e[0] = s.ambient.r * 257u;
    e[1] = s.ambient.g * 257u;
    e[2] = s.ambient.b * 257u;
    for (const Light& light : s.lights) {
        Vec3q30 l = light.direction;
        int32_t dist = INT32_MAX;
        if (light.kind == LightKind::point) {
            const Vec3q16 v = light.position - p;
            uint32_t len = 0;
            if (!unit_q30(v.x.raw(), v.y.raw(), v.z.raw(), l, &len)) continue;
            dist = static_cast<int32_t>(len) - kRayEpsilonRaw;  // |v| < 2^30.8 raw: fits
        }
        const int64_t ndotl_q16 = dot_q60(n, l) >> 44;
        if (ndotl_q16 <= 0) continue;
        ++stats.shadow_rays;
        Hit blocker;
        Ray shadow;
        set_ray(shadow, p, l);
        if (scene_hit<true>(s, shadow, kRayEpsilonRaw, dist, skip, stack, blocker, stats)) continue;
        const uint32_t k = static_cast<uint32_t>(min<int64_t>(ndotl_q16, 65536));
        e[0] += (k * (light.color.r * 257u)) >> 16;
        e[1] += (k * (light.color.g * 257u)) >> 16;
        e[2] += (k * (light.color.b * 257u)) >> 16;
    }
}
}  // namespace detail

/// Colour seen along `primary` (origin inside the world cube): nearest hit, its shaded colour, and the
/// mirror image weighted by reflectivity, bounce after bounce up to s.max_bounces (the last surface
/// shows its own colour with the remaining weight); a ray meeting nothing within s.max_distance shows
/// the background. `cull`: the primary ray's pixel and sphere rectangles, or null.
/// Precondition: validate_scene(s, stack) == ok.
inline Rgb trace(const Scene& s, const Ray& primary, Span<BvhStackEntry> stack, TraceStats& stats,
                 const detail::PixelCull* cull = nullptr) {
    Ray ray;
    set_ray(ray, primary.origin, primary.dir);
    detail::Skip skip;
    uint32_t weight = kReflectOne;  // Q15
    uint32_t acc[3] = {0, 0, 0};    // Q23
    const int32_t t_max = s.max_distance.raw();
    for (uint32_t bounce = 0;; ++bounce) {
        ++stats.rays;
        Hit h;
        if (!detail::scene_hit<false>(s, ray, kRayEpsilonRaw, t_max, skip, stack, h, stats, bounce == 0 ? cull : nullptr)) {
            acc[0] += weight * (s.background.r * 256u);
            acc[1] += weight * (s.background.g * 256u);
            acc[2] += weight * (s.background.b * 256u);
            break;
        }
        ++stats.hits;
        const Vec3q16 p = point_along(ray.origin, h.t_q16, ray.dir);
        const Vec3q30 n = detail::facing_normal(s, h, p, ray.dir);
        const Surface& f = detail::hit_surface(s, h);
        // The next rays leave this object on the side facing the viewer: a flat object or a sphere seen
        // from outside cannot be met again, so it is skipped (no self-shadowing acne at grazing angles).
        skip = (h.kind != ObjectKind::sphere || h.front) ? detail::Skip{h.kind, h.object, h.triangle} : detail::Skip{};
        const Vec3q16 from = detail::ray_start(s, ray, h, p, n);
        uint32_t e[3];
        detail::irradiance(s, from, n, skip, stack, stats, e);
        const Rgb base = detail::surface_color(f, p, n);
        const uint32_t r = bounce < s.max_bounces ? f.reflect_q15 : 0;
        const uint32_t w_local = (weight * (kReflectOne - r)) >> 15;
        const uint8_t channel[3] = {base.r, base.g, base.b};
        for (int c = 0; c < 3; ++c) {
            const uint32_t local_q8 = static_cast<uint32_t>(min<uint64_t>((uint64_t{channel[c]} * e[c]) >> 8, 255u * 256u));
            acc[c] += w_local * local_q8;
        }
        weight = (weight * r) >> 15;
        if (weight == 0) break;
        set_ray(ray, from, reflect(ray.dir, detail::mirror_normal(s, h, n)));
    }
    auto out = [](uint32_t a) { return static_cast<uint8_t>(min<uint32_t>((a + (1u << 22)) >> 23, 255u)); };
    return {out(acc[0]), out(acc[1]), out(acc[2])};
}

/// Traces row y of the frame into `row` (width pixels of Format). With `rects` (sphere_rects() of this
/// frame, one per sphere) primary rays test only the spheres whose rectangle holds their pixel; the
/// frame is the same either way. Borrows `stack` and `rects` for the call.
/// Precondition: validate_scene(s, stack) == ok with this stack (or one no shorter), 0 <= y < rays.height,
/// rects empty or >= spheres.
template <class Format>
TraceStats trace_row(const Scene& s, const PrimaryRays& rays, int32_t y, typename Format::Pixel* row,
                     Span<BvhStackEntry> stack, Span<const SphereRect> rects = {}) {
    HIDER_ASSERT(rects.empty() || rects.size() >= s.spheres.size());
    TraceStats stats;
    RowRays rr(rays, y);
    detail::PixelCull cull{rects.data(), 0, y};
    for (int32_t x = 0; x < rays.width; ++x, rr.next()) {
        cull.x = x;
        Ray ray;
        set_ray(ray, rays.eye, rr.direction());
        row[x] = Format::pack(trace(s, ray, stack, stats, rects.empty() ? nullptr : &cull));
    }
    return stats;
}

}  // namespace hider::ray

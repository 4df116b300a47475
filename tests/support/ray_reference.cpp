// Double-precision reference ray tracer (see ray_reference.hpp). Brute force over every object.
#include "support/ray_reference.hpp"

#include <cmath>

namespace hider::ref {
namespace {

RtVec add(RtVec a, RtVec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
RtVec sub(RtVec a, RtVec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
RtVec mul(RtVec a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(RtVec a, RtVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
RtVec cross(RtVec a, RtVec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
RtVec unit(RtVec a) { return mul(a, 1 / std::sqrt(dot(a, a))); }

enum Kind { kNone, kSphere, kPlane, kTriangle };

struct Hit {
    double t = 0;
    Kind kind = kNone;
    int index = 0;
    bool front = true;  // spheres: met from outside
};

/// Which object a secondary ray ignores (the flat or convex one it leaves).
struct Skip {
    Kind kind = kNone;
    int index = -1;
};

void mix(uint64_t& h, uint64_t v) { h = (h ^ v) * 0x100000001B3ull + 0x9E3779B97F4A7C15ull; }

class Tracer {
public:
    /// Bounds every mesh's triangles by a sphere, so most rays skip them (the answers do not change).
    explicit Tracer(const RtScene& s) : s_(s) {
        for (const RtTriangle& t : s.triangles) {
            if (t.mesh >= int(bounds_.size())) bounds_.resize(size_t(t.mesh) + 1, Bound{});
            Bound& b = bounds_[size_t(t.mesh)];
            for (const RtVec& v : t.v) {
                b.lo = {std::fmin(b.lo.x, v.x), std::fmin(b.lo.y, v.y), std::fmin(b.lo.z, v.z)};
                b.hi = {std::fmax(b.hi.x, v.x), std::fmax(b.hi.y, v.y), std::fmax(b.hi.z, v.z)};
            }
        }
        for (Bound& b : bounds_) {
            b.centre = mul(add(b.lo, b.hi), 0.5);
            b.radius = std::sqrt(dot(sub(b.hi, b.lo), sub(b.hi, b.lo))) * 0.5 * 1.0001 + 1e-9;
        }
    }

    /// Nearest (or any) hit on (t_min, t_max).
    bool hit(RtVec o, RtVec d, double t_min, double t_max, Skip skip, bool any, Hit& out) const {
        bool found = false;
        double best = t_max;
        for (size_t i = 0; i < s_.spheres.size(); ++i) {
            if (skip.kind == kSphere && skip.index == int(i)) continue;
            const RtSphere& sp = s_.spheres[i];
            const RtVec oc = sub(o, sp.centre);
            const double b = dot(oc, d), c = dot(oc, oc) - sp.radius * sp.radius, disc = b * b - c;
            if (disc < 0) continue;
            const double h = std::sqrt(disc), t0 = -b - h, t1 = -b + h;
            const double t = t0 > t_min ? t0 : t1;
            if (t <= t_min || t >= best) continue;
            out = {t, kSphere, int(i), t == t0};
            found = true;
            best = t;
            if (any) return true;
        }
        for (size_t i = 0; i < s_.planes.size(); ++i) {
            if (skip.kind == kPlane && skip.index == int(i)) continue;
            const RtPlane& pl = s_.planes[i];
            const double den = dot(pl.normal, d);
            if (den == 0) continue;
            const double t = (pl.offset - dot(pl.normal, o)) / den;
            if (t <= t_min || t >= best) continue;
            const RtVec p = add(o, mul(d, t));
            if (std::fabs(p.x) >= s_.world || std::fabs(p.y) >= s_.world || std::fabs(p.z) >= s_.world) continue;
            out = {t, kPlane, int(i), den < 0};
            found = true;
            best = t;
            if (any) return true;
        }
        std::vector<char> near_mesh(bounds_.size());
        for (size_t m = 0; m < bounds_.size(); ++m) {  // the segment passes within the bound's radius
            const RtVec oc = sub(bounds_[m].centre, o);
            const double t = std::fmin(std::fmax(dot(oc, d), t_min), best);
            const RtVec gap = sub(oc, mul(d, t));
            near_mesh[m] = dot(gap, gap) <= bounds_[m].radius * bounds_[m].radius;
        }
        for (size_t i = 0; i < s_.triangles.size(); ++i) {
            if (skip.kind == kTriangle && skip.index == int(i)) continue;
            const RtTriangle& tr = s_.triangles[i];  // Moller-Trumbore
            if (!near_mesh[size_t(tr.mesh)]) continue;
            const RtVec e1 = sub(tr.v[1], tr.v[0]), e2 = sub(tr.v[2], tr.v[0]), pv = cross(d, e2);
            const double det = dot(e1, pv);
            if (det == 0) continue;
            const RtVec tv = sub(o, tr.v[0]);
            const double u = dot(tv, pv) / det;
            if (u < 0 || u > 1) continue;
            const RtVec qv = cross(tv, e1);
            const double v = dot(d, qv) / det, t = dot(e2, qv) / det;
            if (v < 0 || u + v > 1 || t <= t_min || t >= best) continue;
            out = {t, kTriangle, int(i), true};
            found = true;
            best = t;
            if (any) return true;
        }
        return found;
    }

    /// Colour (0..255 per channel) along the ray from the eye, the path's signature and its objects'.
    void trace(RtVec o, RtVec d, double (&rgb)[3], uint64_t& sig, uint64_t& objects) const {
        double weight = 1, acc[3] = {0, 0, 0};
        Skip skip;
        sig = 0;
        objects = 0;
        for (int bounce = 0;; ++bounce) {
            Hit h;
            if (!hit(o, d, s_.epsilon, s_.max_distance, skip, false, h)) {
                for (int c = 0; c < 3; ++c) acc[c] += weight * s_.background[c];
                mix(sig, 0xB6);
                mix(objects, 0xB6);
                break;
            }
            const RtVec p = add(o, mul(d, h.t));
            RtVec n{};
            int surface = 0;
            if (h.kind == kSphere) {
                n = unit(sub(p, s_.spheres[h.index].centre));
                surface = s_.spheres[h.index].surface;
            } else if (h.kind == kPlane) {
                n = s_.planes[h.index].normal;
                surface = s_.planes[h.index].surface;
            } else {
                n = s_.triangles[h.index].normal;
                surface = s_.triangles[h.index].surface;
            }
            if (dot(n, d) > 0) n = mul(n, -1);
            skip = (h.kind != kSphere || h.front) ? Skip{h.kind, h.index} : Skip{};
            const RtSurface& f = s_.surfaces[surface];
            const double* base = f.color;
            int parity = 0;
            if (f.checker_size > 0) {
                const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
                double u = p.y, v = p.z;
                if (ay > ax && ay >= az) { u = p.x; v = p.z; }
                else if (az > ax && az > ay) { u = p.x; v = p.y; }
                parity = int(std::floor(u / f.checker_size) + std::floor(v / f.checker_size)) & 1;
                if (parity != 0) base = f.checker_color;
            }
            mix(sig, uint64_t(h.kind) * 1000003 + uint64_t(h.index) * 17 + uint64_t(parity) + (h.front ? 0 : 7));
            mix(objects, uint64_t(h.kind) * 1000003 + uint64_t(h.kind == kTriangle ? s_.triangles[h.index].mesh : h.index) * 17 +
                             (h.front ? 0 : 7));
            double e[3] = {s_.ambient[0] / 255, s_.ambient[1] / 255, s_.ambient[2] / 255};
            for (size_t li = 0; li < s_.lights.size(); ++li) {
                const RtLight& light = s_.lights[li];
                RtVec l = light.direction;
                double dist = 1e300;
                if (light.point) {
                    const RtVec v = sub(light.position, p);
                    dist = std::sqrt(dot(v, v));
                    if (dist == 0) continue;
                    l = mul(v, 1 / dist);
                    dist -= s_.epsilon;
                }
                const double ndotl = dot(n, l);
                if (ndotl <= 0) continue;
                Hit blocker;
                const bool blocked = hit(p, l, s_.epsilon, dist, skip, true, blocker);
                mix(sig, blocked ? 0x51 + li : 0x77 + li);
                if (blocked) continue;
                for (int c = 0; c < 3; ++c) e[c] += ndotl * light.color[c] / 255;
            }
            const double r = bounce < s_.max_bounces ? f.reflect : 0;
            for (int c = 0; c < 3; ++c) acc[c] += weight * (1 - r) * std::fmin(base[c] * e[c], 255.0);
            weight *= r;
            if (weight == 0) break;
            d = sub(d, mul(n, 2 * dot(d, n)));
            o = p;
        }
        for (int c = 0; c < 3; ++c) rgb[c] = acc[c];
    }

private:
    struct Bound {
        RtVec lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300}, centre{};
        double radius = 0;
    };
    const RtScene& s_;
    std::vector<Bound> bounds_;
};

}  // namespace

RtImage ray_trace(const RtScene& s) {
    RtImage img;
    img.rgb.resize(size_t(s.width) * s.height * 3);
    img.signature.resize(size_t(s.width) * s.height);
    img.objects.resize(size_t(s.width) * s.height);
    const RtVec f = unit(sub(s.target, s.eye)), side = unit(cross(f, unit(s.up))), up = cross(side, f);
    const double th = std::tan(s.fovy_deg * M_PI / 360), aspect = double(s.width) / s.height;
    const Tracer tracer(s);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const double nx = (2 * (x + 0.5) / s.width - 1) * th * aspect, ny = (1 - 2 * (y + 0.5) / s.height) * th;
            const RtVec d = unit(add(f, add(mul(side, nx), mul(up, ny))));
            double rgb[3];
            const size_t i = size_t(y) * s.width + x;
            tracer.trace(s.eye, d, rgb, img.signature[i], img.objects[i]);
            for (int c = 0; c < 3; ++c) img.rgb[3 * i + c] = rgb[c];
        }
    return img;
}

}  // namespace hider::ref

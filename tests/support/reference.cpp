// Double-precision reference renderer: per-pixel-centre ray vs. triangle (signed volumes, 3D), candidate pixels
// from the screen bounding box of each triangle clipped (Sutherland-Hodgman) to near <= d <= far in view space.
#include "support/reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hider::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBoxMarginPx = 1.0;  // widens each candidate box; the per-pixel test is exact, extra pixels are free
constexpr int kMaxClipVerts = 8;      // a triangle clipped by two planes has at most 5 vertices

Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d lerp(const Vec3d& a, const Vec3d& b, double t) {
    return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}
double dot(const Vec3d& a, const Vec3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool finite(const Vec3d& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

// Unit vector, or false when a has zero or non-finite length.
bool normalize(const Vec3d& a, Vec3d& out) {
    const double len = std::sqrt(dot(a, a));
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    out = {a.x / len, a.y / len, a.z / len};
    return true;
}

// gluLookAt rows: s, u, -f.
struct ViewBasis {
    Vec3d s, u, f, eye;
};

bool make_basis(const RefCamera& cam, ViewBasis& basis) {
    basis.eye = cam.eye;
    if (!normalize(sub(cam.target, cam.eye), basis.f)) return false;
    if (!normalize(cross(basis.f, cam.up), basis.s)) return false;
    basis.u = cross(basis.s, basis.f);
    return true;
}

Vec3d apply(const ViewBasis& basis, const Vec3d& p) {
    const Vec3d q = sub(p, basis.eye);
    return {dot(basis.s, q), dot(basis.u, q), -dot(basis.f, q)};
}

// Per-pixel ray directions (x_dir, y_dir, -1) through pixel centres; d along such a ray equals the ray parameter.
struct Rays {
    std::vector<double> x_dir;  // per column
    std::vector<double> y_dir;  // per row
    double x_scale, y_scale;    // tan(fovy/2) * aspect, tan(fovy/2)
};

Rays make_rays(const RefCamera& cam) {
    Rays rays;
    rays.y_scale = std::tan(cam.fovy_deg * kPi / 360.0);
    rays.x_scale = rays.y_scale * static_cast<double>(cam.width) / static_cast<double>(cam.height);
    rays.x_dir.resize(static_cast<size_t>(cam.width));
    rays.y_dir.resize(static_cast<size_t>(cam.height));
    for (int px = 0; px < cam.width; ++px) {
        const double x_ndc = 2.0 * (px + 0.5) / cam.width - 1.0;
        rays.x_dir[static_cast<size_t>(px)] = x_ndc * rays.x_scale;
    }
    for (int py = 0; py < cam.height; ++py) {
        const double y_ndc = 1.0 - 2.0 * (py + 0.5) / cam.height;
        rays.y_dir[static_cast<size_t>(py)] = y_ndc * rays.y_scale;
    }
    return rays;
}

// Triangle data in view space. With D the ray direction, D.(v1 x v2), D.(v2 x v0), D.(v0 x v1) are the
// barycentric weights of the line through the eye scaled by det(v0, v1, v2); the line crosses the triangle
// iff all three share a sign. The hit lies at d = N.v0 / N.D (N = (v1-v0) x (v2-v0), D.z = -1).
struct Prepared {
    Vec3d c0, c1, c2, n;
    double n_dot_v0;
    uint32_t id;
    int x0, x1, y0, y1;  // inclusive candidate pixel box
};

// Keeps the part of polygon `in` where side * z + offset >= 0 (Sutherland-Hodgman, one plane).
int clip_z(const Vec3d* in, int count, double side, double offset, Vec3d* out) {
    int n_out = 0;
    for (int i = 0; i < count; ++i) {
        const Vec3d& a = in[i];
        const Vec3d& b = in[(i + 1) % count];
        const double fa = side * a.z + offset;
        const double fb = side * b.z + offset;
        if (fa >= 0.0) out[n_out++] = a;
        if ((fa >= 0.0) != (fb >= 0.0)) out[n_out++] = lerp(a, b, fa / (fa - fb));
    }
    return n_out;
}

// Pixel box of the triangle's part with near <= d <= far; false when that part is empty or off-screen.
bool candidate_box(const Vec3d (&v)[3], const RefCamera& cam, const Rays& rays, Prepared& out) {
    Vec3d poly_a[kMaxClipVerts] = {v[0], v[1], v[2]};
    Vec3d poly_b[kMaxClipVerts];
    int count = clip_z(poly_a, 3, -1.0, -cam.near, poly_b);  // -z - near >= 0
    count = clip_z(poly_b, count, 1.0, cam.far, poly_a);     //  z + far  >= 0
    if (count == 0) return false;
    double x_min = std::numeric_limits<double>::infinity();
    double x_max = -x_min;
    double y_min = x_min;
    double y_max = -x_min;
    for (int i = 0; i < count; ++i) {
        const double inv_d = 1.0 / -poly_a[i].z;  // d >= near > 0 after clipping
        const double x_pix = (poly_a[i].x * inv_d / rays.x_scale + 1.0) * cam.width / 2.0;
        const double y_pix = (1.0 - poly_a[i].y * inv_d / rays.y_scale) * cam.height / 2.0;
        if (std::isnan(x_pix) || std::isnan(y_pix)) {  // overflow on absurd coordinates: test every pixel
            x_min = y_min = -std::numeric_limits<double>::infinity();
            x_max = y_max = std::numeric_limits<double>::infinity();
            break;
        }
        x_min = std::min(x_min, x_pix);
        x_max = std::max(x_max, x_pix);
        y_min = std::min(y_min, y_pix);
        y_max = std::max(y_max, y_pix);
    }
    // Pixel p is a candidate when its centre p + 0.5 lies within the box widened by the margin.
    const auto first = [](double lo, int size) {
        return static_cast<int>(std::clamp(std::ceil(lo - kBoxMarginPx - 0.5), 0.0, static_cast<double>(size)));
    };
    const auto last = [](double hi, int size) {
        return static_cast<int>(std::clamp(std::floor(hi + kBoxMarginPx - 0.5), -1.0, size - 1.0));
    };
    out.x0 = first(x_min, cam.width);
    out.x1 = last(x_max, cam.width);
    out.y0 = first(y_min, cam.height);
    out.y1 = last(y_max, cam.height);
    return out.x0 <= out.x1 && out.y0 <= out.y1;
}

// View-space setup of one triangle; false when it cannot cover any pixel.
bool prepare(const RefTriangle& tri, const ViewBasis& basis, const RefCamera& cam, const Rays& rays, bool cull,
             Prepared& out) {
    const Vec3d v[3] = {apply(basis, tri.v[0]), apply(basis, tri.v[1]), apply(basis, tri.v[2])};
    if (!finite(v[0]) || !finite(v[1]) || !finite(v[2])) return false;
    out.n = cross(sub(v[1], v[0]), sub(v[2], v[0]));
    out.n_dot_v0 = dot(out.n, v[0]);
    if (out.n_dot_v0 == 0.0) return false;          // eye in the plane (or zero area): seen edge-on
    if (cull && out.n_dot_v0 > 0.0) return false;   // front iff dot(N, -v0) > 0
    out.c0 = cross(v[1], v[2]);
    out.c1 = cross(v[2], v[0]);
    out.c2 = cross(v[0], v[1]);
    out.id = tri.id;
    return candidate_box(v, cam, rays, out);
}

// Distance d of the hit of ray (x_dir, y_dir, -1) with the triangle, or -1 when the line misses it.
double hit_depth(const Prepared& t, double x_dir, double y_dir) {
    const double w0 = t.c0.x * x_dir + t.c0.y * y_dir - t.c0.z;
    const double w1 = t.c1.x * x_dir + t.c1.y * y_dir - t.c1.z;
    const double w2 = t.c2.x * x_dir + t.c2.y * y_dir - t.c2.z;
    const bool all_nonneg = w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0;
    const bool all_nonpos = w0 <= 0.0 && w1 <= 0.0 && w2 <= 0.0;
    if (!all_nonneg && !all_nonpos) return -1.0;
    const double n_dot_dir = t.n.x * x_dir + t.n.y * y_dir - t.n.z;
    if (n_dot_dir == 0.0) return -1.0;
    return t.n_dot_v0 / n_dot_dir;
}

bool camera_ok(const RefCamera& cam) {
    return cam.near > 0.0 && cam.far >= cam.near && std::isfinite(cam.far) && cam.fovy_deg > 0.0 &&
           cam.fovy_deg < 180.0;
}

}  // namespace

Vec3d to_view(const RefCamera& cam, const Vec3d& p_world) {
    ViewBasis basis{};
    if (!make_basis(cam, basis)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan};
    }
    return apply(basis, p_world);
}

std::vector<uint32_t> render_ids(const std::vector<RefTriangle>& tris, const RefCamera& cam, bool cull) {
    if (cam.width <= 0 || cam.height <= 0) return {};
    const size_t width = static_cast<size_t>(cam.width);
    std::vector<uint32_t> ids(width * static_cast<size_t>(cam.height), 0);
    ViewBasis basis{};
    if (!camera_ok(cam) || !make_basis(cam, basis)) return ids;
    const Rays rays = make_rays(cam);
    std::vector<double> best_d(ids.size(), std::numeric_limits<double>::infinity());
    Prepared t{};
    for (const RefTriangle& tri : tris) {
        if (!prepare(tri, basis, cam, rays, cull, t)) continue;
        for (int py = t.y0; py <= t.y1; ++py) {
            const double y_dir = rays.y_dir[static_cast<size_t>(py)];
            const size_t row = static_cast<size_t>(py) * width;
            for (int px = t.x0; px <= t.x1; ++px) {
                const double d = hit_depth(t, rays.x_dir[static_cast<size_t>(px)], y_dir);
                if (!(d >= cam.near && d <= cam.far)) continue;
                const size_t i = row + static_cast<size_t>(px);
                if (d < best_d[i] || (d == best_d[i] && t.id < ids[i])) {
                    best_d[i] = d;
                    ids[i] = t.id;
                }
            }
        }
    }
    return ids;
}

double Agreement::rate() const {
    if (off_edge == 0) return 1.0;
    return 1.0 - static_cast<double>(off_edge_mismatch) / static_cast<double>(off_edge);
}

namespace {

// True when some 8-neighbour of (x, y) holds a different id than (x, y) in `img`.
bool on_edge(const std::vector<uint32_t>& img, int width, int height, int x, int y) {
    const uint32_t id = img[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
    for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny) {
        for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx) {
            if (img[static_cast<size_t>(ny) * static_cast<size_t>(width) + static_cast<size_t>(nx)] != id) return true;
        }
    }
    return false;
}

}  // namespace

Agreement compare_ids(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b, int width, int height) {
    Agreement result;
    const bool dims_ok = width > 0 && height > 0;
    const size_t expected = dims_ok ? static_cast<size_t>(width) * static_cast<size_t>(height) : 0;
    if (!dims_ok || a.size() != expected || b.size() != expected) {
        result.off_edge = 1;
        result.off_edge_mismatch = 1;
        result.total_mismatch = static_cast<long>(std::max(a.size(), b.size()));
        return result;
    }
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
            const bool differs = a[i] != b[i];
            if (differs) ++result.total_mismatch;
            if (on_edge(a, width, height, x, y) || on_edge(b, width, height, x, y)) continue;
            ++result.off_edge;
            if (differs) ++result.off_edge_mismatch;
        }
    }
    return result;
}

}  // namespace hider::ref

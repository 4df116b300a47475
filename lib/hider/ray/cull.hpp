// Per-frame culling of spheres for primary rays: the rectangle of pixels whose rays may meet each
// sphere, from the projection of the sphere's view-space bounding box (the box holds the sphere and a
// box's image is bounded by its corners). Widened by a few LSB in space and one pixel on screen, so a
// culled pixel's ray provably misses: frames are byte-identical with and without culling (tested).
#pragma once
#include <hider/ray/camera.hpp>
#include <hider/ray/scene.hpp>

namespace hider::ray {

/// Pixels [x0, x1] x [y0, y1] (inclusive) whose primary rays may meet a sphere; x0 > x1 when none.
struct SphereRect {
    int16_t x0, y0, x1, y1;
    constexpr bool contains(int32_t x, int32_t y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

namespace detail {
/// Floor (or ceil) of n / d for d > 0, clamped to [lo, hi].
constexpr int32_t div_clamped(int64_t n, int64_t d, bool up, int32_t lo, int32_t hi) {
    int64_t q = n / d;
    if (n % d != 0 && ((n < 0) != up)) q += up ? 1 : -1;  // C++ truncates toward zero
    return static_cast<int32_t>(clamp<int64_t>(q, lo, hi));
}

/// Pixel range [first, last] along one screen axis for view-space extent [c - r, c + r] over depth
/// [w - r, w + r] (w - r > 0): the pixel whose ray has ratio (2 p + 1 - n) 2048 / k lies inside when the
/// ratio is within [min, max] of (c -+ r) / (w +- r). `flip` for y (row 0 at the top).
inline void pixel_span(int64_t c, int64_t w, int64_t r, int64_t k, int32_t n, bool flip, int32_t& first, int32_t& last) {
    const int64_t hi_num = c + r, lo_num = c - r;
    const int64_t hi_den = hi_num >= 0 ? w - r : w + r, lo_den = lo_num >= 0 ? w + r : w - r;
    // 2 p + 1 - n = ratio k / 2048  =>  p = (ratio k / 2048 + n - 1) / 2 = (num k + (n - 1) 2048 den) / (4096 den).
    const int64_t lo = div_clamped(lo_num * k + (int64_t{n} - 1) * 2048 * lo_den, 4096 * lo_den, false, -1, n) - 1;
    const int64_t hi = div_clamped(hi_num * k + (int64_t{n} - 1) * 2048 * hi_den, 4096 * hi_den, true, -1, n) + 1;
    first = static_cast<int32_t>(max<int64_t>(flip ? n - 1 - hi : lo, 0));
    last = static_cast<int32_t>(min<int64_t>(flip ? n - 1 - lo : hi, n - 1));
}
}  // namespace detail

/// Fills out[i] with the pixels whose primary rays (of `rays`) may meet sphere i; a sphere reaching
/// behind or nearly to the eye gets the whole frame. invalid_argument when out is shorter than the
/// sphere list. Cost per sphere: three dot products and four 64-bit divisions.
inline Status sphere_rects(const Scene& s, const PrimaryRays& rays, Span<SphereRect> out) {
    if (out.size() < s.spheres.size()) return Status::invalid_argument;
    const Q30(&rot)[3][3] = rays.view.to_view.rot.m;
    const Vec3q30 sx{rot[0][0], rot[0][1], rot[0][2]}, uy{rot[1][0], rot[1][1], rot[1][2]};
    const int64_t k = rays.view.k_q8;
    for (size_t i = 0; i < s.spheres.size(); ++i) {
        const Sphere& sp = s.spheres[i];
        const Vec3q16 rel = sp.centre - rays.eye;  // in the world cube: below 2^30 raw per component
        const int64_t x = round_q46_to_q16(dot_q46(sx, rel)), y = round_q46_to_q16(dot_q46(uy, rel)),
                      w = round_q46_to_q16(dot_q46(rays.forward, rel));
        // Rounding margin: a few LSB for positions, the unit rows and the hit test, plus 2^-24 of the range.
        const int64_t r = int64_t{sp.radius.raw()} + 64 + ((abs_value(w) + sp.radius.raw()) >> 24);
        SphereRect& rect = out[i];
        if (w - r < 256) {  // reaches to within 2^-8 units of the eye's plane, or behind it: no culling
            rect = {0, 0, static_cast<int16_t>(rays.width - 1), static_cast<int16_t>(rays.height - 1)};
            continue;
        }
        int32_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
        detail::pixel_span(x, w, r, k, rays.width, false, x0, x1);
        detail::pixel_span(y, w, r, k, rays.height, true, y0, y1);
        rect = {static_cast<int16_t>(x0), static_cast<int16_t>(y0), static_cast<int16_t>(x1), static_cast<int16_t>(y1)};
    }
    return Status::ok;
}

}  // namespace hider::ray

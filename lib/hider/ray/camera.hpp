// Primary rays: from the eye through the centre of each pixel, with exactly the rasterizer's camera
// (make_view: gluLookAt + gluPerspective, its rounded rotation and its projection scale k). In view
// space the ray through pixel (px, py) runs along (x/w, y/w, -1) = ((2 px + 1 - W), (H - 2 py - 1), -k/8)
// / (k/8), k = View::k_q8 / 256 subpixels per unit of x/w (CONVENTIONS.md, "Screen"). Scaled by 2048 k/8
// the world direction D = k_q8 f + 2048 (2 px + 1 - W) s + 2048 (H - 2 py - 1) u is an exact integer
// combination of the view axes s (right), u (up), f (forward): stepping one pixel adds 4096 s, so a row
// costs additions only (no per-pixel matrix), and equals the closed form exactly.
#pragma once
#include <hider/ray/ray.hpp>
#include <hider/view.hpp>

namespace hider::ray {

static_assert(kRayWorldLimitRaw == kWorldLimitRaw, "the ray tracer's world cube is the rasterizer's world range");

/// Per-frame constants of the primary rays (make_primary_rays()).
struct PrimaryRays {
    Vec3q16 eye{};
    Vec3q30 forward{};  ///< f: a point's view depth is w = (p - eye) . f
    // D times 2^(32 - shift), so the direction's int32 components are the high words (no 64-bit shift
    // per pixel); shift is chosen so D >> shift has |components| < 2^30 everywhere in the frame.
    int64_t corner[3]{};  ///< D of pixel (0, 0), scaled
    int64_t dx[3]{};      ///< D per pixel to the right: 4096 s, scaled
    int64_t dy[3]{};      ///< D per row down: -4096 u, scaled
    int shift = 0;
    int32_t width = 0, height = 0;
    View view{};          ///< the rasterizer's view of the same camera
};

/// Builds the primary rays of a width x height frame; make_view()'s checks and status.
inline Status make_primary_rays(const Camera& cam, int32_t width, int32_t height, PrimaryRays& out) {
    PrimaryRays p;
    const Status st = make_view(cam, width, height, p.view);
    if (st != Status::ok) return st;
    const Q30(&rot)[3][3] = p.view.to_view.rot.m;  // rows: s, u, -f
    p.eye = cam.eye;
    p.forward = {-rot[2][0], -rot[2][1], -rot[2][2]};
    const int64_t k = p.view.k_q8;
    // Every D of the frame is below (k + 2048 (W + H)) 2^30 in each component (axes of length 1 + a few
    // LSB): with twice that as the bound, D >> shift stays below 2^30 and D 2^(32 - shift) below 2^62.
    const uint64_t bound = (static_cast<uint64_t>(k) + 2048 * static_cast<uint64_t>(width + height)) << 31;
    p.shift = max(0, bit_length64(bound) - 30);
    const int64_t scale = int64_t{1} << (32 - p.shift);
    for (int i = 0; i < 3; ++i) {
        const int64_t s = rot[0][i].raw(), u = rot[1][i].raw(), f = -int64_t{rot[2][i].raw()};
        p.corner[i] = (k * f + 2048 * (1 - int64_t{width}) * s + 2048 * (int64_t{height} - 1) * u) * scale;
        p.dx[i] = 4096 * s * scale;
        p.dy[i] = -4096 * u * scale;
    }
    p.width = width;
    p.height = height;
    out = p;
    return Status::ok;
}

/// The primary rays of one row, left to right: direction() of the current pixel, next() steps one pixel.
class RowRays {
public:
    /// Row y of `p` (one product per component). Precondition: 0 <= y < p.height.
    RowRays(const PrimaryRays& p, int32_t y) {
        for (int i = 0; i < 3; ++i) {
            d_[i] = p.corner[i] + p.dy[i] * y;
            step_[i] = p.dx[i];
        }
    }
    /// The current pixel's unnormalised direction, |components| < 2^30.
    void raw_direction(int32_t (&out)[3]) const {
        for (int i = 0; i < 3; ++i) out[i] = static_cast<int32_t>(d_[i] >> 32);  // = D >> shift
    }
    /// The current pixel's unit direction (Q30, within 2 LSB per component).
    Vec3q30 direction() const {
        int32_t d[3];
        raw_direction(d);
        Vec3q30 u{};
        (void)unit_q30(d[0], d[1], d[2], u);  // never zero: the forward part dominates
        return u;
    }
    void next() {
        for (int i = 0; i < 3; ++i) d_[i] += step_[i];
    }

private:
    int64_t d_[3];
    int64_t step_[3];
};

}  // namespace hider::ray

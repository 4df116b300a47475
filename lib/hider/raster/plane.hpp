// The depth plane of a screen triangle, shared by TriangleRaster and the row kernel's set-up: z at the
// centre of pixel (px, py) is z_ref + dzdx (px - ref_px) + dzdy (py - ref_py) modulo 2^32, where the
// gradients are the exact plane's per-pixel steps rounded once and z_ref is the plane rounded at the
// reference pixel (the one whose cell holds the first vertex). Units as in CONVENTIONS.md.
#pragma once
#include <hider/fixed.hpp>
#include <hider/screen.hpp>

namespace hider {

struct DepthPlane {
    uint32_t z_ref, dzdx, dzdy;
    int32_t ref_px, ref_py;

    /// Depth at pixel (px, py): exact modulo 2^32, equal to what stepping by dzdx and dzdy produces.
    __attribute__((always_inline)) uint32_t at(int32_t px, int32_t py) const {
        return z_ref + dzdx * static_cast<uint32_t>(px - ref_px) + dzdy * static_cast<uint32_t>(py - ref_py);
    }
};

namespace detail {
/// (za - z0) d2 - (zb - z0) d1 exactly, for depths z and |d| < 2^15. With s = z - 2^31 as int32 it is
/// s0 (d1 - d2) + sa d2 - sb d1: three 32x32->64 products, one multiply or multiply-accumulate each
/// where the CPU has a long multiply. ARMv6-M keeps the differences' 33x16-bit products by parts.
__attribute__((always_inline)) inline int64_t plane_cross(uint32_t z0, uint32_t za, uint32_t zb, int32_t d1, int32_t d2) {
    if constexpr (kNarrowMultiply) return mul_i33_i16(int64_t{za} - z0, d2) - mul_i33_i16(int64_t{zb} - z0, d1);
    const int32_t s0 = static_cast<int32_t>(z0 ^ 0x80000000u), sa = static_cast<int32_t>(za ^ 0x80000000u),
                  sb = static_cast<int32_t>(zb ^ 0x80000000u);
    return int64_t{s0} * (d1 - d2) + int64_t{sa} * d2 - int64_t{sb} * d1;
}
}  // namespace detail

/// The exact plane's numerators for (v0, v1, v2): dz/dx = npx / (16 area) and dz/dy = nqy / (16 area) per
/// subpixel, so npx / area and nqy / area are the per-pixel steps.
struct PlaneNumerators {
    int64_t npx, nqy;
};
__attribute__((always_inline)) inline PlaneNumerators plane_numerators(const ScreenVertex& v0, const ScreenVertex& v1,
                                                                       const ScreenVertex& v2) {
    const int32_t dx1 = v1.x - v0.x, dy1 = v1.y - v0.y;
    const int32_t dx2 = v2.x - v0.x, dy2 = v2.y - v0.y;
    // Plane through the vertices: z = z0 + p (x - x0) + q (y - y0); per pixel = 16 p, 16 q.
    // |dz| < 2^32 and |dx|, |dy| < 2^15 (kCoordLimit): every product fits 47 bits.
    return {detail::plane_cross(v0.z, v1.z, v2.z, dy1, dy2) * kSubpixel,
            detail::plane_cross(v0.z, v2.z, v1.z, dx2, dx1) * kSubpixel};
}

/// True when n / area rounds to a magnitude below 2^31 (floor((|n| + area / 2) / area) < 2^31).
constexpr bool plane_step_fits(int64_t n, int32_t area) {
    const uint64_t un = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
    return ((un + static_cast<uint32_t>(area / 2)) >> 31) < static_cast<uint32_t>(area);
}

/// The plane of (v0, v1, v2), clockwise on the image, with area = their signed area (> 0), for pixel
/// centres at x_origin + 16 px, y_origin + 16 py. Cost: two 64/32 quotients (one reciprocal of the area
/// on ARMv6-M) and a few multiplies.
__attribute__((always_inline)) inline DepthPlane depth_plane(const ScreenVertex& v0, const PlaneNumerators& n, int32_t area,
                                                             int32_t x_origin, int32_t y_origin) {
    int64_t px = 0, qy = 0;
    if (kSlow64BitDivide) {  // 64/32 divisions (on ARMv6-M one reciprocal for both)
        const SharedDivisor32 d(static_cast<uint32_t>(area));
        px = div_round_prepared(n.npx, d);
        qy = div_round_prepared(n.nqy, d);
    } else {
        px = div_round(n.npx, area);
        qy = div_round(n.nqy, area);
    }
    DepthPlane p;
    p.dzdx = static_cast<uint32_t>(px);
    p.dzdy = static_cast<uint32_t>(qy);
    // Reference pixel: the one whose cell holds v0; its centre is within 8 subpixels of v0.
    p.ref_px = (v0.x - x_origin + kSubpixel / 2) >> kSubpixelBits;
    p.ref_py = (v0.y - y_origin + kSubpixel / 2) >> kSubpixelBits;
    const int32_t ox = p.ref_px * kSubpixel + x_origin - v0.x;  // within [-8, 8]
    const int32_t oy = p.ref_py * kSubpixel + y_origin - v0.y;
    p.z_ref = v0.z + static_cast<uint32_t>(div_round_pow2(mul_i64_i16(px, ox) + mul_i64_i16(qy, oy), kSubpixelBits));
    return p;
}

/// depth_plane() from the vertices.
__attribute__((always_inline)) inline DepthPlane depth_plane(const ScreenVertex& v0, const ScreenVertex& v1,
                                                             const ScreenVertex& v2, int32_t area, int32_t x_origin,
                                                             int32_t y_origin) {
    return depth_plane(v0, plane_numerators(v0, v1, v2), area, x_origin, y_origin);
}

}  // namespace hider

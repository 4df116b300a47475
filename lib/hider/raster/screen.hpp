// Screen space shared by the rasterizers: coordinates in 1/16 pixel from the frame centre (see
// CONVENTIONS.md), the depth range, the projected vertex, and the cheap test that a triangle's bounding
// box holds no pixel centre of a band.
#pragma once
#include <hider/base.hpp>

namespace hider {

constexpr int kSubpixelBits = 4;                    ///< screen coordinates carry 4 fraction bits
constexpr int32_t kSubpixel = 1 << kSubpixelBits;   ///< subpixels per pixel
constexpr int32_t kCoordLimit = (1 << 14) - 1;      ///< |x|, |y| <= this keeps edge functions in int32
constexpr int32_t kGuardBand = (1 << 14) - 64;      ///< clip planes sit here; rounding stays below the limit
/// Depths are kept in [kDepthMargin, 2^32 - 1 - kDepthMargin] so plane-stepping error never wraps.
constexpr uint32_t kDepthMargin = 4096;
constexpr uint32_t kDepthNear = kDepthMargin;
constexpr uint32_t kDepthFar = 0xFFFFFFFFu - kDepthMargin;

/// A projected vertex: x, y in subpixels from the frame centre (y down), z in [kDepthNear, kDepthFar]
/// (smaller = nearer, affine in screen space). A vertex outside a clip plane has z == 0 and its planes
/// in x (8 bytes a vertex: indexing is a shift, and a mesh's vertex array is a third smaller).
/// project_vertices() and project() never give a drawable vertex z == 0; a hand-made vertex with z == 0
/// and x == 0 counts as drawable (outside() == 0) and takes draw_zbuffer's slower clipping path.
struct ScreenVertex {
    int16_t x = 0;
    int16_t y = 0;
    uint32_t z = 0;

    /// The clip planes the vertex lies outside of (0 = drawable).
    constexpr uint8_t outside() const { return z == 0 ? static_cast<uint8_t>(x) : 0; }
    /// Marks the vertex as outside `planes` (nonzero); x, y and z lose their meaning.
    constexpr void mark_outside(uint8_t planes) {
        x = planes;
        y = 0;
        z = 0;
    }
};
static_assert(sizeof(ScreenVertex) == 8, "ScreenVertex is two halfwords and a word");

namespace detail {

/// Rows of the band in centre-relative subpixels, for a cheap reject before setup.
struct BandBounds {
    int32_t y_first, y_last, x_first, x_last;
    int32_t y_origin;  ///< centre of row 0
};
template <class Frame>
BandBounds band_bounds(const Frame& f) {
    const int32_t ox = kSubpixel / 2 - f.width * (kSubpixel / 2), oy = kSubpixel / 2 - f.height * (kSubpixel / 2);
    return {f.y0 * kSubpixel + oy, (f.y1 - 1) * kSubpixel + oy, ox, (f.width - 1) * kSubpixel + ox, oy};
}

/// A triangle's bounding box in centre-relative subpixels.
struct ScreenBox {
    int32_t x_min, x_max, y_min, y_max;
};
inline ScreenBox screen_box(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    return {min<int32_t>(a.x, min<int32_t>(b.x, c.x)), max<int32_t>(a.x, max<int32_t>(b.x, c.x)),
            min<int32_t>(a.y, min<int32_t>(b.y, c.y)), max<int32_t>(a.y, max<int32_t>(b.y, c.y))};
}

/// True when no pixel centre of the band lies in the box: the box is outside the band, or a tiny
/// triangle's box falls between centres. Shifts and compares only, so such triangles skip the setup
/// and its divisions.
inline bool misses_band(const ScreenBox& box, const BandBounds& bb) {
    if (box.y_max < bb.y_first || box.y_min > bb.y_last || box.x_max < bb.x_first || box.x_min > bb.x_last) return true;
    // First centre at or after the minimum: centres sit at origin + 16 k.
    const int32_t cx = ((box.x_min - bb.x_first + kSubpixel - 1) >> kSubpixelBits) * kSubpixel + bb.x_first;
    const int32_t cy = ((box.y_min - bb.y_origin + kSubpixel - 1) >> kSubpixelBits) * kSubpixel + bb.y_origin;
    return cx > box.x_max || cy > box.y_max;
}

}  // namespace detail

}  // namespace hider

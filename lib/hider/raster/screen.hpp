// The band of rows a rasterizer draws, in the screen units of <hider/screen.hpp>, and the cheap test
// that a triangle's bounding box holds no pixel centre of a band (so it skips setup and its divisions).
#pragma once
#include <hider/screen.hpp>

namespace hider {

/// Rows of a band in centre-relative subpixels, for a cheap reject before setup.
struct BandBounds {
    int32_t y_first, y_last, x_first, x_last;  ///< centres of the band's first/last row and column
    int32_t y_origin;                          ///< centre of row 0 of the frame
};

/// The bounds of a frame view's band (any type with width, height, y0, y1).
template <class Frame>
BandBounds band_bounds(const Frame& f) {
    const int32_t ox = pixel_centre_origin(f.width), oy = pixel_centre_origin(f.height);
    return {f.y0 * kSubpixel + oy, (f.y1 - 1) * kSubpixel + oy, ox, (f.width - 1) * kSubpixel + ox, oy};
}

/// A bounding box in centre-relative subpixels (inclusive).
struct ScreenBox {
    int32_t x_min, x_max, y_min, y_max;
};
inline ScreenBox screen_box(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    return {min<int32_t>(a.x, min<int32_t>(b.x, c.x)), max<int32_t>(a.x, max<int32_t>(b.x, c.x)),
            min<int32_t>(a.y, min<int32_t>(b.y, c.y)), max<int32_t>(a.y, max<int32_t>(b.y, c.y))};
}

/// True when no pixel centre of the band lies in the box: the box is outside the band, or a tiny
/// triangle's box falls between centres. Shifts and compares only.
__attribute__((always_inline)) inline bool misses_band(const ScreenBox& box, const BandBounds& bb) {
    if (box.y_max < bb.y_first || box.y_min > bb.y_last || box.x_max < bb.x_first || box.x_min > bb.x_last) return true;
    // First centre at or after the minimum: centres sit at origin + 16 k.
    const int32_t cx = ((box.x_min - bb.x_first + kSubpixel - 1) >> kSubpixelBits) * kSubpixel + bb.x_first;
    const int32_t cy = ((box.y_min - bb.y_origin + kSubpixel - 1) >> kSubpixelBits) * kSubpixel + bb.y_origin;
    return cx > box.x_max || cy > box.y_max;
}

/// The pixels whose centres lie in the box, clipped to the band: columns [x0, x1), rows [y0, y1)
/// (empty when x0 >= x1 or y0 >= y1). For coverage queries over a polygon's screen box.
struct PixelRect {
    int32_t x0, x1, y0, y1;
};
inline PixelRect pixel_rect(const ScreenBox& box, const BandBounds& bb, int32_t band_y0, int32_t band_y1) {
    // ceil((min - first centre) / 16) .. floor((max - first centre) / 16), in pixels.
    const int32_t x0 = max<int32_t>(0, (box.x_min - bb.x_first + kSubpixel - 1) >> kSubpixelBits);
    const int32_t x1 = min<int32_t>((bb.x_last - bb.x_first) / kSubpixel + 1, ((box.x_max - bb.x_first) >> kSubpixelBits) + 1);
    const int32_t y0 = max<int32_t>(band_y0, (box.y_min - bb.y_origin + kSubpixel - 1) >> kSubpixelBits);
    const int32_t y1 = min<int32_t>(band_y1, ((box.y_max - bb.y_origin) >> kSubpixelBits) + 1);
    return {x0, x1, y0, y1};
}

}  // namespace hider

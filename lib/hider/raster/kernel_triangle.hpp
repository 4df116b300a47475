// A flat triangle inside the frame's columns, set up for the row kernel (row_kernel.hpp's KernelTriangle)
// in one pass:
// vertices sorted by y, the band test, the depth plane (plane.hpp), the kernel's two edge walkers on the
// first row to draw and the short edge that takes over at the middle vertex. Drawing then needs no
// further division, in one call or in several (bands): the record holds everything to resume. Rows,
// spans and depths are exactly TriangleRaster's (same walkers, same plane), so frames are identical.
#pragma once
#include <hider/raster/edge.hpp>
#include <hider/raster/plane.hpp>
#include <hider/raster/row_kernel.hpp>
#include <hider/raster/screen.hpp>

namespace hider {

/// Screen constants of a band for kernel set-ups (centre-relative subpixels, rows of the full frame).
/// The layout is the assembly set-ups' contract (kernel_setup_asm.hpp).
struct KernelBand {
    int32_t x_origin, y_origin;  ///< centre of pixel (0, 0)
    int32_t x_last;              ///< centre of the last column
    int32_t y_first, y_last;     ///< centres of the band's first and last row (the band test)
    int32_t row_from, row_end;   ///< rows to set up for: [row_from, row_end)
    int32_t stride_bytes;        ///< bytes from one depth row to the next
    // Read by kernel_draw_v7m() only (the Cortex-M3 draw loops set all three; kernel_band() zeroes
    // depth_origin and color_less_2 and sets stop = row_end):
    uintptr_t depth_origin;      ///< depth row of row 0 modulo 2^32: row_from's less row_from strides
    int32_t stop;                ///< draw rows before this one (none when it is at or above the first)
    intptr_t color_less_2;       ///< bytes from a depth element to its colour, less 2
};
static_assert(sizeof(void*) != 4 || (offsetof(KernelBand, stride_bytes) == 28 &&
                                     offsetof(KernelBand, depth_origin) == 32 && offsetof(KernelBand, stop) == 36 &&
                                     offsetof(KernelBand, color_less_2) == 40),
              "kernel band layout");

/// The constants of rows [row_begin, row_end) of a width x height frame with the given depth stride.
inline KernelBand kernel_band(int32_t width, int32_t height, int32_t row_begin, int32_t row_end, int32_t stride_bytes) {
    const int32_t ox = pixel_centre_origin(width), oy = pixel_centre_origin(height);
    return {ox, oy, (width - 1) * kSubpixel + ox, row_begin * kSubpixel + oy, (row_end - 1) * kSubpixel + oy,
            row_begin, row_end, stride_bytes, 0, row_end, 0};
}

/// What kernel_setup() found.
enum class KernelSetup : uint32_t {
    none = 0,     ///< no pixel centre of the band lies in the triangle's bounding box: nothing to draw
    kernel = 1,   ///< set up; `row` .. `end` may still be empty (the box holds centres the edges exclude)
    generic = 2,  ///< draw it with TriangleRaster: it may cross the frame's left or right side, or a depth
                  ///< step rounds to 2^31 or more (TriangleRaster then also decides whether it misses the band)
};

/// kernel_setup() in C++ (the portable twin of the assembly set-ups).
__attribute__((always_inline)) inline KernelSetup kernel_setup_portable(const ScreenVertex& a, const ScreenVertex& b,
                                                                        const ScreenVertex& c, int32_t area,
                                                                        const KernelBand& band, KernelTriangle& out) {
    const ScreenVertex& v1 = area < 0 ? c : b;  // traverse clockwise on the image
    const ScreenVertex& v2 = area < 0 ? b : c;
    // Sorted by y (top, mid, bottom), counting swaps: the long edge is the left one when (top, mid,
    // bottom) is an even permutation of (a, v1, v2) (TriangleRaster::setup).
    int32_t xt = a.x, yt = a.y, xm = v1.x, ym = v1.y, xb = v2.x, yb = v2.y;
    bool even = true;
    if (ym < yt) { swap_values(xm, xt); swap_values(ym, yt); even = !even; }
    if (yb < ym) { swap_values(xb, xm); swap_values(yb, ym); even = !even; }
    if (ym < yt) { swap_values(xm, xt); swap_values(ym, yt); even = !even; }
    const int32_t x_min = min(xt, min(xm, xb)), x_max = max(xt, max(xm, xb));
    // misses_band() for a box inside the columns; a box reaching past them goes to TriangleRaster, which
    // also decides whether it misses the band.
    if (yb < band.y_first || yt > band.y_last) return KernelSetup::none;
    if (x_min < band.x_origin || x_max > band.x_last) return KernelSetup::generic;
    const int32_t cx = ((x_min - band.x_origin + kSubpixel - 1) >> kSubpixelBits) * kSubpixel + band.x_origin;
    const int32_t cy = ((yt - band.y_origin + kSubpixel - 1) >> kSubpixelBits) * kSubpixel + band.y_origin;
    if (cx > x_max || cy > yb) return KernelSetup::none;
    auto first_row = [&band](int32_t y_sub) { return (y_sub - band.y_origin + kSubpixel - 1) >> kSubpixelBits; };
    const int32_t top = first_row(yt), y0 = max(top, band.row_from), y1 = min(first_row(yb), band.row_end);
    const int32_t row_mid = first_row(ym);
    out.top = static_cast<int16_t>(top);  // rows lie within the guard band: +-1,100
    out.row = static_cast<int16_t>(y0);
    out.mid = static_cast<int16_t>(row_mid);
    out.end = static_cast<int16_t>(y1);
    if (y0 >= y1) return KernelSetup::kernel;  // no row: no plane needed
    const int32_t abs_area = area < 0 ? -area : area;
    const PlaneNumerators n = plane_numerators(a, v1, v2);
    if (!plane_step_fits(n.npx, abs_area) || !plane_step_fits(n.nqy, abs_area)) return KernelSetup::generic;
    const DepthPlane plane = depth_plane(a, n, abs_area, band.x_origin, band.y_origin);
    RowKernel& k = out.k;
    k.dzdx = plane.dzdx;
    const bool long_left = even;
    auto walker = [&band](int32_t xu, int32_t yu, int32_t xl, int32_t yl, int32_t py) __attribute__((always_inline)) {
        return edge_walker(xu, yu, xl, yl, py, band.x_origin, band.y_origin);
    };
    const int32_t stride = band.stride_bytes;
    auto set_left = [&](const EdgeWalker& w, int32_t py) __attribute__((always_inline)) {
        k.lx = 2 * w.px; k.lg = w.g - w.a; k.la = w.a; k.lm = w.m; k.lstep = 2 * w.q + stride;
        k.lz = plane.at(w.px, py);
        k.ldz = plane.dzdy + plane.dzdx * static_cast<uint32_t>(w.q);
    };
    auto set_right = [&](const EdgeWalker& w) __attribute__((always_inline)) {
        k.rx = 2 * w.px; k.rg = w.g - w.a; k.ra = w.a; k.rm = w.m; k.rstep = 2 * w.q + stride;
    };
    const EdgeWalker lw = walker(xt, yt, xb, yb, y0);
    if (long_left) set_left(lw, y0);
    else set_right(lw);
    const bool upper = y0 < row_mid;
    const EdgeWalker sw = upper ? walker(xt, yt, xm, ym, y0) : walker(xm, ym, xb, yb, y0);
    if (long_left) set_right(sw);
    else set_left(sw, y0);
    out.next_left = !long_left;
    if (upper && row_mid < y1) {  // the lower short edge, from the middle row on
        const EdgeWalker w = walker(xm, ym, xb, yb, row_mid);
        out.next_x = 2 * w.px; out.next_g = w.g - w.a; out.next_a = w.a; out.next_m = w.m; out.next_step = 2 * w.q + stride;
    }
    return KernelSetup::kernel;
}

/// One set-up's arguments besides the vertices; a draw loop keeps one and changes `area` per triangle.
/// The layout is the assembly set-ups' contract.
struct KernelSetupIo {
    const KernelBand* band;
    int32_t area;  ///< signed_area(a, b, c) != 0
    KernelTriangle* out;
};

}  // namespace hider

#include <hider/raster/kernel_setup_asm.hpp>  // the assembly set-ups and kernel_setup()

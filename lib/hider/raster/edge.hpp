// One edge of a polygon as an exact DDA over pixel rows: where the edge crosses each row's pixel
// centres, with an integer error term, so rows step without a division (Bresenham's idea, Pineda's edge
// functions). TriangleRaster walks its three edges this way; PieceRaster (piece.hpp) walks cut lines.
#pragma once
#include <hider/fixed.hpp>
#include <hider/screen.hpp>

namespace hider {

/// An edge on one pixel row. g is the (top-left biased) edge function turned so that g >= 0 exactly
/// on and right of the edge and g grows by `a` per pixel to the right; px is the boundary: the smallest
/// pixel whose centre has g >= 0, so g lies in [0, a). Per row down: g += m, px += q, then one
/// correction (g >= a: g -= a, px -= 1). A pixel centre exactly on the edge counts as right of it, so
/// the two sides of an edge share no pixel and miss none (the top-left rule, CONVENTIONS.md).
struct EdgeWalker {
    int32_t px, g, a, m, q;
};

/// The walker on pixel row py for the edge from (xu, yu) down to (xl, yl) (yu < yl); x_origin and
/// y_origin are the centre of pixel (0, 0). Exact in int32 for coordinates within kCoordLimit. Cost:
/// one int32 division, two for edges flatter than one pixel per row.
__attribute__((always_inline)) inline EdgeWalker edge_walker(const int32_t& xu, const int32_t& yu, const int32_t& xl, const int32_t& yl, int32_t py,
                                                             int32_t x_origin, int32_t y_origin) {
    const int32_t dx = xl - xu, dy = yl - yu;  // dy > 0
    const int32_t yc = py * kSubpixel + y_origin;  // centres of row py
    // g at the centre of pixel 0 of the row: dy (x - xu) - dx (y - yu), exact in int32 (CONVENTIONS.md).
    const int32_t g0 = dy * (x_origin - xu) - dx * (yc - yu);
    EdgeWalker w;
    w.a = dy * kSubpixel;
    const int32_t dg = -dx * kSubpixel;  // change of g per row at a fixed px
    w.px = -div_floor32(g0, w.a);
    w.g = g0 + w.px * w.a;
    if (dg >= 0 && dg < w.a) w.q = 0;
    else if (dg < 0 && dg >= -w.a) w.q = 1;
    else w.q = -div_floor32(dg, w.a);
    w.m = dg + w.q * w.a;  // dg mod a, in [0, a)
    return w;
}

/// Steps w one row down.
__attribute__((always_inline)) inline void step(EdgeWalker& w) {
    w.g += w.m;
    w.px += w.q;
    if (w.g >= w.a) { w.g -= w.a; --w.px; }
}

}  // namespace hider

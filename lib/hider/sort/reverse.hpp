// The reverse painter: polygons front to back (the Newell order reversed) with one coverage bit per
// pixel of the band (raster/coverage.hpp), so every pixel is written at most once and nothing is shaded
// under a painted pixel; drawing stops as soon as the band is full.
#pragma once
#include <hider/sort/poly.hpp>

namespace hider {

/// Draws polys in `order` from the last (nearest) to the first, writing each pixel of the band at most
/// once; pieces are drawn with their cut chains in `cuts`. `coverage` is caller memory of rows() *
/// coverage_words(width) words (cleared here). Stops early when the band is full. Returns
/// invalid_argument if the frame is unusable or coverage too small. Precondition (as for
/// paint_in_order()): every entry of `order` indexes polys, and `cuts` is the pool polys were cut into.
template <class Format, class Depth>
FrameStats paint_front_to_back(const View& view, const Mesh& mesh, Span<const ScreenPoly> polys, Span<const PieceCut> cuts,
                               Span<const uint32_t> order, const FrameView<Format, Depth>& frame, const DrawOptions& opt,
                               Span<uint32_t> coverage) {
    FrameStats st;
    Coverage cov;
    if (!frame_matches(view, frame) || !cov.reset(coverage, frame.width, frame.y0, frame.y1)) {
        st.status = Status::invalid_argument;
        return st;
    }
    const FaceShading shading(view, opt);
    const BandBounds bb = band_bounds(frame);
    for (size_t k = order.size(); k-- > 0 && !cov.full();) {
        const ScreenPoly& p = polys[order[k]];
        uint32_t written = 0;
        st.fragments += with_poly_raster(p, cuts, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
            ++st.triangles_drawn;
            return with_face_shader<Format>(opt, shading, mesh, p.tri, (p.flags & kPolyFront) != 0, [&](const auto& shader) {
                return paint_rows_uncovered(r, y0, y1, frame, shader, cov, written);
            });
        });
        st.pixels_written += written;
    }
    return st;
}

}  // namespace hider

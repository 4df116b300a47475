// The reverse painter: polygons front to back (the Newell order reversed) with one coverage bit per
// pixel of the band, so every pixel is written at most once and nothing is shaded under a painted
// pixel; drawing stops as soon as the band is full. Doom's solidsegs (r_bsp.c) is the 1-D form.
#pragma once
#include <hider/sort/painter.hpp>

namespace hider {

/// 32-bit words of coverage per row of a band `width` pixels wide.
constexpr int32_t coverage_words(int32_t width) { return (width + 31) / 32; }

namespace detail {
/// Writes the uncovered pixels of [x0, x1) on one row and marks them; returns how many it wrote.
template <class Pixel, class Shader>
uint32_t span_uncovered(Pixel* crow, uint32_t* cov, int32_t x0, int32_t x1, uint32_t z, uint32_t dz, const Shader& shade) {
    uint32_t written = 0;
    int32_t x = x0;
    while (x < x1) {
        const int32_t w = x >> 5, bit = x & 31;
        const int32_t n = min(x1 - x, 32 - bit);  // pixels of this span in word w
        const uint32_t want = (n == 32 ? 0xFFFFFFFFu : ((uint32_t{1} << n) - 1)) << bit;
        const uint32_t todo = want & ~cov[w];
        if (todo == want) {  // nothing covered yet: the whole run
            for (int32_t k = 0; k < n; ++k, z += dz) crow[x + k] = shade(z);
            written += static_cast<uint32_t>(n);
        } else if (todo != 0) {
            uint32_t bits = todo >> bit;
            for (int32_t k = 0; k < n; ++k, z += dz, bits >>= 1)
                if ((bits & 1u) != 0) { crow[x + k] = shade(z); ++written; }
        } else {
            z += dz * static_cast<uint32_t>(n);
        }
        cov[w] |= want;
        x += n;
    }
    return written;
}
}  // namespace detail

/// Draws polys in `order` from the last (nearest) to the first, writing each pixel of the band at most
/// once. `coverage` is caller memory of rows() * coverage_words(width) words (cleared here). Stops early
/// when the band is full. Returns invalid_argument if the frame is unusable or coverage too small.
template <class Format, class Depth>
FrameStats paint_front_to_back(const View& view, const Mesh& mesh, Span<const ScreenPoly> polys, Span<const uint32_t> order,
                               const FrameView<Format, Depth>& frame, const DrawOptions& opt, Span<uint32_t> coverage) {
    FrameStats st;
    const int32_t wpr = coverage_words(frame.width);
    if (!detail::frame_matches(view, frame) ||
        coverage.size() < static_cast<size_t>(wpr) * static_cast<size_t>(frame.rows())) {
        st.status = Status::invalid_argument;
        return st;
    }
    for (size_t i = 0; i < static_cast<size_t>(wpr) * static_cast<size_t>(frame.rows()); ++i) coverage[i] = 0;
    uint32_t remaining = static_cast<uint32_t>(frame.width) * static_cast<uint32_t>(frame.rows());
    const FaceShading shading(view, opt);
    const detail::BandBounds bb = detail::band_bounds(frame);
    for (size_t k = order.size(); k-- > 0 && remaining != 0;) {
        const ScreenPoly& p = polys[order[k]];
        TriangleRaster tr;
        int32_t y0 = 0, y1 = 0;
        if (!detail::setup_in_band(p, bb, frame, tr, y0, y1)) continue;
        ++st.triangles_drawn;
        const uint32_t dz = tr.dzdx();
        uint32_t written = 0;
        st.fragments += detail::with_poly_shader<Format>(opt, shading, mesh, p, [&](const auto& shader) {
            return tr.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t z) {
                written += detail::span_uncovered(frame.row(y), coverage.data() + static_cast<size_t>(y - frame.y0) * wpr, x0, x1, z, dz, shader);
            });
        });
        st.pixels_written += written;
        remaining -= written;
    }
    return st;
}

}  // namespace hider

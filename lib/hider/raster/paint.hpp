// Painting one polygon into a band without a depth buffer, for the object-space algorithms (painter,
// Newell, reverse painter, BSP): the face's shader, then every covered pixel (back to front) or only the
// pixels not yet covered (front to back, coverage.hpp). The polygon is a TriangleRaster or a
// PieceRaster (piece.hpp) already set up.
#pragma once
#include <hider/raster/coverage.hpp>
#include <hider/raster/triangle.hpp>
#include <hider/raster/span.hpp>
#include <hider/shade.hpp>

namespace hider {

/// True when the frame is usable and sized like the view.
template <class Frame>
bool frame_matches(const View& view, const Frame& frame) {
    return frame.valid() && frame.width == view.width && frame.height == view.height;
}

/// Returns draw(shader) with the shader of mesh triangle `tri` seen from its front (or back): grey by
/// depth per pixel for Shade::depth, else its flat face colour.
template <class Format, class Draw>
__attribute__((always_inline)) inline uint32_t with_face_shader(const DrawOptions& opt, const FaceShading& shading,
                                                                const Mesh& mesh, size_t tri, bool front, Draw&& draw) {
    if (opt.shade == Shade::depth) return draw(DepthShader<Format>(opt.depth_range));
    return draw(FlatShader<typename Format::Pixel>{Format::pack(shading.color(mesh, tri, front))});
}

/// with_face_shader() for a face given by its id and unit normal.
template <class Format, class Draw>
__attribute__((always_inline)) inline uint32_t with_face_shader(const DrawOptions& opt, const FaceShading& shading, uint32_t id,
                                                                const Normal14& normal, bool front, Draw&& draw) {
    if (opt.shade == Shade::depth) return draw(DepthShader<Format>(opt.depth_range));
    return draw(FlatShader<typename Format::Pixel>{Format::pack(shading.color(id, normal, front))});
}

/// Paints every pixel of rows [y0, y1) of a set-up raster into the band; returns the pixels painted.
template <class Raster, class Format, class Depth, class Shader>
uint32_t paint_rows(const Raster& r, int32_t y0, int32_t y1, const FrameView<Format, Depth>& frame, const Shader& shader) {
    const uint32_t dz = r.dzdx();
    return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t z) { span_paint(frame.row(y), x0, x1, z, dz, shader); });
}

/// Paints the pixels of rows [y0, y1) of a set-up raster that `cov` does not hold yet, and marks them.
/// Returns the pixels the raster covers in those rows; adds the pixels painted to `written`.
template <class Raster, class Format, class Depth, class Shader>
uint32_t paint_rows_uncovered(const Raster& r, int32_t y0, int32_t y1, const FrameView<Format, Depth>& frame,
                              const Shader& shader, Coverage& cov, uint32_t& written) {
    const uint32_t dz = r.dzdx();
    return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t z) {
        written += cov.paint_span(frame.row(y), y, x0, x1, z, dz, shader);
    });
}

}  // namespace hider

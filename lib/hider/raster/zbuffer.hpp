// The z-buffer renderer: per triangle trivial reject, clip (rare), cull by the exact sign of the
// snapped screen area, flat shading, then TriangleRaster rows into span_depth_test. Works on any band
// of rows; drawing every band of a frame gives exactly the bytes of drawing the whole frame.
#pragma once
#include <hider/raster/span.hpp>
#include <hider/raster/triangle.hpp>
#include <hider/raster/vertices.hpp>
#include <hider/shade.hpp>

namespace hider {

namespace detail {

/// Row functor for TriangleRaster::scan: depth-tested spans, row pointers stepped by the stride.
/// kPaired (colour and depth elements of one size, so a pixel's colour sits a fixed number of bytes
/// from its depth): only the depth row is stepped and the span gets four register arguments.
template <bool kCount, class Format, class Depth, class Shader,
          bool kPaired = sizeof(typename Format::Pixel) == sizeof(Depth)>
struct DepthTestRows {
    static constexpr bool kCountFragments = kCount;  ///< the default path counts nothing per row
    static constexpr bool kRowKernel = false;
    // Every member set explicitly: default initialisers made GCC memset the struct per triangle.
    DepthTestRows(const FrameView<Format, Depth>& f, Shader s, uint32_t dz_q32)
        : frame(&f), shader(s), dz(dz_q32), crow(nullptr), zrow(nullptr), written(0), stride(0) {}
    const FrameView<Format, Depth>* frame;
    Shader shader;
    uint32_t dz;
    typename Format::Pixel* crow;
    Depth* zrow;
    uint32_t written;
    int32_t stride;

    __attribute__((always_inline)) void begin(int32_t y) {
        crow = frame->row(y);
        zrow = frame->depth_row(y);
        stride = frame->stride;
    }
    __attribute__((always_inline)) void operator()(int32_t x0, int32_t x1, uint32_t z) {
        if (x0 < x1) {
            const uint32_t n = span_depth_test<kCount>(crow, zrow, x0, x1, z, dz, shader);
            if constexpr (kCount) written += n;
        }
        crow += stride;
        zrow += stride;
    }
};

template <bool kCount, class Format, class Depth, class Shader>
struct DepthTestRows<kCount, Format, Depth, Shader, true> {
    static constexpr bool kCountFragments = kCount;
    using Pixel = typename Format::Pixel;
    /// `span` (dz, colour offset, shader) stays with the caller: a copy of this functor then has no
    /// member whose address escapes, so its fields live in registers.
    DepthTestRows(const FrameView<Format, Depth>& f, const PairedSpan<Pixel, Shader>& s)
        : frame(&f), span(&s), zrow(nullptr), written(0), stride(0) {}
    const FrameView<Format, Depth>* frame;
    const PairedSpan<Pixel, Shader>* span;
    Depth* zrow;
    uint32_t written;
    int32_t stride;

    static constexpr bool kRowKernel = false;
    __attribute__((always_inline)) void begin(int32_t y) {
        zrow = frame->depth_row(y);
        stride = frame->stride;
    }
    __attribute__((always_inline)) void operator()(int32_t x0, int32_t x1, uint32_t z) {
        const int32_t n = x1 - x0;
        if (n > 0) {
            const uint32_t w = span_depth_test_paired<kCount>(zrow + x0, n, z, *span);
            if constexpr (kCount) written += w;
        }
        zrow += stride;
    }
};

/// Flat-coloured rows of 16-bit pixels over 16-bit depth without fragment counting: TriangleRaster
/// runs triangles inside the frame's columns through the RowKernel (row_kernel.hpp), the rest
/// through operator() like the other functors.
template <class Format>
struct FlatRows16 : DepthTestRows<false, Format, uint16_t, FlatShader<typename Format::Pixel>, true> {
    static constexpr bool kRowKernel = true;
    using DepthTestRows<false, Format, uint16_t, FlatShader<typename Format::Pixel>, true>::DepthTestRows;

    /// Fills k's row and span fields for rows from begin()'s row on (the caller fills edges and rows).
    void fill_kernel(RowKernel& k) const {
        k.zrow = this->zrow;
        k.stride_bytes = this->stride * static_cast<int32_t>(sizeof(uint16_t));
        k.dz = this->span->dz_q32;
        k.color_offset = this->span->color_offset;
        k.color = this->span->shader.color;
    }
};

template <class Shader> struct is_flat_shader { static constexpr bool value = false; };
template <class Pixel> struct is_flat_shader<FlatShader<Pixel>> { static constexpr bool value = true; };

/// Depth-tested rows [y_begin, y_end) of a set-up triangle with `shader`; returns the fragments
/// (counted when kCount) and adds the pixels written to `written`.
template <bool kCount, class Format, class Depth, class Shader>
uint32_t scan_depth_tested(const TriangleRaster& tr, int32_t y_begin, int32_t y_end,
                           const FrameView<Format, Depth>& frame, Shader shader, uint32_t& written) {
    using Pixel = typename Format::Pixel;
    if constexpr (sizeof(Pixel) == sizeof(Depth)) {
        // Same stride, same element size: every pixel's colour is this many bytes after its depth.
        const intptr_t offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(frame.color) -
                                                      reinterpret_cast<uintptr_t>(frame.depth));
        const PairedSpan<Pixel, Shader> span{tr.dzdx(), offset, shader};
        if constexpr (!kCount && sizeof(Depth) == 2 && is_flat_shader<Shader>::value) {
            FlatRows16<Format> rows(frame, span);
            return tr.scan(y_begin, y_end, rows);
        } else {
            DepthTestRows<kCount, Format, Depth, Shader> rows(frame, span);
            const uint32_t fragments = tr.scan(y_begin, y_end, rows);
            written += rows.written;
            return fragments;
        }
    } else {
        DepthTestRows<kCount, Format, Depth, Shader> rows(frame, shader, tr.dzdx());
        const uint32_t fragments = tr.scan(y_begin, y_end, rows);
        written += rows.written;
        return fragments;
    }
}

}  // namespace detail

/// Draws `mesh` into `frame` with the z-buffer. The caller cleared the band (clear()) and projected
/// the vertices into `verts` with project_vertices() for the same view. Borrows everything for the call.
/// Errors: invalid_argument when the frame is unusable, has no depth buffer, or its size differs from the view.
template <bool kCount = false, class Format, class Depth>
FrameStats draw_zbuffer(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                        const FrameView<Format, Depth>& frame, const DrawOptions& opt) {
    FrameStats st;
    if (!frame.valid() || frame.depth == nullptr || frame.width != view.width || frame.height != view.height ||
        verts.size() < mesh.positions.size()) {
        st.status = Status::invalid_argument;
        return st;
    }
    using Pixel = typename Format::Pixel;
    const BandBounds bb = band_bounds(frame);
    const FaceShading shading(view, opt);
    const bool whole_frame = frame.y0 == 0 && frame.y1 == frame.height;
    // Triangles are counted only by the band holding their first row, so band counts add up.
    auto owns = [&](int32_t first_row) {
        const int32_t first = clamp(first_row, int32_t{0}, frame.height - 1);
        return frame.y0 <= first && first < frame.y1;
    };
    // One drawable triangle with its signed area (< 0: front face), culling already decided.
    auto draw = [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t area, size_t t) {
        TriangleRaster tr;
        if (!tr.setup(a, b, c, area, frame.width, frame.height, bb)) return;  // no pixel centre of the band
        st.triangles_drawn += whole_frame || owns(tr.first_row());  // first_row(): the same rounding
        const int32_t y_begin = max(frame.y0, tr.first_row()), y_end = min(frame.y1, tr.end_row());
        if (opt.shade == Shade::depth) {
            st.fragments += detail::scan_depth_tested<kCount>(tr, y_begin, y_end, frame,
                                                              DepthShader<Format>(opt.depth_range), st.pixels_written);
            return;
        }
        st.fragments += detail::scan_depth_tested<kCount>(
            tr, y_begin, y_end, frame, FlatShader<Pixel>{Format::pack(shading.color(mesh, t, tr.front()))},
            st.pixels_written);
    };
    // Loop invariants in locals: the lambdas capture st by reference, so GCC would reload them per triangle.
    const bool cull = opt.cull;
    const Tri* const tris = mesh.tris.data();
    const ScreenVertex* const vp = verts.data();
    const size_t tri_count = mesh.tris.size();
    // False for zero area and culled faces (counted). Inline: most triangles end here.
    auto keep = [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t area)
                    __attribute__((always_inline)) {
        if (area == 0) return false;
        if (cull && area > 0) {
            st.triangles_culled += whole_frame ||
                owns((min(a.y, min(b.y, c.y)) - bb.y_origin + kSubpixel - 1) >> kSubpixelBits);
            return false;
        }
        return true;
    };
    st.triangles_in = static_cast<uint32_t>(tri_count);
    for (size_t t = 0; t < tri_count; ++t) {
        const Tri& tri = tris[t];
        const ScreenVertex& a = vp[tri.v[0]];
        const ScreenVertex& b = vp[tri.v[1]];
        const ScreenVertex& c = vp[tri.v[2]];
        if (a.z != 0 && b.z != 0 && c.z != 0) {  // drawable vertices: the common case, no call for culled faces
            const int32_t area = TriangleRaster::signed_area(a, b, c);
            if (keep(a, b, c, area)) draw(a, b, c, area, t);
            continue;
        }
        for_each_clipped(view, mesh, verts, t, st, [&](const ScreenVertex& pa, const ScreenVertex& pb,
                                                             const ScreenVertex& pc) {
            const int32_t area = TriangleRaster::signed_area(pa, pb, pc);
            if (keep(pa, pb, pc, area)) draw(pa, pb, pc, area, t);
        });
    }
    return st;
}

}  // namespace hider

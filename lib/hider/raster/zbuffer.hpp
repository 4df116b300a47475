// The z-buffer renderer: per triangle trivial reject, clip (rare), cull by the exact sign of the
// snapped screen area, flat shading, then TriangleRaster rows into span_depth_test. Works on any band
// of rows; drawing every band of a frame gives exactly the bytes of drawing the whole frame.
#pragma once
#include <hider/raster/draw_loop_asm.hpp>
#include <hider/raster/kernel_triangle.hpp>
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

/// Depth-tested rows [y_begin, y_end) of a set-up triangle with `shader`; returns the fragments
/// (counted when kCount) and adds the pixels written to `written`.
template <bool kCount, class Format, class Depth, class Shader>
uint32_t scan_depth_tested(const TriangleRaster& tr, int32_t y_begin, int32_t y_end,
                           const FrameView<Format, Depth>& frame, Shader shader, uint64_t& written) {
    using Pixel = typename Format::Pixel;
    if constexpr (sizeof(Pixel) == sizeof(Depth)) {
        // Same stride, same element size: every pixel's colour is this many bytes after its depth.
        const intptr_t offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(frame.color) -
                                                      reinterpret_cast<uintptr_t>(frame.depth));
        const PairedSpan<Pixel, Shader> span{tr.dzdx(), offset, shader};
        DepthTestRows<kCount, Format, Depth, Shader> rows(frame, span);
        const uint32_t fragments = tr.scan(y_begin, y_end, rows);
        written += rows.written;
        return fragments;
    } else {
        DepthTestRows<kCount, Format, Depth, Shader> rows(frame, shader, tr.dzdx());
        const uint32_t fragments = tr.scan(y_begin, y_end, rows);
        if constexpr (kCount) written += rows.written;
        return fragments;
    }
}

template <class T, class U> struct is_same_type { static constexpr bool value = false; };
template <class T> struct is_same_type<T, T> { static constexpr bool value = true; };

/// for_each_drawable()'s scan that leaves every triangle to its own loop.
struct EveryTriangle {};

/// The z-buffer's triangle loop: trivial reject, clip (rare), cull by the sign of the snapped area,
/// then draw(a, b, c, area, t) for each drawable triangle, in mesh order. Counts culled, clipped and
/// outside triangles in `st` (culled ones only in the band holding their first row). scan(t) returns the
/// next triangle from t on that this loop handles (the Thumb-1 draw loop does the ones before it itself).
template <class Draw, class Scan>
__attribute__((always_inline)) inline void for_each_drawable(const View& view, const Mesh& mesh,
                                                             Span<const ScreenVertex> verts, bool cull, const BandBounds& bb,
                                                             bool whole_frame, int32_t band_y0, int32_t band_y1,
                                                             int32_t height, FrameStats& st, Draw&& draw, Scan&& scan) {
    // Loop invariants in locals, captured by value: the lambdas capture st by reference, so GCC would
    // reload them (and the flags behind references) per triangle.
    const Tri* const tris = mesh.tris.data();
    const ScreenVertex* const vp = verts.data();
    const size_t tri_count = mesh.tris.size();
    const bool cull_faces = cull, whole = whole_frame;
    // False for zero area and culled faces (counted). Inline: most triangles end here.
    auto keep = [cull_faces, whole, &st, &bb, band_y0, band_y1, height](const ScreenVertex& a, const ScreenVertex& b,
                                                                        const ScreenVertex& c, int32_t area)
                    __attribute__((always_inline)) {
        if (area == 0) return false;
        if (cull_faces && area > 0) {
            if (whole) {
                ++st.triangles_culled;
            } else {  // counted only by the band holding the first row, so band counts add up
                const int32_t first = clamp((min(a.y, min(b.y, c.y)) - bb.y_origin + kSubpixel - 1) >> kSubpixelBits,
                                            int32_t{0}, height - 1);
                st.triangles_culled += band_y0 <= first && first < band_y1;
            }
            return false;
        }
        return true;
    };
    st.triangles_in = static_cast<uint32_t>(tri_count);
    auto one = [&](const Tri& tri, size_t t) __attribute__((always_inline)) {
        const ScreenVertex& a = vp[tri.v[0]];
        const ScreenVertex& b = vp[tri.v[1]];
        const ScreenVertex& c = vp[tri.v[2]];
        if (a.z != 0 && b.z != 0 && c.z != 0) {  // drawable vertices: the common case, no call for culled faces
            const int32_t area = TriangleRaster::signed_area(a, b, c);
            if (keep(a, b, c, area)) draw(a, b, c, area, t);
            return;
        }
        for_each_clipped(view, mesh, verts, t, st, [&](const ScreenVertex& pa, const ScreenVertex& pb,
                                                             const ScreenVertex& pc) {
            const int32_t area = TriangleRaster::signed_area(pa, pb, pc);
            if (keep(pa, pb, pc, area)) draw(pa, pb, pc, area, t);
        });
    };
    if constexpr (is_same_type<Scan, EveryTriangle>::value) {  // walked by pointer
        const Tri* tri_p = tris;
        for (size_t t = 0; t < tri_count; ++t, ++tri_p) one(*tri_p, t);
    } else {
        for (size_t t = scan(size_t{0}); t < tri_count; t = scan(t + 1)) one(tris[t], t);
    }
}

/// for_each_drawable() over every triangle.
template <class Draw>
__attribute__((always_inline)) inline void for_each_drawable(const View& view, const Mesh& mesh,
                                                             Span<const ScreenVertex> verts, bool cull, const BandBounds& bb,
                                                             bool whole_frame, int32_t band_y0, int32_t band_y1,
                                                             int32_t height, FrameStats& st, Draw&& draw) {
    for_each_drawable(view, mesh, verts, cull, bb, whole_frame, band_y0, band_y1, height, st, draw, EveryTriangle{});
}

/// One drawable triangle through TriangleRaster and the depth-tested span (any format, shader, band).
template <bool kCount, class Format, class Depth>
void draw_raster(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t area, size_t t,
                 const FrameView<Format, Depth>& frame, const BandBounds& bb, bool whole_frame, const Mesh& mesh,
                 const FaceShading& shading, const DrawOptions& opt, FrameStats& st) {
    TriangleRaster tr;
    if (!tr.setup(a, b, c, area, frame.width, frame.height, bb)) return;  // no pixel centre of the band
    const int32_t first = clamp(tr.first_row(), int32_t{0}, frame.height - 1);  // counted by one band only
    st.triangles_drawn += whole_frame || (frame.y0 <= first && first < frame.y1);
    const int32_t y_begin = max(frame.y0, tr.first_row()), y_end = min(frame.y1, tr.end_row());
    if (opt.shade == Shade::depth) {
        st.fragments += scan_depth_tested<kCount>(tr, y_begin, y_end, frame, DepthShader<Format>(opt.depth_range),
                                                  st.pixels_written);
        return;
    }
    st.fragments += scan_depth_tested<kCount>(
        tr, y_begin, y_end, frame,
        FlatShader<typename Format::Pixel>{Format::pack(shading.color(mesh, t, tr.front()))}, st.pixels_written);
}

/// The flat RGB565 + 16-bit depth path without fragment counting: triangles inside the frame's columns
/// are set up straight into the row kernel (kernel_triangle.hpp), the others take draw_raster(). On
/// Cortex-M, whole frames with headlight normals go through the assembly draw loop (draw_loop_asm.hpp),
/// which hands clipped and generic triangles back to this loop; kAsmLoop false keeps it out (the
/// kernelcheck firmware compares both).
template <class Format, bool kAsmLoop = true>
void draw_flat_kernel(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                      const FrameView<Format, uint16_t>& frame, const DrawOptions& opt, FrameStats& st) {
    const BandBounds bb = band_bounds(frame);
    const FaceShading shading(view, opt);
    const bool whole_frame = frame.y0 == 0 && frame.y1 == frame.height;
    KernelBand band = kernel_band(frame.width, frame.height, frame.y0, frame.y1,
                                  frame.stride * static_cast<int32_t>(sizeof(uint16_t)));
    const KernelTarget target{static_cast<intptr_t>(reinterpret_cast<uintptr_t>(frame.color) -
                                                    reinterpret_cast<uintptr_t>(frame.depth)),
                              band.stride_bytes};
    uint16_t* const depth = frame.depth;
    const int32_t stride = frame.stride, y0 = frame.y0, y1 = frame.y1, height = frame.height;
    KernelTriangle kt;
    KernelSetupIo io{&band, 0, &kt};
    auto draw = [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t area, size_t t)
                    __attribute__((always_inline)) {
        io.area = area;
        const KernelSetup s = kernel_setup(a, b, c, io);
        if (s == KernelSetup::none) return;
        if (s == KernelSetup::generic) {
            draw_raster<false>(a, b, c, area, t, frame, bb, whole_frame, mesh, shading, opt, st);
            return;
        }
        const int32_t first = clamp<int32_t>(kt.top, 0, height - 1);
        st.triangles_drawn += whole_frame || (y0 <= first && first < y1);
        if (kt.row >= kt.end) return;
        if constexpr (is_same_type<Format, Rgb565Format>::value) kt.k.color = shading.color565(mesh, t, area < 0);
        else kt.k.color = Format::pack(shading.color(mesh, t, area < 0));
        run_kernel_triangle(kt, depth + static_cast<ptrdiff_t>(kt.row - y0) * stride, y1, target);
    };
#if defined(HIDER_ARMV6M) || defined(HIDER_ARMV7M)
    if constexpr (kAsmLoop && is_same_type<Format, Rgb565Format>::value) {
        if (whole_frame && opt.shade == Shade::headlight && !mesh.normals.empty()) {
            const Tri* const tris = mesh.tris.data();
            DrawLoopArm d = draw_loop_arm(tris, mesh, verts, shading, opt.cull, io, depth, y0, stride, y1, target);
#if !defined(HIDER_ARMV6M)
            d.projected = all_projected(verts.data(), mesh.positions.size());
            band.depth_origin = reinterpret_cast<uintptr_t>(depth) -
                                static_cast<uintptr_t>(y0) * static_cast<uintptr_t>(band.stride_bytes);
            band.color_less_2 = target.color_offset - 2;
            band.stop = y1;
#endif
            for_each_drawable(view, mesh, verts, opt.cull, bb, whole_frame, y0, y1, height, st, draw, [&](size_t t) {
#if defined(HIDER_ARMV6M)
                return static_cast<size_t>(draw_flat_v6m(tris + t, &d) - tris);
#else
                return static_cast<size_t>(draw_flat_v7m(tris + t, &d) - tris);
#endif
            });
            st.triangles_culled += d.culled;
            st.triangles_drawn += d.drawn;
            return;
        }
    }
#endif
    for_each_drawable(view, mesh, verts, opt.cull, bb, whole_frame, y0, y1, height, st, draw);
}

}  // namespace detail

/// Draws `mesh` into `frame` with the z-buffer. The caller cleared the band (clear()) and projected
/// the vertices into `verts` with project_vertices() for the same view (hand-made ones must pass
/// screen_vertex_valid(); HIDER_ASSERT checks). Borrows everything for the call.
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
    HIDER_ASSERT(screen_vertices_valid(verts.data(), mesh.positions.size()));
    if constexpr (!kCount && detail::is_same_type<Format, Rgb565Format>::value && sizeof(Depth) == 2) {
        if (opt.shade != Shade::depth) {
            detail::draw_flat_kernel(view, mesh, verts, frame, opt, st);
            return st;
        }
    }
    const BandBounds bb = band_bounds(frame);
    const FaceShading shading(view, opt);
    const bool whole_frame = frame.y0 == 0 && frame.y1 == frame.height;
    detail::for_each_drawable(view, mesh, verts, opt.cull, bb, whole_frame, frame.y0, frame.y1, frame.height, st,
                              [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t area,
                                  size_t t) {
        detail::draw_raster<kCount>(a, b, c, area, t, frame, bb, whole_frame, mesh, shading, opt, st);
    });
    return st;
}

}  // namespace hider

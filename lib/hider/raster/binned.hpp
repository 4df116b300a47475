// Binned band rendering: a whole frame drawn band by band through one band-sized buffer, without
// walking every triangle again per band. One pass puts each drawable triangle into the list of the band
// holding its first row (lists linked through a caller array indexed by triangle, built back to front so
// each list runs in mesh order). Each band then merges, in mesh order, the triangles carried over from
// the band above with its own list: a flat RGB565 triangle inside the columns is set up once into a
// carried slot (kernel_triangle.hpp: edges, depth, the next short edge) and resumed by the next band
// without any division; other triangles, and kernel triangles that find no free slot, are re-linked into
// the next band's list and set up there again. Triangles are drawn in mesh order in every band, as
// draw_zbuffer() draws them, so the frame is byte for byte the full-frame one. The lists are in
// band_lists.hpp, the carried set-ups in band_carry.hpp.
#pragma once
#include <hider/raster/band_carry.hpp>

namespace hider {

namespace detail {
/// The bands of draw_zbuffer_binned() for any other format or shading: each band sets up its triangles
/// and re-links those that continue into the next band.
template <class Format, class Depth, class BandDone>
__attribute__((noinline)) void draw_bands_generic(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                                                  const FrameView<Format, Depth>& buffers, const DrawOptions& opt,
                                                  Rgb background, const BinnedScratch& scratch, BandDone& done,
                                                  BinnedStats& out, FrameStats& st) {
    const int32_t rows = buffers.y1, height = buffers.height;
    const size_t bands = static_cast<size_t>((height + rows - 1) / rows);
    uint16_t* const next = scratch.next.data();
    uint16_t* const head = scratch.head.data();
    const FaceShading shading(view, opt);
    for (size_t b = 0; b < bands; ++b) {
        const int32_t y0 = static_cast<int32_t>(b) * rows, y1 = min(height, y0 + rows);
        const FrameView<Format, Depth> band = band_in(buffers, y0, y1);
        clear(band, background);
        const BandBounds band_bb = band_bounds(band);
        uint16_t last = kNoTriangle;
        uint16_t& next_head = b + 1 < bands ? head[b + 1] : last;
        uint16_t insert_prev = kNoTriangle;
        for (uint16_t t = head[b]; t != kNoTriangle;) {
            const uint16_t tri = t;
            t = next[t];
            bool continues = false;
            for_each_piece(view, mesh, verts, tri, [&](const ScreenVertex& pa, const ScreenVertex& pb, const ScreenVertex& pc) {
                const int32_t area = TriangleRaster::signed_area(pa, pb, pc);
                if (area == 0 || (opt.cull && area > 0)) return;
                draw_raster<false>(pa, pb, pc, area, tri, band, band_bb, false, mesh, shading, opt, st);
                const int32_t y_max = max<int32_t>(pa.y, max<int32_t>(pb.y, pc.y));
                // Its box holds a centre of a later band (where it is counted as drawn when its first
                // row lies there, even if its edges exclude every centre).
                continues = continues || ((y_max - band_bb.y_origin) >> kSubpixelBits) >= y1;
            });
            if (!continues || b + 1 == bands) continue;  // below the last band: nothing to set up again
            ++out.set_up_again;
            insert_prev = insert_sorted(next, next_head, insert_prev, tri);
        }
        if (!done(band)) {
            st.status = Status::invalid_argument;
            return;
        }
    }
}

/// The bands of draw_zbuffer_binned() for flat RGB565 over 16-bit depth (KernelBands). Out of line:
/// the class's state stays off the frame under draw_bands_generic(), the other way a frame goes.
template <bool kAsmLoop, class BandDone>
__attribute__((noinline)) bool draw_kernel_bands(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                                                 const FrameView<Rgb565Format, uint16_t>& buffers, const DrawOptions& opt,
                                                 Rgb background, const BinnedScratch& scratch, BandDone& done,
                                                 BinnedStats& out, FrameStats& st, uint32_t projected) {
    KernelBands<kAsmLoop> kb(view, mesh, verts, buffers, opt, scratch, out, st, projected);
    return kb.draw(buffers.y1, buffers.height, background, done);
}

/// draw_zbuffer_binned(); kAsmLoop false keeps the assembly band and binning loops out (kernelcheck
/// compares both).
template <bool kAsmLoop, class Format, class Depth, class BandDone>
FrameStats draw_binned(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, const FrameView<Format, Depth>& buffers,
                       const DrawOptions& opt, Rgb background, const BinnedScratch& scratch, BandDone& done, BinnedStats* bs) {
    FrameStats st;
    if (bs != nullptr) *bs = BinnedStats{};  // this frame's figures, also in a struct kept across frames
    const int32_t rows = buffers.y1, height = buffers.height;
    const size_t tri_count = mesh.tris.size();
    const size_t bands = buffers.valid() ? static_cast<size_t>((height + rows - 1) / rows) : 0;
    if (!buffers.valid() || buffers.y0 != 0 || buffers.depth == nullptr || buffers.width != view.width ||
        height != view.height || verts.size() < mesh.positions.size() || tri_count > kNoTriangle ||
        scratch.next.size() < tri_count || scratch.head.size() < bands || scratch.carried.size() > 255 ||
        scratch.slots.size() < 3 * scratch.carried.size()) {
        st.status = Status::invalid_argument;
        return st;
    }
    HIDER_ASSERT(screen_vertices_valid(verts.data(), mesh.positions.size()));
    for (size_t b = 0; b < bands; ++b) scratch.head[b] = kNoTriangle;
    st.triangles_in = static_cast<uint32_t>(tri_count);
    const BandBounds bb = band_bounds(band_view<Format, Depth>(nullptr, nullptr, buffers.width, height, 0, height));
    const uint32_t projected = bin_triangles<kAsmLoop>(view, mesh, verts, opt.cull, bb, height, rows,
                                                       scratch.next.data(), scratch.head.data(), st);
    BinnedStats local;
    BinnedStats& out = bs != nullptr ? *bs : local;
    if constexpr (is_same_type<Format, Rgb565Format>::value && sizeof(Depth) == 2) {
        if (opt.shade != Shade::depth) {
            if (!draw_kernel_bands<kAsmLoop>(view, mesh, verts, buffers, opt, background, scratch, done, out, st, projected))
                st.status = Status::invalid_argument;
            return st;
        }
    }
    draw_bands_generic(view, mesh, verts, buffers, opt, background, scratch, done, out, st);
    return st;
}

}  // namespace detail

/// Draws `mesh` band by band: for each band of `buffers.y1` rows (buffers: a view of rows [0, y1) whose
/// memory, `buffers.stride` elements a row, is reused for every band), clears it to `background`, draws
/// every triangle's rows in it and calls done(band), a FrameView of the band's rows; done() returns
/// false to stop the frame, and must only read the band: a band after one that nothing drew into (no
/// triangle listed or carried there) may find that band's background instead of a clear of its own (a
/// done() that converts pixels in place, a byte swap for SPI, must convert a copy). `verts` as for draw_zbuffer(). Same
/// bytes as clear() + draw_zbuffer() on the whole frame; statistics as the whole frame's. `bs`, if
/// given, receives this frame's carried-slot figures (it is reset, not added to). Errors: invalid_argument (unusable buffers: among them a
/// band taller than the frame, y1 > height, which is refused rather than clamped; a mesh of more
/// than 65,535 triangles, scratch too small: next < triangles, head < bands, slots < 3 x carried, more
/// than 255 carried slots, or done() returned false). Borrows everything for the call.
template <class Format, class Depth, class BandDone>
FrameStats draw_zbuffer_binned(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                               const FrameView<Format, Depth>& buffers, const DrawOptions& opt, Rgb background,
                               const BinnedScratch& scratch, BandDone&& done, BinnedStats* bs = nullptr) {
    return detail::draw_binned<true>(view, mesh, verts, buffers, opt, background, scratch, done, bs);
}

}  // namespace hider

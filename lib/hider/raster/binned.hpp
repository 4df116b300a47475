// Binned band rendering: a whole frame drawn band by band through one band-sized buffer, without
// walking every triangle again per band. One pass puts each drawable triangle into the list of the band
// holding its first row (lists linked through a caller array indexed by triangle, built back to front so
// each list runs in mesh order). Each band then merges, in mesh order, the triangles carried over from
// the band above with its own list: a flat RGB565 triangle inside the columns is set up once into a
// carried slot (kernel_triangle.hpp: edges, depth, the next short edge) and resumed by the next band
// without any division; other triangles, and kernel triangles that find no free slot, are re-linked into
// the next band's list and set up there again. Triangles are drawn in mesh order in every band, as
// draw_zbuffer() draws them, so the frame is byte for byte the full-frame one.
#pragma once
#include <hider/raster/zbuffer.hpp>

namespace hider {

/// Caller-owned memory of draw_zbuffer_binned() (sizes per mesh and frame; see README.md for the formula).
struct BinnedScratch {
    Span<uint16_t> next;             ///< one per mesh triangle: the band lists (mesh of <= 65,535 triangles)
    Span<uint16_t> head;             ///< one per band: the first triangle whose first row it holds
    Span<KernelTriangle> carried;    ///< kernel set-ups carried into the next band (<= 255); fewer only costs set-ups
    Span<uint8_t> slots;             ///< three per carried slot: this band's and the next band's order, free slots
};

/// What draw_zbuffer_binned() measured besides the frame's statistics.
struct BinnedStats {
    uint32_t carried = 0;           ///< band continuations resumed from a carried slot
    uint32_t set_up_again = 0;      ///< band continuations set up again (not a kernel triangle, or no free slot)
    uint32_t carried_high_water = 0;  ///< most slots in use at a band boundary (to size `carried`)
};

namespace detail {
constexpr uint16_t kNoTriangle = 0xFFFF;

/// First row of the box of a drawable triangle, clamped to the frame.
inline int32_t first_row_in_frame(int32_t y_min, const BandBounds& bb, int32_t height) {
    return clamp((y_min - bb.y_origin + kSubpixel - 1) >> kSubpixelBits, int32_t{0}, height - 1);
}

/// Inserts t into the ascending list starting at head, searching from after `prev` (kNoTriangle: from
/// the start); returns t, the next insertion's `prev`. Insertions come in ascending order.
inline uint16_t insert_sorted(uint16_t* next, uint16_t& head, uint16_t prev, uint16_t t) {
    uint16_t at = prev == kNoTriangle ? head : next[prev];
    while (at != kNoTriangle && at < t) {
        prev = at;
        at = next[at];
    }
    next[t] = at;
    if (prev == kNoTriangle) head = t;
    else next[prev] = t;
    return t;
}
}  // namespace detail

/// Draws `mesh` band by band: for each band of `buffers.y1` rows (buffers: a view of rows [0, y1) whose
/// memory is reused for every band), clears it to `background`, draws every triangle's rows in it and
/// calls done(band), a FrameView of the band's rows; done() returns false to stop the frame. Same
/// bytes as clear() + draw_zbuffer() on the whole frame; statistics as the whole frame's. `bs`, if
/// given, receives the carried-slot figures. Errors: invalid_argument (unusable buffers, a mesh of more
/// than 65,535 triangles, scratch too small: next < triangles, head < bands, slots < 3 x carried, more
/// than 255 carried slots, or done() returned false). Borrows everything for the call.
template <class Format, class Depth, class BandDone>
FrameStats draw_zbuffer_binned(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                               const FrameView<Format, Depth>& buffers, const DrawOptions& opt, Rgb background,
                               BinnedScratch& scratch, BandDone&& done, BinnedStats* bs = nullptr) {
    FrameStats st;
    const int32_t rows = buffers.y1, width = buffers.width, height = buffers.height;
    const size_t tri_count = mesh.tris.size();
    const size_t bands = buffers.valid() ? static_cast<size_t>((height + rows - 1) / rows) : 0;
    if (!buffers.valid() || buffers.y0 != 0 || buffers.depth == nullptr || width != view.width ||
        height != view.height || verts.size() < mesh.positions.size() || tri_count > detail::kNoTriangle ||
        scratch.next.size() < tri_count || scratch.head.size() < bands || scratch.carried.size() > 255 ||
        scratch.slots.size() < 3 * scratch.carried.size()) {
        st.status = Status::invalid_argument;
        return st;
    }
    const FrameView<Format, Depth> whole = band_view<Format, Depth>(nullptr, nullptr, width, height, 0, height);
    const BandBounds bb = band_bounds(whole);
    uint16_t* const next = scratch.next.data();
    uint16_t* const head = scratch.head.data();
    for (size_t b = 0; b < bands; ++b) head[b] = detail::kNoTriangle;
    // Binning, back to front: each list ends up in mesh order. Culled, clipped and outside triangles are
    // counted here, as draw_zbuffer() counts them on a whole frame.
    st.triangles_in = static_cast<uint32_t>(tri_count);
    for (size_t i = tri_count; i-- > 0;) {
        int32_t first = height;  // first row of any drawable piece
        for_each_clipped(view, mesh, verts, i, st, [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
            const int32_t area = TriangleRaster::signed_area(a, b, c);
            if (area == 0) return;
            if (opt.cull && area > 0) {
                ++st.triangles_culled;
                return;
            }
            const ScreenBox box = screen_box(a, b, c);
            if (misses_band(box, bb)) return;  // no pixel centre of the frame: never drawn
            first = min(first, detail::first_row_in_frame(box.y_min, bb, height));
        });
        if (first == height) continue;
        const size_t band = static_cast<size_t>(first / rows);
        next[i] = head[band];
        head[band] = static_cast<uint16_t>(i);
    }
    // Carried slots: cur (this band, mesh order), nxt (the next band), and a stack of free ones.
    const uint8_t capacity = static_cast<uint8_t>(scratch.carried.size());
    KernelTriangle* const pool = scratch.carried.data();
    uint8_t* cur = scratch.slots.data();
    uint8_t* nxt = cur + capacity;
    uint8_t* const free_slots = nxt + capacity;
    uint8_t n_cur = 0, n_free = capacity;
    for (uint8_t k = 0; k < capacity; ++k) free_slots[k] = static_cast<uint8_t>(capacity - 1 - k);
    BinnedStats local;
    BinnedStats& out = bs != nullptr ? *bs : local;
    const FaceShading shading(view, opt);
    constexpr bool kKernel = detail::is_same_type<Format, Rgb565Format>::value && sizeof(Depth) == 2;
    const bool use_kernel = kKernel && opt.shade != Shade::depth;
    KernelBand kband = kernel_band(width, height, 0, height, buffers.stride * static_cast<int32_t>(sizeof(Depth)));
    KernelTriangle spare;  // a kernel set-up without a free slot: drawn here, set up again next band
    for (size_t b = 0; b < bands; ++b) {
        const int32_t y0 = static_cast<int32_t>(b) * rows, y1 = min(height, y0 + rows);
        const FrameView<Format, Depth> band =
            band_view<Format, Depth>(buffers.color, buffers.depth, width, height, y0, y1);
        clear(band, background);
        const BandBounds band_bb = band_bounds(band);
        const intptr_t color_offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(band.color) -
                                                            reinterpret_cast<uintptr_t>(band.depth));
        kband.row_from = y0;
        uint16_t dummy_head = detail::kNoTriangle;
        uint16_t& next_head = b + 1 < bands ? head[b + 1] : dummy_head;
        uint16_t insert_prev = detail::kNoTriangle;
        auto again = [&](uint16_t t) {  // set up again in the next band
            ++out.set_up_again;
            if (b + 1 < bands) insert_prev = detail::insert_sorted(next, next_head, insert_prev, t);
        };
        auto run = [&](KernelTriangle& kt) {  // this band's rows of a kernel set-up; true when it continues
            if constexpr (kKernel) {
                uint16_t* const zrow = band.depth + static_cast<ptrdiff_t>(kt.row - y0) * band.stride;
                run_kernel_triangle(kt, zrow, y1, color_offset);
            }
            return kt.row < kt.end;
        };
        uint8_t n_nxt = 0, ci = 0;
        uint16_t t = head[b];
        while (ci < n_cur || t != detail::kNoTriangle) {
            if (ci < n_cur && (t == detail::kNoTriangle || pool[cur[ci]].tri < t)) {  // carried from the band above
                const uint8_t s = cur[ci++];
                ++out.carried;
                if (run(pool[s])) nxt[n_nxt++] = s;
                else free_slots[n_free++] = s;
                continue;
            }
            const uint16_t tri = t;
            t = next[t];
            bool continues = false;
            FrameStats pieces;  // clipping counts were taken while binning
            for_each_clipped(view, mesh, verts, tri, pieces, [&](const ScreenVertex& pa, const ScreenVertex& pb,
                                                                 const ScreenVertex& pc) {
                const int32_t area = TriangleRaster::signed_area(pa, pb, pc);
                if (area == 0 || (opt.cull && area > 0)) return;
                if (kKernel && use_kernel) {
                    const bool slot = n_free != 0 && verts[mesh.tris[tri].v[0]].z != 0 && verts[mesh.tris[tri].v[1]].z != 0 &&
                                      verts[mesh.tris[tri].v[2]].z != 0;  // clipped pieces are set up per band
                    KernelTriangle& kt = slot ? pool[free_slots[n_free - 1]] : spare;
                    KernelSetupIo io{&kband, area, &kt};
                    const KernelSetup s = kernel_setup(pa, pb, pc, io);
                    if (s == KernelSetup::none) return;
                    if (s == KernelSetup::kernel) {
                        const int32_t first = clamp(kt.top, int32_t{0}, height - 1);
                        st.triangles_drawn += y0 <= first && first < y1;
                        if (kt.row >= kt.end) return;
                        if constexpr (kKernel) kt.k.color = Format::pack(shading.color(mesh, tri, area < 0));
                        kt.tri = tri;
                        if (!run(kt)) return;
                        if (slot) nxt[n_nxt++] = free_slots[--n_free];
                        else continues = true;
                        return;
                    }
                }
                // Generic: any format, or a kernel triangle crossing the side columns.
                detail::draw_raster<false>(pa, pb, pc, area, tri, band, band_bb, false, mesh, shading, opt, st);
                const int32_t y_max = max<int32_t>(pa.y, max<int32_t>(pb.y, pc.y));
                continues = continues || ((y_max - bb.y_origin + kSubpixel - 1) >> kSubpixelBits) > y1;  // end row
            });
            if (continues) again(tri);
        }
        out.carried_high_water = max<uint32_t>(out.carried_high_water, n_nxt);
        uint8_t* const swap = cur;
        cur = nxt;
        nxt = swap;
        n_cur = n_nxt;
        if (!done(band)) {
            st.status = Status::invalid_argument;
            return st;
        }
    }
    return st;
}

}  // namespace hider

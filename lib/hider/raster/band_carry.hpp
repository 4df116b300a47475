// The band renderer's carried set-ups (binned.hpp): a flat RGB565 triangle inside the columns is set
// up once into a slot (kernel_triangle.hpp: edges, depth, the next short edge) and resumed by the next
// bands without any division; each band merges them in mesh order with its own list. KernelBands draws
// the bands; on ARMv7-M through the assembly loop of band_loop_asm.hpp, on ARMv6-M and RV32 with the
// resumes in assembly (band_resume.hpp).
#pragma once
#include <hider/raster/band_loop_asm.hpp>
#include <hider/raster/band_resume.hpp>

namespace hider {

namespace detail {
/// The bands of draw_zbuffer_binned() for flat RGB565 over 16-bit depth: kernel set-ups carried in
/// slots. A class rather than lambdas: the per-triangle code reaches the band's state through `this`
/// (GCC rebuilt a closure of sixteen references per triangle). kAsmLoop: on ARMv7-M, runs of listed
/// triangles go through draw_band_v7m() (headlight shading with normals), on ARMv6-M and RV32 the
/// resumes through resume_carried_v6m() and resume_carried_rv32(); false keeps them out (the kernelcheck
/// firmware compares); `projected` (all_projected() of the vertices) spares the assembly its
/// per-triangle clip test.
template <bool kAsmLoop>
class KernelBands {
public:
    KernelBands(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                const FrameView<Rgb565Format, uint16_t>& buffers, const DrawOptions& opt, const BinnedScratch& scratch,
                BinnedStats& out, FrameStats& st, uint32_t projected)
        : view_(view), mesh_(mesh), verts_(verts), opt_(opt), shading_(view, opt), out_(out), st_(st),
          next_(scratch.next.data()), head_(scratch.head.data()), pool_(scratch.carried.data()),
          free_base_(scratch.slots.data() + 2 * scratch.carried.size()),
          kband_(kernel_band(buffers.width, buffers.height, 0, buffers.height, buffers.stride * 2)),
          bt_{{static_cast<intptr_t>(reinterpret_cast<uintptr_t>(buffers.color) - reinterpret_cast<uintptr_t>(buffers.depth)),
               kband_.stride_bytes},
              buffers.depth, 0},
          io_{&kband_, 0, &spare_},
          band_(buffers),  // band() sets the rows
          band_bb_(band_bounds(buffers)) {
        const uint8_t capacity = static_cast<uint8_t>(scratch.carried.size());
        for (uint32_t k = 0; k < capacity; ++k) free_base_[k] = static_cast<uint8_t>(k);
        cs_ = {pool_, scratch.slots.data(), scratch.slots.data(), scratch.slots.data() + capacity, free_base_ + capacity};
#if defined(HIDER_ARMV7M)
        use_asm_ = kAsmLoop && opt.shade == Shade::headlight && !mesh.normals.empty();
        loop_.tris = mesh.tris.data();
        loop_.verts = verts.data();
        loop_.next = next_;
        loop_.io = &io_;
        loop_.normals_offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(mesh.normals.data()) -
                                                     reinterpret_cast<uintptr_t>(mesh.tris.data()));
        for (int j = 0; j < 3; ++j) loop_.view_z[j] = shading_.view_z(j);
        loop_.base_r = opt.base.r;
        loop_.base_g = opt.base.g;
        loop_.base_b = opt.base.b;
        loop_.color_less_2 = bt_.target.color_offset - 2;
        kband_.color_less_2 = loop_.color_less_2;
        loop_.stride_bytes = bt_.target.stride_bytes;
        loop_.pool = pool_;
        loop_.record_size = sizeof(KernelTriangle);
        loop_.free_base = free_base_;
        loop_.projected = projected;
        loop_.depth = band_.depth;
#else
        (void)projected;
#endif
    }

    /// Draws the frame's bands of `rows` rows (the last one may be shorter), each after clearing it to
    /// `background`; false when done() refuses one (the bands before it drawn and counted). Out of line:
    /// one call a frame, with the band loop's values in registers and off draw_binned()'s frame.
    template <class BandDone>
    __attribute__((noinline)) bool draw(int32_t rows, int32_t height, Rgb background, BandDone& done) {
        const size_t bands = static_cast<size_t>((height + rows - 1) / rows);
        color_word_ = uint32_t{Rgb565Format::pack(background)} * 0x00010001u;
        packed_ = band_.stride == band_.width &&
                  ((reinterpret_cast<uintptr_t>(band_.color) | reinterpret_cast<uintptr_t>(band_.depth)) & 3u) == 0;
        bool ok = true;
        for (size_t b = 0; b < bands && ok; ++b) {
            const int32_t y0 = static_cast<int32_t>(b) * rows;
            ok = band(b, bands, y0, min(height, y0 + rows), background, done);
        }
#if defined(HIDER_ARMV7M)
        st_.triangles_drawn += loop_.drawn;  // the assembly loop's, counted up by every band
#endif
        return ok;
    }

private:
    /// Draws band b (rows [y0, y1)) after clearing it to `background` (the same in every band); false
    /// when done() refuses it. In draw()'s loop.
    template <class BandDone>
    __attribute__((always_inline)) bool band(size_t b, size_t bands, int32_t y0, int32_t y1, const Rgb& background,
                                             BandDone& done) {
        // band_in(buffers, y0, y1) and its band_bounds(): only the rows change from band to band (buffers'
        // stride: the kernel's rows (kband_) are buffers' rows too).
        band_.y0 = y0;
        band_.y1 = y1;
        band_bb_.y_first = y0 * kSubpixel + band_bb_.y_origin;
        band_bb_.y_last = (y1 - 1) * kSubpixel + band_bb_.y_origin;
        // Nothing listed and nothing carried: nothing draws into this band, and the band after it finds the
        // background this one's clear left (done() leaves a band as it was): it skips its clear.
        const bool empty = head_[b] == kNoTriangle && cs_.cur == cs_.cur_end;
        if (!clean_) clear_band(background);
        clean_ = empty;
        kband_.row_from = y0;
        bt_.row_end = y1;
        count_from_ = y0 == 0 ? INT32_MIN : y0;
        next_head_ = b + 1 < bands ? &head_[b + 1] : nullptr;
        insert_prev_ = kNoTriangle;
        const uint8_t* const band_cur = cs_.cur;
        uint8_t* const band_nxt = cs_.nxt;
#if defined(HIDER_ARMV7M)
        if (use_asm_ && !empty) {  // the band in assembly but for the listed triangles it hands back
            loop_.y0 = y0;
            loop_.y1 = y1;
            kband_.depth_origin = reinterpret_cast<uintptr_t>(band_.depth) -
                                  static_cast<uintptr_t>(y0) * static_cast<uintptr_t>(kband_.stride_bytes);
            kband_.stop = y1;
            loop_.count_from = count_from_;
            loop_.cur = cs_.cur;
            loop_.cur_end = cs_.cur_end;
            for (uint32_t t = head_[b];;) {
                loop_.free_top = cs_.free_top;
                loop_.nxt = cs_.nxt;
                t = draw_band_v7m(t, &loop_);
                cs_.free_top = loop_.free_top;
                cs_.nxt = loop_.nxt;
                if (t == kNoTriangle) break;
                const uint16_t tri = static_cast<uint16_t>(t);
                const uint32_t flags = t;
                t = next_[tri];
                if ((flags & kGenericHandBack) != 0) generic_again(tri);  // the assembly's set-up said generic
                else new_triangle(tri);
            }
            cs_.cur = loop_.cur;
        } else
#endif
        if (!empty) {
            uint32_t pending = pending_carried(cs_);
            for (uint32_t t = head_[b];;) {
                if (pending < t) pending = resume(t);  // the carried triangles before t, in mesh order
                if (t == kNoTriangle) break;
                const uint16_t tri = static_cast<uint16_t>(t);
                t = next_[t];
                new_triangle(tri);
            }
        }
        out_.carried += static_cast<uint32_t>(cs_.cur - band_cur);
        out_.carried_high_water = max<uint32_t>(out_.carried_high_water, static_cast<uint32_t>(cs_.nxt - band_nxt));
        cs_.cur = band_nxt;  // the next band resumes what this one carried
        cs_.cur_end = cs_.nxt;
        cs_.nxt = const_cast<uint8_t*>(band_cur);
        return done(band_);
    }

    /// clear() of the band: whole words straight to fill_words() when the rows are packed, both buffers
    /// word-aligned (packed_) and the band holds an even number of pixels (clear() and fill() cost a band
    /// more around the stores).
    void clear_band(const Rgb& background) {
        const size_t n = static_cast<size_t>(band_.width) * static_cast<size_t>(band_.rows());
        if ((n & 1u) != 0 || !packed_) {
            clear(band_, background);
            return;
        }
        fill_words(band_.color, n / 2, color_word_);
        fill_words(band_.depth, n / 2, 0xFFFFFFFFu);
    }

    /// A triangle of this band's list: set up in a free slot (or the spare), its rows drawn; continuing
    /// into the next band in its slot, or re-linked there when it has none.
#if defined(HIDER_ARMV6M)
    __attribute__((noinline))  // Thumb-1's low registers cannot hold the band loop's values and this one's
#else
    __attribute__((always_inline))  // in the band loop: no call, no registers saved per triangle
#endif
    void new_triangle(uint16_t tri) {
        const Tri& t = mesh_.tris[tri];
        const ScreenVertex& a = verts_[t.v[0]];
        const ScreenVertex& b = verts_[t.v[1]];
        const ScreenVertex& c = verts_[t.v[2]];
        bool continues;
        if (a.z != 0 && b.z != 0 && c.z != 0) {
            continues = whole(a, b, c, tri);
        } else {  // clipped pieces are set up again in every band
            continues_ = false;
            for_each_piece(view_, mesh_, verts_, tri, [this, tri](const ScreenVertex& pa, const ScreenVertex& pb,
                                                                 const ScreenVertex& pc) { piece(pa, pb, pc, tri); });
            continues = continues_;
        }
        if (continues) relink(tri);
    }

    /// resume_carried() of the carried set-ups before `limit` (on ARMv6-M and RV32 in assembly but when
    /// kAsmLoop is false: kernelcheck compares both).
    __attribute__((always_inline)) uint32_t resume(uint32_t limit) {
#if defined(HIDER_RV32_ASM)
        if constexpr (kAsmLoop) return resume_carried_rv32(&cs_, limit, &bt_);
#elif defined(HIDER_ARMV6M)
        if constexpr (kAsmLoop) return resume_carried_v6m(&cs_, limit, &bt_);
#endif
        return resume_carried(cs_, limit, bt_);
    }

    /// A triangle that continues below the band without a slot: linked into the next band's list, to be
    /// set up there again. Below the last band there is none: nothing is set up again, nothing counted.
    __attribute__((always_inline)) void relink(uint16_t tri) {
        if (next_head_ == nullptr) return;
        ++out_.set_up_again;
        insert_prev_ = insert_sorted(next_, *next_head_, insert_prev_, tri);
    }

#if defined(HIDER_ARMV7M)
    /// A listed triangle whose set-up draw_band_v7m() found generic: drawn by draw_generic() and
    /// re-linked when it continues, as new_triangle() does after its own set-up.
    __attribute__((noinline)) void generic_again(uint16_t tri) {
        const Tri& t = mesh_.tris[tri];
        const ScreenVertex& a = verts_[t.v[0]];
        const ScreenVertex& b = verts_[t.v[1]];
        const ScreenVertex& c = verts_[t.v[2]];
        if (draw_generic(a, b, c, TriangleRaster::signed_area(a, b, c), tri)) relink(tri);
    }
#endif

    /// A whole triangle of the lists (bin_triangles() linked only those of non-zero area, not culled),
    /// set up in a free slot or the spare; true when it continues into the next band without a slot.
    __attribute__((always_inline)) bool whole(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                              uint16_t tri) {
        const int32_t area = screen_area(a, b, c);
        const bool slot = cs_.free_top != free_base_;
        KernelTriangle& kt = slot ? pool_[cs_.free_top[-1]] : spare_;
        io_.area = area;
        io_.out = &kt;
        const KernelSetup s = kernel_setup(a, b, c, io_);
        if (s == KernelSetup::kernel) {
            // Binned by its top row (re-linked ones start above the band): drawn here when top >= y0.
            st_.triangles_drawn += kt.top >= count_from_;
            if (!run_set_up(kt, tri, area)) return false;
            if (!slot) return true;
            *cs_.nxt++ = *--cs_.free_top;
            return false;
        }
        return s == KernelSetup::generic && draw_generic(a, b, c, area, tri);
    }

    /// A piece of a clipped triangle: set up in the spare, drawn; sets continues_ when it reaches the
    /// next band.
    __attribute__((noinline)) void piece(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, uint16_t tri) {
        const int32_t area = TriangleRaster::signed_area(a, b, c);
        if (area == 0 || (opt_.cull && area > 0)) return;
        io_.area = area;
        io_.out = &spare_;
        const KernelSetup s = kernel_setup(a, b, c, io_);
        bool continues = false;
        if (s == KernelSetup::kernel) {
            // A piece may start in a later band than its triangle's bin: counted as drawn in the band of
            // its top row, so it continues to there even when it has no row (the whole frame counts it).
            const bool below = spare_.top >= band_.y1;
            st_.triangles_drawn += spare_.top >= count_from_ && !below;
            continues = run_set_up(spare_, tri, area) || below;
        } else if (s == KernelSetup::generic) {
            continues = draw_generic(a, b, c, area, tri);
        }
        continues_ = continues_ || continues;
    }

    /// Draws the rows of this band of a kernel set-up (its callers count it as drawn in the band of its
    /// first row, clamped to the frame); true when rows remain for the next band.
    __attribute__((always_inline)) bool run_set_up(KernelTriangle& kt, uint16_t tri, int32_t area) {
        if (kt.row >= kt.end) return false;
        kt.k.color = shading_.color565(mesh_, tri, area < 0);
        kt.tri = tri;
        run_kernel_triangle(kt, band_.depth + static_cast<ptrdiff_t>(kt.row - band_.y0) * band_.stride, band_.y1,
                            bt_.target);
        return kt.row < kt.end;
    }

    /// A triangle the kernel set-up leaves to TriangleRaster (it crosses the side columns, or a steep
    /// plane); true when it reaches below the band.
    __attribute__((noinline)) bool draw_generic(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                                int32_t area, uint16_t tri) {
        draw_raster<false>(a, b, c, area, tri, band_, band_bb_, false, mesh_, shading_, opt_, st_);
        const int32_t y_max = max<int32_t>(a.y, max<int32_t>(b.y, c.y));
        return ((y_max - band_bb_.y_origin) >> kSubpixelBits) >= band_.y1;  // its box holds a later band's centre
    }

    const View& view_;
    const Mesh& mesh_;
    Span<const ScreenVertex> verts_;
    const DrawOptions& opt_;
    const FaceShading shading_;
    BinnedStats& out_;
    FrameStats& st_;
    uint16_t* const next_;
    uint16_t* const head_;
    KernelTriangle* const pool_;
    uint8_t* const free_base_;
    CarriedSlots cs_{};
    KernelBand kband_;
    KernelBandTarget bt_;
    KernelTriangle spare_;  // a set-up without a free slot: drawn here, set up again in the next band
    KernelSetupIo io_;
    FrameView<Rgb565Format, uint16_t> band_;  // the band's rows of buffers
    BandBounds band_bb_;                      // band_bounds(band_)
    uint32_t color_word_ = 0;  // two background pixels
    uint16_t* next_head_ = nullptr;
    uint16_t insert_prev_ = kNoTriangle;
    int32_t count_from_ = 0;  // a set-up counts as drawn in this band from this top row on (INT32_MIN: band 0)
    bool continues_ = false;
    bool packed_ = false;  // clear_band(): rows packed and both buffers word-aligned
    bool clean_ = false;   // the band memory holds only the background (a band with nothing to draw)
#if defined(HIDER_ARMV7M)
    bool use_asm_ = false;
    BandLoopArm loop_{};
#endif
};
}  // namespace detail

}  // namespace hider

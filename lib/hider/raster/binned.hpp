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
#include <hider/raster/band_loop_asm.hpp>
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
constexpr uint16_t kNoTriangle = 0xFFFF;  ///< ends a list; above every triangle index

/// First row of the box of a drawable triangle, clamped to the frame.
inline int32_t first_row_in_frame(int32_t y_min, const BandBounds& bb, int32_t height) {
    return clamp((y_min - bb.y_origin + kSubpixel - 1) >> kSubpixelBits, int32_t{0}, height - 1);
}

/// Inserts t into the ascending list starting at head, searching from after `prev` (kNoTriangle: from
/// the start); returns t, the next insertion's `prev`. Insertions come in ascending order.
inline uint16_t insert_sorted(uint16_t* next, uint16_t& head, uint16_t prev, uint16_t t) {
    uint16_t at = prev == kNoTriangle ? head : next[prev];
    while (at < t) {  // kNoTriangle stops it
        prev = at;
        at = next[at];
    }
    next[t] = at;
    if (prev == kNoTriangle) head = t;
    else next[prev] = t;
    return t;
}

/// What binning a clipped triangle needs, behind one pointer so that the binning loop keeps its own
/// values in registers.
struct ClippedBinning {
    const View& view;
    const Mesh& mesh;
    Span<const ScreenVertex> verts;
    bool cull;
    const BandBounds& bb;
    int32_t height;
    FrameStats& st;
};

/// First row of the drawable pieces of clipped triangle t (height if none); counts its culled pieces,
/// and it as clipped or outside. Out of line: the clipped polygon's 200 bytes stay off the binning
/// loop's stack frame.
__attribute__((noinline)) inline int32_t first_row_clipped(const ClippedBinning& cb, size_t t) {
    int32_t first = cb.height;
    for_each_clipped(cb.view, cb.mesh, cb.verts, t, cb.st, [&](const ScreenVertex& pa, const ScreenVertex& pb,
                                                               const ScreenVertex& pc) {
        const int32_t area = TriangleRaster::signed_area(pa, pb, pc);
        if (area == 0) return;
        if (cb.cull && area > 0) {
            ++cb.st.triangles_culled;
            return;
        }
        first = min(first, first_row_in_frame(min<int32_t>(pa.y, min<int32_t>(pb.y, pc.y)), cb.bb, cb.height));
    });
    return first;
}

/// for_each_clipped() out of line, without counting (binning counted): the clipped polygon stays off the
/// band loop's stack frame.
template <class Piece>
__attribute__((noinline)) void for_each_piece(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, size_t t,
                                              Piece&& piece) {
    struct {
        uint32_t triangles_outside, triangles_clipped;
    } counted{};
    for_each_clipped(view, mesh, verts, t, counted, piece);
}

/// x and y of a vertex; on ARMv6-M from one 32-bit load (x is the low half): Thumb-1 has no
/// immediate-offset signed halfword load, and two of them cost four instructions. Elsewhere the
/// halfword loads are cheaper than the load and two extensions.
struct ScreenXY {
    int32_t x, y;
};
__attribute__((always_inline)) inline ScreenXY screen_xy(const ScreenVertex& v) {
#if defined(__ARM_ARCH_6M__)
    const uint32_t w = *reinterpret_cast<const AliasWord*>(&v);  // ScreenVertex is word-aligned
    return {static_cast<int16_t>(w), static_cast<int32_t>(w) >> 16};
#else
    return {v.x, v.y};
#endif
}

/// Links every drawable triangle of the mesh (non-zero area, not culled) into the list of the band
/// holding its first row, back to front so each list runs in mesh order; counts culled, clipped and outside triangles as draw_zbuffer()
/// does on a whole frame. band_scale = ceil(2^20 / rows): band = first row * band_scale >> 20, exact for
/// rows of frames up to 1,024. Out of line with few live values, so the loop stays in registers.
__attribute__((noinline)) inline void bin_triangles(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, bool cull,
                                                    const BandBounds& bb, int32_t height, uint32_t band_scale, uint16_t* next,
                                                    uint16_t* head, FrameStats& st) {
    const ScreenVertex* const vp = verts.data();
    // first_row_in_frame() with the rounding folded into the origin: rows from (y - y_lift) >> 4, y_lift
    // = y_origin - 15.
    const int32_t y_lift = bb.y_origin - (kSubpixel - 1), last = height - 1;
    // Culled: area > cull_above (0 when culling, else above every area).
    const int32_t cull_above = cull ? 0 : INT32_MAX;
    uint32_t culled = 0;
    const ClippedBinning clipped{view, mesh, verts, cull, bb, height, st};
    const Tri* tri = mesh.tris.data() + mesh.tris.size();
    for (uint32_t i = static_cast<uint32_t>(mesh.tris.size()); i != 0;) {
        --i;
        --tri;
        const ScreenVertex& a = vp[tri->v[0]];
        const ScreenVertex& b = vp[tri->v[1]];
        const ScreenVertex& c = vp[tri->v[2]];
        int32_t first;
        if (a.z != 0 && b.z != 0 && c.z != 0) {
            const ScreenXY pa = screen_xy(a), pb = screen_xy(b), pc = screen_xy(c);
            const int32_t area = (pb.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (pb.y - pa.y);  // signed_area()
            if (area == 0) continue;
            if (area > cull_above) {
                ++culled;
                continue;
            }
            // A box without a pixel centre of the frame is binned too: its set-up finds nothing to draw.
            first = clamp((min(pa.y, min(pb.y, pc.y)) - y_lift) >> kSubpixelBits, int32_t{0}, last);
        } else {
            first = first_row_clipped(clipped, i);
            if (first > last) continue;
        }
        const uint32_t band = (static_cast<uint32_t>(first) * band_scale) >> 20;
        next[i] = head[band];
        head[band] = static_cast<uint16_t>(i);
    }
    st.triangles_culled += culled;
}

/// The carried set-ups of draw_bands_kernel(): slots in use this band (mesh order) from `cur` to
/// `cur_end`, the next band's from `nxt` (growing), and a stack of free slots below `free_top`.
struct CarriedSlots {
    KernelTriangle* pool;
    const uint8_t* cur;
    const uint8_t* cur_end;
    uint8_t* nxt;
    uint8_t* free_top;
};

/// Where a band's kernel rows go: the target, the band's first depth row and its end row.
struct KernelBandTarget {
    KernelTarget target;
    uint16_t* zrow;
    int32_t row_end;
};

/// The mesh triangle of the first carried set-up still to resume this band (kNoTriangle: none).
inline uint32_t pending_carried(const CarriedSlots& cs) { return cs.cur != cs.cur_end ? cs.pool[*cs.cur].tri : kNoTriangle; }

/// Resumes the carried set-ups whose triangle comes before `limit`: draws their rows of the band (each
/// is on the band's first row) and moves each to the next band's slots or back to the free ones.
/// Returns pending_carried() after them. Out of line with few live values, so GCC keeps the loop in
/// registers.
__attribute__((noinline)) inline uint32_t resume_carried(CarriedSlots& cs, uint32_t limit, const KernelBandTarget& bt) {
    KernelTriangle* const pool = cs.pool;
    const uint8_t* cur = cs.cur;
    const uint8_t* const end = cs.cur_end;
    uint8_t* nxt = cs.nxt;
    uint8_t* free_top = cs.free_top;
    uint32_t pending = kNoTriangle;
    for (; cur != end; ++cur) {
        const uint8_t s = *cur;
        KernelTriangle& kt = pool[s];
        if (kt.tri >= limit) {
            pending = kt.tri;
            break;
        }
        run_kernel_triangle(kt, bt.zrow, bt.row_end, bt.target);
        if (kt.row < kt.end) *nxt++ = s;
        else *free_top++ = s;
    }
    cs.cur = cur;
    cs.nxt = nxt;
    cs.free_top = free_top;
    return pending;
}

/// The bands of draw_zbuffer_binned() for flat RGB565 over 16-bit depth: kernel set-ups carried in
/// slots. A class rather than lambdas: the per-triangle code reaches the band's state through `this`
/// (GCC rebuilt a closure of sixteen references per triangle). kAsmLoop: on ARMv7-M, runs of listed
/// triangles go through draw_band_v7m() (headlight shading with normals); false keeps it out (the
/// kernelcheck firmware compares both).
template <bool kAsmLoop>
class KernelBands {
public:
    KernelBands(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                const FrameView<Rgb565Format, uint16_t>& buffers, const DrawOptions& opt, const BinnedScratch& scratch,
                BinnedStats& out, FrameStats& st)
        : view_(view), mesh_(mesh), verts_(verts), buffers_(buffers), opt_(opt), shading_(view, opt), out_(out), st_(st),
          next_(scratch.next.data()), head_(scratch.head.data()), pool_(scratch.carried.data()),
          free_base_(scratch.slots.data() + 2 * scratch.carried.size()),
          kband_(kernel_band(buffers.width, buffers.height, 0, buffers.height, buffers.stride * 2)),
          bt_{{static_cast<intptr_t>(reinterpret_cast<uintptr_t>(buffers.color) - reinterpret_cast<uintptr_t>(buffers.depth)),
               kband_.stride_bytes},
              buffers.depth, 0},
          io_{&kband_, 0, &spare_} {
        const uint8_t capacity = static_cast<uint8_t>(scratch.carried.size());
        for (uint8_t k = 0; k < capacity; ++k) free_base_[k] = k;
        cs_ = {pool_, scratch.slots.data(), scratch.slots.data(), scratch.slots.data() + capacity, free_base_ + capacity};
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
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
        loop_.stride_bytes = kband_.stride_bytes;
        loop_.target = &bt_.target;
        loop_.pool = pool_;
        loop_.free_base = free_base_;
#endif
    }

    /// Draws band b (rows [y0, y1)) after clearing it; false when done() refuses it.
    template <class BandDone>
    bool band(size_t b, size_t bands, int32_t y0, int32_t y1, Rgb background, BandDone& done) {
        band_ = band_view<Rgb565Format, uint16_t>(buffers_.color, buffers_.depth, buffers_.width, buffers_.height, y0, y1);
        clear_band(background);
        band_bb_ = band_bounds(band_);
        kband_.row_from = y0;
        bt_.row_end = y1;
        count_from_ = y0 == 0 ? INT32_MIN : y0;
        next_head_ = b + 1 < bands ? &head_[b + 1] : nullptr;
        insert_prev_ = kNoTriangle;
        const uint8_t* const band_cur = cs_.cur;
        uint8_t* const band_nxt = cs_.nxt;
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
        if (use_asm_) {  // the band in assembly but for the listed triangles it hands back
            loop_.depth = band_.depth;
            loop_.y0 = y0;
            loop_.y1 = y1;
            loop_.count_from = count_from_;
            loop_.drawn = 0;
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
                t = next_[t];
                new_triangle(tri);
            }
            cs_.cur = loop_.cur;
            st_.triangles_drawn += loop_.drawn;
        } else
#endif
        {
            uint32_t pending = pending_carried(cs_);
            for (uint32_t t = head_[b];;) {
                if (pending < t) pending = resume_carried(cs_, t, bt_);  // the carried triangles before t, in mesh order
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

private:
    /// clear() of the band: whole words straight to fill_words() when both buffers are word-aligned and
    /// the band holds an even number of pixels (clear() and fill() spent about 130 instructions a band
    /// around the store-multiples).
    void clear_band(Rgb background) {
        const size_t n = static_cast<size_t>(band_.width) * static_cast<size_t>(band_.rows());
        if ((n & 1u) != 0 || ((reinterpret_cast<uintptr_t>(band_.color) | reinterpret_cast<uintptr_t>(band_.depth)) & 3u) != 0) {
            clear(band_, background);
            return;
        }
        fill_words(band_.color, n / 2, uint32_t{Rgb565Format::pack(background)} * 0x00010001u);
        fill_words(band_.depth, n / 2, 0xFFFFFFFFu);
    }

    /// A triangle of this band's list: set up in a free slot (or the spare), its rows drawn; continuing
    /// into the next band in its slot, or re-linked there when it has none.
#if defined(__ARM_ARCH_6M__)
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
        if (!continues) return;
        ++out_.set_up_again;
        if (next_head_ != nullptr) insert_prev_ = insert_sorted(next_, *next_head_, insert_prev_, tri);
    }

    /// A whole triangle of the lists (bin_triangles() linked only those of non-zero area, not culled),
    /// set up in a free slot or the spare; true when it continues into the next band without a slot.
    __attribute__((always_inline)) bool whole(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                              uint16_t tri) {
        const int32_t area = TriangleRaster::signed_area(a, b, c);
        const bool slot = cs_.free_top != free_base_;
        KernelTriangle& kt = slot ? pool_[cs_.free_top[-1]] : spare_;
        io_.area = area;
        io_.out = &kt;
        const KernelSetup s = kernel_setup(a, b, c, io_);
        if (s == KernelSetup::kernel) {
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
        if (s == KernelSetup::kernel) continues = run_set_up(spare_, tri, area);
        else if (s == KernelSetup::generic) continues = draw_generic(a, b, c, area, tri);
        continues_ = continues_ || continues;
    }

    /// Counts a kernel set-up as drawn in the band of its first row (clamped to the frame) and draws its
    /// rows of this band; true when rows remain for the next band.
    __attribute__((always_inline)) bool run_set_up(KernelTriangle& kt, uint16_t tri, int32_t area) {
        // The set-up found a pixel centre of the band in the box, so kt.top < y1.
        st_.triangles_drawn += kt.top >= count_from_;
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
        return ((y_max - band_bb_.y_origin + kSubpixel - 1) >> kSubpixelBits) > band_.y1;
    }

    const View& view_;
    const Mesh& mesh_;
    Span<const ScreenVertex> verts_;
    const FrameView<Rgb565Format, uint16_t>& buffers_;
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
    FrameView<Rgb565Format, uint16_t> band_{};
    BandBounds band_bb_{};
    uint16_t* next_head_ = nullptr;
    uint16_t insert_prev_ = kNoTriangle;
    int32_t count_from_ = 0;  // a set-up counts as drawn in this band from this top row on (INT32_MIN: band 0)
    bool continues_ = false;
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    bool use_asm_ = false;
    BandLoopArm loop_{};
#endif
};

/// The bands of draw_zbuffer_binned() for any other format or shading: each band sets up its triangles
/// and re-links those that continue into the next band.
template <class Format, class Depth, class BandDone>
__attribute__((noinline)) void draw_bands_generic(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts,
                        const FrameView<Format, Depth>& buffers, const DrawOptions& opt, Rgb background,
                        const BinnedScratch& scratch, BandDone& done, BinnedStats& out, FrameStats& st) {
    const int32_t rows = buffers.y1, width = buffers.width, height = buffers.height;
    const size_t bands = static_cast<size_t>((height + rows - 1) / rows);
    uint16_t* const next = scratch.next.data();
    uint16_t* const head = scratch.head.data();
    const FaceShading shading(view, opt);
    for (size_t b = 0; b < bands; ++b) {
        const int32_t y0 = static_cast<int32_t>(b) * rows, y1 = min(height, y0 + rows);
        const FrameView<Format, Depth> band = band_view<Format, Depth>(buffers.color, buffers.depth, width, height, y0, y1);
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
                continues = continues || ((y_max - band_bb.y_origin + kSubpixel - 1) >> kSubpixelBits) > y1;
            });
            if (!continues) continue;
            ++out.set_up_again;
            if (b + 1 < bands) insert_prev = insert_sorted(next, next_head, insert_prev, tri);
        }
        if (!done(band)) {
            st.status = Status::invalid_argument;
            return;
        }
    }
}

/// draw_zbuffer_binned(); kAsmLoop false keeps the assembly band loop out (kernelcheck compares both).
template <bool kAsmLoop, class Format, class Depth, class BandDone>
FrameStats draw_binned(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, const FrameView<Format, Depth>& buffers,
                       const DrawOptions& opt, Rgb background, const BinnedScratch& scratch, BandDone& done, BinnedStats* bs) {
    FrameStats st;
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
    for (size_t b = 0; b < bands; ++b) scratch.head[b] = kNoTriangle;
    st.triangles_in = static_cast<uint32_t>(tri_count);
    const BandBounds bb = band_bounds(band_view<Format, Depth>(nullptr, nullptr, buffers.width, height, 0, height));
    const uint32_t band_scale = ((uint32_t{1} << 20) + static_cast<uint32_t>(rows) - 1) / static_cast<uint32_t>(rows);
    bin_triangles(view, mesh, verts, opt.cull, bb, height, band_scale, scratch.next.data(), scratch.head.data(), st);
    BinnedStats local;
    BinnedStats& out = bs != nullptr ? *bs : local;
    if constexpr (is_same_type<Format, Rgb565Format>::value && sizeof(Depth) == 2) {
        if (opt.shade != Shade::depth) {
            KernelBands<kAsmLoop> kb(view, mesh, verts, buffers, opt, scratch, out, st);
            for (size_t b = 0; b < bands; ++b) {
                const int32_t y0 = static_cast<int32_t>(b) * rows;
                if (!kb.band(b, bands, y0, min(height, y0 + rows), background, done)) {
                    st.status = Status::invalid_argument;
                    break;
                }
            }
            return st;
        }
    }
    draw_bands_generic(view, mesh, verts, buffers, opt, background, scratch, done, out, st);
    return st;
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
                               const BinnedScratch& scratch, BandDone&& done, BinnedStats* bs = nullptr) {
    return detail::draw_binned<true>(view, mesh, verts, buffers, opt, background, scratch, done, bs);
}

}  // namespace hider

// The band renderer's lists (binned.hpp): the caller's scratch, and one pass that links each drawable
// triangle into the list of the band holding its first row, through a caller array indexed by
// triangle, back to front so that each list runs in mesh order.
#pragma once
#include <hider/raster/band_bin_asm.hpp>
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
    /// Most slots in use at a band boundary: a lower bound for sizing the slots, since inside a band a
    /// continuing triangle of the band's own list may take a slot before earlier carried ones give theirs
    /// back (mesh order): add slots while `set_up_again` still falls.
    uint32_t carried_high_water = 0;
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
#if defined(HIDER_ARMV6M)
    const uint32_t w = *reinterpret_cast<const AliasWord*>(&v);  // ScreenVertex is word-aligned
    return {static_cast<int16_t>(w), static_cast<int32_t>(w) >> 16};
#else
    return {v.x, v.y};
#endif
}

/// TriangleRaster::signed_area() of three screen_xy() points, or of three vertices through screen_xy().
__attribute__((always_inline)) inline int32_t screen_area(const ScreenXY& a, const ScreenXY& b, const ScreenXY& c) {
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}
__attribute__((always_inline)) inline int32_t screen_area(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    return screen_area(screen_xy(a), screen_xy(b), screen_xy(c));
}

/// Links every drawable triangle of the mesh (non-zero area, not culled) into the list of the band
/// holding its first row, back to front so each list runs in mesh order; counts culled, clipped and outside triangles as draw_zbuffer()
/// does on a whole frame. `rows`: rows per band (band_scale = ceil(2^20 / rows): band = first row *
/// band_scale >> 20, exact for frames of up to 1,024 rows). Out of line with few live values, so the loop stays in registers. kAsm: on
/// ARMv7-M and ARMv6-M the whole triangles go through bin_triangles_v7m() or bin_triangles_v6m() (false
/// keeps them out: kernelcheck compares both), without a clip test when every vertex is projected
/// (all_projected()); returns that flag there (the ARMv7-M band loop uses it; 0 elsewhere).
template <bool kAsm = true>
__attribute__((noinline)) uint32_t bin_triangles(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, bool cull,
                                                 const BandBounds& bb, int32_t height, int32_t rows, uint16_t* next,
                                                 uint16_t* head, FrameStats& st) {
    const ScreenVertex* const vp = verts.data();
    // first_row_in_frame() with the rounding folded into the origin: rows from (y - y_lift) >> 4, y_lift
    // = y_origin - 15.
    const int32_t y_lift = bb.y_origin - (kSubpixel - 1), last = height - 1;
    // Culled: area > cull_above (0 when culling, else above every area).
    const int32_t cull_above = cull ? 0 : INT32_MAX;
    const uint32_t band_scale = ((uint32_t{1} << 20) + static_cast<uint32_t>(rows) - 1) / static_cast<uint32_t>(rows);
    uint32_t culled = 0;
    const ClippedBinning clipped{view, mesh, verts, cull, bb, height, st};
#if defined(HIDER_ARMV7M) || defined(HIDER_ARMV6M)
    if constexpr (kAsm) {
        const uint32_t projected = all_projected(vp, mesh.positions.size());  // one scan a frame
        BinLoopArm d{y_lift, height * kSubpixel - 1, bin_scale(static_cast<uint32_t>(rows)), head, next,
                     mesh.tris.data(), vp, cull_above, 0, projected};
        for (uint32_t i = static_cast<uint32_t>(mesh.tris.size()); (i = bin_triangles_asm(i, &d)) != 0;) {
            --i;  // a vertex of triangle i lies outside a clip plane
            const int32_t first = first_row_clipped(clipped, i);
            if (first > last) continue;
            const uint32_t band = (static_cast<uint32_t>(first) * band_scale) >> 20;
            next[i] = head[band];
            head[band] = static_cast<uint16_t>(i);
        }
        st.triangles_culled += d.culled;
        return projected;
    }
#endif
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
            const int32_t area = screen_area(pa, pb, pc);
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
    return 0;
}
}  // namespace detail

}  // namespace hider

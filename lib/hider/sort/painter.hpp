// The painter's algorithm (Newell, Newell & Sancha's sort, without their tests): one depth key per
// screen triangle, an O(n) LSD radix sort into caller arrays (no heap), drawing far to near with no
// depth buffer. Its known failures (cyclic overlap, piercing) are real and tested; newell.hpp fixes them.
#pragma once
#include <hider/sort/poly.hpp>

namespace hider {

/// Which depth orders the painter: the farthest vertex (Newell's choice) or the barycentre.
enum class DepthKey : uint8_t { farthest, barycenter };

/// A sort entry: key (larger = farther) and the index of its polygon. 8 bytes.
struct SortKey {
    uint32_t key;
    uint32_t index;
};
static_assert(sizeof(SortKey) == 8, "SortKey's size is documented in README.md");

/// Sorts keys[0..n) by key, ascending and stable, with `scratch` (>= n entries) as the second
/// buffer: four passes of 8 bits, O(n + 256) each. The result ends up in `keys`.
inline void radix_sort(Span<SortKey> keys, Span<SortKey> scratch) {
    const size_t n = keys.size();
    SortKey* src = keys.data();
    SortKey* dst = scratch.data();
    for (int shift = 0; shift < 32; shift += 8) {
        uint32_t count[256] = {};
        for (size_t i = 0; i < n; ++i) ++count[(src[i].key >> shift) & 255];
        uint32_t sum = 0;
        for (uint32_t& c : count) { const uint32_t t = c; c = sum; sum += t; }
        for (size_t i = 0; i < n; ++i) dst[count[(src[i].key >> shift) & 255]++] = src[i];
        swap_values(src, dst);
    }
    // Four passes: the sorted data is back in `keys`.
}

/// Back-to-front order of polys[0..n): order[k] = index of the k-th polygon to draw. Ties keep the
/// mesh order. Returns invalid_argument (and writes nothing) unless keys, scratch and order hold at
/// least polys.size() entries. Cost: O(n).
[[nodiscard]] inline Status painter_order(Span<const ScreenPoly> polys, DepthKey key, Span<SortKey> keys,
                                          Span<SortKey> scratch, Span<uint32_t> order) {
    const size_t n = polys.size();
    if (keys.size() < n || scratch.size() < n || order.size() < n) return Status::invalid_argument;
    for (size_t i = 0; i < n; ++i) {
        const ScreenPoly& p = polys[i];
        const uint32_t k = key == DepthKey::farthest
                               ? p.zmax
                               : static_cast<uint32_t>((uint64_t{p.v[0].z} + p.v[1].z + p.v[2].z) / 3);
        keys[i] = {~k, static_cast<uint32_t>(i)};  // ascending on ~z = farthest first
    }
    radix_sort({keys.data(), n}, {scratch.data(), n});
    for (size_t i = 0; i < n; ++i) order[i] = keys[i].index;
    return Status::ok;
}

/// Draws polys in `order` (back to front) into the band, painting every covered pixel; pieces (from
/// newell_order) are drawn with their cut chains in `cuts` (empty for whole triangles). With kCount
/// the statistics count written pixels. Precondition: order indexes polys.
template <bool kCount = false, class Format, class Depth>
FrameStats paint_in_order(const View& view, const Mesh& mesh, Span<const ScreenPoly> polys, Span<const PieceCut> cuts,
                          Span<const uint32_t> order, const FrameView<Format, Depth>& frame, const DrawOptions& opt) {
    FrameStats st;
    if (!frame_matches(view, frame)) {
        st.status = Status::invalid_argument;
        return st;
    }
    const FaceShading shading(view, opt);
    const BandBounds bb = band_bounds(frame);
    for (size_t k = 0; k < order.size(); ++k) {
        const ScreenPoly& p = polys[order[k]];
        const uint32_t n = with_poly_raster(p, cuts, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
            ++st.triangles_drawn;
            return with_face_shader<Format>(opt, shading, mesh, p.tri, (p.flags & kPolyFront) != 0,
                                            [&](const auto& shader) { return paint_rows(r, y0, y1, frame, shader); });
        });
        st.fragments += n;
        if constexpr (kCount) st.pixels_written += n;
    }
    return st;
}

}  // namespace hider

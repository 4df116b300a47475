// Screen space as every part of hider sees it: coordinates in 1/16 pixel from the frame centre (see
// CONVENTIONS.md), the depth range, the projected vertex and a depth range for shading.
#pragma once
#include <hider/base.hpp>

namespace hider {

constexpr int kSubpixelBits = 4;                    ///< screen coordinates carry 4 fraction bits
constexpr int32_t kSubpixel = 1 << kSubpixelBits;   ///< subpixels per pixel
constexpr int32_t kCoordLimit = (1 << 14) - 1;      ///< |x|, |y| <= this keeps edge functions in int32
constexpr int32_t kGuardBand = (1 << 14) - 64;      ///< clip planes sit here; rounding stays below the limit

/// The coordinate (subpixels from the frame centre) of the centre of pixel 0 on an axis of `size` pixels.
constexpr int32_t pixel_centre_origin(int32_t size) { return kSubpixel / 2 - size * (kSubpixel / 2); }
/// Depths are kept in [kDepthMargin, 2^32 - 2^16 - 1 - kDepthMargin] so plane-stepping error never wraps,
/// and so a 16-bit buffer's z >> 16 stays below its clear value 0xFFFF: the farthest surface still draws.
constexpr uint32_t kDepthMargin = 4096;
constexpr uint32_t kDepthNear = kDepthMargin;
constexpr uint32_t kDepthFar = 0xFFFF0000u - 1 - kDepthMargin;

/// A projected vertex: x, y in subpixels from the frame centre (y down), z in [kDepthNear, kDepthFar]
/// (smaller = nearer, affine in screen space). A vertex outside a clip plane has z == 0 and its planes
/// in x (8 bytes a vertex: indexing is a shift, and a mesh's vertex array is a third smaller).
/// project_vertices() and project() never give a drawable vertex z == 0; a hand-made vertex with z == 0
/// and no plane in x's low byte would count as drawable (outside() == 0), at depth 0, and fails
/// screen_vertex_valid().
struct ScreenVertex {
    int16_t x = 0;
    int16_t y = 0;
    uint32_t z = 0;

    /// The clip planes the vertex lies outside of (0 = drawable).
    constexpr uint8_t outside() const { return z == 0 ? static_cast<uint8_t>(x) : 0; }
    /// Marks the vertex as outside `planes` (nonzero); x, y and z lose their meaning.
    constexpr void mark_outside(uint8_t planes) {
        x = planes;
        y = 0;
        z = 0;
    }
};
static_assert(sizeof(ScreenVertex) == 8, "ScreenVertex is two halfwords and a word");

/// Whether v is a vertex the drawing code can trust, as project_vertices() gives them: outside a clip
/// plane (z == 0, a plane in x's low byte; x and y are not read), or within |x|, |y| <= kCoordLimit and
/// z in [kDepthNear, kDepthFar]. The draw calls take their vertices on trust (an edge function past the
/// limit overflows int32); with HIDER_ENABLE_ASSERTS they check them with screen_vertices_valid().
constexpr bool screen_vertex_valid(const ScreenVertex& v) {
    if (v.z == 0) return v.outside() != 0;
    return v.x >= -kCoordLimit && v.x <= kCoordLimit && v.y >= -kCoordLimit && v.y <= kCoordLimit &&
           v.z >= kDepthNear && v.z <= kDepthFar;
}

/// screen_vertex_valid() for the first n vertices.
constexpr bool screen_vertices_valid(const ScreenVertex* v, size_t n) {
    for (size_t i = 0; i < n; ++i)
        if (!screen_vertex_valid(v[i])) return false;
    return true;
}

/// 1 when none of the first n vertices has z == 0 (outside a clip plane, or hand-made with z == 0): the
/// Cortex-M3 triangle loops then skip their per-triangle clip test (a vertex serves about six triangles,
/// so one scan a frame costs less than the tests).
inline uint32_t all_projected(const ScreenVertex* v, size_t n) {
    // Eight a turn; written as the loop's condition so each test is a forward branch out (ldr, cbz).
    const ScreenVertex* const block_end = v + (n & ~size_t{7});
    while (v != block_end && v[0].z != 0 && v[1].z != 0 && v[2].z != 0 && v[3].z != 0 && v[4].z != 0 &&
           v[5].z != 0 && v[6].z != 0 && v[7].z != 0)
        v += 8;
    if (v != block_end) return 0;
    for (n &= 7; n != 0; --n, ++v)
        if (v->z == 0) return 0;
    return 1;
}

/// Smallest and largest depth among drawable projected vertices (for depth shading).
struct DepthRange {
    uint32_t min = kDepthFar, max = kDepthNear;
};

}  // namespace hider

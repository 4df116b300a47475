// Static storage of a band renderer for one baked scene: every array draw_zbuffer_binned() and the PPM
// sink need, sized at compile time (the RAM formula of README.md "Bands"), in one struct the firmware
// declares as a static.
#pragma once
#include "bands/bands.hpp"

namespace bands {

/// Sizes of a W x H scene of V vertices and T triangles drawn in bands of `Rows` rows of the full width
/// (more of a column window: render_in_bands()) in a band memory of `Pixels` pixels, with `Carried`
/// carried set-ups.
template <int32_t W, int32_t H, size_t V, size_t T, int32_t Rows, size_t Carried, size_t Pixels = size_t{W} * Rows>
struct Sizes {
    static_assert(Pixels >= size_t{W} * Rows, "the band memory holds Rows rows of the full width");
    static constexpr size_t kBands = static_cast<size_t>((H + Rows - 1) / Rows);
    static constexpr size_t kPpmChunk = 8;  ///< pixels converted to RGB888 at a time for the PPM sink

    struct Storage {
        hider::ScreenVertex verts[V];
        uint16_t color[Pixels];
        uint16_t depth[Pixels];
        uint16_t next[T];
        uint16_t head[kBands];
        hider::KernelTriangle carried[Carried];
        uint8_t slots[3 * Carried];
        uint8_t ppm_chunk[3 * kPpmChunk];

        constexpr BandBuffers buffers() {
            return {verts, color, depth, Rows, {next, head, carried, slots}};
        }
    };
};

}  // namespace bands

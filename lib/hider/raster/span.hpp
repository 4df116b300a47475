// Inner loops over one row span [x0, x1). Setup happens outside; the body is a load, a compare,
// two stores and adds. Depth is a uint32 stepped by dz per pixel (wrapping add);
// the buffer stores its top bits (DepthTraits). Smaller = nearer; ties keep what is there.
#pragma once
#include <hider/frame.hpp>

namespace hider {

/// Flat colour: the same pixel for every fragment of a triangle.
template <class Pixel>
struct FlatShader {
    Pixel color;
    Pixel operator()(uint32_t) const { return color; }
};

/// Depth-test span: writes colour and depth where the fragment is nearer. Returns pixels written
/// when kCount (the count costs one add per written pixel; the default path does not count).
/// Precondition: x0 < x1. Kept out of line so the loop owns the registers: at -Os on Cortex-M, inlining it into the row
/// walk spilled its pointers to the stack (loads and stores in every pixel).
template <bool kCount, class Depth, class Pixel, class Shader>
__attribute__((noinline)) uint32_t span_depth_test(Pixel* crow, Depth* zrow, int32_t x0, int32_t x1, uint32_t z_q32,
                                                  uint32_t dz_q32, const Shader& shade) {
    constexpr int kShift = DepthTraits<Depth>::kShift;
    const Shader shader = shade;  // a local copy: stores to the buffers cannot alias it
    uint32_t written = 0;
    int32_t x = x0;
    do {  // precondition x0 < x1: the test sits at the bottom, one branch a pixel
        const Depth depth = static_cast<Depth>(z_q32 >> kShift);
        if (depth < zrow[x]) {
            zrow[x] = depth;
            crow[x] = shader(z_q32);
            if constexpr (kCount) ++written;
        }
        z_q32 += dz_q32;
    } while (++x != x1);
    return written;
}

/// What span_depth_test_paired() needs besides the row: the depth step, the byte offset from a depth
/// element to its pixel (fixed when both are one size and share the stride) and the shader.
template <class Pixel, class Shader>
struct PairedSpan {
    uint32_t dz_q32;
    intptr_t color_offset;
    Shader shader;
};

/// span_depth_test() for colour and depth elements of one size (RGB565 + 16-bit depth): zp points at
/// the depth of the first pixel, n >= 1 pixels. Four register arguments and one pointer stepped per
/// pixel: the z-buffer's row loop passes less and keeps fewer values live. Writes the same bytes as
/// span_depth_test().
template <bool kCount, class Depth, class Pixel, class Shader>
__attribute__((noinline)) uint32_t span_depth_test_paired(Depth* zp, int32_t n, uint32_t z_q32,
                                                         const PairedSpan<Pixel, Shader>& p) {
    static_assert(sizeof(Pixel) == sizeof(Depth), "paired spans need elements of one size");
    constexpr int kShift = DepthTraits<Depth>::kShift;
    const uint32_t dz_q32 = p.dz_q32;
    const intptr_t offset = p.color_offset;
    const Shader shader = p.shader;  // a local copy: stores to the buffers cannot alias it
    uint32_t written = 0;
    do {
        const Depth depth = static_cast<Depth>(z_q32 >> kShift);
        if (depth < *zp) {
            *zp = depth;
            *reinterpret_cast<Pixel*>(reinterpret_cast<uintptr_t>(zp) + static_cast<uintptr_t>(offset)) = shader(z_q32);
            if constexpr (kCount) ++written;
        }
        z_q32 += dz_q32;
        ++zp;
    } while (--n != 0);
    return written;
}

/// Painting span without a depth buffer (painter's algorithms): every pixel is written.
template <class Pixel, class Shader>
inline void span_paint(Pixel* crow, int32_t x0, int32_t x1, uint32_t z_q32, uint32_t dz_q32, const Shader& shade) {
    const Shader shader = shade;
    Pixel* cp = crow + x0;
    for (int32_t n = x1 - x0; n > 0; --n, ++cp, z_q32 += dz_q32) *cp = shader(z_q32);
}

}  // namespace hider

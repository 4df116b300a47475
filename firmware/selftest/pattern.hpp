// Deterministic 16x8 binary PPM (P6, 8-bit RGB) built from the integer operations the renderer
// relies on: 32x32->64 multiply, signed 64/32 and 32/32 division and remainder, and arithmetic
// right shifts of negative values. Shared by the selftest firmware and its host reference, whose
// outputs must be byte-identical. Includes only <stddef.h>/<stdint.h> (freestanding).
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace selftest {

constexpr int32_t kWidth = 16;
constexpr int32_t kHeight = 8;
constexpr char kPpmHeader[] = "P6\n16 8\n255\n";
constexpr size_t kPpmHeaderSize = sizeof(kPpmHeader) - 1;
constexpr size_t kPpmSize = kPpmHeaderSize + size_t{kWidth} * kHeight * 3;
/// Seed of the reference image. The firmware reads it through a volatile so nothing folds.
constexpr int32_t kSeed = 0x01234567;

/// Colour of pixel (x, y); each channel mixes in one operation. No divisor is ever zero, and
/// every intermediate fits its type for x < kWidth, y < kHeight and |seed| < 2^28.
inline void pixel(int32_t x, int32_t y, int32_t seed, uint8_t* rgb) {
    const int32_t a = (x - 8) * 40503 + seed;                      // crosses zero in x
    const int32_t b = (y - 4) * -7919 - (seed >> 3);                // mostly negative
    const int64_t product = static_cast<int64_t>(a) * b;            // 32x32 -> 64
    const int32_t divisor64 = (y - 3) * 977 + ((x & 1) != 0 ? -13 : 29);
    const int64_t quotient64 = product / divisor64;                 // signed 64 / 32, truncates
    const int32_t quotient32 = a / ((x + 1) * ((y & 1) != 0 ? -3 : 5));  // signed 32 / 32
    const int32_t remainder32 = b % 97;                             // takes the dividend's sign
    const int32_t shifted32 = b >> 5;                               // arithmetic: rounds to -inf
    const int64_t shifted64 = product >> 17;
    rgb[0] = static_cast<uint8_t>(quotient64 ^ (quotient64 >> 8));
    rgb[1] = static_cast<uint8_t>(quotient32 + remainder32);
    rgb[2] = static_cast<uint8_t>(shifted32 ^ static_cast<int32_t>(shifted64));
}

/// Writes the whole PPM file (header + pixels, kPpmSize bytes) into `out`.
inline void write_ppm(uint8_t* out, int32_t seed) {
    for (size_t i = 0; i < kPpmHeaderSize; ++i) out[i] = static_cast<uint8_t>(kPpmHeader[i]);
    uint8_t* rgb = out + kPpmHeaderSize;
    for (int32_t y = 0; y < kHeight; ++y) {
        for (int32_t x = 0; x < kWidth; ++x, rgb += 3) pixel(x, y, seed, rgb);
    }
}

}  // namespace selftest

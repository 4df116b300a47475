// Host port: minimal PNG writer (8-bit RGB, uncompressed deflate blocks) so frames can go straight
// into documents without extra tools. Deterministic: same pixels, same bytes.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "host/ppm.hpp"

namespace hider::port {

/// The most bytes a PNG chunk may hold (PNG specification: 2^31 - 1).
constexpr size_t kPngMaxChunk = 0x7FFFFFFF;

/// The bytes of a PNG file holding width x height RGB888 pixels (row 0 first); empty unless
/// rgb_size_ok(width, height, rgb.size()) (host/ppm.hpp). The image data goes into IDAT chunks of at most kPngMaxChunk bytes.
std::vector<uint8_t> png_bytes(int width, int height, const std::vector<uint8_t>& rgb);

namespace detail {
/// png_bytes() with IDAT chunks of at most `max_idat` (1..kPngMaxChunk) bytes: the split, testable.
std::vector<uint8_t> png_bytes(int width, int height, const std::vector<uint8_t>& rgb, size_t max_idat);
}  // namespace detail

/// Writes a PNG; on failure returns false and sets `error` to "path: reason".
bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string& error);

}  // namespace hider::port

// Host port: minimal PNG writer (8-bit RGB, uncompressed deflate blocks) so frames can go straight
// into documents without extra tools. Deterministic: same pixels, same bytes.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace hider::port {

/// The bytes of a PNG file holding width x height RGB888 pixels (row 0 first).
std::vector<uint8_t> png_bytes(int width, int height, const std::vector<uint8_t>& rgb);

/// Writes a PNG; on failure returns false and sets `error` to "path: reason".
bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string& error);

}  // namespace hider::port

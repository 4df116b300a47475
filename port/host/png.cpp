// Minimal PNG encoder: IHDR, IDAT chunks of stored (uncompressed) deflate blocks, IEND.
#include "host/png.hpp"

#include <algorithm>
#include <cstdint>


namespace hider::port {
namespace {

uint32_t crc32(const uint8_t* data, size_t n, uint32_t crc = 0) {
    crc = ~crc;
    for (size_t i = 0; i < n; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void put32(std::vector<uint8_t>& out, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
}

void chunk(std::vector<uint8_t>& out, const char* type, const uint8_t* body, size_t n) {
    put32(out, static_cast<uint32_t>(n));
    const size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), body, body + n);
    put32(out, crc32(out.data() + start, out.size() - start));
}

}  // namespace

std::vector<uint8_t> png_bytes(int width, int height, const std::vector<uint8_t>& rgb) {
    return detail::png_bytes(width, height, rgb, kPngMaxChunk);
}

namespace detail {
std::vector<uint8_t> png_bytes(int width, int height, const std::vector<uint8_t>& rgb, size_t max_idat) {
    if (!rgb_size_ok(width, height, rgb.size()) || max_idat == 0 || max_idat > kPngMaxChunk) return {};
    std::vector<uint8_t> raw;  // each row: filter byte 0, then the pixels
    raw.reserve(static_cast<size_t>(height) * (static_cast<size_t>(width) * 3 + 1));
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        const uint8_t* row = rgb.data() + static_cast<size_t>(y) * static_cast<size_t>(width) * 3;
        raw.insert(raw.end(), row, row + static_cast<size_t>(width) * 3);
    }
    std::vector<uint8_t> z = {0x78, 0x01};  // zlib header, no compression preset
    uint32_t a = 1, b = 0;
    for (uint8_t c : raw) { a = (a + c) % 65521; b = (b + a) % 65521; }
    for (size_t pos = 0; pos < raw.size() || pos == 0;) {
        const size_t n = std::min<size_t>(65535, raw.size() - pos);
        const bool last = pos + n == raw.size();
        z.push_back(last ? 1 : 0);
        z.push_back(static_cast<uint8_t>(n));
        z.push_back(static_cast<uint8_t>(n >> 8));
        z.push_back(static_cast<uint8_t>(~n));
        z.push_back(static_cast<uint8_t>(~n >> 8));
        z.insert(z.end(), raw.begin() + static_cast<long>(pos), raw.begin() + static_cast<long>(pos + n));
        pos += n;
        if (last) break;
    }
    put32(z, (b << 16) | a);
    std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::vector<uint8_t> ihdr;
    put32(ihdr, static_cast<uint32_t>(width));
    put32(ihdr, static_cast<uint32_t>(height));
    ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8-bit, RGB, deflate, adaptive filters, no interlace
    chunk(out, "IHDR", ihdr.data(), ihdr.size());
    for (size_t pos = 0; pos < z.size();) {  // a chunk holds at most 2^31 - 1 bytes
        const size_t n = std::min(max_idat, z.size() - pos);
        chunk(out, "IDAT", z.data() + pos, n);
        pos += n;
    }
    chunk(out, "IEND", nullptr, 0);
    return out;
}
}  // namespace detail

bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string& error) {
    if (!rgb_size_ok(width, height, rgb.size())) {
        error = path + ": image size does not match its pixel data";
        return false;
    }
    return write_file(path, png_bytes(width, height, rgb), error);
}

}  // namespace hider::port

// Host references' capture of what a firmware program writes (one file at a time), and the pixel
// comparison of two PPM captures. Shared by the painter and BSP host twins.
#pragma once
#include <cstdint>
#include <vector>

#include "stdio_io.hpp"

namespace spin {

/// Io that keeps the bytes of the one file written; with `disk` also writes it through stdio.
struct CaptureIo {
    bool disk = false;
    bool quiet = false;
    StdioIo file;
    std::vector<uint8_t> bytes;

    bool open(const char* path) {
        bytes.clear();
        return !disk || file.open(path);
    }
    bool write(const void* data, size_t size) {
        const auto* p = static_cast<const uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
        return !disk || file.write(data, size);
    }
    bool close() { return !disk || file.close(); }
    void print(const char* text) {
        if (!quiet) file.print(text);
    }
    void print_u32(uint32_t v) {
        if (!quiet) file.print_u32(v);
    }
};

/// Pixels (3-byte groups after the common header) that differ between two PPMs of `pixels` pixels;
/// all of them when the sizes differ.
inline int32_t pixel_mismatches(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int32_t pixels) {
    if (a.size() != b.size() || a.size() < static_cast<size_t>(pixels) * 3) return pixels;
    const size_t header = a.size() - static_cast<size_t>(pixels) * 3;
    int32_t n = 0;
    for (size_t i = header; i < a.size(); i += 3) n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    return n;
}

}  // namespace spin

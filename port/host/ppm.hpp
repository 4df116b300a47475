// Host port: binary PPM (P6) output from a frame view in any pixel format, and RGB888 conversion.
#pragma once
#include <hider/frame.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hider::port {

/// Appends the band's rows as RGB888 bytes (row 0 first) to `out`.
template <class Format, class Depth>
void append_rgb888(const FrameView<Format, Depth>& f, std::vector<uint8_t>& out) {
    for (int32_t y = f.y0; y < f.y1; ++y) {
        const typename Format::Pixel* p = f.row(y);
        for (int32_t x = 0; x < f.width; ++x) {
            const Rgb c = Format::unpack(p[x]);
            out.push_back(c.r);
            out.push_back(c.g);
            out.push_back(c.b);
        }
    }
}

/// Whether width x height RGB888 pixels make a positive size of exactly `rgb_bytes` bytes, computed without
/// wrapping (also where size_t has 32 bits) and small enough to encode (under SIZE_MAX / 2).
bool rgb_size_ok(int width, int height, size_t rgb_bytes);

/// The bytes of a P6 file: "P6\n<W> <H>\n255\n" then W*H*3 bytes of `rgb`.
std::vector<uint8_t> ppm_bytes(int width, int height, const std::vector<uint8_t>& rgb);

/// Writes `bytes` to `path` (binary) through a fresh temporary file beside it (mkstemp, the existing
/// file's mode), renamed over `path` only when every byte is written: a failed write leaves an existing
/// file as it was and no partial one. Written in place: a device, a pipe, a symlink, a file with other
/// hard links, a writable file in a directory that is not, and every file in the WebAssembly build; a
/// failed write there leaves what was written. Standard output (is_standard_output()) is written through
/// descriptor 1 after stdout's buffer, never reopened: a redirection's file is neither truncated nor
/// overwritten from its start, an append stays one. On failure returns false and sets `error` to "path: reason".
/// Shared by the PPM and PNG writers and the tools' other outputs.
bool write_file(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error);
bool write_file(const std::string& path, const std::string& bytes, std::string& error);

/// Whether `path` names the file open as standard output (the same device and inode as descriptor 1:
/// /dev/stdout, or the file or pipe the shell redirected it to). write_file() writes such a path through
/// descriptor 1, and the tools then print their statistics on stderr. False in the WebAssembly build.
bool is_standard_output(const std::string& path);

/// Writes a P6 file; on failure returns false and sets `error` to "path: reason".
bool write_ppm(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string& error);

/// Writes a whole-frame view (y0 == 0, y1 == height) as P6.
template <class Format, class Depth>
bool write_ppm(const std::string& path, const FrameView<Format, Depth>& f, std::string& error) {
    std::vector<uint8_t> rgb;
    append_rgb888(f, rgb);
    return write_ppm(path, f.width, f.height, rgb, error);
}

/// Reads a P6 file with maxval 255 (for golden comparisons). Returns false on any format error.
bool read_ppm(const std::string& path, int& width, int& height, std::vector<uint8_t>& rgb);

}  // namespace hider::port

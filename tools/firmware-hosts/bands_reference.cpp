// Host twin of the bands firmware: writes bands.ppm with the same band renderer and PPM sink, and
// first checks on the host that band-by-band rendering (several band heights) gives exactly the bytes
// of spin's full-frame frame 0. Exit 0 ok, 1 on a failure or a mismatch.
#include <cstdio>
#include <vector>

#include "bands/bands.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "spin/app.hpp"
#include "stdio_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

namespace scene = hider::scenes::torus_160x128;

/// Io that collects the one file written into memory.
struct MemoryIo {
    std::vector<uint8_t> bytes;
    bool open(const char*) { bytes.clear(); return true; }
    bool write(const void* data, size_t size) {
        const auto* p = static_cast<const uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
        return true;
    }
    bool close() { return true; }
    void print(const char*) {}
    void print_u32(uint32_t) {}
};

const spin::Scene kScene{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
hider::ScreenVertex g_verts[scene::kVertexCount];
uint8_t g_row[scene::kWidth * 3];

std::vector<uint8_t> full_frame_ppm() {
    static uint16_t color[scene::kWidth * scene::kHeight], depth[scene::kWidth * scene::kHeight];
    MemoryIo io;
    if (spin::run(io, kScene, {g_verts, color, depth, g_row}, 1, "frame") != 0) return {};
    return io.bytes;
}

std::vector<uint8_t> banded_ppm(int32_t rows) {
    std::vector<uint16_t> color(static_cast<size_t>(scene::kWidth) * rows), depth(color.size());
    MemoryIo io;
    const bands::BandBuffers buf{g_verts, {color.data(), color.size()}, {depth.data(), depth.size()}, rows};
    if (bands::run(io, kScene, buf, g_row, "bands.ppm") != 0) return {};
    return io.bytes;
}

}  // namespace

int main() {
    const std::vector<uint8_t> full = full_frame_ppm();
    if (full.empty()) {
        std::fputs("bands_reference: full-frame render failed\n", stderr);
        return 1;
    }
    for (int32_t rows : {1, 7, bands::kBandRows, 13, scene::kHeight}) {
        if (banded_ppm(rows) != full) {
            std::fprintf(stderr, "bands_reference: bands of %d rows differ from the full frame\n", static_cast<int>(rows));
            return 1;
        }
    }
    static uint16_t color[scene::kWidth * bands::kBandRows], depth[scene::kWidth * bands::kBandRows];
    spin::StdioIo io;
    return bands::run(io, kScene, {g_verts, color, depth, bands::kBandRows}, g_row, "bands.ppm");
}

// Host twin of the bands firmware (argument 160), bands320 (argument 320) and bands_city (argument city):
// writes bands.ppm or bands320.ppm with the same band renderer and PPM sink, after checking on the host that band-by-band
// rendering (several band heights and carried-slot counts) gives exactly the bytes of the full-frame
// render of the same scene. Exit 0 ok, 1 on a failure or a mismatch, 2 on a bad argument.
#include <cstdio>
#include <cstring>
#include <vector>

#include "bands/bands.hpp"
#include "common/scenes/city_street_160x128.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "common/scenes/torus_320x240.hpp"
#include "spin/app.hpp"
#include "band_memory.hpp"
#include "stdio_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

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

using Memory = host::BandMemory;

std::vector<uint8_t> full_frame_ppm(const spin::Scene& s) {
    std::vector<uint16_t> color(static_cast<size_t>(s.width) * s.height), depth(color.size());
    std::vector<hider::ScreenVertex> verts(s.mesh.positions.size());
    std::vector<uint8_t> row(static_cast<size_t>(s.width) * 3);
    MemoryIo io;
    if (spin::run(io, s, {{verts.data(), verts.size()}, color.data(), depth.data(), {row.data(), row.size()}}, 1, "frame") != 0)
        return {};
    return io.bytes;
}

int run(const spin::Scene& s, const char* path, int32_t rows, size_t carried, size_t pixels) {
    const std::vector<uint8_t> full = full_frame_ppm(s);
    if (full.empty()) {
        std::fputs("bands_reference: full-frame render failed\n", stderr);
        return 1;
    }
    uint8_t chunk[3 * 32];
    for (int32_t r : {1, 3, 7, 8, 13, s.height})
        for (size_t slots : {size_t{0}, size_t{5}, size_t{64}})
            for (bool window : {true, false}) {
                Memory m(s, r, slots);
                MemoryIo io;
                const int status = window ? bands::run<true>(io, s, m.buffers(), chunk, path)
                                          : bands::run<false>(io, s, m.buffers(), chunk, path);
                if (status != 0 || io.bytes != full) {
                    std::fprintf(stderr, "bands_reference: bands of %d rows with %d slots%s differ from the full frame\n",
                                 static_cast<int>(r), static_cast<int>(slots), window ? " in a window" : "");
                    return 1;
                }
            }
    Memory m(s, rows, carried, pixels);
    spin::StdioIo io;
    return bands::run(io, s, m.buffers(), chunk, path);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::strcmp(argv[1], "160") == 0) {
        namespace sc = hider::scenes::torus_160x128;
        return run({sc::kCamera, sc::kWidth, sc::kHeight, sc::mesh()}, "bands.ppm", 5, 49, 832);  // as firmware/bands/main.cpp
    }
    if (argc == 2 && std::strcmp(argv[1], "320") == 0) {
        namespace sc = hider::scenes::torus_320x240;
        return run({sc::kCamera, sc::kWidth, sc::kHeight, sc::mesh()}, "bands320.ppm", 3, 43, 970);  // as main320.cpp
    }
    if (argc == 2 && std::strcmp(argv[1], "city") == 0) {
        namespace sc = hider::scenes::city_street_160x128;
        return run({sc::kCamera, sc::kWidth, sc::kHeight, sc::mesh()}, "bands.ppm", 5, 49, 832);  // as bands_city
    }
    std::fputs("usage: bands_reference 160|320|city\n", stderr);
    return 2;
}

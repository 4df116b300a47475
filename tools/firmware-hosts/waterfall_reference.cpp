// Host twin of the waterfall firmware: `waterfall_reference mono|projection|colour` writes the files the
// firmware of that name writes, with the same lib/ code. Before writing the colour frames it checks that
// bands of several heights give exactly the bytes of one whole-frame band. Exit 0 ok, 1 on a failure.
#include <cstdio>
#include <cstring>
#include <vector>

#include "stdio_io.hpp"
#include "waterfall/waterfall.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

/// Io that collects everything written, for in-memory comparisons.
struct MemoryIo {
    std::vector<uint8_t> bytes;
    bool open(const char*) { return true; }
    bool write(const void* data, size_t size) {
        const auto* p = static_cast<const uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
        return true;
    }
    bool close() { return true; }
    void print(const char*) {}
    void print_u32(uint32_t) {}
};

waterfall::History g_history;
int16_t g_upper[160], g_lower[160];
hider::horizon::PlotPoint g_points[waterfall::kSamples];
uint8_t g_ppm_row[160 * 3];

template <class Io>
int colour(Io& io, int32_t rows) {
    std::vector<uint16_t> band(static_cast<size_t>(160) * rows);
    return waterfall::run_colour(io, g_history, {g_upper, g_lower, g_points}, {band.data(), band.size()}, rows,
                                 g_ppm_row, "waterfall_colour", waterfall::Measure::frame);
}

}  // namespace

int main(int argc, char** argv) {
    const char* what = argc > 1 ? argv[1] : "";
    spin::StdioIo io;
    if (std::strcmp(what, "mono") == 0 || std::strcmp(what, "projection") == 0) {
        static uint8_t pages[128 * 64 / 8];
        const hider::horizon::MonoFrame frame{pages, 128, 64, 0, 8};
        const bool mono = std::strcmp(what, "mono") == 0;
        return waterfall::run_mono(io, g_history, {g_upper, g_lower, g_points}, frame,
                                   mono ? "waterfall_mono" : "waterfall_projection",
                                   mono ? waterfall::Measure::frame : waterfall::Measure::projection);
    }
    if (std::strcmp(what, "colour") == 0) {
        MemoryIo whole;
        if (colour(whole, 128) != 0) return 1;
        for (int32_t rows : {1, 7, 8, 13, 64}) {
            MemoryIo banded;
            if (colour(banded, rows) != 0 || banded.bytes != whole.bytes) {
                std::fprintf(stderr, "waterfall_reference: bands of %d rows differ from the whole frame\n", static_cast<int>(rows));
                return 1;
            }
        }
        return colour(io, 8);
    }
    std::fputs("usage: waterfall_reference mono|projection|colour\n", stderr);
    return 1;
}

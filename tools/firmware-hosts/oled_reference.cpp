// Host twin of the oled firmware: writes oled.pbm with the same program (firmware/oled/oled.hpp), after
// checking on the host that the simulated module shows exactly the full-frame render of the same scene
// dithered by this file's own code (the printed 8x8 Bayer matrix, BT.601 luma of the RGB565 expansion),
// for several band heights. Exit 0 ok, 1 on a failure or a mismatch, 2 on arguments.
#include <cstdio>
#include <vector>

#include "common/scenes/torus_160x128.hpp"
#include "oled/oled.hpp"
#include "spin/render.hpp"
#include "band_memory.hpp"
#include "stdio_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

namespace scene = hider::scenes::torus_160x128;

struct NullIo {
    bool open(const char*) { return true; }
    bool write(const void*, size_t) { return true; }
    bool close() { return true; }
    void print(const char*) {}
    void print_u32(uint32_t) {}
};

constexpr int kBayer[8][8] = {{0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
                              {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
                              {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
                              {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21}};

bool lit(uint16_t p, int x, int y) {
    const int r5 = p >> 11, g6 = (p >> 5) & 63, b5 = p & 31;
    const int luma = (77 * ((r5 << 3) | (r5 >> 2)) + 150 * ((g6 << 2) | (g6 >> 4)) + 29 * ((b5 << 3) | (b5 >> 2))) >> 8;
    return luma > kBayer[y & 7][x & 7] * 4 + 2;
}

using Memory = host::BandMemory;

}  // namespace

int main(int argc, char**) {
    if (argc != 1) {
        std::fputs("usage: oled_reference (writes oled.pbm)\n", stderr);
        return 2;
    }
    const spin::Scene s{scene::kCamera, oled::kWidth, oled::kHeight, scene::mesh()};
    std::vector<uint16_t> color(size_t{oled::kWidth} * oled::kHeight), depth(color.size());
    std::vector<hider::ScreenVertex> verts(s.mesh.positions.size());
    const auto frame = hider::frame_view<hider::Rgb565Format, uint16_t>(color.data(), depth.data(), s.width, s.height);
    if (!spin::render_frame(s, 0, {verts.data(), verts.size()}, frame).ok()) {
        std::fputs("oled_reference: full-frame render failed\n", stderr);
        return 1;
    }
    long lit_expected = 0;
    for (int32_t rows : {1, 5, 8, 16, 64}) {
        Memory m(s, rows, 64);
        hider::port::OledModel module(oled::kConfig.controller, oled::kWidth, oled::kHeight, 0);
        NullIo null_io;
        if (oled::run(null_io, s, m.buffers(), module, "oled.pbm") != 0) {
            std::fprintf(stderr, "oled_reference: %d-row bands failed\n", static_cast<int>(rows));
            return 1;
        }
        long wrong = 0;
        lit_expected = 0;
        for (int y = 0; y < oled::kHeight; ++y)
            for (int x = 0; x < oled::kWidth; ++x) {
                const bool want = lit(color[static_cast<size_t>(y * oled::kWidth + x)], x, y);
                lit_expected += want;
                wrong += module.pixel(static_cast<uint32_t>(x), static_cast<uint32_t>(y)) != want;
            }
        if (wrong != 0) {
            std::fprintf(stderr, "oled_reference: %d-row bands: %ld of %d pixels differ from the dithered full frame\n",
                         static_cast<int>(rows), wrong, oled::kWidth * oled::kHeight);
            return 1;
        }
    }
    if (lit_expected < 500) {  // the torus must show, not only the black background
        std::fprintf(stderr, "oled_reference: only %ld pixels lit\n", lit_expected);
        return 1;
    }
    Memory m(s, 8, 24);  // as firmware/oled/main.cpp
    hider::port::OledModel module(oled::kConfig.controller, oled::kWidth, oled::kHeight, 0);
    spin::StdioIo io;
    return oled::run(io, s, m.buffers(), module, "oled.pbm");
}

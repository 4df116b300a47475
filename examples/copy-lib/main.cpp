// hider as a single-folder copy of lib/: this file compiles with nothing but `-std=c++17 -I <copy>/lib`
// (no CMake, no port/). It renders the example scene like the other examples and writes a PPM with
// plain stdio, expanding RGB565 exactly as hider's PPM writer does (Rgb565Format::unpack).
// Usage: copy_lib OUT.ppm
#include <hider/raster/zbuffer.hpp>

#include <cstdio>
#include <vector>

#include "../scene/example_scene.hpp"

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    std::vector<uint16_t> color(example::kWidth * example::kHeight), depth(color.size());
    std::vector<hider::ScreenVertex> verts(16);
    hider::View view;
    if (hider::make_view(example::camera(), example::kWidth, example::kHeight, view) != hider::Status::ok) return 1;
    if (hider::project_vertices(view, example::mesh().positions, {verts.data(), verts.size()}) != hider::Status::ok) return 1;
    const auto frame = hider::frame_view<hider::Rgb565Format, uint16_t>(color.data(), depth.data(), example::kWidth,
                                                                       example::kHeight);
    if (!example::draw(view, {verts.data(), verts.size()}, frame).ok()) return 1;
    std::FILE* f = std::fopen(argv[1], "wb");
    if (f == nullptr) return 1;
    std::fprintf(f, "P6\n%d %d\n255\n", example::kWidth, example::kHeight);
    for (uint16_t p : color) {
        const hider::Rgb c = hider::Rgb565Format::unpack(p);
        const unsigned char rgb[3] = {c.r, c.g, c.b};
        std::fwrite(rgb, 1, 3, f);
    }
    return std::fclose(f) == 0 ? 0 : 1;
}

// Host twin of spin, spin320 and teapot320: the same scene, render and PPM streaming code (spin/app.hpp)
// compiled for the host, writing into the current directory. Usage: spin_reference 160 (spin_000..003.ppm),
// spin_reference 320 (spin320_000.ppm) or spin_reference teapot (teapot320_000.ppm).
#include <cstring>

#include "common/scenes/teapot_320x240.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "common/scenes/torus_320x240.hpp"
#include "spin/app.hpp"
#include "stdio_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

template <int32_t W, int32_t H, size_t V>
int run_scene(const spin::Scene& s, uint32_t frames, const char* prefix, bool split = false) {
    static hider::ScreenVertex verts[V];
    static uint16_t color[W * H], depth[W * H];
    static uint8_t row[W * 3];
    spin::StdioIo io;
    if (split) return spin::run_split(io, s, {verts, color, depth, row}, prefix);
    return spin::run(io, s, {verts, color, depth, row}, frames, prefix);
}

}  // namespace

int main(int argc, char** argv) {
    namespace small = hider::scenes::torus_160x128;
    namespace large = hider::scenes::torus_320x240;
    if (argc == 2 && std::strcmp(argv[1], "160") == 0)
        return run_scene<small::kWidth, small::kHeight, small::kVertexCount>(
            {small::kCamera, small::kWidth, small::kHeight, small::mesh()}, spin::kSpinFrames, "spin");
    if (argc == 2 && std::strcmp(argv[1], "320") == 0)
        return run_scene<large::kWidth, large::kHeight, large::kVertexCount>(
            {large::kCamera, large::kWidth, large::kHeight, large::mesh()}, 1, "spin320");
    namespace teapot = hider::scenes::teapot_320x240;
    if (argc == 2 && std::strcmp(argv[1], "teapot") == 0)
        return run_scene<teapot::kWidth, teapot::kHeight, teapot::kVertexCount>(
            {teapot::kCamera, teapot::kWidth, teapot::kHeight, teapot::mesh()}, 1, "teapot320", true);
    std::fputs("usage: spin_reference 160|320|teapot\n", stderr);
    return 2;
}

// spin firmware (big machine): the torus at 160x128 turning over 4 frames, full frame in RAM
// (colour 40 KB + depth 40 KB), each frame's render bracketed by bench_begin()/bench_end() and
// written as spin_000.ppm .. spin_003.ppm through semihosting. Host twin: tools/firmware-hosts/spin_reference.cpp.
#include "common/scenes/torus_160x128.hpp"
#include "spin/app.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::torus_160x128;

hider::ScreenVertex g_verts[scene::kVertexCount];
uint16_t g_color[scene::kWidth * scene::kHeight];
uint16_t g_depth[scene::kWidth * scene::kHeight];
uint8_t g_ppm_row[scene::kWidth * 3];

}  // namespace

int main() {
    spin::SemihostIo io;
    const spin::Scene s{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
    return spin::run(io, s, {g_verts, g_color, g_depth, g_ppm_row}, spin::kSpinFrames, "spin");
}

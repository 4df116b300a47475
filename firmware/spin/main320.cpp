// spin320 firmware (big machine, 512 KB RAM region): one frame of the torus at 320x240 (colour 150 KB
// + depth 150 KB), bracketed by bench_begin()/bench_end(): the 320x240 benchmark. Writes spin320_000.ppm.
#include "common/scenes/torus_320x240.hpp"
#include "spin/app.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::torus_320x240;

hider::ScreenVertex g_verts[scene::kVertexCount];
uint16_t g_color[scene::kWidth * scene::kHeight];
uint16_t g_depth[scene::kWidth * scene::kHeight];
uint8_t g_ppm_row[scene::kWidth * 3];

}  // namespace

int main() {
    spin::SemihostIo io;
    const spin::Scene s{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
    return spin::run(io, s, {g_verts, g_color, g_depth, g_ppm_row}, 1, "spin320");
}

// teapot320 firmware (big machine, 512 KB RAM region): the Utah teapot (6,320 triangles, hider-render's
// default framing) at 320x240 in four bench pairs: view set-up and projection, clear, draw, and the draw
// again with every face turned away (all culled). hider-bench targets reads the pairs (pairs=1) for the
// per-vertex, per-culled and per-drawn-triangle figures.
// Writes teapot320_000.ppm; host twin: tools/firmware-hosts/spin_reference.cpp (argument teapot).
#include "common/scenes/teapot_320x240.hpp"
#include "spin/app.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::teapot_320x240;

hider::ScreenVertex g_verts[scene::kVertexCount];
uint16_t g_color[scene::kWidth * scene::kHeight];
uint16_t g_depth[scene::kWidth * scene::kHeight];
uint8_t g_ppm_row[scene::kWidth * 3];
hider::Tri g_turned[scene::kTriangleCount];

}  // namespace

int main() {
    spin::SemihostIo io;
    const spin::Scene s{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
    return spin::run_split(io, s, {g_verts, g_color, g_depth, g_ppm_row}, "teapot320", g_turned);
}

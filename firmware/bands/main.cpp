// bands firmware (small machine, 16 KB RAM budget for data + bss + stack): spin's frame 0 at 160x128
// rendered band by band (8 rows, 16 bands) into a BandSink that streams rows to bands.ppm through
// semihosting. RAM: 6 KB vertex cache + 2.5 KB colour band + 2.5 KB depth band + a 480 B PPM row
// + 3 KB stack (CMakeLists.txt) = 14.3 KB of the 16 KB.
#include "bands/bands.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "spin/ppm_sink.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::torus_160x128;

hider::ScreenVertex g_verts[scene::kVertexCount];
uint16_t g_color[scene::kWidth * bands::kBandRows];
uint16_t g_depth[scene::kWidth * bands::kBandRows];
uint8_t g_ppm_row[scene::kWidth * 3];

}  // namespace

int main() {
    spin::SemihostIo io;
    const spin::Scene s{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
    return bands::run(io, s, {g_verts, g_color, g_depth, bands::kBandRows}, g_ppm_row, "bands.ppm");
}

// bands320 firmware (small machine, 16 KB RAM budget for data + bss + stack): the torus at 320x240 (spin320's frame)
// rendered band by band (bands/bands.hpp) into a BandSink that streams rows to bands320.ppm through
// semihosting. RAM: README.md ("Bands"): vertices, bins, band buffers, carried set-ups, a PPM chunk and
// the stack (CMakeLists.txt) within the 16 KB.
#include "bands/bands.hpp"
#include "bands/sizes.hpp"
#include "common/scenes/torus_320x240.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::torus_320x240;
using Sizes = bands::Sizes<scene::kWidth, scene::kHeight, scene::kVertexCount, scene::kTriangleCount, 3, 43>;
Sizes::Storage g;

}  // namespace

int main() {
    spin::SemihostIo io;
    const spin::Scene s{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
    return bands::run(io, s, g.buffers(), g.ppm_chunk, "bands320.ppm");
}

// bands firmware (small machine, 16 KB RAM budget for data + bss + stack): spin's frame 0 at 160x128
// rendered band by band (bands/bands.hpp) into a BandSink that streams rows to bands.ppm through
// semihosting. RAM: README.md ("Bands"): vertices, bins, band buffers, carried set-ups, a PPM chunk and
// the stack (CMakeLists.txt) within the 16 KB.
#include "bands/bands.hpp"
#include "bands/sizes.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::torus_160x128;
// 6-row bands leave the 16 KB room for more carried slots than this frame holds at any band boundary;
// 8-row bands left too few, and a continuation without a slot is set up again, which costs more than
// the extra bands (README.md, "Bands").
using Sizes = bands::Sizes<scene::kWidth, scene::kHeight, scene::kVertexCount, scene::kTriangleCount, 6, 44>;
Sizes::Storage g;

}  // namespace

int main() {
    spin::SemihostIo io;
    const spin::Scene s{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
    return bands::run(io, s, g.buffers(), g.ppm_chunk, "bands.ppm");
}

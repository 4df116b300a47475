// bands320 firmware (small machine, 16 KB RAM budget for data + bss + stack): the torus at 320x240 (spin320's frame)
// rendered band by band (bands/bands.hpp) into a BandSink that streams rows to bands320.ppm through
// semihosting. RAM: README.md ("Bands"): vertices, bins, band buffers, carried set-ups, a PPM chunk and
// the stack (CMakeLists.txt) within the 16 KB.
#include "bands/bands.hpp"
#include "bands/sizes.hpp"
#include "common/scenes/torus_320x240.hpp"
#include "spin/semihost_io.hpp"

namespace {

// Band memory and carried slots: 970 pixels hold 5 rows of the torus's 194-column window (3 of the full
// width, should a frame need it) and, with 47 slots, fill the 16 KB; hider-bench builds other heights on
// the big machine for README.md's table of band height against RAM and cost.
#ifndef BANDS320_PIXELS
#define BANDS320_PIXELS 970
#endif
#ifndef BANDS320_SLOTS
#define BANDS320_SLOTS 47
#endif

namespace scene = hider::scenes::torus_320x240;
using Sizes = bands::Sizes<scene::kWidth, scene::kHeight, scene::kVertexCount, scene::kTriangleCount,
                           BANDS320_PIXELS / scene::kWidth, BANDS320_SLOTS, BANDS320_PIXELS>;
Sizes::Storage g;
// The scene and the buffer spans are constants: in flash, not on the stack (hider-stack's bound).
constexpr spin::Scene kScene{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
constexpr bands::BandBuffers kBuffers = g.buffers();

}  // namespace

int main() {
    spin::SemihostIo io;
    const int status = bands::run(io, kScene, kBuffers, g.ppm_chunk, "bands320.ppm");
    io.print("bands320: storage ");
    io.print_u32(static_cast<uint32_t>(sizeof g));
    io.print(" bytes\n");
    return status;
}

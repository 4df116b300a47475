// bands firmware (small machine, 16 KB RAM budget for data + bss + stack): spin's frame 0 at 160x128
// rendered band by band (bands/bands.hpp) into a BandSink that streams rows to bands.ppm through
// semihosting. RAM: README.md ("Bands"): vertices, bins, band buffers, carried set-ups, a PPM chunk and
// the stack (CMakeLists.txt) within the 16 KB.
#include "bands/bands.hpp"
#include "bands/sizes.hpp"
#include "spin/semihost_io.hpp"
#if defined(BANDS_CITY)  // bands_city: the deepest stack path, clipped triangles in bands (CMakeLists.txt)
#include "common/scenes/city_street_160x128.hpp"
#else
#include "common/scenes/torus_160x128.hpp"
#endif

namespace {

#if defined(BANDS_CITY)
namespace scene = hider::scenes::city_street_160x128;
#else
namespace scene = hider::scenes::torus_160x128;
#endif
// 1,040 band pixels hold 10 rows of the torus's 104-column window (6 of the full width, should a frame
// need it) and leave the 16 KB room for 45 carried slots: a continuation without a slot is set up again,
// which costs more than a row (README.md, "Bands": other choices, measured with BANDS_PIXELS and
// BANDS_SLOTS).
#ifndef BANDS_SLOTS
#define BANDS_SLOTS 45
#endif
#ifndef BANDS_PIXELS
#define BANDS_PIXELS 1040
#endif
using Sizes = bands::Sizes<scene::kWidth, scene::kHeight, scene::kVertexCount, scene::kTriangleCount,
                           BANDS_PIXELS / scene::kWidth, BANDS_SLOTS, BANDS_PIXELS>;
Sizes::Storage g;
// The scene and the buffer spans are constants: in flash, not on the stack (hider-stack's bound).
constexpr spin::Scene kScene{scene::kCamera, scene::kWidth, scene::kHeight, scene::mesh()};
constexpr bands::BandBuffers kBuffers = g.buffers();

}  // namespace

int main() {
    spin::SemihostIo io;
    return bands::run(io, kScene, kBuffers, g.ppm_chunk, "bands.ppm");
}

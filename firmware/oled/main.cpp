// oled firmware (small machine, 16 KB RAM budget for data + bss + stack): the torus at 128x64 drawn in
// 8-row bands into an SSD1306 (oled/oled.hpp) whose bus feeds a simulated module; writes oled.pbm
// through semihosting. RAM: the band renderer's (README.md "Bands") plus the module's 1,100 bytes.
#include "bands/sizes.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "oled/oled.hpp"
#include "spin/semihost_io.hpp"

namespace {

namespace scene = hider::scenes::torus_160x128;
using Sizes = bands::Sizes<oled::kWidth, oled::kHeight, scene::kVertexCount, scene::kTriangleCount, 8, 24>;
Sizes::Storage g;
hider::port::OledModel g_module(oled::kConfig.controller, oled::kWidth, oled::kHeight, 0);
// The scene (the 160x128 torus's camera on a 128x64 frame) and the buffer spans are constants in flash.
constexpr spin::Scene kScene{scene::kCamera, oled::kWidth, oled::kHeight, scene::mesh()};
constexpr bands::BandBuffers kBuffers = g.buffers();

}  // namespace

int main() {
    spin::SemihostIo io;
    return oled::run(io, kScene, kBuffers, g_module, "oled.pbm");
}

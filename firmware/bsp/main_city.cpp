// bsp_city firmware (big machine): the city tree seen from street level, 160x128 with back-face culling,
// drawn front to back (draw_bsp_front) in one band: each pixel written once, hidden subtrees skipped.
// Output bsp_city.ppm; host twin: tools/firmware-hosts/bsp_reference.cpp.
#include "bsp/scenes.hpp"
#include "spin/semihost_io.hpp"

namespace {

bspfw::CityStorage g_storage;

}  // namespace

int main() {
    spin::SemihostIo io;
    return bspfw::run(io, bspfw::city_scene(), bspfw::Algo::front_to_back, g_storage.buffers(), "bsp_city.ppm");
}

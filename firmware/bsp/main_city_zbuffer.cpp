// bsp_city_zbuffer firmware (big machine): the same city view as bsp_city, its mesh z-buffered (16-bit
// depth, full frame): the instruction count bsp_city is measured against. Output bsp_city_zbuffer.ppm.
#include "bsp/scenes.hpp"
#include "spin/semihost_io.hpp"

namespace {

bspfw::CityZStorage g_storage;

}  // namespace

int main() {
    spin::SemihostIo io;
    return bspfw::run(io, bspfw::city_mesh_scene(), bspfw::Algo::zbuffer, g_storage.buffers(), "bsp_city_zbuffer.ppm");
}

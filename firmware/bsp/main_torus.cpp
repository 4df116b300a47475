// bsp_torus firmware (big machine): the torus tree baked by hider-bsp, 160x128 without back-face culling,
// drawn back to front in 16-row bands with no depth buffer (the tree walked once a frame by order_bsp,
// each band drawn from its list by draw_bsp_list), streamed to bsp_torus.ppm.
// Host twin: tools/firmware-hosts/bsp_reference.cpp.
#include "bsp/scenes.hpp"
#include "spin/semihost_io.hpp"

namespace {

bspfw::TorusStorage g_storage;

}  // namespace

int main() {
    spin::SemihostIo io;
    return bspfw::run(io, bspfw::torus_scene(), bspfw::Algo::listed, g_storage.buffers(), "bsp_torus.ppm");
}

// painter_reverse firmware (big machine): the torus at 160x128 without back-face culling, drawn in
// Newell's order front to back with coverage bits (each pixel written once) in 16-row bands with no
// depth buffer, streamed to reverse.ppm through semihosting. Host twin: tools/firmware-hosts/painter_reference.cpp.
#include "painter/torus.hpp"
#include "spin/semihost_io.hpp"

namespace {

painter::TorusStorage g_storage;

}  // namespace

int main() {
    spin::SemihostIo io;
    return painter::run(io, painter::torus_scene(), painter::Algo::reverse, g_storage.buffers(), g_storage.ppm_row);
}

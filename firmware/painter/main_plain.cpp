// painter_plain firmware (big machine): the torus at 160x128 without back-face culling, drawn by the
// plain painter (farthest-vertex key, back to front) in 16-row bands with no depth buffer, streamed
// to painter.ppm through semihosting. Host twin: tools/firmware-hosts/painter_reference.cpp.
#include "painter/torus.hpp"
#include "spin/semihost_io.hpp"

namespace {

painter::TorusStorage g_storage;

}  // namespace

int main() {
    spin::SemihostIo io;
    return painter::run(io, painter::torus_scene(), painter::Algo::painter, g_storage.buffers(), g_storage.ppm_row);
}

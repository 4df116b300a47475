// raytrace firmware (small machine, 16 KB RAM budget for data + bss + stack): the demo scene ray traced
// at 160x128 one row at a time into a BandSink that streams raytrace.ppm through semihosting. RAM: one
// 320-byte RGB565 row, a 480-byte PPM row and the BVH stack; the scene stays in flash.
#include "raytrace/raytrace.hpp"
#include "spin/semihost_io.hpp"

namespace {

uint16_t g_row[raytrace::demo::kWidth];
hider::ray::BvhStackEntry g_stack[raytrace::demo::kStackDepth];
hider::ray::SphereRect g_rects[raytrace::demo::kSphereCount];
uint8_t g_ppm_row[raytrace::demo::kWidth * 3];

}  // namespace

int main() {
    spin::SemihostIo io;
    return raytrace::run(io, {g_row, g_stack, g_rects}, g_ppm_row, "raytrace.ppm");
}

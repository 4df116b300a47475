// Host twin of the raytrace firmware: writes raytrace.ppm with the same row tracer and PPM sink. Exit 0
// ok, 1 on a failure.
#include <cstdio>

#include "raytrace/raytrace.hpp"
#include "stdio_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

uint16_t g_row[raytrace::demo::kWidth];
hider::ray::BvhStackEntry g_stack[raytrace::demo::kStackDepth];
hider::ray::SphereRect g_rects[raytrace::demo::kSphereCount];
uint8_t g_ppm_row[raytrace::demo::kWidth * 3];

}  // namespace

int main() {
    spin::StdioIo io;
    return raytrace::run(io, {g_row, g_stack, g_rects}, g_ppm_row, "raytrace.ppm");
}

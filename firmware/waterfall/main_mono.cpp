// waterfall_mono firmware (small machine, 16 KB RAM): the 128x64 1-bit waterfall, 4 frames written as
// waterfall_mono_000.pbm .. _003.pbm through semihosting, each frame's clear + plot bracketed by
// bench_begin()/bench_end(). RAM: history 8 KB + frame 1 KB + points 1 KB + horizons 512 B + stack.
#include "spin/semihost_io.hpp"
#include "waterfall/waterfall.hpp"

namespace {

waterfall::History g_history;
uint8_t g_pages[128 * 64 / 8];
int16_t g_upper[128], g_lower[128];
hider::horizon::PlotPoint g_points[waterfall::kSamples];

}  // namespace

int main() {
    spin::SemihostIo io;
    const hider::horizon::MonoFrame frame{g_pages, 128, 64, 0, 8};
    return waterfall::run_mono(io, g_history, {g_upper, g_lower, g_points}, frame, "waterfall_mono",
                               waterfall::Measure::frame);
}

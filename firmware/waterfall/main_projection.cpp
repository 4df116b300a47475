// waterfall_projection firmware: waterfall_mono with bench_begin()/bench_end() around the projection of
// the 64 curves alone (then each frame is plotted unmeasured and written as waterfall_projection_NNN.pbm,
// equal to waterfall_mono's). hider-bench waterfall takes drawing = frame - projection.
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
    return waterfall::run_mono(io, g_history, {g_upper, g_lower, g_points}, frame, "waterfall_projection",
                               waterfall::Measure::projection);
}

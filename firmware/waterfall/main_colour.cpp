// waterfall_colour firmware (small machine, 16 KB RAM): the 160x128 RGB565 waterfall coloured by height,
// plotted in 8-row bands (each band re-plots every curve into its rows) and streamed as
// waterfall_colour_000.ppm .. _003.ppm; each band's clear + plot is bracketed by bench_begin()/bench_end().
// RAM: history 8 KB + band 2.5 KB + points 1 KB + horizons 640 B + PPM row 480 B + stack.
#include "spin/semihost_io.hpp"
#include "waterfall/waterfall.hpp"

namespace {

constexpr int32_t kBandRows = 8;
waterfall::History g_history;
uint16_t g_band[160 * kBandRows];
uint8_t g_ppm_row[160 * 3];
int16_t g_upper[160], g_lower[160];
hider::horizon::PlotPoint g_points[waterfall::kSamples];

}  // namespace

int main() {
    spin::SemihostIo io;
    return waterfall::run_colour(io, g_history, {g_upper, g_lower, g_points}, g_band, kBandRows, g_ppm_row,
                                 "waterfall_colour", waterfall::Measure::frame);
}

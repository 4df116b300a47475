// spanbench firmware (big machine): one call of a z-buffer inner span for RGB565 pixels and uint16_t depth
// (flat colour) on pixels [0, kPixels) of a row: span_depth_test_paired<false>, or with
// HIDER_SPANBENCH_KERNEL run_kernel_triangle() for one row (what draw_zbuffer runs for triangles inside the
// frame's columns), bracketed by bench_begin() /
// bench_end(). The case (HIDER_SPANBENCH_PIXELS, HIDER_SPANBENCH_PASS) is fixed per ELF by CMake, so
// the plugin's one region count is one call; hider-bench targets derives instructions per pixel as
// (count at 320 px - count at 1 px) / 319 for each of "all fragments pass" and "none passes".
#include <hider/raster/row_kernel.hpp>
#include <hider/raster/span.hpp>
#include <hider/raster/triangle.hpp>

#include "common/bench.hpp"
#include "semihost/semihost.hpp"

namespace {

/// Pixels the measured call draws (320 or the 1-pixel baseline; the span needs x0 < x1).
constexpr int32_t kPixels = HIDER_SPANBENCH_PIXELS;
/// True: the depth row is clear, every fragment is nearer and writes. False: the row holds 0, the
/// nearest depth, so every test fails and nothing is written.
constexpr bool kPass = HIDER_SPANBENCH_PASS != 0;
/// True: the row kernel; false: the out-of-line paired span.
constexpr bool kKernel = HIDER_SPANBENCH_KERNEL != 0;
static_assert(kPixels >= 1 && kPixels <= 320, "spanbench draws 1..320 pixels of a 320-pixel row");

constexpr int32_t kRowPixels = 320;
constexpr uint16_t kPixel = 0xF81F;   // magenta: never the clear colour 0
constexpr uint16_t kOldPixel = 0x0000;
constexpr uint32_t kDzQ32 = uint32_t{1} << 16;  // one 16-bit depth step per pixel, far below the clear value

uint16_t g_color[kRowPixels];
uint16_t g_depth[kRowPixels];

// Every argument of the measured call is read through a volatile, so the compiler knows neither the
// values nor the buffers: it cannot specialise the span for them (constant propagation), hoist
// the work or drop the stores. The call itself compiles as in the rasterizer (one call site, .isra).
uint16_t* volatile g_color_row = g_color;
uint16_t* volatile g_depth_row = g_depth;
volatile int32_t g_x1 = kPixels;
volatile uint32_t g_z_q32 = hider::kDepthNear;
volatile uint32_t g_dz_q32 = kDzQ32;
volatile uint16_t g_shade = kPixel;
// The rasterizer uses the (always 0) return value, so its copy of the span returns it: keep it used
// here too, so both ELFs hold the same instructions.
volatile uint32_t g_written = 0;

/// Fills the row as the case needs it; outside the measured region.
void prepare_row() {
    for (int32_t x = 0; x < kRowPixels; ++x) {
        g_color[x] = kOldPixel;
        g_depth[x] = kPass ? hider::DepthTraits<uint16_t>::kClear : uint16_t{0};
    }
}

/// True when pixels [0, kPixels) hold what the depth test must give and the rest are untouched.
bool row_ok() {
    for (int32_t x = 0; x < kRowPixels; ++x) {
        const bool drawn = kPass && x < kPixels;
        const uint32_t z_q32 = hider::kDepthNear + kDzQ32 * static_cast<uint32_t>(x);
        const uint16_t old_depth = kPass ? hider::DepthTraits<uint16_t>::kClear : uint16_t{0};
        const uint16_t depth = drawn ? static_cast<uint16_t>(z_q32 >> 16) : old_depth;
        if (g_color[x] != (drawn ? kPixel : kOldPixel) || g_depth[x] != depth) return false;
    }
    return true;
}

}  // namespace

int main() {
    namespace sh = hider::semihost;
    prepare_row();
    uint16_t* const crow = g_color_row;
    uint16_t* const zrow = g_depth_row;
    const int32_t x1 = g_x1;
    const uint32_t z_q32 = g_z_q32, dz_q32 = g_dz_q32;
    const hider::FlatShader<uint16_t> shader{g_shade};
    const intptr_t offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(crow) - reinterpret_cast<uintptr_t>(zrow));
    uint32_t written = 0;
    if constexpr (kKernel) {
        hider::KernelTriangle t{};  // one row [0, x1); edges that do not move (m = q = 0); no middle row
        t.row = 0;
        t.mid = -1;
        t.end = 1;
        hider::RowKernel& k = t.k;
        k.lx = 0;
        k.rx = 2 * x1;
        k.lstep = k.rstep = 2 * kRowPixels;
        k.la = k.ra = 16;
        k.lg = k.rg = -16;  // biased error terms in [-a, 0): no correction
        k.lz = z_q32;
        k.dzdx = dz_q32;
        k.color = shader.color;
        const hider::KernelTarget target{offset, 2 * kRowPixels};
        bench_begin();
        (void)hider::run_kernel_triangle(t, zrow, 1, target);
        bench_end();
    } else {
        const hider::PairedSpan<uint16_t, hider::FlatShader<uint16_t>> span{dz_q32, offset, shader};
        bench_begin();
        written = hider::span_depth_test_paired<false>(zrow, x1, z_q32, span);
        bench_end();
    }
    g_written = written;

    if (!row_ok()) {
        sh::print("spanbench: the row is not what the depth test should give\n");
        return 1;
    }
    sh::print(kKernel ? "spanbench: run_kernel_triangle, RGB565 + 16-bit depth, " : "spanbench: span_depth_test_paired<false>, RGB565 + 16-bit depth, ");
    sh::print_u32(static_cast<uint32_t>(kPixels));
    sh::print(kPass ? " px, all pass\n" : " px, none pass\n");
    return 0;
}

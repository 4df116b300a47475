// kernelcheck firmware: the chip's assembly against its portable twins, on random states.
// - kernelcheck::kCases kernel states (cases.hpp) through run_kernel_triangle() (Thumb-2, Thumb-1 or RV32
//   assembly) and run_kernel_triangle_portable(), two calls each: same buffers and final state.
// - kernelcheck::kSetupCases triangle set-ups (setup_cases.hpp) through kernel_setup() (the Thumb-2 set-up
//   on ARMv7-M) and kernel_setup_portable(): same outcome and kernel fields for every case.
// - The frame clear (detail::fill, store-multiples on Cortex-M) against a plain loop for every length up
//   to kFillMax.
// The chip's digests go to kernelcheck.bin, which the host twin writes from the portable code (ctest
// kernelcheck.matches_host).
#include "common/bench.hpp"
#include "kernelcheck/cases.hpp"
#include "kernelcheck/setup_cases.hpp"
#include "semihost/semihost.hpp"

namespace {

constexpr int kWords = kernelcheck::kCases + kernelcheck::kSetupCases + 1;  // the last word: the fill digest
kernelcheck::Buffers g_buffers;
uint32_t g_digests[kWords];

}  // namespace

int main() {
    namespace sh = hider::semihost;
    const int kernel_case = kernelcheck::run_cases(
        [](hider::KernelTriangle& t, uint16_t* zrow, int32_t stop, const hider::KernelTarget& target) {
            return hider::run_kernel_triangle(t, zrow, stop, target);
        },
        [](hider::KernelTriangle& t, uint16_t* zrow, int32_t stop, const hider::KernelTarget& target) {
            return hider::run_kernel_triangle_portable(t, zrow, stop, target);
        },
        g_buffers, g_digests);
    if (kernel_case >= 0) {
        sh::print("kernelcheck: run_kernel_triangle differs from the portable kernel in case ");
        sh::print_u32(static_cast<uint32_t>(kernel_case));
        sh::print("\n");
        return 1;
    }
    const int setup_case = kernelcheck::run_setup_cases(
        [](const hider::ScreenVertex& a, const hider::ScreenVertex& b, const hider::ScreenVertex& c,
           hider::KernelSetupIo& io) { return hider::kernel_setup(a, b, c, io); },
        [](const hider::ScreenVertex& a, const hider::ScreenVertex& b, const hider::ScreenVertex& c,
           hider::KernelSetupIo& io) { return hider::kernel_setup_portable(a, b, c, io.area, *io.band, *io.out); },
        g_digests + kernelcheck::kCases);
    if (setup_case >= 0) {
        sh::print("kernelcheck: kernel_setup differs from kernel_setup_portable in case ");
        sh::print_u32(static_cast<uint32_t>(setup_case));
        sh::print("\n");
        return 1;
    }
    g_digests[kWords - 1] = kernelcheck::fill_digest(
        [](uint16_t* p, uint32_t n, uint16_t v) { hider::detail::fill<uint16_t>(p, n, v); }, g_buffers);
    if (g_digests[kWords - 1] != kernelcheck::fill_digest(kernelcheck::fill_plain, g_buffers)) {
        sh::print("kernelcheck: the frame clear (detail::fill) differs from a plain loop\n");
        return 1;
    }
    if (!sh::write_file("kernelcheck.bin", g_digests, sizeof g_digests)) {
        sh::print("kernelcheck: cannot write kernelcheck.bin\n");
        return 1;
    }
    sh::print("kernelcheck: ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kCases));
    sh::print(" kernel cases and ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kSetupCases));
    sh::print(" set-ups equal the portable code; the clear equals a plain loop\n");
    return 0;
}

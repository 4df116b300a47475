// kernelcheck firmware (big machine): kernelcheck::kCases random row-kernel states (cases.hpp) run through
// run_row_kernel() (the Thumb-2 loop on ARMv7-M) and through run_row_kernel_portable(); every case must
// give the same buffers and final state. Then the frame clear (detail::fill, store-multiples on Cortex-M)
// against a plain loop for every length up to kFillMax. The digests go to kernelcheck.bin, which the
// host twin writes from the portable kernel and the plain loop (ctest kernelcheck.matches_host).
#include "common/bench.hpp"
#include "kernelcheck/cases.hpp"
#include "semihost/semihost.hpp"

namespace {

kernelcheck::Buffers g_buffers;
uint32_t g_fast[kernelcheck::kCases + 1];  // the last word: the fill digest
uint32_t g_portable[kernelcheck::kCases];

}  // namespace

int main() {
    namespace sh = hider::semihost;
    bench_begin();
    kernelcheck::run_cases([](hider::RowKernel& k) { hider::run_row_kernel(k); }, g_buffers, g_fast);
    bench_end();
    kernelcheck::run_cases([](hider::RowKernel& k) { hider::run_row_kernel_portable(k); }, g_buffers, g_portable);
    for (int c = 0; c < kernelcheck::kCases; ++c) {
        if (g_fast[c] != g_portable[c]) {
            sh::print("kernelcheck: run_row_kernel differs from the portable kernel in case ");
            sh::print_u32(static_cast<uint32_t>(c));
            sh::print("\n");
            return 1;
        }
    }
    g_fast[kernelcheck::kCases] = kernelcheck::fill_digest(
        [](uint16_t* p, uint32_t n, uint16_t v) { hider::detail::fill<uint16_t>(p, n, v); }, g_buffers);
    if (g_fast[kernelcheck::kCases] != kernelcheck::fill_digest(kernelcheck::fill_plain, g_buffers)) {
        sh::print("kernelcheck: the frame clear (detail::fill) differs from a plain loop\n");
        return 1;
    }
    if (!sh::write_file("kernelcheck.bin", g_fast, sizeof g_fast)) {
        sh::print("kernelcheck: cannot write kernelcheck.bin\n");
        return 1;
    }
    sh::print("kernelcheck: ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kCases));
    sh::print(" cases, the target's row kernel equals the portable one; the clear equals a plain loop\n");
    return 0;
}

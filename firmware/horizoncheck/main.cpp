// horizoncheck firmware: the floating horizon's hot loops (row passes, level pass, walk kernel; Thumb-1
// on ARMv6-M) against their portable twins on horizoncheck::kCases random cases of each (cases.hpp);
// every case must give the same digest. The digests go to horizoncheck.bin, which the host twin writes
// from the portable loops (ctest horizoncheck.matches_host): every target equals the host too.
#include "common/bench.hpp"
#include "horizoncheck/cases.hpp"
#include "semihost/semihost.hpp"

namespace {

horizoncheck::Buffers g_buffers;
uint32_t g_fast[3 * horizoncheck::kCases];
uint32_t g_portable[3 * horizoncheck::kCases];

}  // namespace

int main() {
    namespace sh = hider::semihost;
    using namespace hider::horizon;
    bench_begin();
    horizoncheck::run_cases([](const RowPass& p) { run_row_passes(p); }, [](const LevelPass& p) { run_level_pass(p); },
                            [](WalkKernel& k) { return run_walk_kernel(k); }, g_buffers, g_fast);
    bench_end();
    horizoncheck::run_cases(
        [](const RowPass& p) {
            reciprocal_pass_portable(p);
            coordinate_pass_portable(p);
        },
        [](const LevelPass& p) { level_pass_portable(p); }, [](WalkKernel& k) { return walk_kernel_portable(k); },
        g_buffers, g_portable);
    const char* const names[3] = {"row passes", "level pass", "walk kernel"};
    for (int c = 0; c < 3 * horizoncheck::kCases; ++c) {
        if (g_fast[c] != g_portable[c]) {
            sh::print("horizoncheck: the ");
            sh::print(names[c / horizoncheck::kCases]);
            sh::print(" differ from the portable loop in case ");
            sh::print_u32(static_cast<uint32_t>(c % horizoncheck::kCases));
            sh::print("\n");
            return 1;
        }
    }
    if (!sh::write_file("horizoncheck.bin", g_fast, sizeof g_fast)) {
        sh::print("horizoncheck: cannot write horizoncheck.bin\n");
        return 1;
    }
    sh::print("horizoncheck: ");
    sh::print_u32(static_cast<uint32_t>(horizoncheck::kCases));
    sh::print(" cases each: the target's row passes, level pass and walk kernel equal the portable loops\n");
    return 0;
}

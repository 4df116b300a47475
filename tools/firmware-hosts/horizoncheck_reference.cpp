// Host twin of the horizoncheck firmware: writes horizoncheck.bin (one digest per case, cases.hpp) from
// the portable loops, the reference for the horizoncheck.matches_host ctest.
#include "horizoncheck/cases.hpp"
#include "stdio_io.hpp"

int main() {
    using namespace hider::horizon;
    static horizoncheck::Buffers buffers;
    static uint32_t digests[3 * horizoncheck::kCases];
    horizoncheck::run_cases(
        [](const RowPass& p) {
            reciprocal_pass_portable(p);
            coordinate_pass_portable(p);
        },
        [](const LevelPass& p) { level_pass_portable(p); }, [](WalkKernel& k) { return walk_kernel_portable(k); },
        buffers, digests);
    return host::write_file("horizoncheck.bin", digests, sizeof digests) ? 0 : 1;
}

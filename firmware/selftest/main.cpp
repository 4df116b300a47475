// selftest firmware: checks the runtime (.data copy, .bss zeroing, static constructors), runs the
// integer pattern of pattern.hpp between bench_begin/bench_end, writes it to selftest.ppm through
// semihosting and exits 0. The ctest selftest_*.matches_host compares the file with the host's.
#include "common/bench.hpp"
#include "selftest/pattern.hpp"
#include "semihost/semihost.hpp"

namespace {

volatile int32_t g_seed = selftest::kSeed;  // .data; volatile so the pattern is computed at run time
uint8_t g_image[selftest::kPpmSize];        // .bss

// Dynamic initialisation (the volatile read), so it runs from .init_array before main().
struct ConstructorProbe {
    int32_t seed;
    ConstructorProbe() : seed(g_seed) {}
};
ConstructorProbe g_constructed;

bool fail(const char* why) {
    hider::semihost::print(why);
    return false;
}

bool runtime_ok() {
    if (g_seed != selftest::kSeed) return fail("selftest: .data was not copied\n");
    for (uint8_t byte : g_image) {
        if (byte != 0) return fail("selftest: .bss was not zeroed\n");
    }
    if (g_constructed.seed != selftest::kSeed) return fail("selftest: static constructor did not run\n");
    return true;
}

}  // namespace

int main() {
    namespace sh = hider::semihost;
    if (!runtime_ok()) return 1;

    bench_begin();
    selftest::write_ppm(g_image, g_seed);
    bench_end();

    if (!sh::write_file("selftest.ppm", g_image, sizeof g_image)) {
        sh::print("selftest: cannot write selftest.ppm through semihosting\n");
        return 1;
    }
    sh::print("selftest: wrote selftest.ppm (16x8 P6)\n");
    return 0;
}

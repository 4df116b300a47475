// Host twin of the selftest firmware: writes selftest.ppm into the current directory from the
// same pattern code, as the reference for the selftest_*.matches_host ctests.
#include "selftest/pattern.hpp"
#include "stdio_io.hpp"

int main() {
    static uint8_t image[selftest::kPpmSize];
    selftest::write_ppm(image, selftest::kSeed);
    return host::write_file("selftest.ppm", image, sizeof image) ? 0 : 1;
}

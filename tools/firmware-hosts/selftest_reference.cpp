// Host twin of the selftest firmware: writes selftest.ppm into the current directory from the
// same pattern code, as the reference for the selftest_*.matches_host ctests.
#include <cstdio>

#include "selftest/pattern.hpp"

int main() {
    static uint8_t image[selftest::kPpmSize];
    selftest::write_ppm(image, selftest::kSeed);
    std::FILE* file = std::fopen("selftest.ppm", "wb");
    if (file == nullptr) {
        std::perror("selftest.ppm");
        return 1;
    }
    const bool written = std::fwrite(image, 1, sizeof image, file) == sizeof image;
    if (std::fclose(file) != 0 || !written) {
        std::perror("selftest.ppm");
        return 1;
    }
    return 0;
}

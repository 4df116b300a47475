// Host twin of the kernelcheck firmware: writes kernelcheck.bin (one digest per case, cases.hpp) from
// the portable row kernel and a plain fill loop, as the reference for the kernelcheck.matches_host ctest.
#include <cstdio>

#include "kernelcheck/cases.hpp"

int main() {
    static kernelcheck::Buffers buffers;
    static uint32_t digests[kernelcheck::kCases + 1];
    kernelcheck::run_cases([](hider::RowKernel& k) { hider::run_row_kernel_portable(k); }, buffers, digests);
    digests[kernelcheck::kCases] = kernelcheck::fill_digest(kernelcheck::fill_plain, buffers);
    std::FILE* file = std::fopen("kernelcheck.bin", "wb");
    if (file == nullptr) {
        std::perror("kernelcheck.bin");
        return 1;
    }
    const bool written = std::fwrite(digests, 1, sizeof digests, file) == sizeof digests;
    if (std::fclose(file) != 0 || !written) {
        std::perror("kernelcheck.bin");
        return 1;
    }
    return 0;
}

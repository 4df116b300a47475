// Host twin of the kernelcheck firmware: writes kernelcheck.bin (one digest per case, cases.hpp) from
// the portable row kernel and a plain fill loop, as the reference for the kernelcheck.matches_host ctest.
#include "kernelcheck/cases.hpp"
#include "stdio_io.hpp"

int main() {
    static kernelcheck::Buffers buffers;
    static uint32_t digests[kernelcheck::kCases + 1];
    kernelcheck::run_cases([](hider::RowKernel& k) { hider::run_row_kernel_portable(k); }, buffers, digests);
    digests[kernelcheck::kCases] = kernelcheck::fill_digest(kernelcheck::fill_plain, buffers);
    return host::write_file("kernelcheck.bin", digests, sizeof digests) ? 0 : 1;
}

// libFuzzer target (clang -fsanitize=fuzzer,address,undefined): arbitrary bytes as a BSP blob. Each
// input is loaded as given and again with its checksum recomputed (random mutations almost never keep
// FNV-1a right and would otherwise stop at the checksum); a tree bsp_load() accepts is walked back to
// front and front to back from fixed cameras into a small frame (tests/bsp/bsp_exercise.hpp). A walk
// that fails on an accepted tree, or a front-to-back walk that writes a pixel twice, aborts like a
// sanitizer error. Run by ctest (bsp_load_fuzz, host-asan preset) for a bounded time.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bsp/bsp_exercise.hpp"

namespace {

void check(const hider::test::BspExercise& r, const char* variant) {
    if (r.load != hider::Status::ok) return;
    if (r.walk_failures == 0 && r.overdraw_failures == 0) return;
    std::fprintf(stderr, "bsp_load_fuzz (%s): tree accepted, but %d of %d walks failed and %d wrote a pixel twice\n", variant,
                 r.walk_failures, r.walks, r.overdraw_failures);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    check(hider::test::exercise_bsp(data, size), "as given");
    if (size >= sizeof(hider::BspHeader)) {
        std::vector<uint8_t> sealed(data, data + size);
        hider::BspHeader h;
        std::memcpy(&h, sealed.data(), sizeof h);
        h.checksum = hider::bsp_checksum(sealed.data(), sealed.size());
        std::memcpy(sealed.data(), &h, sizeof h);
        check(hider::test::exercise_bsp(sealed.data(), sealed.size()), "checksum recomputed");
        // A load stack for 3 levels only, so load's capacity_exceeded path is fuzzed too (no walk), with
        // its BspLoadInfo: a problem named exactly when the load fails.
        std::vector<uint64_t> storage;
        std::vector<uint32_t> stack(hider::bsp_stack_entries(3));
        hider::BspTree tree;
        hider::BspLoadInfo info;
        const hider::Status s = hider::bsp_load(hider::test::aligned_copy(sealed.data(), sealed.size(), storage),
                                                {stack.data(), stack.size()}, tree, &info);
        if ((s == hider::Status::ok) != (info.problem == hider::BspProblem::none)) {
            std::fprintf(stderr, "bsp_load_fuzz: status %d with problem '%s'\n", static_cast<int>(s),
                         hider::bsp_problem_text(info.problem));
            std::abort();
        }
    }
    return 0;
}

// Host default for the HIDER_ASSERT hook declared in lib/hider/base.hpp (asserts are checked when
// HIDER_ENABLE_ASSERTS is defined: hider's own host-asan build and fuzzers): prints file:line on stderr
// and aborts, so a sanitizer or fuzzer reports the stack. Weak: a program defines its own to override it.
#include <hider/base.hpp>

#include <cstdio>
#include <cstdlib>

extern "C" __attribute__((weak)) void hider_assert_fail(const char* file, int line) {
    std::fprintf(stderr, "hider: assertion failed at %s:%d\n", file, line);
    std::abort();
}

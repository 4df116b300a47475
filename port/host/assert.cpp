// Host default for the HIDER_ASSERT hook declared in lib/hider/base.hpp (asserts are checked when
// HIDER_ENABLE_ASSERTS is defined: hider's own host-asan build and fuzzers): calls the handler of
// set_assert_handler() if any, then prints file:line on stderr, and the stack under AddressSanitizer
// (which does not report an abort by default), and aborts. Weak: a program's own definition overrides it.
#include "host/assert.hpp"

#include <hider/base.hpp>

#include <cstdio>
#include <cstdlib>

#if defined(__SANITIZE_ADDRESS__)
#define HIDER_HOST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HIDER_HOST_ASAN 1
#endif
#endif
#if defined(HIDER_HOST_ASAN)
#include <sanitizer/common_interface_defs.h>
#endif

namespace {
hider::port::AssertHandler g_handler = nullptr;
}  // namespace

hider::port::AssertHandler hider::port::set_assert_handler(AssertHandler handler) {
    const AssertHandler previous = g_handler;
    g_handler = handler;
    return previous;
}

extern "C" __attribute__((weak)) void hider_assert_fail(const char* file, int line) {
    if (g_handler != nullptr) g_handler(file, line);
    std::fprintf(stderr, "hider: assertion failed at %s:%d\n", file, line);
#if defined(HIDER_HOST_ASAN)
    __sanitizer_print_stack_trace();
#endif
    std::abort();
}

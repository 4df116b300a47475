// Startup of the example board (Cortex-M0+): vector table, .data copy, .bss zeroing, static
// constructors, firmware_main(), and the exit status through semihosting. Plus the four mem* functions GCC
// expects from a freestanding program. Any fault ends the run with status 3.
#include <semihost/semihost.hpp>
#include <stddef.h>
#include <stdint.h>

extern "C" {
extern uint32_t __data_start[], __data_end[], __data_load[], __bss_start[], __bss_end[], __stack_top[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
int firmware_main();  // the application (main.cpp); ISO C++ forbids calling main itself

[[noreturn]] void reset_handler() {
    for (uint32_t *src = __data_load, *dst = __data_start; dst < __data_end;) *dst++ = *src++;
    for (uint32_t* dst = __bss_start; dst < __bss_end;) *dst++ = 0;
    for (void (**ctor)() = __init_array_start; ctor < __init_array_end; ++ctor) (*ctor)();
    hider::semihost::exit(firmware_main());
}

[[noreturn]] void fault_handler() {
    hider::semihost::print("panel_demo: fault\n");
    hider::semihost::exit(3);
}

void* memcpy(void* dst, const void* src, size_t n) {
    auto* d = static_cast<unsigned char*>(dst);
    const auto* s = static_cast<const unsigned char*>(src);
    while (n-- != 0) *d++ = *s++;
    return dst;
}
void* memmove(void* dst, const void* src, size_t n) {
    auto* d = static_cast<unsigned char*>(dst);
    const auto* s = static_cast<const unsigned char*>(src);
    if (d < s) {
        while (n-- != 0) *d++ = *s++;
    } else {
        while (n-- != 0) d[n] = s[n];
    }
    return dst;
}
void* memset(void* dst, int value, size_t n) {
    auto* d = static_cast<unsigned char*>(dst);
    while (n-- != 0) *d++ = static_cast<unsigned char>(value);
    return dst;
}
int memcmp(const void* a, const void* b, size_t n) {
    const auto* x = static_cast<const unsigned char*>(a);
    const auto* y = static_cast<const unsigned char*>(b);
    for (; n != 0; --n, ++x, ++y)
        if (*x != *y) return *x < *y ? -1 : 1;
    return 0;
}
}

using Handler = void (*)();
// Word 0: initial stack pointer; 1: reset; 2-15: core exceptions (7-10 and 13 reserved).
extern "C" __attribute__((used, section(".vectors"))) const Handler vectors[16] = {
    reinterpret_cast<Handler>(__stack_top), reset_handler, fault_handler, fault_handler,
    fault_handler, fault_handler, fault_handler, nullptr, nullptr, nullptr, nullptr,
    fault_handler, fault_handler, nullptr, fault_handler, fault_handler,
};

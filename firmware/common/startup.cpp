// Shared C++ runtime start: .data copy, .bss zeroing, static constructors, main(), and the exit
// status through semihosting. Also measures the stack high-water mark by painting the stack, fails
// a run that used all but the last 32 bytes of it (it may have overrun into .bss), and writes the mark
// to stack.txt in the run's directory, where ctest <name>.stack_bound holds hider-stack's static bound
// against it.
// Symbols come from firmware/common/{cortex_m,riscv}.ld.
#include "common/decimal.hpp"
#include "common/runtime.hpp"
#include "semihost/semihost.hpp"

extern "C" {
extern uint32_t __data_start__[];
extern uint32_t __data_end__[];
extern uint32_t __data_load__[];
extern uint32_t __bss_start__[];
extern uint32_t __bss_end__[];
extern uint32_t __stack_bottom__[];
extern uint32_t __stack_top__[];
extern void (*const __init_array_start[])();
extern void (*const __init_array_end[])();
}

int main();

namespace {

constexpr uint32_t kStackPaint = 0x5AC3A55Cu;
constexpr uintptr_t kPaintMargin = 64;  // bytes below the current sp left unpainted (our own frame)
constexpr uint32_t kStackReserve = 32;  // a run that leaves fewer bytes of its stack untouched fails

/// Paints the stack below this frame; returns the depth the painting starts at (no smaller mark can be measured).
uint32_t paint_stack() {
    uint32_t here = 0;
    const uintptr_t limit = (reinterpret_cast<uintptr_t>(&here) - kPaintMargin) & ~uintptr_t{3};
    for (uint32_t* p = __stack_bottom__; reinterpret_cast<uintptr_t>(p) < limit; ++p) *p = kStackPaint;
    return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(__stack_top__) - limit);
}

/// Writes text at p (no terminator); returns the end.
char* append_text(char* p, const char* text) {
    while (*text != '\0') *p++ = *text++;
    return p;
}

uint32_t stack_used_bytes() {
    const uint32_t* p = __stack_bottom__;
    while (p < __stack_top__ && *p == kStackPaint) ++p;
    return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(__stack_top__) - reinterpret_cast<uintptr_t>(p));
}

/// stack.txt: "high-water N floor F size S". Out of line, so its buffer is not in hider_reset's frame
/// beneath main().
__attribute__((noinline)) void write_stack_report(uint32_t used, uint32_t floor, uint32_t size) {
    char text[64];
    char* p = append_text(text, "high-water ");
    p = append_text(append_decimal(p, used), " floor ");
    p = append_text(append_decimal(p, floor), " size ");
    p = append_text(append_decimal(p, size), "\n");
    if (!hider::semihost::write_file("stack.txt", text, static_cast<size_t>(p - text)))
        hider::semihost::print("hider: cannot write stack.txt\n");
}

/// After main(): the stack report and the exit status. Out of line, so that hider_reset's frame, under
/// every path of main(), holds no more than the floor.
[[noreturn]] __attribute__((noinline)) void finish(int status, uint32_t floor) {
    namespace sh = hider::semihost;
    const uint32_t used = stack_used_bytes();
    const uint32_t size = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(__stack_top__) -
                                                reinterpret_cast<uintptr_t>(__stack_bottom__));
    sh::print("hider: stack high-water ");
    sh::print_u32(used);
    sh::print(" of ");
    sh::print_u32(size);
    sh::print(" bytes\n");
    write_stack_report(used, floor, size);
    if (size - used < kStackReserve) {  // the stack may have run into the data below it: not a pass
        sh::print("hider: stack exhausted (fewer than 32 bytes never used): give the firmware more stack\n");
        sh::exit(status != 0 ? status : 4);
    }
    sh::exit(status);
}

}  // namespace

extern "C" void hider_reset() {
    const uint32_t* src = __data_load__;
    for (uint32_t* dst = __data_start__; dst < __data_end__; ++dst, ++src) *dst = *src;
    for (uint32_t* dst = __bss_start__; dst < __bss_end__; ++dst) *dst = 0;
    const uint32_t floor = paint_stack();
    for (auto* ctor = __init_array_start; ctor < __init_array_end; ++ctor) (*ctor)();
    finish(main(), floor);
}

extern "C" void hider_fault(uint32_t cause, uint32_t pc) {
    namespace sh = hider::semihost;
    sh::print("hider: unexpected exception/trap, cause ");
    sh::print_hex32(cause);
    sh::print(" pc ");
    sh::print_hex32(pc);
    sh::print("\n");
    sh::exit(3);
}

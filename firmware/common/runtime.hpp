// Interface between the per-architecture reset code and the shared C++ runtime in startup.cpp.
#pragma once
#include <stdint.h>

extern "C" {
/// Copies .data, zeroes .bss, paints the stack, runs .init_array, calls main() and exits through
/// semihosting with main()'s status. Entered with sp = __stack_top__ (and gp set on RISC-V).
[[noreturn]] void hider_reset();

/// Reports an unexpected exception or trap (`cause`, faulting `pc`) and exits with status 3.
[[noreturn]] void hider_fault(uint32_t cause, uint32_t pc);
}

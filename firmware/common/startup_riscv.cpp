// RISC-V (machine mode) entry. virt -bios none jumps to the ELF entry, sifive_e to 0x20400000:
// the linker script puts .text.start first in ROM for both. Traps report
// mcause and mepc through hider_fault() and exit with status 3.
#include "common/runtime.hpp"

extern "C" __attribute__((interrupt("machine"), aligned(4))) void hider_trap_handler() {
    uint32_t cause = 0;
    uint32_t pc = 0;
    __asm__ volatile(
        ".option push\n"
        ".option arch, +zicsr\n"
        "csrr %0, mcause\n"
        "csrr %1, mepc\n"
        ".option pop\n"
        : "=r"(cause), "=r"(pc));
    hider_fault(cause, pc);
}

// gp must be loaded without relaxation (a relaxed `la gp` would be gp-relative to itself).
extern "C" __attribute__((naked, used, section(".text.start"))) void _start() {
    __asm__ volatile(
        ".option push\n"
        ".option norelax\n"
        "la gp, __global_pointer$\n"
        ".option pop\n"
        "la sp, __stack_top__\n"
        ".option push\n"
        ".option arch, +zicsr\n"
        "la t0, hider_trap_handler\n"
        "csrw mtvec, t0\n"
        ".option pop\n"
        "tail hider_reset\n");
}

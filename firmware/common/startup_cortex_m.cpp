// Cortex-M (v6-M and v7-M) vector table. QEMU takes the initial SP and the reset PC from words 0
// and 1 at address 0 and ignores the ELF entry. Every other exception reports
// its number (IPSR) and stacked PC through hider_fault() and exits with status 3.
#include "common/runtime.hpp"

extern "C" uint32_t __stack_top__[];

// Handler mode on MSP: the exception frame is at sp; word 6 is the stacked PC. Reached from asm only.
extern "C" [[noreturn]] __attribute__((used)) void hider_fault_from_frame(const uint32_t* frame) {
    uint32_t ipsr = 0;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    hider_fault(ipsr & 0x1FFu, frame[6]);
}

namespace {

using Handler = void (*)();

__attribute__((naked)) void fault_entry() {
    __asm__ volatile(
        "mrs r0, msp\n"
        "ldr r1, =hider_fault_from_frame\n"
        "bx r1\n"
        ".ltorg\n");
}

constexpr int kCoreVectors = 16;
constexpr int kExternalVectors = 32;

}  // namespace

// Word 0 is the initial SP; 7-10 and 13 are reserved (0).
extern "C" __attribute__((used, section(".vectors")))
const Handler hider_vectors[kCoreVectors + kExternalVectors] = {
    reinterpret_cast<Handler>(__stack_top__),
    hider_reset,
    fault_entry,  // NMI
    fault_entry,  // HardFault
    fault_entry,  // MemManage
    fault_entry,  // BusFault
    fault_entry,  // UsageFault
    nullptr, nullptr, nullptr, nullptr,
    fault_entry,  // SVCall
    fault_entry,  // DebugMon
    nullptr,
    fault_entry,  // PendSV
    fault_entry,  // SysTick
    fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry,
    fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry,
    fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry,
    fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry, fault_entry,
};

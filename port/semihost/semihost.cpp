// Semihosting calls for ARM M-profile and RISC-V. Each call passes an operation number and a
// pointer to a block of 32-bit words; the host answers in r0/a0 (Arm's semihosting specification;
// RISC-V's semihosting specification for the trap sequence).
#include "semihost/semihost.hpp"

namespace hider::semihost {
namespace {

enum Op : uintptr_t {
    kSysOpen = 0x01,
    kSysClose = 0x02,
    kSysWrite0 = 0x04,
    kSysWrite = 0x05,
    kSysExitExtended = 0x20,
};
constexpr uintptr_t kModeWriteBinary = 5;                  // fopen "wb"
constexpr uintptr_t kApplicationExit = 0x20026;            // ADP_Stopped_ApplicationExit

}  // namespace
}  // namespace hider::semihost

#if defined(__arm__) && !(defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M')
// A- and R-profile cores trap with SVC (0x123456 in A32, 0xAB in T32), not BKPT: BKPT there would
// stop in the debugger or hang under QEMU. Not built or tested here: refuse rather than hang.
#error "semihost: ARM M-profile (Cortex-M) or RV32 only; this ARM core is A- or R-profile"
#elif defined(__riscv) && __riscv_xlen != 32
#error "semihost: RV32 only (RV64 passes 64-bit parameter blocks)"
#elif defined(__arm__)
namespace {
intptr_t semihost_call(uintptr_t op, const void* arg) {
    register uintptr_t r0 __asm__("r0") = op;
    register const void* r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return static_cast<intptr_t>(r0);
}
}  // namespace
#elif defined(__riscv)
// The host recognises the trap only as these three uncompressed instructions within one page,
// so they live in their own 16-byte aligned function (a0 = op, a1 = block, result in a0).
extern "C" intptr_t hider_semihost_trap(uintptr_t op, const void* arg);
__asm__(
    ".pushsection .text.hider_semihost_trap,\"ax\",@progbits\n"
    ".globl hider_semihost_trap\n"
    ".type hider_semihost_trap, @function\n"
    ".balign 16\n"
    "hider_semihost_trap:\n"
    ".option push\n"
    ".option norvc\n"
    "slli x0, x0, 0x1f\n"
    "ebreak\n"
    "srai x0, x0, 7\n"
    ".option pop\n"
    "ret\n"
    ".size hider_semihost_trap, . - hider_semihost_trap\n"
    ".popsection\n");
namespace {
intptr_t semihost_call(uintptr_t op, const void* arg) { return hider_semihost_trap(op, arg); }
}  // namespace
#else
#error "semihost: unsupported architecture (ARM M-profile or RISC-V only)"
#endif

namespace hider::semihost {
namespace {

size_t length_of(const char* text) {
    size_t n = 0;
    while (text[n] != '\0') ++n;
    return n;
}

}  // namespace

int32_t open_write(const char* path) {
    const uintptr_t block[3] = {reinterpret_cast<uintptr_t>(path), kModeWriteBinary, length_of(path)};
    return static_cast<int32_t>(semihost_call(kSysOpen, block));
}

bool write(int32_t handle, const void* data, size_t size) {
    const uintptr_t block[3] = {static_cast<uintptr_t>(handle), reinterpret_cast<uintptr_t>(data), size};
    return semihost_call(kSysWrite, block) == 0;  // the host returns the count NOT written
}

bool close(int32_t handle) {
    const uintptr_t block[1] = {static_cast<uintptr_t>(handle)};
    return semihost_call(kSysClose, block) == 0;
}

bool write_file(const char* path, const void* data, size_t size) {
    const int32_t handle = open_write(path);
    if (handle == kInvalidHandle) return false;
    const bool written = write(handle, data, size);
    return close(handle) && written;
}

void print(const char* text) { semihost_call(kSysWrite0, text); }

void print_u32(uint32_t value) {
    char text[11];  // 4294967295 + NUL
    size_t pos = sizeof(text) - 1;
    text[pos] = '\0';
    do {
        text[--pos] = static_cast<char>('0' + value % 10u);
        value /= 10u;
    } while (value != 0);
    print(text + pos);
}

void print_hex32(uint32_t value) {
    char text[11] = {'0', 'x'};
    for (int i = 0; i < 8; ++i) {
        const uint32_t nibble = (value >> (28 - 4 * i)) & 0xFu;
        text[2 + i] = static_cast<char>(nibble < 10 ? '0' + nibble : 'a' + nibble - 10);
    }
    text[10] = '\0';
    print(text);
}

void exit(int status) {
    const uintptr_t block[2] = {kApplicationExit, static_cast<uintptr_t>(status)};
    semihost_call(kSysExitExtended, block);
    for (;;) {
    }  // unreachable under QEMU; a debugger without semihosting parks here
}

}  // namespace hider::semihost

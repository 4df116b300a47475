// Freestanding semihosting port: host files, console text and the exit status of a firmware run
// under QEMU (-semihosting-config enable=on,target=native). Cortex-M: bkpt 0xAB; RV32: the
// slli/ebreak/srai sequence (other ARM profiles and RV64 are refused at compile time). Operation numbers
// and blocks: Arm's "Semihosting for AArch32 and AArch64" (version 2), RISC-V's semihosting specification.
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace hider::semihost {

/// Handle value returned when the host refuses to open a file.
constexpr int32_t kInvalidHandle = -1;

/// Opens `path` on the host for binary writing ("wb", truncates). Relative paths resolve against
/// QEMU's working directory (under ctest: the test's WORKING_DIRECTORY). Returns a handle or kInvalidHandle.
int32_t open_write(const char* path);

/// Writes `size` bytes of `data` to `handle`; returns true when every byte was written.
bool write(int32_t handle, const void* data, size_t size);

/// Closes `handle`; returns true on success.
bool close(int32_t handle);

/// Creates (or truncates) `path` and writes `size` bytes into it; returns true on success.
bool write_file(const char* path, const void* data, size_t size);

/// Prints a NUL-terminated string on QEMU's stdout.
void print(const char* text);

/// Prints `value` in decimal (no newline).
void print_u32(uint32_t value);

/// Prints `value` as 0x followed by 8 hex digits (no newline).
void print_hex32(uint32_t value);

/// Ends the run; QEMU exits with `status` (0..255) through SYS_EXIT_EXTENDED.
[[noreturn]] void exit(int status);

}  // namespace hider::semihost

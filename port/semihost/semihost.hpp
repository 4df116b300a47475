// Freestanding semihosting port: host files, console text and the exit status of a firmware run
// under QEMU (-semihosting-config enable=on,target=native). ARM: bkpt 0xAB; RISC-V: the
// slli/ebreak/srai sequence. Operation numbers and blocks: docs/targets.md s.5, ARM "Semihosting v2".
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

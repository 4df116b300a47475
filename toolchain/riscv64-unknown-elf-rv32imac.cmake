# RV32IMAC, ilp32 soft-float ABI (keep -march=rv32imac: "_zicsr" selects the rv64 multilib).
# big = virt (no F/D, no firmware: -bios none), small = sifive_e (E31, 16 KB DTIM at 0x80000000).
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(HIDER_TRIPLE riscv64-unknown-elf)
set(HIDER_ARCH riscv)
set(HIDER_TARGET rv32imac)
set(MCU_CPU "-march=rv32imac -mabi=ilp32 -mcmodel=medany")
set(HIDER_QEMU_BIG qemu-system-riscv32 -M virt -cpu rv32,f=off,d=off -bios none -nographic
    -semihosting-config enable=on,target=native -kernel)
set(HIDER_QEMU_SMALL qemu-system-riscv32 -M sifive_e -nographic -semihosting-config enable=on,target=native -kernel)
include(${CMAKE_CURRENT_LIST_DIR}/common-gcc-bare.cmake)

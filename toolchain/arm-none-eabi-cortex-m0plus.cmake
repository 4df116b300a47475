# Cortex-M0+ (ARMv6-M: no divide, no 32x32->64 multiply, no FPU). QEMU has no M0+ machine:
# big = mps2-an385 (a Cortex-M3 that runs v6-M code), small = microbit (strict Cortex-M0, 16 KB RAM).
set(CMAKE_SYSTEM_PROCESSOR arm)
set(HIDER_TRIPLE arm-none-eabi)
set(HIDER_ARCH arm)
set(HIDER_TARGET cm0plus)
set(MCU_CPU "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(HIDER_QEMU_BIG qemu-system-arm -M mps2-an385 -nographic -semihosting-config enable=on,target=native -kernel)
set(HIDER_QEMU_SMALL qemu-system-arm -M microbit -nographic -semihosting-config enable=on,target=native -kernel)
include(${CMAKE_CURRENT_LIST_DIR}/common-gcc-bare.cmake)

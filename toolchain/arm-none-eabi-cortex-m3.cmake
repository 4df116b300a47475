# Cortex-M3 (ARMv7-M: hardware divide and smull, no FPU). Both machines are mps2-an385;
# "small" only shrinks the linker's RAM region to MCU_SMALL_RAM_SIZE (16 KB).
set(CMAKE_SYSTEM_PROCESSOR arm)
set(HIDER_TRIPLE arm-none-eabi)
set(HIDER_ARCH arm)
set(HIDER_TARGET cm3)
set(MCU_CPU "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
set(HIDER_QEMU_BIG qemu-system-arm -M mps2-an385 -nographic -semihosting-config enable=on,target=native -kernel)
set(HIDER_QEMU_SMALL ${HIDER_QEMU_BIG})
include(${CMAKE_CURRENT_LIST_DIR}/common-gcc-bare.cmake)

# Shared part of the bare-metal GCC toolchain files. The per-CPU file sets:
#   HIDER_TRIPLE        compiler prefix (arm-none-eabi, riscv64-unknown-elf)
#   HIDER_ARCH          arm | riscv (selects startup code and linker script in firmware/)
#   HIDER_TARGET        preset name: cm0plus | cm3 | rv32imac
#   MCU_CPU             CPU flags, e.g. "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft"
#   HIDER_QEMU_BIG / HIDER_QEMU_SMALL   QEMU command lines (lists) ending in -kernel
#   HIDER_SMALL_*       memory map of the small machine
# Nothing here downloads anything; the toolchain and QEMU come from Debian packages.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_C_COMPILER ${HIDER_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${HIDER_TRIPLE}-g++)
set(CMAKE_ASM_COMPILER ${HIDER_TRIPLE}-gcc)

# Checks compile a static library, so they need no startup code or linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES MCU_CPU HIDER_TRIPLE HIDER_ARCH HIDER_TARGET)

set(_hider_common "${MCU_CPU} -ffreestanding -ffunction-sections -fdata-sections -fstack-usage")
set(CMAKE_C_FLAGS_INIT "${_hider_common}")
# No -fno-exceptions/-fno-rtti here: hider's targets get them from hider_target_flags()
# (cmake/hider_flags.cmake), and a project that borrows this file keeps its own choice. The two below
# only spare bare metal the guard and atexit helpers that -nostdlib leaves undefined.
set(CMAKE_CXX_FLAGS_INIT "${_hider_common} -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_ASM_FLAGS_INIT "${MCU_CPU}")
# The driver adds no start files and no libraries; libgcc (integer division, 64-bit helpers) goes last.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -nostartfiles -Wl,--gc-sections")
set(CMAKE_C_STANDARD_LIBRARIES "-lgcc")
set(CMAKE_CXX_STANDARD_LIBRARIES "-lgcc")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Memory of the "big" machine (mps2-an385 / virt), as the linker sees it. A smaller value makes the
# link fail with "region `RAM' overflowed", which is the point: QEMU's own RAM is no check.
set(MCU_RAM_SIZE 256K CACHE STRING "RAM region given to the linker on the big machine (ld size, e.g. 64K)")
set(MCU_FLASH_SIZE 1M CACHE STRING "Flash region given to the linker on the big machine (ld size, at most 1M on virt)")
set(MCU_SMALL_RAM_SIZE 16K CACHE STRING "RAM region on the small machine (microbit, sifive_e: 16K)")
set(MCU_SMALL_FLASH_SIZE 256K CACHE STRING "Flash region on the small machine (microbit: 256K)")

# add_test(NAME x COMMAND <firmware target>) runs the ELF on the big machine under a timeout;
# hider_add_firmware() overrides this per target for the small machine.
set(CMAKE_CROSSCOMPILING_EMULATOR timeout --kill-after=5 60 ${HIDER_QEMU_BIG})

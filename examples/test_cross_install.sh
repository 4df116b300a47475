#!/usr/bin/env bash
# examples.cross_install: hider configured at top level with a user's own cross toolchain file (the
# firmware example's Cortex-M0+ one, not one of hider's toolchain/ files), built and installed, as
# README "find_package" tells users to get hider::port_semihost for their CPU. Checks: configure does not
# need hider's QEMU/firmware set-up (no firmware/ in the build), and the prefix holds the package files
# and the ARM port_semihost library, exported as hider::port_semihost.
# Usage: test_cross_install.sh <hider-source> <work-dir>      (exit 77: no ARM toolchain)
set -euo pipefail
src=$1 work=$2
for tool in arm-none-eabi-g++ arm-none-eabi-objdump ninja; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed (bash scripts/install-deps.sh all)"; exit 77; }
done
rm -rf "$work" && mkdir -p "$work"
cmake -S "$src" -B "$work/build" -G Ninja --toolchain "$src/examples/firmware-fetchcontent/cortex-m0plus.cmake" \
      >"$work/configure.log"
[ ! -e "$work/build/firmware" ] || { echo "FAIL: hider's firmware/ was configured for a user's toolchain" >&2; exit 1; }
cmake --build "$work/build" -j 2
cmake --install "$work/build" --prefix "$work/prefix" >"$work/install.log"
for f in lib/cmake/hider/hiderConfig.cmake lib/cmake/hider/hiderConfigVersion.cmake include/hider/raster/zbuffer.hpp; do
    [ -f "$work/prefix/$f" ] || { echo "FAIL: $f not installed" >&2; exit 1; }
done
lib=$(find "$work/prefix" -name libhider_port_semihost.a | head -1)
[ -n "$lib" ] || { echo "FAIL: libhider_port_semihost.a not installed" >&2; exit 1; }
header=$(arm-none-eabi-objdump -f "$lib")
[[ $header == *elf32-littlearm* ]] || { echo "FAIL: $lib is not ARM code" >&2; exit 1; }
grep -q "hider::port_semihost" "$work/prefix/lib/cmake/hider/hiderTargets.cmake" ||
    { echo "FAIL: the installed package does not export hider::port_semihost" >&2; exit 1; }
echo "installed with a user's Cortex-M0+ toolchain: package files and an ARM port_semihost"

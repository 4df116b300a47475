#!/usr/bin/env bash
# examples.firmware_fetchcontent: the Cortex-M0+ firmware example, configured from outside the tree with
# its own toolchain file, pulling hider with FetchContent from this checkout (FETCHCONTENT_FULLY_DISCONNECTED:
# no network). Checks: the build graph holds none of hider's firmware/tools/tests (only hider's
# port_semihost library is built), the consumer's compile commands carry none of hider's flags while
# hider's own semihost.cpp keeps them, the ELF runs under QEMU, and its frame equals the host example's.
# Usage: test_fetchcontent.sh <hider-source> <work-dir> <reference.ppm>      (exit 77: no ARM toolchain/QEMU)
set -euo pipefail
src=$1 work=$2 reference=$3
. "$src/examples/consumer_checks.sh"
for tool in arm-none-eabi-g++ qemu-system-arm ninja; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed (bash scripts/install-deps.sh all)"; exit 77; }
done
example=$src/examples/firmware-fetchcontent
rm -rf "$work" && mkdir -p "$work"
cmake -S "$example" -B "$work/build" -G Ninja --toolchain "$example/cortex-m0plus.cmake" \
      -DHIDER_SOURCE_DIR="$src" -DFETCHCONTENT_FULLY_DISCONNECTED=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
      >"$work/configure.log"
ninja -C "$work/build" -t targets all >"$work/targets.txt"
check_no_hider_extras "$work/targets.txt"
grep -q "_deps/hider-build/port/libhider_port_semihost.a" "$work/targets.txt" ||
    { echo "FAIL: hider::port_semihost is not in the build" >&2; exit 1; }
for d in firmware tools tests lib examples; do
    [ ! -e "$work/build/_deps/hider-build/$d" ] || { echo "FAIL: hider's $d/ was added to the consumer's build" >&2; exit 1; }
done
cmake --build "$work/build"
check_flags_consumer "$work/build/compile_commands.json" "$example" "$src"
# Control: hider's own file in the same database keeps hider's flags (the check above could see them).
cmake -DCOMPILE_COMMANDS="$work/build/compile_commands.json" -DSOURCE_DIR="$src/port" -DMODE=consumer \
      "-DFLAGS=$hider_flags" -P "$src/cmake/check_compile_flags.cmake" >/dev/null 2>&1 &&
    { echo "FAIL: hider's semihost.cpp lost hider's own flags" >&2; exit 1; }
tests=$(cd "$work/build" && ctest -N | sed -n 's/^Total Tests: //p')
[ "$tests" = 1 ] || { echo "FAIL: the consumer's build has $tests tests, expected its own 1" >&2; exit 1; }
(cd "$work/build" && ctest --output-on-failure)
cmp "$work/build/frame.ppm" "$reference"
echo "firmware (Cortex-M0+, 8-row bands, ST7789 sink): frame identical to the host example's"

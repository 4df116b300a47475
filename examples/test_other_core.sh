#!/usr/bin/env bash
# examples.other_core: hider as a dependency of a project for a core its semihosting port does not serve
# (a Cortex-A15 in ARM state, named cortex-a15; then arm64). The library and the display port must build,
# and hider::port_semihost must not exist (the compiler, asked with the user's -mcpu, says the core is
# not M-profile: BKPT is not the A-profile trap, it would hang). With -DHIDER_INSTALL=ON the consumer's
# build and hider's install must then succeed (they stopped at the semihost library before).
# Usage: test_other_core.sh <hider-source> <work-dir>      (exit 77: no ARM toolchain)
set -euo pipefail
src=$1 work=$2
for tool in arm-none-eabi-g++ ninja; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed (bash scripts/install-deps.sh all)"; exit 77; }
done
rm -rf "$work" && mkdir -p "$work/app"
cat >"$work/app/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(other_core LANGUAGES CXX)
include(FetchContent)
FetchContent_Declare(hider SOURCE_DIR ${HIDER_SOURCE_DIR})
FetchContent_MakeAvailable(hider)
add_library(app STATIC app.cpp)
target_include_directories(app PRIVATE ${HIDER_SOURCE_DIR}/examples/scene)
target_link_libraries(app PRIVATE hider::hider hider::port_display)
CMAKE
cat >"$work/app/app.cpp" <<'CPP'
#include "display/sink.hpp"
#include "example_scene.hpp"
// The example scene's draw (the z-buffer's portable paths: no Cortex-M or RV32 assembly on this core).
hider::FrameStats draw_band(const hider::View& view, hider::Span<const hider::ScreenVertex> verts,
                            const example::Frame& band) {
    return example::draw(view, verts, band);
}
CPP
for proc in cortex-a15 arm64; do
    cat >"$work/$proc.cmake" <<CMAKE
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR $proc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-a15 -marm -mfloat-abi=soft -ffreestanding")
CMAKE
    build=$work/build-$proc
    cmake -S "$work/app" -B "$build" -G Ninja --toolchain "$work/$proc.cmake" -DHIDER_SOURCE_DIR="$src" \
          -DFETCHCONTENT_FULLY_DISCONNECTED=ON >"$work/configure-$proc.log"
    cmake --build "$build" >"$work/build-$proc.log" 2>&1 ||
        { cat "$work/build-$proc.log"; echo "FAIL: $proc: the consumer's build failed" >&2; exit 1; }
    if ninja -C "$build" -t targets all | grep -q hider_port_semihost; then
        echo "FAIL: $proc: hider_port_semihost is defined" >&2; exit 1
    fi
    if [ "$proc" = cortex-a15 ]; then
        cmake -S "$work/app" -B "$build-install" -G Ninja --toolchain "$work/$proc.cmake" -DHIDER_SOURCE_DIR="$src" \
              -DFETCHCONTENT_FULLY_DISCONNECTED=ON -DHIDER_INSTALL=ON >"$work/configure-$proc-install.log"
        { cmake --build "$build-install" && cmake --install "$build-install" --prefix "$work/prefix-$proc"; } \
            >"$work/install-$proc.log" 2>&1 ||
            { cat "$work/install-$proc.log"; echo "FAIL: $proc: build or install with HIDER_INSTALL=ON failed" >&2; exit 1; }
        [ -f "$work/prefix-$proc/lib/cmake/hider/hiderConfig.cmake" ] ||
            { echo "FAIL: $proc: no hiderConfig.cmake installed" >&2; exit 1; }
    fi
    echo "$proc: library and display port built; no semihosting port$([ "$proc" = cortex-a15 ] && echo "; installs")"
done

#!/usr/bin/env bash
# examples.host_on_demand: hider as a host project's dependency (FetchContent) builds none of its own
# sources unless a target of the user's links them: a consumer that adds its own strict warnings
# (-Werror -Wuseless-cast here) and links only hider::hider must build, without libhider_port_host.a;
# a target that links hider::port_host then builds it.
# Usage: test_host_on_demand.sh <hider-source> <work-dir>
set -euo pipefail
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work/app"
cat >"$work/app/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(host_on_demand LANGUAGES CXX)
add_compile_options(-Werror -Wuseless-cast)  # the user's own policy, for the user's sources
include(FetchContent)
FetchContent_Declare(hider SOURCE_DIR ${HIDER_SOURCE_DIR})
FetchContent_MakeAvailable(hider)
add_executable(app app.cpp)
target_include_directories(app PRIVATE ${HIDER_SOURCE_DIR}/examples/scene)
target_link_libraries(app PRIVATE hider::hider)
add_library(writer STATIC writer.cpp)
target_link_libraries(writer PRIVATE hider::port_host)
set_target_properties(writer PROPERTIES EXCLUDE_FROM_ALL ON)
CMAKE
cat >"$work/app/app.cpp" <<'CPP'
#include "example_scene.hpp"
int main() { return 0; }
CPP
cat >"$work/app/writer.cpp" <<'CPP'
#include "host/ppm.hpp"
CPP
build=$work/build
cmake -S "$work/app" -B "$build" -G Ninja -DHIDER_SOURCE_DIR="$src" -DFETCHCONTENT_FULLY_DISCONNECTED=ON >"$work/configure.log"
cmake --build "$build" >"$work/build.log" 2>&1 || { cat "$work/build.log"; echo "FAIL: the consumer's build failed" >&2; exit 1; }
[ ! -e "$build/_deps/hider-build/port/libhider_port_host.a" ] ||
    { echo "FAIL: all built hider_port_host, which nothing links" >&2; exit 1; }
echo "all: the consumer's app built, hider_port_host left out"
# Asked for, the port builds, also under the user's -Wuseless-cast (port/host/ppm.cpp's mode_t cast).
cmake --build "$build" --target writer >"$work/writer.log" 2>&1 || { cat "$work/writer.log"; echo "FAIL: writer failed" >&2; exit 1; }
[ -e "$build/_deps/hider-build/port/libhider_port_host.a" ] || { echo "FAIL: writer built without the port" >&2; exit 1; }
echo "writer: hider_port_host built on demand"

#!/usr/bin/env bash
# examples.copy_lib: hider as a copy of the lib/ folder alone. One compiler call with only that folder
# on the include path builds examples/copy-lib/main.cpp; its frame must equal the host example's. Then
# the same copy through CMake: a project that calls add_subdirectory(vendor/lib) and links hider::hider
# (with its own strict warnings) builds the same file to the same frame.
# Usage: test_copy_lib.sh <hider-source> <work-dir> <c++ compiler> <reference.ppm>
set -euo pipefail
src=$1 work=$2 cxx=$3 reference=$4
rm -rf "$work" && mkdir -p "$work/vendor"
cp -R "$src/lib" "$work/vendor/lib"
"$cxx" -std=c++17 -O2 -Werror -Wall -Wextra -I "$work/vendor/lib" "$src/examples/copy-lib/main.cpp" -o "$work/copy_lib"
(cd "$work" && ./copy_lib copy_frame.ppm)
cmp "$work/copy_frame.ppm" "$reference"
echo "copy of lib/: frame identical to the find_package example's ($(wc -c <"$reference") bytes)"

mkdir -p "$work/cmake_project"
cat >"$work/cmake_project/CMakeLists.txt" <<EOF_CMAKE
cmake_minimum_required(VERSION 3.25)
project(copy_lib_cmake LANGUAGES CXX)
add_subdirectory(\${CMAKE_CURRENT_SOURCE_DIR}/../vendor/lib hider_lib)
add_executable(copy_lib "$src/examples/copy-lib/main.cpp")
target_link_libraries(copy_lib PRIVATE hider::hider)
target_compile_options(copy_lib PRIVATE -Werror -Wall -Wextra)
EOF_CMAKE
cmake -S "$work/cmake_project" -B "$work/cmake_build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" >"$work/cmake_configure.log"
cmake --build "$work/cmake_build" >"$work/cmake_build.log"
(cd "$work" && ./cmake_build/copy_lib copy_frame_cmake.ppm)
cmp "$work/copy_frame_cmake.ppm" "$reference"
echo "add_subdirectory of the copied lib/: frame identical"

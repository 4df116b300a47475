#!/usr/bin/env bash
# examples.find_package: `cmake --install` of this hider build into a temporary prefix, then the
# host-find-package example configured against that prefix only (find_package(hider 0.2 CONFIG
# REQUIRED)), built from outside the tree and run; its frame is the reference of the other examples.
# Also: versions 0.1, 0.3 and 1.0 are refused; the consumer's compile commands carry none of hider's flags
# and include the installed headers, not the source tree.
# Usage: test_find_package.sh <hider-source> <hider-build> <work-dir>
set -euo pipefail
src=$1 build=$2 work=$3
. "$src/examples/consumer_checks.sh"
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in lib/cmake/hider/hiderConfig.cmake lib/cmake/hider/hiderConfigVersion.cmake lib/cmake/hider/hiderTargets.cmake \
         include/hider/raster/zbuffer.hpp include/hider-port/host/ppm.hpp include/hider-port/display/sink.hpp \
         lib/libhider_port_host.a; do
    [ -f "$prefix/$f" ] || { echo "FAIL: $prefix/$f not installed" >&2; exit 1; }
done
echo "installed $(find "$prefix" -type f | wc -l) files into $prefix"

cmake -S "$src/examples/host-find-package" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$work/configure.log"
grep -q "hider" "$work/build/CMakeCache.txt"
grep -q "^hider_DIR:PATH=$prefix/lib/cmake/hider$" "$work/build/CMakeCache.txt" ||
    { echo "FAIL: hider was not found in the temporary prefix" >&2; grep hider_DIR "$work/build/CMakeCache.txt" >&2; exit 1; }
cmake --build "$work/build"
(cd "$work/build" && ctest --output-on-failure)
[ -s "$work/build/host_frame.ppm" ] || { echo "FAIL: no frame written" >&2; exit 1; }
cp "$work/build/host_frame.ppm" "$work/host_frame.ppm"

check_flags_consumer "$work/build/compile_commands.json" "$src/examples/host-find-package" "$src"
grep -q -- "-isystem $prefix/include" "$work/build/compile_commands.json" ||
    { echo "FAIL: the consumer does not compile against the installed headers" >&2; exit 1; }
if grep -q -- "$src/lib" "$work/build/compile_commands.json"; then
    echo "FAIL: the consumer compiles against hider's source tree, not the installed package" >&2; exit 1
fi

# Version check: only 0.2.x satisfies a request; others fail at configure time with CMake's message.
for want in 0.1 0.3 1.0 0.2; do
    mkdir -p "$work/version_$want"
    printf 'cmake_minimum_required(VERSION 3.25)\nproject(v LANGUAGES CXX)\nfind_package(hider %s CONFIG REQUIRED)\n' "$want" \
        >"$work/version_$want/CMakeLists.txt"
    if cmake -S "$work/version_$want" -B "$work/version_$want/build" -DCMAKE_PREFIX_PATH="$prefix" \
             >"$work/version_$want/log" 2>&1; then
        [ "$want" = 0.2 ] || { echo "FAIL: find_package(hider $want) accepted version 0.2" >&2; exit 1; }
    else
        [ "$want" != 0.2 ] || { cat "$work/version_$want/log" >&2; echo "FAIL: find_package(hider 0.2) failed" >&2; exit 1; }
        grep -q 'version: 0\.2\.0' "$work/version_$want/log" ||
            { cat "$work/version_$want/log" >&2; echo "FAIL: no version message for $want" >&2; exit 1; }
    fi
done
echo "find_package: 0.2 accepted; 0.1, 0.3, 1.0 refused"

# Components: the ports this host install holds are accepted, one it lacks and an unknown name refused
# with CMake's message naming the component.
for comps in "hider port_host port_display" "port_semihost" "port_hsot"; do
    dir=$work/components_${comps// /_}
    mkdir -p "$dir"
    printf 'cmake_minimum_required(VERSION 3.25)\nproject(c LANGUAGES CXX)\nfind_package(hider 0.2 CONFIG REQUIRED COMPONENTS %s)\n' "$comps" \
        >"$dir/CMakeLists.txt"
    if cmake -S "$dir" -B "$dir/build" -DCMAKE_PREFIX_PATH="$prefix" >"$dir/log" 2>&1; then
        [ "$comps" = "hider port_host port_display" ] || { echo "FAIL: COMPONENTS $comps accepted" >&2; exit 1; }
    else
        [ "$comps" != "hider port_host port_display" ] || { cat "$dir/log" >&2; echo "FAIL: COMPONENTS $comps refused" >&2; exit 1; }
        grep -q "$comps" "$dir/log" || { cat "$dir/log" >&2; echo "FAIL: the message does not name $comps" >&2; exit 1; }
    fi
done
echo "find_package COMPONENTS: port_host, port_display accepted; port_semihost (not on a host), port_hsot refused"

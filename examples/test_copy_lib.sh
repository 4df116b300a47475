#!/usr/bin/env bash
# examples.copy_lib: hider as a copy of the lib/ folder alone. One compiler call with only that folder
# on the include path builds examples/copy-lib/main.cpp; its frame must equal the host example's.
# Usage: test_copy_lib.sh <hider-source> <work-dir> <c++ compiler> <reference.ppm>
set -euo pipefail
src=$1 work=$2 cxx=$3 reference=$4
rm -rf "$work" && mkdir -p "$work/vendor"
cp -R "$src/lib" "$work/vendor/lib"
"$cxx" -std=c++17 -O2 -Werror -Wall -Wextra -I "$work/vendor/lib" "$src/examples/copy-lib/main.cpp" -o "$work/copy_lib"
(cd "$work" && ./copy_lib copy_frame.ppm)
cmp "$work/copy_frame.ppm" "$reference"
echo "copy of lib/: frame identical to the find_package example's ($(wc -c <"$reference") bytes)"

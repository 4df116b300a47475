#!/bin/sh
# ctest helper: a model or scene file whose name holds a newline or a carriage return still gives
# headers that compile (the name is recorded in a // comment line; a raw newline there ended the comment
# and left the rest of the name as code). Usage: odd_name_test.sh BAKE BAKE_RAY BSP CXX LIB_DIR WORK_DIR OBJ SCENE
set -u
bake=$1 bake_ray=$2 bsp=$3 cxx=$4 lib=$5 work=$6 obj=$7 scene=$8
rm -rf "$work" && mkdir -p "$work" || exit 1
nl='
'
cr=$(printf '\r')
cp "$obj" "$work/odd${nl}name${cr}x.obj" && cp "$scene" "$work/odd${nl}scene${cr}x.txt" || exit 1
"$bake" "$work/odd${nl}name${cr}x.obj" -o "$work/baked.hpp" --name odd_mesh || exit 1
"$bsp" "$work/odd${nl}name${cr}x.obj" -o "$work/tree.hpp" --name odd_tree || exit 1
"$bake_ray" "$work/odd${nl}scene${cr}x.txt" -o "$work/ray.hpp" --name odd_ray || exit 1
printf '#include "baked.hpp"\n#include "tree.hpp"\n#include "ray.hpp"\nint main() { return 0; }\n' > "$work/all.cpp"
if ! "$cxx" -std=c++17 -Wall -Wextra -Werror -pedantic -fsyntax-only -I "$lib" -I "$work" "$work/all.cpp"; then
    echo "FAIL: the headers baked from odd file names do not compile"
    exit 1
fi
echo "ok: headers from file names with a newline and a carriage return compile"

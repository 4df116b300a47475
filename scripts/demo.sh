#!/usr/bin/env bash
# Renders the demo: the benchmark torus and the Utah teapot, as PPM and PNG, and the ray-traced spheres
# (tests/data/scenes/spheres.txt), with lib/ fixed-point code.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh host
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release -DHIDER_BUILD_TESTS=OFF >/dev/null
cmake --build build/demo --target hider-render >/dev/null
render=build/demo/tools/hider-render
$render tests/data/models/teapot.obj --eye 2,4,5 --no-cull -o demo.ppm
$render tests/data/models/teapot.obj --eye 2,4,5 --no-cull -o demo.png
$render tests/data/models/torus.obj --eye 0,0,-2.5 --target 0,0,0 --fov 73.7398 --near 0.25 --stats -o torus.png
$render --scene tests/data/scenes/spheres.txt --size 320x256 --stats -o raytrace.png
echo "wrote demo.ppm, demo.png (teapot), torus.png (benchmark view) and raytrace.png (ray-traced spheres)"

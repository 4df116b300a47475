#!/usr/bin/env bash
# Renders the demo: the benchmark torus and the Utah teapot, as PPM and PNG, and the ray-traced spheres
# (tests/data/scenes/spheres.txt), with lib/ fixed-point code.
#   bash scripts/demo.sh --web [PORT]   instead builds the web playground (hider-render as WebAssembly)
#                                       and serves it on http://127.0.0.1:PORT/ (default 8000) until Ctrl-C
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--web" ]; then
  bash scripts/install-deps.sh web
  cmake -S web -B build/web-demo -G Ninja -DCMAKE_TOOLCHAIN_FILE="$PWD/toolchain/wasm32-wasi.cmake" \
        -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build/web-demo -j 2
  exec python3 web/serve.py build/web-demo/site "${2:-8000}"
fi
bash scripts/install-deps.sh host
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release -DHIDER_BUILD_TESTS=OFF >/dev/null
cmake --build build/demo --target hider-render >/dev/null
render=build/demo/tools/hider-render
$render tests/data/models/teapot.obj --eye 2,4,5 --no-cull -o demo.ppm
$render tests/data/models/teapot.obj --eye 2,4,5 --no-cull -o demo.png
$render tests/data/models/torus.obj --eye 0,0,-2.5 --target 0,0,0 --fov 73.7398 --near 0.25 --stats -o torus.png
$render --scene tests/data/scenes/spheres.txt --size 320x256 --stats -o raytrace.png
echo "wrote demo.ppm, demo.png (teapot), torus.png (benchmark view) and raytrace.png (ray-traced spheres) in $PWD"

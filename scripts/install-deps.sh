#!/usr/bin/env bash
# Installs the Debian packages hider needs that are missing. Usage: install-deps.sh host|web|all
#   host: compiler, CMake, Ninja (enough to render the demo)
#   web:  host + clang 14 for wasm32-wasi (wasi-libc, libc++ and compiler-rt for wasm32, lld) and python3:
#         builds and serves the web playground (scripts/demo.sh --web)
#   all:  host + web + doctest, valgrind, clang's x86-64 runtimes (libFuzzer, ASan, UBSan: the fuzzers),
#         the ARM and RISC-V cross compilers, QEMU and Chromium (every test)
set -euo pipefail
want=(g++ cmake ninja-build)
web=(clang-14 lld-14 wasi-libc libc++-14-dev-wasm32 libc++abi-14-dev-wasm32 libclang-rt-14-dev-wasm32 python3)
case "${1:-all}" in
  host) ;;
  web) want+=("${web[@]}") ;;
  all) want+=("${web[@]}" doctest-dev valgrind libclang-rt-14-dev gcc-arm-none-eabi gcc-riscv64-unknown-elf qemu-system-arm
              qemu-system-misc chromium) ;;
  *) echo "usage: install-deps.sh host|web|all" >&2; exit 2 ;;
esac
missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "install-deps.sh: not root and no sudo; as root, run: apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
# --no-install-recommends: gcc-arm-none-eabi would otherwise pull in a 360 MB newlib we do not use.
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"

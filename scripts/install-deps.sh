#!/usr/bin/env bash
# Installs the Debian packages hider needs that are missing. Usage: install-deps.sh host|all
#   host: compiler, CMake, Ninja (enough to render the demo)
#   all:  also doctest, valgrind, the ARM and RISC-V cross compilers and QEMU (every test)
set -euo pipefail
want=(g++ cmake ninja-build)
if [ "${1:-all}" = all ]; then
  want+=(doctest-dev valgrind gcc-arm-none-eabi gcc-riscv64-unknown-elf qemu-system-arm qemu-system-misc)
fi
missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
# --no-install-recommends: gcc-arm-none-eabi would otherwise pull in a 360 MB newlib we do not use.
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"

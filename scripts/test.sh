#!/usr/bin/env bash
# Installs what is missing and runs every test: host build + tests (with the consumer examples and the
# web playground in headless Chromium), the same under ASan/UBSan,
# the three cross builds (Cortex-M0+, Cortex-M3, RV32IMAC) with their firmware under QEMU.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh all
start=$SECONDS
step() { echo; echo "=== $* ($((SECONDS - start)) s)"; }
step "host: configure, build, test"
cmake --workflow --preset host
step "host with AddressSanitizer + UndefinedBehaviorSanitizer"
cmake --workflow --preset host-asan
for preset in cm0plus cm3 rv32imac; do
  step "cross: $preset (build, nm/RAM checks, firmware under QEMU)"
  cmake --workflow --preset "$preset"
done
step "all tests passed"

#!/bin/sh
# ctest for the nm check itself: runs check_firmware_symbols.sh on a probe ELF that uses float.
# Prints "nm check rejected <elf>" followed by the check's output only when the check exits
# non-zero; the test's PASS_REGULAR_EXPRESSION then also requires a soft-float symbol name.
# Usage: check_firmware_symbols_rejects.sh <nm> <probe.elf>
set -u
here=$(cd "$(dirname "$0")" && pwd)
status=0
output=$(sh "$here/check_firmware_symbols.sh" "$1" "$2" 2>&1) || status=$?
if [ "$status" -eq 0 ]; then
    echo "nm check ACCEPTED $2, which links soft-float code"
    exit 1
fi
echo "nm check rejected $2 (exit $status):"
printf '%s\n' "$output"

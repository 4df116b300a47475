#!/bin/sh
# Fails (exit 1) when a firmware ELF links soft-float, half-float or complex helpers, the heap,
# operator new/delete, exceptions or RTTI, and names each offending symbol;
# the pattern was checked against every libgcc symbol for v6-M, v7-M and rv32imac.
# Usage: check_firmware_symbols.sh <nm> <firmware.elf> [--delete-on-failure]
# The POST_BUILD step passes --delete-on-failure so no rejected ELF is left for ctest to run
# (Ninja, unlike Make, keeps the outputs of a failed step).
set -eu
if [ $# -lt 2 ] || [ $# -gt 3 ] || { [ $# -eq 3 ] && [ "$3" != "--delete-on-failure" ]; }; then
    echo "usage: $0 <nm> <firmware.elf> [--delete-on-failure]" >&2
    exit 2
fi
nm_tool=$1 elf=$2 delete=${3:-}
pattern='^(__aeabi_(f|d|cf|cd|u?[il]2[fd]|h2f|f2h)[a-z0-9_]*|__[a-z]+(sf|df|tf|hf)[0-9]|__(float|fix|extend|trunc)[a-z0-9]+|__powi[a-z0-9]+|__(mul|div)[sdxt]c3|malloc|free|calloc|realloc|_malloc_r|_free_r|_?sbrk|_Zn[wa][jm].*|_Zd[la]Pv.*|__gnu_(d2h|f2h|h2f)_[a-z]+|__cxa_[a-z_]+|__g(cc|xx)_personality_v0|_Unwind_[A-Za-z_]+|__aeabi_unwind_cpp_pr[0-9]|_ZTI.*|_ZTS.*)$'

if ! symbols=$("$nm_tool" "$elf"); then
    echo "$0: '$nm_tool $elf' failed" >&2
    exit 2
fi
bad=$(printf '%s\n' "$symbols" | awk 'NF { print $NF }' | grep -E "$pattern" | grep -vx '__cxa_pure_virtual' | sort -u || true)
if [ -n "$bad" ]; then
    echo "$elf: forbidden symbols (soft-float, heap, exceptions or RTTI):" >&2
    printf '%s\n' "$bad" | sed 's/^/  /' >&2
    echo "Keep float/double, new/malloc and exceptions out of firmware and lib/." >&2
    if [ -n "$delete" ]; then
        rm -f "$elf"
        echo "$elf deleted" >&2
    fi
    exit 1
fi

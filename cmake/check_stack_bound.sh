#!/bin/sh
# ctest <firmware>.stack_bound: the static worst-case stack of a firmware ELF (tools/hider-stack, from
# its disassembly) must fit <limit> (the reserved stack less the bytes the start-up requires untouched),
# and must not be below the high-water mark the firmware measured on its run (stack.txt, written by
# firmware/common/startup.cpp), which would mean the analysis missed a path. A mark at the painting's
# floor says nothing (tiny runs).
# Usage: check_stack_bound.sh <objdump> <hider-stack> <elf> <dump-file> <limit-bytes> <stack.txt|-> [hider-stack options]...
set -eu
objdump=$1 tool=$2 elf=$3 dump=$4 limit=$5 measured=$6
shift 6
"$objdump" -t -s -d --no-show-raw-insn "$elf" > "$dump"
status=0
out=$("$tool" "$dump" --limit "$limit" "$@") || status=$?
printf '%s\n' "$out"
[ "$status" -eq 0 ] || exit "$status"
[ "$measured" = "-" ] && exit 0
if [ ! -f "$measured" ]; then
    echo "check_stack_bound: $measured missing (the firmware's run writes it)" >&2
    exit 1
fi
bound=$(printf '%s\n' "$out" | sed -n 's/^stack bound from [^:]*: \([0-9]*\) bytes.*/\1/p')
set -- $(cat "$measured")  # high-water N floor F size S
if [ "$#" -ne 6 ] || [ "$1" != high-water ] || [ -z "$bound" ]; then
    echo "check_stack_bound: cannot read $measured or the bound" >&2
    exit 1
fi
echo "measured on the run: high-water $2 bytes (painting floor $4)"
if [ "$2" -gt "$4" ] && [ "$2" -gt "$bound" ]; then
    echo "check_stack_bound: the bound of $bound bytes is below the measured $2: hider-stack missed a path" >&2
    exit 1
fi

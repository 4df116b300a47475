#!/bin/sh
# ctest (cross builds): lib/'s assembly routines keep their exact code under a user's instrumentation
# flags. Compiles cmake/probes/naked_probe.cpp, whose table references every routine of the target,
# once plain and once with -fstack-protector-all -finstrument-functions -fprofile-arcs -pg
# -fsanitize-coverage=trace-pc -fzero-call-used-regs=all, and requires each routine's section
# (disassembly and relocations) to be identical in both objects: a guard load, a profiling counter or
# a call before the routine's own push corrupts its registers and stack.
# Usage: check_naked_uninstrumented.sh <c++ compiler> <objdump> <expected routine count>
#        <routines on all targets> <lib dir> <probe.cpp> <work dir> <cpu flags...>
# <routines on all targets> must equal the HIDER_NAKED definitions in lib/ (the probe lists them by hand).
set -eu
cxx=$1 objdump=$2 expected=$3 total=$4 lib=$5 probe=$6 work=$7
shift 7
in_lib=$(grep -r --include='*.hpp' -c '^HIDER_NAKED inline' "$lib" | awk -F: '{ n += $2 } END { print n + 0 }')
if [ "$in_lib" -ne "$total" ]; then
    echo "FAIL: lib/ defines $in_lib HIDER_NAKED routines, the probe's lists expect $total: list the new ones in"
    echo "      $probe and its count in firmware/CMakeLists.txt"
    exit 1
fi
mkdir -p "$work"
base="-std=c++17 -Os -ffreestanding -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections -I$lib"
"$cxx" "$@" $base -c "$probe" -o "$work/plain.o"
"$cxx" "$@" $base -fstack-protector-all -finstrument-functions -fprofile-arcs -pg -fsanitize-coverage=trace-pc \
    -fzero-call-used-regs=all -c "$probe" -o "$work/instrumented.o"
# The routines: the symbols the probe's table refers to (one relocation each).
routines=$("$objdump" -r "$work/plain.o" | awk '/^RELOCATION RECORDS FOR \[/ { table = ($0 ~ /hider_naked_routines/); next }
    table && NF >= 3 && $3 != "VALUE" { print $3 }' | sed 's/[+-]0x[0-9a-f]*$//' | sort -u)
count=$(printf '%s\n' "$routines" | grep -c . || true)
if [ "$count" -ne "$expected" ]; then
    echo "FAIL: the probe's table refers to $count routines, expected $expected:"; printf '%s\n' "$routines"
    exit 1
fi
section_code() {  # disassembly with relocations of section $2 of object $1, without the file header
    "$objdump" -d -r -j "$2" "$1" | sed -n '/^Disassembly of section/,$p'
}
status=0
for r in $routines; do
    a=$(section_code "$work/plain.o" ".text.$r")
    b=$(section_code "$work/instrumented.o" ".text.$r")
    if [ -z "$a" ]; then
        echo "FAIL: no section .text.$r in the plain object"; status=1
    elif [ "$a" != "$b" ]; then
        echo "FAIL: $r changes under the instrumentation flags:"
        printf '%s\n' "$a" > "$work/a.txt"; printf '%s\n' "$b" > "$work/b.txt"
        diff "$work/a.txt" "$work/b.txt" | head -20 || true
        status=1
    else
        echo "ok: $r ($(printf '%s\n' "$a" | grep -c '^ ') lines)"
    fi
done
[ "$status" -eq 0 ] && echo "all $count assembly routines uninstrumented"
exit "$status"

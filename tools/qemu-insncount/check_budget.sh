#!/bin/sh
# ctest: an instruction budget that a target of the issues set and that must keep holding. Runs
# firmware A (and B) under the insncount plugin and passes if
#     count(A) * DEN <= NUM            (no B: an absolute budget, DEN usually 1)
#     count(A) * DEN <= NUM * count(B) (with B: a ratio budget NUM / DEN)
# where a count is the bench region (`region`: bench_begin..bench_end summed over pairs) or its first
# pair (`pair0`). Counts are deterministic (QEMU's TCG plugin), so a failure is a real regression.
# Usage: check_budget.sh <preset> <work-dir> <NUM> <DEN> <elfA> <machineA> <fieldA> [<elfB> <machineB> <fieldB>]
# Env: INSNCOUNT_PLUGIN, NM as for run.sh.
set -eu
if [ $# -ne 7 ] && [ $# -ne 10 ]; then
    echo "usage: $0 <preset> <work-dir> <NUM> <DEN> <elfA> <machineA> <region|pair0> [<elfB> <machineB> <region|pair0>]" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
preset=$1 work=$2 num=$3 den=$4
shift 4
for n in "$num" "$den"; do
    case $n in '' | *[!0-9]* | 0) echo "$0: budget '$num/$den' must be positive integers" >&2; exit 2 ;; esac
done
[ ${#num} -le 8 ] && [ ${#den} -le 8 ] || { echo "$0: budget '$num/$den': at most 8 digits each" >&2; exit 2; }
for f in "$3" ${6:+"$6"}; do
    case $f in region | pair0) ;; *) echo "$0: unknown field '$f' (region or pair0)" >&2; exit 2 ;; esac
done
mkdir -p "$work"
cd "$work"

# count <elf> <machine> <field> <name>: prints the chosen count of one run
count() {
    if ! INSNCOUNT_ARGS=pairs=1 sh "$here/run.sh" "$preset" "$1" "$4.txt" "$2" >/dev/null; then
        echo "FAIL: $1 did not run to a clean exit under QEMU" >&2
        exit 1
    fi
    case "$3" in
        region) v=$(sed -n 's/^insncount .* region=\([0-9]*\).*/\1/p' "$4.txt") ;;
        *) v=$(sed -n 's/^pair 0 insns=\([0-9]*\).*/\1/p' "$4.txt") ;;
    esac
    if [ -z "$v" ] || [ "$v" -eq 0 ] || [ ${#v} -gt 10 ]; then
        echo "FAIL: no $3 count (or one over 10 digits) for $1" >&2
        exit 1
    fi
    echo "$v"
}

# (each count is checked here, not only by set -e: bash as sh does not stop inside $(...))
a=$(count "$1" "$2" "$3" a) || exit 1
echo "A: $(basename "$1") $3 = $a"
b=1 limit_text="$num/$den" ratio=""
if [ $# -eq 6 ]; then
    b=$(count "$4" "$5" "$6" b) || exit 1
    echo "B: $(basename "$4") $6 = $b"
    limit_text="$num/$den x B"
    ratio=" (A / B = $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", a / b }'))"
fi
# the shell's 64-bit arithmetic, exact: counts of at most 10 digits times budgets of at most 8
if [ $((a * den <= num * b)) -eq 1 ]; then
    echo "within budget: A <= $limit_text$ratio"
else
    echo "FAIL: over budget: A = $a > $limit_text$ratio" >&2
    exit 1
fi

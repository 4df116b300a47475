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
mkdir -p "$work"
cd "$work"

# count <elf> <machine> <field> <name>: prints the chosen count of one run
count() {
    INSNCOUNT_ARGS=pairs=1 sh "$here/run.sh" "$preset" "$1" "$4.txt" "$2" >/dev/null
    case "$3" in
        region) v=$(sed -n 's/^insncount .* region=\([0-9]*\).*/\1/p' "$4.txt") ;;
        pair0) v=$(sed -n 's/^pair 0 insns=\([0-9]*\).*/\1/p' "$4.txt") ;;
        *) echo "$0: unknown field '$3'" >&2; exit 2 ;;
    esac
    if [ -z "$v" ] || [ "$v" -eq 0 ]; then
        echo "FAIL: no $3 count for $1" >&2
        exit 1
    fi
    echo "$v"
}

a=$(count "$1" "$2" "$3" a)
echo "A: $(basename "$1") $3 = $a"
if [ $# -eq 6 ]; then
    b=$(count "$4" "$5" "$6" b)
    echo "B: $(basename "$4") $6 = $b"
    limit_text="$num/$den x B"
else
    b=1
    limit_text="$num/$den"
fi
ratio=""
[ "$b" -ne 1 ] && ratio=" (A / B = $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", a / b }'))"
# awk: exact in doubles (counts below 2^31 times budgets below 2^21)
if awk -v a="$a" -v b="$b" -v n="$num" -v d="$den" 'BEGIN { exit !(a * d <= n * b) }'; then
    echo "within budget: A <= $limit_text$ratio"
else
    echo "FAIL: over budget: A = $a > $limit_text$ratio" >&2
    exit 1
fi

#!/bin/sh
# ctest: the waterfall's frame (bench region / pairs: one pair per frame) stays within a budget of
# instructions. Usage: check_budget.sh <preset> <elf> <work-dir> <machine> <budget>
set -eu
preset=$1 elf=$2 work=$3 machine=$4 budget=$5
here=$(cd "$(dirname "$0")/../../tools/qemu-insncount" && pwd)
mkdir -p "$work"
cd "$work"
sh "$here/run.sh" "$preset" "$elf" counts.txt "$machine" >/dev/null
region=$(sed -n 's/.* region=\([0-9]*\).*/\1/p' counts.txt)
pairs=$(sed -n 's/.* pairs=\([0-9]*\).*/\1/p' counts.txt)
if [ -z "$region" ] || [ -z "$pairs" ] || [ "$pairs" -eq 0 ]; then
    echo "FAIL: no counts: $(cat counts.txt)" >&2
    exit 1
fi
frame=$((region / pairs))
echo "$(basename "$elf"): $frame instructions a frame ($pairs frames), budget $budget"
if [ "$frame" -gt "$budget" ]; then
    echo "FAIL: over the budget by $((frame - budget))" >&2
    exit 1
fi

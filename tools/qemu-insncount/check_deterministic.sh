#!/bin/sh
# ctest: runs a firmware twice under the insncount plugin; passes if both runs give identical
# counts and the bench region is nonzero. Usage: check_deterministic.sh <preset> <elf> <work-dir> [big|small]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
preset=$1 elf=$2 work=$3 machine=${4:-big}
mkdir -p "$work"
cd "$work"
sh "$here/run.sh" "$preset" "$elf" counts1.txt "$machine" >/dev/null
sh "$here/run.sh" "$preset" "$elf" counts2.txt "$machine" >/dev/null
echo "run 1: $(cat counts1.txt)"
echo "run 2: $(cat counts2.txt)"
if ! cmp -s counts1.txt counts2.txt; then
    echo "FAIL: counts differ between identical runs" >&2
    exit 1
fi
region=$(sed -n 's/.* region=\([0-9]*\).*/\1/p' counts1.txt)
if [ -z "$region" ] || [ "$region" -eq 0 ]; then
    echo "FAIL: bench region count is zero" >&2
    exit 1
fi
echo "deterministic, region=$region"

#!/bin/sh
# ctest: runs a firmware whose bench pairs each hold one hand-written sequence (firmware/cyclecheck) under
# the plugin's cycle model and compares every pair, less pair 0 (the empty sequence), with the expected
# file's cycles less its first entry, for the lower and the upper bound.
# Usage: check_cycles.sh <cm0plus|cm3> <elf> <expected.txt> <work-dir>
# expected.txt: lines "<name> <min> <max>" in the firmware's order; '#' starts a comment.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
preset=$1 elf=$2 expected=$3 work=$4
mkdir -p "$work"
cd "$work"
INSNCOUNT_ARGS=pairs=1 sh "$here/run.sh" "$preset" "$elf" counts.txt big >/dev/null 2>&1
sed 's/#.*//' "$expected" | awk 'NF == 3' >expected.txt
grep '^pair ' counts.txt | sed 's/[a-z_]*=//g' >pairs.txt
awk 'NR == FNR { name[NR] = $1; lo[NR] = $2; hi[NR] = $3; n = NR; next }
     { i = $2 + 1; mlo[i] = $4; mhi[i] = $5; m = i }
     END {
       if (m != n) { printf "FAIL: %d pairs measured, %d sequences expected\n", m, n; exit 1 }
       bad = 0
       for (i = 1; i <= n; ++i) {
         dl = mlo[i] - mlo[1]; dh = mhi[i] - mhi[1]; el = lo[i] - lo[1]; eh = hi[i] - hi[1]
         ok = dl == el && dh == eh
         printf "%-20s manual %3d..%-3d  model %3d..%-3d  %s\n", name[i], lo[i], hi[i], dl + lo[1], dh + hi[1], ok ? "ok" : "MISMATCH"
         if (!ok) bad = 1
       }
       if (bad) { print "FAIL: the cycle model differs from the manual"; exit 1 }
       printf "cycle model matches the manual on %d sequences\n", n
     }' expected.txt pairs.txt

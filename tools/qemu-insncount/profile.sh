#!/bin/sh
# Where a firmware's bench region spends its instructions: runs it under the insncount plugin with
# profile= and maps each executed address to its function (nm) or, with LINES=1, to its source line
# (addr2line; build with -g for useful lines). Prints the top entries by instructions, with the share
# and, on ARM targets, the modelled cycles (lower bound).
# Usage: profile.sh <cm0plus|cm3|rv32imac> <firmware.elf> [big|small] [top entries, default 30]
# Env:   INSNCOUNT_PLUGIN, NM as for run.sh; ADDR2LINE (default: from the preset); LINES=1;
#        PAIR=<n> profiles only the n-th bench pair (from 0).
set -eu
if [ $# -lt 2 ] || [ $# -gt 4 ]; then
    echo "usage: $0 <cm0plus|cm3|rv32imac> <firmware.elf> [big|small] [top]" >&2
    exit 2
fi
preset=$1 elf=$2 machine=${3:-big} top=${4:-30}
case "$preset" in
    cm0plus | cm3) triple=arm-none-eabi ;;
    rv32imac) triple=riscv64-unknown-elf ;;
    *) echo "$0: unknown target '$preset'" >&2; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
elf_abs=$(cd "$(dirname "$elf")" && pwd)/$(basename "$elf")
(cd "$work" && INSNCOUNT_ARGS="profile=$work/profile.txt${PAIR:+,profile_pair=$PAIR}" sh "$here/run.sh" "$preset" "$elf_abs" "$work/counts.txt" "$machine" >/dev/null 2>&1) || true
if [ ! -s "$work/profile.txt" ]; then
    echo "$0: no profile written" >&2
    exit 1
fi
head -1 "$work/counts.txt"
if [ "${LINES:-0}" = 1 ]; then
    # address -> file:line, one addr2line call for all addresses
    awk '{ print "0x" $1 }' "$work/profile.txt" | "${ADDR2LINE:-$triple-addr2line}" -e "$elf_abs" >"$work/lines.txt"
    paste -d ' ' "$work/profile.txt" "$work/lines.txt" |
        awk '{ n[$4] += $2; c[$4] += $2 * $3; t += $2 } END { for (k in n) printf "%d %d %.1f%% %s\n", n[k], c[k], 100 * n[k] / t, k }'
else
    # address -> function: the last symbol at or below it (nm -n order)
    "${NM:-$triple-nm}" -n "$elf_abs" | awk '$2 ~ /^[tTwW]$/ { print $1, $3 }' >"$work/syms.txt"
    # both lists hold 8 lowercase hex digits: string order is address order (any awk)
    awk 'NR == FNR { a[NR] = $1; s[NR] = $2; m = NR; next }
         { pc = $1; lo = 1; hi = m
           while (lo < hi) { mid = int((lo + hi + 1) / 2); if (a[mid] "" <= pc "") lo = mid; else hi = mid - 1 }
           n[s[lo]] += $2; c[s[lo]] += $2 * $3; t += $2 }
         END { for (k in n) printf "%d %d %.1f%% %s\n", n[k], c[k], 100 * n[k] / t, k }' "$work/syms.txt" "$work/profile.txt"
fi | sort -rn | head -n "$top" | awk 'BEGIN { print "instructions cycles(lo) share where" } { print }'

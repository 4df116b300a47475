#!/bin/sh
# Instruction profile of a firmware run under QEMU: executed instructions per function symbol (the whole
# run, startup and output included), largest first, with the share of the total.
# Usage: profile.sh <cm0plus|cm3|rv32imac> <firmware.elf> [big|small] [lines, default 20]
# Env:   NM (default: the target's nm), CC (to build the plugin, default cc)
# The firmware's semihosted files land in a temporary directory. Exit status: QEMU's.
set -eu
if [ $# -lt 2 ] || [ $# -gt 4 ]; then
    echo "usage: $0 <cm0plus|cm3|rv32imac> <firmware.elf> [big|small] [lines]" >&2
    exit 2
fi
preset=$1 elf=$(cd "$(dirname "$2")" && pwd)/$(basename "$2") machine=${3:-big} lines=${4:-20}
semi="-semihosting-config enable=on,target=native"
case "$preset:$machine" in
    cm0plus:big | cm3:big | cm3:small) qemu="qemu-system-arm -M mps2-an385" triple=arm-none-eabi ;;
    cm0plus:small) qemu="qemu-system-arm -M microbit" triple=arm-none-eabi ;;
    rv32imac:big) qemu="qemu-system-riscv32 -M virt -cpu rv32,f=off,d=off -bios none" triple=riscv64-unknown-elf ;;
    rv32imac:small) qemu="qemu-system-riscv32 -M sifive_e" triple=riscv64-unknown-elf ;;
    *) echo "$0: unknown target/machine '$preset' '$machine'" >&2; exit 2 ;;
esac
nm_tool=${NM:-$triple-nm}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
${CC:-cc} -O2 -shared -fPIC -Wall -o "$work/libtbprofile.so" "$(cd "$(dirname "$0")" && pwd)/tbprofile.c"
status=0
(cd "$work" && timeout --kill-after=5 600 $qemu -nographic $semi -kernel "$elf" \
    -plugin "$work/libtbprofile.so,out=$work/blocks.txt" >/dev/null 2>&1) || status=$?
if [ ! -s "$work/blocks.txt" ]; then
    echo "$0: QEMU wrote no profile (status $status)" >&2
    exit 1
fi
# Function symbols in decimal, sorted by address; blocks sorted by address; one merge pass.
"$nm_tool" -n -S -C --radix=d --defined-only "$elf" | awk 'NF >= 4 && $3 ~ /^[tTwW]$/' >"$work/syms.txt"
sort -n -k1,1 "$work/blocks.txt" >"$work/sorted.txt"
awk -v lines="$lines" '
    NR == FNR { a[n] = $1 + 0; e[n] = $1 + $2; name = $4; for (i = 5; i <= NF; ++i) name = name " " $i; s[n++] = name; next }
    {
        pc = $1 + 0; c = $2 * $3; total += c
        while (k + 1 < n && a[k + 1] <= pc) ++k
        key = (n > 0 && pc >= a[k] && pc < e[k]) ? s[k] : "(no symbol)"
        sum[key] += c
    }
    END {
        printf "%d instructions\n", total
        for (key in sum) printf "%d\t%.1f%%\t%s\n", sum[key], 100 * sum[key] / total, key | "sort -rn | head -n " lines
    }' "$work/syms.txt" "$work/sorted.txt"
exit "$status"

#!/bin/sh
# Runs a firmware ELF under QEMU with the insncount plugin and writes
#   insncount total=<n> region=<n> pairs=<n> max=<n>
# to <out-file> (region = bench_begin .. bench_end summed over pairs, max = the largest pair; see
# firmware/common/bench.hpp).
# Usage: run.sh <cm0plus|cm3|rv32imac> <firmware.elf> <out-file> [big|small]
# On cm0plus and cm3 the plugin also estimates cycles (model=m0plus, model=m3: arm_cycles.h), so the
# line gains cycles=/cycles_max=/region_cycles=/region_cycles_max= fields.
# Env:   INSNCOUNT_PLUGIN  path of libinsncount.so (default: built from insncount.c into a cache dir)
#        INSNCOUNT_ARGS    more plugin options, comma-separated (pairs=1, profile=<file>)
#        NM                the target nm (default: from the preset)
# The firmware's own semihosted files land in the current directory. Exit status: QEMU's.
set -eu
if [ $# -lt 3 ] || [ $# -gt 4 ]; then
    echo "usage: $0 <cm0plus|cm3|rv32imac> <firmware.elf> <out-file> [big|small]" >&2
    exit 2
fi
preset=$1 elf=$2 out=$3 machine=${4:-big}
semi="-semihosting-config enable=on,target=native"
case "$preset:$machine" in
    cm0plus:big) qemu="qemu-system-arm -M mps2-an385" triple=arm-none-eabi cycle_opt=,model=m0plus ;;
    cm3:big | cm3:small) qemu="qemu-system-arm -M mps2-an385" triple=arm-none-eabi cycle_opt=,model=m3 ;;
    cm0plus:small) qemu="qemu-system-arm -M microbit" triple=arm-none-eabi cycle_opt=,model=m0plus ;;
    rv32imac:big) qemu="qemu-system-riscv32 -M virt -cpu rv32,f=off,d=off -bios none" triple=riscv64-unknown-elf cycle_opt= ;;
    rv32imac:small) qemu="qemu-system-riscv32 -M sifive_e" triple=riscv64-unknown-elf cycle_opt= ;;
    *) echo "$0: unknown target/machine '$preset' '$machine'" >&2; exit 2 ;;
esac
nm_tool=${NM:-$triple-nm}

plugin=${INSNCOUNT_PLUGIN:-}
if [ -z "$plugin" ]; then
    here=$(cd "$(dirname "$0")" && pwd)
    src=$here/insncount.c
    cache=${XDG_CACHE_HOME:-$HOME/.cache}/hider-insncount
    # one plugin per source text, so checkouts with different models never share a build
    key=$(cat "$src" "$here/arm_cycles.h" | cksum | cut -d ' ' -f 1)
    plugin=$cache/libinsncount-$key.so
    if [ ! -f "$plugin" ]; then
        mkdir -p "$cache"
        ${CC:-cc} -O2 -shared -fPIC -Wall -o "$plugin.$$" "$src" && mv -f "$plugin.$$" "$plugin"
    fi
fi

symbol() { "$nm_tool" "$elf" | awk -v s="$1" '$3 == s { print $1 }'; }
start=$(symbol bench_begin)
end=$(symbol bench_end)
if [ -z "$start" ] || [ -z "$end" ]; then
    echo "$0: $elf has no bench_begin/bench_end (link firmware/common/bench.cpp)" >&2
    exit 2
fi

rm -f "$out"
status=0
# shellcheck disable=SC2086 # $qemu and $semi are word lists on purpose
timeout --kill-after=5 300 $qemu -nographic $semi -kernel "$elf" \
    -plugin "$plugin,start=0x$start,end=0x$end,out=$out$cycle_opt${INSNCOUNT_ARGS:+,$INSNCOUNT_ARGS}" || status=$?
if [ ! -s "$out" ]; then
    echo "$0: QEMU wrote no counts (status $status)" >&2
    exit 1
fi
exit "$status"

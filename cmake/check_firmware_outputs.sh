#!/bin/sh
# ctest: firmware output files must equal, byte for byte, the ones a host program computes.
# Runs <host-command...> in <ref-dir> (emptied first), then compares each <file> in <fw-dir>
# (written by the firmware's run test through semihosting) with the one in <ref-dir>.
# Usage: check_firmware_outputs.sh <fw-dir> <ref-dir> <firmware.elf> <file>... -- <host-command>...
set -eu
fw_dir=$1 ref_dir=$2 elf=$3
shift 3
files=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    files="$files $1"
    shift
done
if [ $# -lt 2 ] || [ -z "$files" ]; then
    echo "usage: $0 <fw-dir> <ref-dir> <firmware.elf> <file>... -- <host-command>..." >&2
    exit 2
fi
shift  # the --
rm -rf "$ref_dir"
mkdir -p "$ref_dir"
if ! (cd "$ref_dir" && "$@"); then
    echo "FAIL: host reference command failed: $*" >&2
    exit 1
fi
failed=0
for f in $files; do
    if [ ! -f "$fw_dir/$f" ]; then
        echo "FAIL: firmware wrote no $fw_dir/$f"
        failed=1
    elif [ -z "$(find "$fw_dir/$f" -newer "$elf")" ]; then
        echo "FAIL: $fw_dir/$f is older than $elf (stale: the firmware did not rewrite it)"
        failed=1
    elif [ ! -f "$ref_dir/$f" ]; then
        echo "FAIL: host command wrote no $ref_dir/$f"
        failed=1
    elif cmp "$fw_dir/$f" "$ref_dir/$f"; then
        echo "ok: $f ($(wc -c <"$fw_dir/$f") bytes) matches the host"
    else
        echo "FAIL: $fw_dir/$f differs from host reference $ref_dir/$f"
        failed=1
    fi
done
exit "$failed"

#!/bin/sh
# Stack report from GCC's -fstack-usage files: the largest static frame overall and the largest
# whose source lies under <lib-dir>. These are per-function frames, not call-chain depths; the
# firmware prints its measured high-water mark at exit (firmware/common/startup.cpp).
# Usage: check_firmware_stack.sh <name> <lib-dir> <limit-bytes|0> <object-dir>...
# Exits 1 when a limit is given and some frame exceeds it.
set -eu
name=$1 lib=$2 limit=$3
shift 3
files=$(find "$@" -name '*.su' 2>/dev/null | sort)
if [ -z "$files" ]; then
    echo "$name: no .su files (build with -fstack-usage)" >&2
    exit 1
fi
# .su line: <file>:<line>:<col>:<function>\t<bytes>\t<static|dynamic|dynamic,bounded>
# shellcheck disable=SC2086 # $files is a list of paths without spaces (build tree)
awk -F '\t' -v name="$name" -v lib="$lib/" -v limit="$limit" '
    function where(loc) { return substr(loc, 1, index(loc, ":") - 1) }
    function fname(loc,   rest, i) {
        rest = loc
        for (i = 0; i < 3; ++i) rest = substr(rest, index(rest, ":") + 1)
        return rest
    }
    {
        bytes = $2 + 0
        if (bytes > all_bytes) { all_bytes = bytes; all_line = $0 }
        if (index(where($1), lib) == 1 && bytes > lib_bytes) { lib_bytes = bytes; lib_line = $0 }
        if ($3 != "static") dynamic = dynamic "\n    " $1 " (" $3 ")"
    }
    function show(label, line,   f) {
        if (line == "") { printf "  %-9s none\n", label; return }
        split(line, f, "\t")
        printf "  %-9s %5d bytes  %s  (%s)\n", label, f[2], fname(f[1]), where(f[1])
    }
    END {
        printf "%s: largest stack frames (-fstack-usage)\n", name
        show("overall", all_line)
        show("in lib/", lib_line)
        if (dynamic != "") printf "  dynamic frames:%s\n", dynamic
        if (limit > 0 && all_bytes > limit) {
            printf "%s: a stack frame of %d bytes exceeds the limit of %d\n", name, all_bytes, limit
            exit 1
        }
    }' $files

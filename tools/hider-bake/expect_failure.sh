#!/bin/sh
# ctest helper: runs <command...>, passes when it exits with <status> and its stderr matches the
# extended regular expression <pattern>.  Usage: expect_failure.sh <status> <pattern> <command>...
set -u
want=$1 pattern=$2
shift 2
err=$("$@" 2>&1 >/dev/null)
got=$?
if [ "$got" -ne "$want" ]; then
    echo "FAIL: exit status $got, expected $want: $*"
    echo "$err"
    exit 1
fi
if ! printf '%s\n' "$err" | grep -Eq -- "$pattern"; then
    echo "FAIL: stderr does not match '$pattern': $err"
    exit 1
fi
echo "ok: exit $got: $err"

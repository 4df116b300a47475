#!/usr/bin/env bash
# examples.flag_checks_fail: the consumer checks must be able to fail. A planted -fno-rtti on a consumer
# file, a hider file without -fno-exceptions, an empty database and a hider tool in a consumer's
# build graph are each rejected.
# Usage: test_checks_fail.sh <hider-source> <work-dir>
set -euo pipefail
src=$1 work=$2
. "$src/examples/consumer_checks.sh"
rm -rf "$work" && mkdir -p "$work/app"
cat >"$work/leak.json" <<JSON
[{"directory": "$work", "file": "$work/app/main.cpp", "command": "c++ -O2 -fno-rtti -c $work/app/main.cpp"}]
JSON
cat >"$work/own.json" <<JSON
[{"directory": "$work", "file": "$src/tools/x.cpp", "command": "c++ -Wall -Wextra -Wshadow -Wdouble-promotion -Werror=double-promotion -fno-rtti -c $src/tools/x.cpp"}]
JSON
echo "[]" >"$work/empty.json"
expect_fail() {  # <pattern> <command...>
    local pattern=$1; shift
    if "$@" >"$work/out.log" 2>&1; then echo "FAIL: accepted: $*" >&2; exit 1; fi
    # CMake wraps a long message (long paths) across lines: match with the line breaks as spaces.
    tr -s ' \n' '  ' <"$work/out.log" | grep -q -- "$pattern" ||
        { cat "$work/out.log" >&2; echo "FAIL: no '$pattern'" >&2; exit 1; }
}
expect_fail "carries -fno-rtti" check_flags_consumer "$work/leak.json" "$work/app" "$src"
expect_fail "missing -fno-exceptions" cmake -DCOMPILE_COMMANDS="$work/own.json" -DSOURCE_DIR="$src" -DMODE=own \
    "-DFLAGS=$hider_flags" -P "$src/cmake/check_compile_flags.cmake"
expect_fail "only 0 compile" check_flags_consumer "$work/empty.json" "$work/app" "$src"
printf '_deps/hider-build/tools/hider-render: phony\n' >"$work/targets.txt"
expect_fail "hider-render" check_no_hider_extras "$work/targets.txt"
echo "all four planted faults rejected"

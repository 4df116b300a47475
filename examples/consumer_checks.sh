# Shared checks of the consumer tests (sourced by test_*.sh).
#   check_flags_consumer <compile_commands.json> <consumer source dir> <hider source dir>
#       none of hider's own flags on a compile command of the consumer's files
#   check_no_hider_extras <file with `ninja -t targets all` output>
#       the consumer's build graph holds none of hider's firmware, tools, tests or lib checks
hider_flags="-Wall;-Wextra;-Wshadow;-Wdouble-promotion;-Werror=double-promotion;-fno-exceptions;-fno-rtti"

check_flags_consumer() {
    cmake -DCOMPILE_COMMANDS="$1" -DSOURCE_DIR="$2" -DMODE=consumer "-DFLAGS=$hider_flags" \
          -P "$3/cmake/check_compile_flags.cmake"
}

check_no_hider_extras() {
    local bad
    bad=$(grep -E '(^|/)_deps/hider-build/(firmware|tools|tests|lib|examples|web)/|hider_tests|hider-render|hider-bench|hider-bake|hider_toolkit|hider_fw_runtime|hider_freestanding_check|hider_include_check|qemu_insncount|hider_web' "$1" || true)
    if [ -n "$bad" ]; then
        echo "FAIL: the consumer's build contains hider's own firmware/tools/tests:" >&2
        echo "$bad" | head -20 >&2
        return 1
    fi
}

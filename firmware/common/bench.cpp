// Benchmark markers. noinline keeps the calls; no_icf and the distinct asm
// comments stop GCC from folding the two identical bodies into one address.
#include "common/bench.hpp"

extern "C" __attribute__((noinline, no_icf)) void bench_begin() { __asm__ volatile("/* bench_begin */" ::: "memory"); }
extern "C" __attribute__((noinline, no_icf)) void bench_end() { __asm__ volatile("/* bench_end */" ::: "memory"); }

// Benchmark markers. tools/qemu-insncount counts the instructions executed from the first
// instruction of bench_begin() up to the first of bench_end(), summed over all pairs.
#pragma once

extern "C" {
/// Marks the start of a measured region. Never inlined, so its address is in the ELF.
void bench_begin();
/// Marks the end of a measured region.
void bench_end();
}

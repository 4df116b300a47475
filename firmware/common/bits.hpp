// Counting set bits without a builtin (__builtin_popcount is a libgcc call on some targets), for the
// examples' coverage checks outside the measured regions.
#pragma once
#include <stddef.h>
#include <stdint.h>

/// Set bits of words[0..n).
inline uint32_t bits_set(const uint32_t* words, size_t n) {
    uint32_t count = 0;
    for (size_t i = 0; i < n; ++i)
        for (uint32_t w = words[i]; w != 0; w &= w - 1) ++count;
    return count;
}

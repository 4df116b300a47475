// Decimal text of an unsigned number without a C library, for the examples' PPM headers and the
// start-up's stack report.
#pragma once
#include <stdint.h>

/// Writes the decimal digits of v at p (no terminator); returns the end.
inline char* append_decimal(char* p, uint32_t v) {
    char digits[10];
    int n = 0;
    do {
        digits[n++] = static_cast<char>('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    while (n > 0) *p++ = digits[--n];
    return p;
}

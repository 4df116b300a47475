// A minimal exact signed 128-bit integer for the few sums of 64x64-bit products lib/ must sign-test
// exactly (Newell's plane-side tests in screen space). Portable: 32-bit targets have no __int128.
#pragma once
#include <hider/fixed.hpp>

namespace hider {

/// Two's-complement 128-bit value: hi * 2^64 + lo.
struct Int128 {
    uint64_t lo = 0;
    int64_t hi = 0;

    friend constexpr Int128 operator+(Int128 a, Int128 b) {
        Int128 r;
        r.lo = a.lo + b.lo;
        r.hi = static_cast<int64_t>(static_cast<uint64_t>(a.hi) + static_cast<uint64_t>(b.hi) + (r.lo < a.lo ? 1u : 0u));
        return r;
    }
    friend constexpr Int128 operator-(Int128 a) {
        Int128 r;
        r.lo = ~a.lo + 1;
        r.hi = static_cast<int64_t>(~static_cast<uint64_t>(a.hi) + (r.lo == 0 ? 1u : 0u));
        return r;
    }
    friend constexpr Int128 operator-(Int128 a, Int128 b) { return a + (-b); }
    /// -1, 0 or +1.
    constexpr int sign() const { return hi < 0 ? -1 : ((hi == 0 && lo == 0) ? 0 : 1); }
    /// Arithmetic shift right by 0 < s < 64.
    constexpr Int128 shr(int s) const {
        Int128 r;
        r.lo = (lo >> s) | (static_cast<uint64_t>(hi) << (64 - s));
        r.hi = hi >> s;
        return r;
    }
    /// True when the value fits an int64.
    constexpr bool fits64() const { return (hi == 0 && lo <= static_cast<uint64_t>(INT64_MAX)) || (hi == -1 && lo > static_cast<uint64_t>(INT64_MAX)); }
};

/// Exact product of two signed 64-bit values, from four 32x32 -> 64 products.
constexpr Int128 mul128(int64_t a, int64_t b) {
    const bool negative = (a < 0) != (b < 0);
    const uint64_t ua = a < 0 ? 0 - static_cast<uint64_t>(a) : static_cast<uint64_t>(a);
    const uint64_t ub = b < 0 ? 0 - static_cast<uint64_t>(b) : static_cast<uint64_t>(b);
    const uint32_t a0 = static_cast<uint32_t>(ua), a1 = static_cast<uint32_t>(ua >> 32);
    const uint32_t b0 = static_cast<uint32_t>(ub), b1 = static_cast<uint32_t>(ub >> 32);
    const uint64_t p00 = mul_wide_u(a0, b0), p01 = mul_wide_u(a0, b1), p10 = mul_wide_u(a1, b0), p11 = mul_wide_u(a1, b1);
    const uint64_t mid = (p00 >> 32) + static_cast<uint32_t>(p01) + static_cast<uint32_t>(p10);
    Int128 r;
    r.lo = (mid << 32) | static_cast<uint32_t>(p00);
    r.hi = static_cast<int64_t>(p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32));
    return negative ? -r : r;
}

/// Exact product of a and b when it fits 128 bits: the low word times b exactly, the high word's
/// product only in its low 64 bits (the rest would overflow).
constexpr Int128 mul128(const Int128& a, int64_t b) {
    const Int128 upper = mul128(static_cast<int64_t>(a.lo >> 32), b);  // times 2^32
    Int128 r = mul128(static_cast<int64_t>(a.lo & 0xFFFFFFFFu), b);
    Int128 shifted;
    shifted.lo = upper.lo << 32;
    shifted.hi = static_cast<int64_t>((static_cast<uint64_t>(upper.hi) << 32) | (upper.lo >> 32));
    r = r + shifted;
    r.hi = static_cast<int64_t>(static_cast<uint64_t>(r.hi) + static_cast<uint64_t>(a.hi) * static_cast<uint64_t>(b));
    return r;
}

}  // namespace hider

// Fixed-point numbers: Fixed<F> is a signed Q(31-F).F value in an int32_t, plus the exact integer
// helpers the pipeline is built from. Rounding rules (the only ones in lib/, see CONVENTIONS.md):
//   * products (operator*, mul, mul_shift) floor: 64-bit product, then arithmetic shift (toward -inf);
//   * quotients (div, recip, div_round) round to nearest, ties away from zero, and saturate;
//   * isqrt floors.
#pragma once
#include <hider/base.hpp>

namespace hider {

/// True where the CPU has no 32x32 -> 64-bit multiply (ARMv6-M): wide products are built from 32-bit
/// ones (the *_by_parts forms, available everywhere for tests).
constexpr bool kNarrowMultiply =
#if defined(HIDER_ARMV6M)
    true;
#else
    false;
#endif

/// Exact 32x32 -> 64-bit unsigned product from four 16x16 products (what ARMv6-M uses: it has no
/// long multiply instruction, and __aeabi_lmul is a full 64x64 routine).
__attribute__((always_inline)) constexpr uint64_t mul_wide_u_by_parts(uint32_t a, uint32_t b) {
    const uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    const uint32_t ll = al * bl, lh = al * bh, hl = ah * bl;
    const uint32_t mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu);
    const uint32_t hi = ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
    return (uint64_t{hi} << 32) | ((mid << 16) | (ll & 0xFFFFu));
}

/// Exact signed 32x32 -> 64-bit product from the unsigned one (two's-complement correction).
constexpr int64_t mul_wide_by_parts(int32_t a, int32_t b) {
    const uint32_t ua = static_cast<uint32_t>(a), ub = static_cast<uint32_t>(b);
    uint64_t p = mul_wide_u_by_parts(ua, ub);
    if (a < 0) p -= uint64_t{ub} << 32;
    if (b < 0) p -= uint64_t{ua} << 32;
    return static_cast<int64_t>(p);
}

/// Exact 32x32 -> 64-bit unsigned product: the single place a target-specific multiply goes.
constexpr uint64_t mul_wide_u(uint32_t a, uint32_t b) {
    if constexpr (kNarrowMultiply) return mul_wide_u_by_parts(a, b);
    return uint64_t{a} * b;
}

/// Exact 32x32 -> 64-bit signed product.
constexpr int64_t mul_wide(int32_t a, int32_t b) {
    if constexpr (kNarrowMultiply) return mul_wide_by_parts(a, b);
    return static_cast<int64_t>(a) * b;
}

/// Number of leading zero bits of a nonzero 32-bit value (one instruction where the CPU has CLZ).
constexpr int clz32(uint32_t v) {
#if defined(__GNUC__)
    return __builtin_clz(v);
#else
    int n = 0;
    if (v <= 0x0000FFFFu) { n += 16; v <<= 16; }
    if (v <= 0x00FFFFFFu) { n += 8; v <<= 8; }
    if (v <= 0x0FFFFFFFu) { n += 4; v <<= 4; }
    if (v <= 0x3FFFFFFFu) { n += 2; v <<= 2; }
    if (v <= 0x7FFFFFFFu) { n += 1; }
    return n;
#endif
}

/// True where a 64-bit division is a library call (every 32-bit target of hider).
constexpr bool kSlow64BitDivide = sizeof(void*) < 8;

/// True where the CPU divides 32 bits in one instruction (Cortex-M3/M4, RV32IM, 64-bit hosts).
constexpr bool kHardwareDivide32 =
#if defined(__ARM_FEATURE_IDIV) || defined(__riscv_div) || defined(__x86_64__) || defined(__aarch64__)
    true;
#else
    false;
#endif

/// floor(m / w) for a quotient known to be small: false (q untouched) unless m < w * 2^15. One 32-bit
/// hardware division of m and w shifted right until w has 16 bits gives the quotient or up to two
/// less (the divisor is rounded up); the exact remainder, which fits 32 bits for w < 2^30, corrects it.
/// Precondition: w > 0 (w >= 2^30 returns false).
constexpr bool div_small_quotient(uint64_t m, uint32_t w, uint32_t& q) {
    if (w >= (uint32_t{1} << 30) || (m >> 15) >= w) return false;
    if (w < (uint32_t{1} << 16)) {  // m < 2^31: one exact division
        q = static_cast<uint32_t>(m) / w;
        return true;
    }
    const int s = 16 - clz32(w);  // w >> s in [2^15, 2^16); 1 <= s <= 14
    const uint32_t ms = (static_cast<uint32_t>(m) >> s) | (static_cast<uint32_t>(m >> 32) << (32 - s));  // m >> s < 2^31
    uint32_t e = ms / ((w >> s) + 1);
    uint32_t r = static_cast<uint32_t>(m) - e * w;  // m - e w < 3 w < 2^32: the low words suffice
    if (r >= w) { r -= w; ++e; }
    if (r >= w) ++e;
    q = e;
    return true;
}

/// floor(n / d) and the remainder for n < d * 2^32 (so the quotient fits 32 bits), d != 0.
/// Long division in two 16-bit digits with 32-bit divides (Hacker's Delight, divlu): exact, and far
/// cheaper than a generic 64-bit division where the CPU has no 64-bit divide (all our targets).
constexpr uint32_t udiv64_32(uint64_t n, uint32_t d, uint32_t& rem) {
    const int s = clz32(d);
    const uint32_t v = d << s, vn1 = v >> 16, vn0 = v & 0xFFFFu;
    const uint32_t u1 = static_cast<uint32_t>(n >> 32), u0 = static_cast<uint32_t>(n);
    const uint32_t un32 = s == 0 ? u1 : (u1 << s) | (u0 >> (32 - s));
    const uint32_t un10 = u0 << s, un1 = un10 >> 16, un0 = un10 & 0xFFFFu;
    uint32_t q1 = un32 / vn1, rhat = un32 - q1 * vn1;
    while (q1 > 0xFFFFu || q1 * vn0 > ((rhat << 16) | un1)) {
        --q1;
        rhat += vn1;
        if (rhat > 0xFFFFu) break;
    }
    const uint32_t un21 = (un32 << 16) + un1 - q1 * v;
    uint32_t q0 = un21 / vn1;
    rhat = un21 - q0 * vn1;
    while (q0 > 0xFFFFu || q0 * vn0 > ((rhat << 16) | un0)) {
        --q0;
        rhat += vn1;
        if (rhat > 0xFFFFu) break;
    }
    rem = ((un21 << 16) + un0 - q0 * v) >> s;
    return (q1 << 16) | q0;
}

/// a * b for |a| < 2^32 and |b| < 2^15 from two 32-bit products (a = ah 2^16 + al; both ah b and al b
/// fit int32): the depth-plane products of a triangle's setup, on ARMv6-M without a wide multiply.
constexpr int64_t mul_i33_i16_by_parts(int64_t a, int32_t b) {
    const int32_t ah = static_cast<int32_t>(a >> 16);     // |ah| <= 2^16
    const int32_t al = static_cast<int32_t>(a & 0xFFFF);  // [0, 2^16)
    return int64_t{ah * b} * 65536 + al * b;
}

/// a * b for |a| < 2^32 and |b| < 2^15.
constexpr int64_t mul_i33_i16(int64_t a, int32_t b) {
    if constexpr (kNarrowMultiply) return mul_i33_i16_by_parts(a, b);
    return a * b;
}

/// a * b modulo 2^64 for |b| < 2^15 from three 32-bit products (a's low word in 16-bit halves): the
/// exact value modulo 2^64 without a wide product.
constexpr int64_t mul_i64_i16_by_parts(int64_t a, int32_t b) {
    const uint64_t ua = static_cast<uint64_t>(a);
    const uint32_t al = static_cast<uint32_t>(ua), ah = static_cast<uint32_t>(ua >> 32);
    const int64_t lo = int64_t{static_cast<int32_t>(al >> 16) * b} * 65536 + int64_t{static_cast<int32_t>(al & 0xFFFFu) * b};
    return static_cast<int64_t>(static_cast<uint64_t>(lo) + (uint64_t{ah * static_cast<uint32_t>(b)} << 32));
}

/// a * b for |b| < 2^15 and a product that fits int64.
constexpr int64_t mul_i64_i16(int64_t a, int32_t b) {
    if constexpr (kNarrowMultiply) return mul_i64_i16_by_parts(a, b);
    return a * b;
}

/// a * b modulo 2^64 for unsigned a from 32-bit parts: one 32x32->64 product and one 32-bit multiply.
constexpr uint64_t mul_u32_u64_by_parts(uint32_t a, uint64_t b) {
    return mul_wide_u(a, static_cast<uint32_t>(b)) + (uint64_t{a * static_cast<uint32_t>(b >> 32)} << 32);
}

/// a * b modulo 2^64 for unsigned a.
constexpr uint64_t mul_u32_u64(uint32_t a, uint64_t b) {
    if constexpr (kNarrowMultiply) return mul_u32_u64_by_parts(a, b);
    return a * b;
}

namespace detail {
/// 2^32 / m - 2^16 for m the middle of each of the 256 ranges of a 16-bit normalised divisor's top bits
/// (m = (256 + i) 128 + 64): the starting point of reciprocal_word(). Built at compile time; 512 bytes.
struct ReciprocalTable {
    uint16_t v[256];
    constexpr ReciprocalTable() : v() {
        for (uint32_t i = 0; i < 256; ++i) v[i] = static_cast<uint16_t>((uint64_t{1} << 32) / ((256 + i) * 128 + 64) - 65536);
    }
};
inline constexpr ReciprocalTable kReciprocalTable{};
}  // namespace detail

/// reciprocal_word()'s table, for assembly that starts the same way (raster/vertices_v6m.hpp,
/// raster/kernel_setup_v6m.hpp).
inline constexpr const uint16_t* kReciprocalTableData = detail::kReciprocalTable.v;

/// floor((2^64 - 1) / d) - 2^32 for d with its top bit set (the reciprocal of Moller and Granlund)
/// with 32-bit multiplies and no division: a table and one Newton step give 2^48 / d to about 16 bits,
/// a remainder step with two 32-bit products refines it to a few units, and the exact 64-bit remainder
/// then corrects it (the last step alone makes the result exact for any estimate; the estimate only
/// keeps it to a few iterations). On ARMv6-M far cheaper than udiv64_32, whose loop it replaces.
constexpr uint32_t reciprocal_word(uint32_t d) {
    const uint64_t r = (uint64_t{~d} << 32) | 0xFFFFFFFFu;  // 2^64 - 1 - d 2^32: v = floor(r / d)
    // 2^32 / dh for the top 16 bits dh: table (9 bits), then x1 = x0 + x0 e / 2^32 with e = 2^32 - dh x0.
    const uint32_t dh = d >> 16;
    const uint32_t x0 = 65536u + detail::kReciprocalTable.v[(dh >> 7) - 256];
    const int32_t e = static_cast<int32_t>(0u - dh * x0);  // |e| < 2^24: the product wraps past 2^32
    const int32_t x1 = static_cast<int32_t>(x0) + ((static_cast<int32_t>(x0 >> 2) * (e >> 8)) >> 22);
    const uint32_t v16 = static_cast<uint32_t>(min(max(x1 - 65536, int32_t{0}), int32_t{65535}));  // v / 2^16, within a few
    // Remainder of v16 2^16 (two 32-bit products: v16 < 2^16), and the correction rh (2^32 + v) / 2^32.
    const uint64_t pa = (uint64_t{v16 * (d & 0xFFFFu)} + (uint64_t{v16 * (d >> 16)} << 16)) << 16;
    const int64_t rem = static_cast<int64_t>(r - pa);
    const int32_t rh = static_cast<int32_t>(rem >> 32);  // |rh| < 2^21
    const int32_t a = (rh >> 8) * static_cast<int32_t>(v16), b = (rh & 0xFF) * static_cast<int32_t>(v16);
    // + 1: the truncations leave the estimate low (exhaustively over all 2^31 divisors: from 10 low to
    // 1 high, about one correction on average).
    const int64_t est = int64_t{static_cast<int32_t>(v16)} * 65536 + rh + (a >> 8) + (b >> 16) + 1;
    uint32_t v = static_cast<uint32_t>(est < 0 ? 0 : (est > 0xFFFFFFFF ? 0xFFFFFFFF : est));
    // Exact: the largest v with v d <= r.
    uint64_t p = mul_wide_u(v, d);
    while (p > r) { --v; p -= d; }
    while (r - p >= d) { ++v; p += d; }
    return v;
}

/// A 32-bit divisor prepared for several divisions (Moller and Granlund, "Improved division by
/// invariant integers", IEEE TC 2011, algorithm 4): reciprocal_word() makes the reciprocal, then each
/// quotient costs a 32x32->64 multiply and two corrections. Exact: divide() == udiv64_32() always.
class Divisor32 {
public:
    /// Precondition: d != 0.
    explicit constexpr Divisor32(uint32_t d) : shift_(clz32(d)), dn_(d << shift_), v_(reciprocal(d << shift_)) {}
    constexpr uint32_t value() const { return dn_ >> shift_; }

    /// floor(n / d) and the remainder, for n < d * 2^32 (the quotient fits 32 bits).
    constexpr uint32_t divide(uint64_t n, uint32_t& rem) const {
        const int s = shift_;
        const uint32_t n1 = static_cast<uint32_t>(n >> 32), n0 = static_cast<uint32_t>(n);
        const uint32_t u1 = s == 0 ? n1 : (n1 << s) | (n0 >> (32 - s));  // n << s < dn * 2^32: two words
        const uint32_t u0 = n0 << s;
        const uint64_t p = mul_wide_u(v_, u1) + ((uint64_t{u1} << 32) | u0);
        uint32_t q = static_cast<uint32_t>(p >> 32) + 1;  // estimate: the quotient or one more
        uint32_t r = u0 - q * dn_;                        // modulo 2^32
        if (r > static_cast<uint32_t>(p)) { --q; r += dn_; }
        if (r >= dn_) { ++q; r -= dn_; }                  // rare
        rem = r >> s;
        return q;
    }

private:
    /// floor((2^64 - 1) / dn) - 2^32 for dn with its top bit set.
    static constexpr uint32_t reciprocal(uint32_t dn) { return reciprocal_word(dn); }
    int shift_;
    uint32_t dn_, v_;
};

/// floor(a * b / 2^shift) for 0 <= shift < 63, computed exactly in 64 bits.
constexpr int64_t mul_shift(int32_t a, int32_t b, int shift) { return mul_wide(a, b) >> shift; }

/// n / d rounded to nearest, ties away from zero; d == 0 saturates to the sign of n (0 / 0 = 0).
/// The result is exact for every int64 pair except INT64_MIN / -1, which saturates to INT64_MAX.
/// On 32-bit targets, quotients below 2^32 with a 32-bit divisor take udiv64_32 instead of a library
/// 64-bit division; 64-bit hosts divide natively. Both are exact, so results are identical.
constexpr int64_t div_round(int64_t n, int64_t d) {
    if (d == 0) return n > 0 ? INT64_MAX : (n < 0 ? INT64_MIN : 0);
    if (d == -1 && n == INT64_MIN) return INT64_MAX;
    const uint64_t un = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
    const uint64_t ud = d < 0 ? 0 - static_cast<uint64_t>(d) : static_cast<uint64_t>(d);
    uint64_t q = 0, r = 0;
    if (kSlow64BitDivide && ud <= 0xFFFFFFFFu && (un >> 32) < ud) {
        uint32_t r32 = 0;
        q = udiv64_32(un, static_cast<uint32_t>(ud), r32);
        r = r32;
    } else {
        q = un / ud;
        r = un - q * ud;
    }
    if (r >= ud - r) ++q;  // r >= d/2 without overflow: ties go away from zero
    const bool negative = (n < 0) != (d < 0);
    if (!negative) return q > static_cast<uint64_t>(INT64_MAX) ? INT64_MAX : static_cast<int64_t>(q);
    return q > static_cast<uint64_t>(INT64_MAX) ? INT64_MIN : -static_cast<int64_t>(q);
}

/// udiv64_32 behind Divisor32's interface: where the CPU divides 32 bits in one instruction (Cortex-M3,
/// RV32IM), the long division costs about what a prepared reciprocal's multiply and corrections do.
/// Divisors below 2^16 (the area of most triangles a small display draws) skip the normalisation:
/// two 16-bit quotient digits, each one 32-bit division.
class LongDivisor32 {
public:
    explicit constexpr LongDivisor32(uint32_t d) : d_(d) {}
    constexpr uint32_t value() const { return d_; }
    __attribute__((always_inline)) constexpr uint32_t divide(uint64_t n, uint32_t& rem) const {
        if (d_ <= 0xFFFFu) {  // two 16-bit digits, each one 32-bit division (n < d 2^32 < 2^48)
            const uint32_t u1 = (static_cast<uint32_t>(n >> 32) << 16) | (static_cast<uint32_t>(n) >> 16);
            const uint32_t q1 = u1 / d_;
            const uint32_t u0 = ((u1 - q1 * d_) << 16) | (static_cast<uint32_t>(n) & 0xFFFFu);
            const uint32_t q0 = u0 / d_;
            rem = u0 - q0 * d_;
            return (q1 << 16) + q0;
        }
        return udiv64_32(n, d_, rem);
    }

private:
    uint32_t d_;
};

/// The divisor for several 64/32 quotients by one value on this target: a reciprocal where 32-bit
/// division is itself a library call (ARMv6-M: two library divisions saved a quotient), else udiv64_32.
#if defined(HIDER_ARMV6M)
using SharedDivisor32 = Divisor32;
#else
using SharedDivisor32 = LongDivisor32;
#endif

/// div_round(n, d) for d > 0 through one 64/32 quotient of the prepared divisor D (Divisor32 or
/// LongDivisor32): round(|n| / d) = floor((|n| + d / 2) / d). False (out untouched) when the quotient
/// would not fit 32 bits.
template <class D>
constexpr bool div_round_prepared_by_parts(int64_t n, const D& d, int64_t& out) {
    const uint64_t un = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
    const uint64_t m = un + (d.value() >> 1);
    if (m < un || (m >> 32) >= d.value()) return false;
    uint32_t r = 0;
    const int64_t q = d.divide(m, r);
    out = n < 0 ? -q : q;
    return true;
}

/// div_round(n, d.value()) with a prepared divisor D (Divisor32 or LongDivisor32).
template <class D>
constexpr int64_t div_round_prepared(int64_t n, const D& d) {
    int64_t q = 0;
    if (div_round_prepared_by_parts(n, d, q)) return q;
    return div_round(n, int64_t{d.value()});
}

/// n / 2^shift rounded to nearest, ties away from zero (div_round for a power of two, with shifts).
constexpr int64_t div_round_pow2(int64_t n, int shift) {
    const int64_t half = int64_t{1} << (shift - 1);
    return n >= 0 ? (n + half) >> shift : -((-n + half) >> shift);
}

/// floor(n / d) for int32 n and d > 0 (C++ '/' truncates toward zero instead).
__attribute__((always_inline)) constexpr int32_t div_floor32(int32_t n, int32_t d) {
    // One unsigned division (the library's signed divmod costs more on ARMv6-M, which has no divide).
    if (n >= 0) return static_cast<int32_t>(static_cast<uint32_t>(n) / static_cast<uint32_t>(d));
    const uint32_t un = 0u - static_cast<uint32_t>(n);  // floor(-m / d) = -ceil(m / d) = -floor((m + d - 1) / d)
    return static_cast<int32_t>(0u - ((un - 1u) / static_cast<uint32_t>(d) + 1u));  // INT32_MIN / 1 stays defined
}

/// floor(n / d) for d > 0 (exact; C++ '/' truncates toward zero instead).
constexpr int64_t div_floor(int64_t n, int64_t d) {
    const int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

/// Saturates a 64-bit value into int32_t.
constexpr int32_t saturate32(int64_t v) {
    return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : static_cast<int32_t>(v));
}

/// Number of leading zero bits of a 64-bit value (64 for 0), in two clz32 steps.
constexpr int clz64(uint64_t v) {
    const uint32_t hi = static_cast<uint32_t>(v >> 32);
    if (hi != 0) return clz32(hi);
    const uint32_t lo = static_cast<uint32_t>(v);
    return lo != 0 ? 32 + clz32(lo) : 64;
}

namespace detail {
/// floor(sqrt(v)) bit by bit (32 iterations): builds the table below at compile time.
constexpr uint32_t isqrt64_bits(uint64_t v) {
    uint64_t root = 0;
    uint64_t bit = uint64_t{1} << 62;
    while (bit > v) bit >>= 2;
    while (bit != 0) {
        if (v >= root + bit) { v -= root + bit; root = (root >> 1) + bit; }
        else { root >>= 1; }
        bit >>= 2;
    }
    return static_cast<uint32_t>(root);
}

/// 2^15 / sqrt(m) for m the middle of each 1/256-wide bucket of [1/4, 1): entry i is for
/// X / 2^32 in [(64 + i) / 256, (65 + i) / 256). Built at compile time; 384 bytes.
struct RsqrtTable {
    uint16_t v[192];
    constexpr RsqrtTable() : v() {
        // 2^15 / sqrt((2 (64 + i) + 1) / 512) = sqrt(2^30 512 / (2 (64 + i) + 1)), floored.
        for (uint32_t i = 0; i < 192; ++i)
            v[i] = static_cast<uint16_t>(isqrt64_bits((uint64_t{1} << 39) / (2 * (64 + i) + 1)));
    }
};
inline constexpr RsqrtTable kRsqrtTable{};
}  // namespace detail

/// 2^30 / sqrt(x / 2^32) for x in [2^30, 2^32), i.e. 1 / sqrt(X) in Q30 for X = x / 2^32 in [1/4, 1):
/// a result in (2^30, 2^31]. Table start (relative error < 2^-8), then two Newton steps
/// y' = y + y (1 - X y^2) / 2 with rounded intermediates; |relative error| < 2^-29.5, about one LSB of
/// the result (tests/ray/math_test.cpp checks every bucket).
constexpr uint32_t rsqrt_q30(uint32_t x) {
    uint32_t y = uint32_t{detail::kRsqrtTable.v[(x >> 24) - 64]} << 15;
    for (int step = 0; step < 2; ++step) {
        const uint32_t y2_q29 = static_cast<uint32_t>((mul_wide_u(y, y) + (uint64_t{1} << 30)) >> 31);  // y^2 <= 4
        const uint64_t p_q61 = mul_wide_u(x, y2_q29);  // X y^2, about 2^61
        const int64_t e_q61 = static_cast<int64_t>((uint64_t{1} << 61) - p_q61);  // 1 - X y^2
        const int32_t e_q30 = static_cast<int32_t>((e_q61 + (int64_t{1} << 30)) >> 31);
        const int64_t dy = mul_wide(static_cast<int32_t>(y >> 1), e_q30);             // y (1 - X y^2) / 2
        y = static_cast<uint32_t>(static_cast<int64_t>(y) + ((dy + (int64_t{1} << 29)) >> 30));
    }
    return y;
}

/// floor(sqrt(v)) for any 64-bit unsigned v: rsqrt_q30() of the normalised top word gives the root to
/// about 2^-29, then the exact square decides the last unit or two (tests compare it with the
/// bit-by-bit root).
constexpr uint32_t isqrt64(uint64_t v) {
    if (v == 0) return 0;
    const int k = clz64(v) >> 1;                                      // v << 2k in [2^62, 2^64)
    const uint32_t x = static_cast<uint32_t>((v << (2 * k)) >> 32);  // in [2^30, 2^32)
    // sqrt(v << 2k) ~ sqrt(x) 2^16 = x rsqrt(x) 2^16 / 2^46.
    uint64_t s = (mul_wide_u(x, rsqrt_q30(x)) >> 30) >> k;
    if (s > 0xFFFFFFFFu) s = 0xFFFFFFFFu;
    while (s * s > v) --s;
    while (s < 0xFFFFFFFFu && (s + 1) * (s + 1) <= v) ++s;
    return static_cast<uint32_t>(s);
}

/// Signed fixed-point number with F fraction bits held in an int32_t (value = raw / 2^F).
template <int F>
class Fixed {
    static_assert(F > 0 && F < 31, "fraction bits out of range");

public:
    static constexpr int kFracBits = F;
    static constexpr int32_t kOne = int32_t{1} << F;

    constexpr Fixed() = default;
    static constexpr Fixed from_raw(int32_t r) { Fixed x; x.raw_ = r; return x; }
    /// Precondition: i fits the format (|i| < 2^(31-F)).
    static constexpr Fixed from_int(int32_t i) { return from_raw(i * kOne); }
    /// num / den rounded to nearest (ties away from zero), saturating. Precondition: |num| < 2^(63-F).
    static constexpr Fixed from_ratio(int64_t num, int64_t den) {
        return from_raw(saturate32(div_round(num * kOne, den)));
    }
    static constexpr Fixed max() { return from_raw(INT32_MAX); }
    static constexpr Fixed min() { return from_raw(INT32_MIN); }

    constexpr int32_t raw() const { return raw_; }
    /// Largest integer <= value.
    constexpr int32_t floor_int() const { return raw_ >> F; }
    /// Nearest integer, ties toward +inf.
    constexpr int32_t round_int() const { return static_cast<int32_t>((int64_t{raw_} + (kOne >> 1)) >> F); }

    friend constexpr Fixed operator+(Fixed a, Fixed b) { return from_raw(a.raw_ + b.raw_); }
    friend constexpr Fixed operator-(Fixed a, Fixed b) { return from_raw(a.raw_ - b.raw_); }
    friend constexpr Fixed operator-(Fixed a) { return from_raw(-a.raw_); }
    /// Product, floored (toward -inf). Precondition: the result fits the format.
    friend constexpr Fixed operator*(Fixed a, Fixed b) {
        return from_raw(static_cast<int32_t>(mul_shift(a.raw_, b.raw_, F)));
    }
    constexpr Fixed& operator+=(Fixed b) { raw_ += b.raw_; return *this; }
    constexpr Fixed& operator-=(Fixed b) { raw_ -= b.raw_; return *this; }
    friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw_ == b.raw_; }
    friend constexpr bool operator!=(Fixed a, Fixed b) { return a.raw_ != b.raw_; }
    friend constexpr bool operator<(Fixed a, Fixed b) { return a.raw_ < b.raw_; }
    friend constexpr bool operator<=(Fixed a, Fixed b) { return a.raw_ <= b.raw_; }
    friend constexpr bool operator>(Fixed a, Fixed b) { return a.raw_ > b.raw_; }
    friend constexpr bool operator>=(Fixed a, Fixed b) { return a.raw_ >= b.raw_; }

private:
    int32_t raw_ = 0;
};

using Q16 = Fixed<16>;  ///< world and view coordinates, distances
using Q30 = Fixed<30>;  ///< unit vectors, rotation matrices, sin/cos

/// Product a * b, floored; the named form of operator*.
template <int F> constexpr Fixed<F> mul(Fixed<F> a, Fixed<F> b) { return a * b; }

/// Quotient a / b rounded to nearest (ties away from zero); b == 0 or overflow saturates.
template <int F> constexpr Fixed<F> div(Fixed<F> a, Fixed<F> b) {
    return Fixed<F>::from_raw(saturate32(div_round(int64_t{a.raw()} * Fixed<F>::kOne, b.raw())));
}

/// 1 / a rounded to nearest; a == 0 or overflow saturates.
template <int F> constexpr Fixed<F> recip(Fixed<F> a) {
    return Fixed<F>::from_raw(saturate32(div_round(int64_t{Fixed<F>::kOne} * Fixed<F>::kOne, a.raw())));
}

/// floor(sqrt(a)) in the same format; a < 0 gives 0.
template <int F> constexpr Fixed<F> isqrt(Fixed<F> a) {
    if (a.raw() <= 0) return Fixed<F>::from_raw(0);
    return Fixed<F>::from_raw(static_cast<int32_t>(isqrt64(static_cast<uint64_t>(a.raw()) << F)));
}

/// Converts between formats: more fraction bits multiply exactly (saturating), fewer floor.
template <int G, int F> constexpr Fixed<G> fixed_cast(Fixed<F> a) {
    if constexpr (G >= F) {
        return Fixed<G>::from_raw(saturate32(int64_t{a.raw()} * (int64_t{1} << (G - F))));
    } else {
        return Fixed<G>::from_raw(a.raw() >> (F - G));
    }
}

}  // namespace hider

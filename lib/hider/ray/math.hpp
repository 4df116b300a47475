// Integer helpers of the ray tracer: unit vectors in Q30 from fixed.hpp's reciprocal square root (a few
// dozen instructions where a 32x32->64 multiply is one instruction, Cortex-M3 and RV32IM, no division)
// and the mixed-format dot products rays use (Q30 directions, Q16 positions). See CONVENTIONS.md.
#pragma once
#include <hider/vec.hpp>

namespace hider::ray {

/// Number of significant bits of v (0 for 0).
constexpr int bit_length64(uint64_t v) { return 64 - clz64(v); }

namespace detail {
/// round(|c| 2^e r / 2^31) with c's sign, for |c| < 2^30 and e in {0, 1}: one unsigned 32x32->64
/// product (r may be 2^31) and a constant shift.
__attribute__((always_inline)) constexpr int32_t scale_rounded(int32_t c, uint32_t r, int e) {
    const uint32_t m = static_cast<uint32_t>(c < 0 ? -int64_t{c} : int64_t{c}) << e;
    const int32_t v = static_cast<int32_t>((mul_wide_u(m, r) + (uint64_t{1} << 30)) >> 31);
    return c < 0 ? -v : v;
}
}  // namespace detail

/// The unit vector of (x, y, z) in Q30, each component within 2 LSB of the exact quotient (tested):
/// the largest component is scaled into [2^29, 2^30) first, so the precision does not depend on the
/// length. With `length`, also |(x, y, z)| in the components' units, within 1 + 2^-28 relative (the
/// same reciprocal root gives it). Returns false (out untouched) for the zero vector.
/// Precondition: |components| < 2^31.
__attribute__((always_inline)) constexpr bool unit_q30(int32_t x, int32_t y, int32_t z, Vec3q30& out,
                                                      uint32_t* length = nullptr) {
    const uint32_t ax = static_cast<uint32_t>(x < 0 ? -int64_t{x} : int64_t{x});
    const uint32_t ay = static_cast<uint32_t>(y < 0 ? -int64_t{y} : int64_t{y});
    const uint32_t az = static_cast<uint32_t>(z < 0 ? -int64_t{z} : int64_t{z});
    const uint32_t m = max(ax, max(ay, az));
    if (m == 0) return false;
    const int shift = clz32(m) - 2;  // m << shift in [2^29, 2^30); -1 or -2 for m >= 2^30
    if (shift >= 0) {
        x = static_cast<int32_t>(static_cast<uint32_t>(x) << shift);
        y = static_cast<int32_t>(static_cast<uint32_t>(y) << shift);
        z = static_cast<int32_t>(static_cast<uint32_t>(z) << shift);
    } else {
        x >>= -shift;
        y >>= -shift;
        z >>= -shift;
    }
    const uint64_t len2 = static_cast<uint64_t>(mul_wide(x, x)) + static_cast<uint64_t>(mul_wide(y, y)) +
                          static_cast<uint64_t>(mul_wide(z, z));  // [2^58, 3 2^60]
    // The top word of len2 normalised into [2^30, 2^32): len2 << 2k >> 32 for k = 1 or 2 (constant shifts).
    const bool big = (len2 >> 60) != 0;
    const uint32_t top = static_cast<uint32_t>(big ? len2 >> 30 : len2 >> 28);
    const uint32_t r = rsqrt_q30(top);
    // c / sqrt(len2) in Q30 = c r 2^k / 2^32 = (c 2^(k - 1)) r / 2^31, rounded.
    const int e = big ? 0 : 1;
    out = {Q30::from_raw(detail::scale_rounded(x, r, e)), Q30::from_raw(detail::scale_rounded(y, r, e)),
           Q30::from_raw(detail::scale_rounded(z, r, e))};
    if (length != nullptr) {  // sqrt(len2) = sqrt(top 2^32) / 2^k = top r / 2^(30 + k), then undo the shift
        const uint32_t root = static_cast<uint32_t>(mul_wide_u(top, r) >> 31) >> e;
        *length = shift >= 0 ? root >> shift : root << -shift;
    }
    return true;
}

/// Dot product of two Q30 vectors, exact, in Q60.
__attribute__((always_inline)) constexpr int64_t dot_q60(const Vec3q30& a, const Vec3q30& b) {
    return mul_wide(a.x.raw(), b.x.raw()) + mul_wide(a.y.raw(), b.y.raw()) + mul_wide(a.z.raw(), b.z.raw());
}

/// Dot product of a Q30 direction and a Q16 vector, exact, in Q46 (|v| < 2^30 raw: below 3 2^60).
__attribute__((always_inline)) constexpr int64_t dot_q46(const Vec3q30& d, const Vec3q16& v) {
    return mul_wide(d.x.raw(), v.x.raw()) + mul_wide(d.y.raw(), v.y.raw()) + mul_wide(d.z.raw(), v.z.raw());
}

/// Q46 to Q16, rounded to nearest (add half, shift: ties toward +inf). Precondition: fits int32.
constexpr int32_t round_q46_to_q16(int64_t v) { return static_cast<int32_t>((v + (int64_t{1} << 29)) >> 30); }

/// p + t d for a Q16 point, a Q16 distance and a Q30 direction, each component rounded to nearest.
constexpr Vec3q16 point_along(const Vec3q16& p, int32_t t_q16, const Vec3q30& d) {
    return {Q16::from_raw(p.x.raw() + round_q46_to_q16(mul_wide(t_q16, d.x.raw()))),
            Q16::from_raw(p.y.raw() + round_q46_to_q16(mul_wide(t_q16, d.y.raw()))),
            Q16::from_raw(p.z.raw() + round_q46_to_q16(mul_wide(t_q16, d.z.raw())))};
}

/// Mirror direction r = d - 2 (d.n) n for a unit normal n (Whitted 1980), Q30, d.n rounded once. The
/// product 2 (d.n) n reaches 2^31 for d = -n along an axis (a unit component may be 2^30 + 1): it is
/// subtracted in 64 bits, and each component of r, a unit vector's, fits again.
constexpr Vec3q30 reflect(const Vec3q30& d, const Vec3q30& n) {
    const int32_t dn_q30 = static_cast<int32_t>((dot_q60(d, n) + (int64_t{1} << 29)) >> 30);
    auto comp = [dn_q30](Q30 dc, Q30 nc) {
        return Q30::from_raw(static_cast<int32_t>(dc.raw() - ((mul_wide(dn_q30, nc.raw()) + (int64_t{1} << 28)) >> 29)));
    };
    return {comp(d.x, n.x), comp(d.y, n.y), comp(d.z, n.z)};
}

}  // namespace hider::ray

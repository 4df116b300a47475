// The eye's side of a BSP node's plane, exact: a 32-bit filter, then 128-bit products. Shared by the
// walks (walk.hpp, order.hpp) and the cell lookup (cells.hpp).
#pragma once
#include <hider/bsp/load.hpp>
#include <hider/int128.hpp>

namespace hider {

namespace detail {

/// True when -2^bits <= v < 2^bits.
constexpr bool fits_bits(int64_t v, int bits) {
    return static_cast<uint64_t>(v + (int64_t{1} << bits)) < (uint64_t{2} << bits);
}

/// fits_bits() for int32 values, kBits < 31.
template <int kBits>
constexpr bool fits_bits32(int32_t v) {
    static_assert(kBits > 0 && kBits < 31, "an int32 range narrower than int32's");
    return static_cast<uint32_t>(v) + (uint32_t{1} << kBits) < (uint32_t{2} << kBits);
}

/// |v| as unsigned (exact for INT32_MIN too).
constexpr uint32_t unsigned_abs(int32_t v) { return v < 0 ? 0u - static_cast<uint32_t>(v) : static_cast<uint32_t>(v); }

/// 32 x 32 -> 64-bit product (one instruction where the CPU has it).
constexpr int64_t mul32(int32_t a, int32_t b) { return int64_t{a} * b; }

/// n . (p - origin) of node n's plane at point p, exact (bsp_load() keeps |n_i| < 2^62 and points within
/// 2^31, so the three products and their sum fit 128 bits).
inline Int128 plane_value(const BspTree& tree, const BspNode& n, const Vec3q16& p) {
    const Vec3q16& o = tree.vertices[n.origin];
    return mul128(n.n[0], int64_t{p.x.raw()} - o.x.raw()) + mul128(n.n[1], int64_t{p.y.raw()} - o.y.raw()) +
           mul128(n.n[2], int64_t{p.z.raw()} - o.z.raw());
}

/// The eye's side of node n's plane: +1 front (the normal's side), -1 back, 0 in the plane. Exact. A
/// filter first: with n = 2^27 h + r (0 <= r < 2^27) and d = eye - origin, n.d = 2^27 (h.d) + r.d where
/// |r.d| < 3 2^27 max|d|, so when |h.d| > 3 max|d| its sign is the answer. In 32-bit arithmetic for an eye
/// within 2^30 (the origin lies within 2^27, bsp_load() checks it, so |d| < 2^31) and |h| < 2^30 (|n| <
/// 2^57: every plane through grid vertices); otherwise, or with the eye near the plane, the 128-bit
/// product decides.
inline int eye_side(const BspTree& tree, const BspNode& n, const Vec3q16& eye) {
    const Vec3q16& o = tree.vertices[n.origin];
    const int32_t e0 = eye.x.raw(), e1 = eye.y.raw(), e2 = eye.z.raw();
    // h = n >> 27 from the words of n: |n| < 2^57 when its high word is within 2^25.
    auto high_fits = [](int64_t v) { return fits_bits32<25>(static_cast<int32_t>(v >> 32)); };
    auto h = [](int64_t v) { return static_cast<int32_t>(static_cast<uint64_t>(v) >> 27); };
    if (fits_bits32<30>(e0) && fits_bits32<30>(e1) && fits_bits32<30>(e2) && high_fits(n.n[0]) && high_fits(n.n[1]) &&
        high_fits(n.n[2])) {
        const int32_t d0 = e0 - o.x.raw(), d1 = e1 - o.y.raw(), d2 = e2 - o.z.raw();
        const int64_t s = mul32(h(n.n[0]), d0) + mul32(h(n.n[1]), d1) + mul32(h(n.n[2]), d2);
        const int64_t bound = 3 * int64_t{max(unsigned_abs(d0), max(unsigned_abs(d1), unsigned_abs(d2)))};
        if (s > bound) return 1;
        if (s < -bound) return -1;
    }
    return plane_value(tree, n, eye).sign();
}

}  // namespace detail

}  // namespace hider

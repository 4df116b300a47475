// The floating-horizon plotter's description of a surface (a grid of integer heights in world units),
// the homogeneous screen coordinates of its points, and the small exact-integer helpers project.hpp's
// setup and per-point paths use.
#pragma once
#include <hider/fixed.hpp>
#include <hider/horizon/point.hpp>
#include <hider/int128.hpp>

namespace hider::horizon {

/// Where the samples lie. Heights are integers of any type; world y (Q16 raw) = value * y_unit_raw.
struct Surface {
    int32_t samples = 0;  ///< points per curve, >= 2
    int32_t curves = 0;   ///< curves, >= 2
    Q16 x0{}, dx{};       ///< sample i at x = x0 + i dx, dx > 0
    Q16 z0{}, dz{};       ///< curve k at z = z0 + k dz, dz > 0 (curve index grows with z)
    int32_t value_min = 0, value_max = 0;  ///< every height value lies here; others are clamped (and counted)
    int32_t y_unit_raw = 1;                ///< world y per value unit, Q16 raw (1: values are Q16 heights)
};

/// Homogeneous screen coordinates of a surface point, each in its own per-frame scale.
struct HomPoint {
    int32_t u, v, w;
};

/// Which planes a plot sweeps in order of distance from the eye: the curves z = const (their lines run
/// along x), or, when x runs into the picture (seen from the side), the planes x = const.
enum class Sweep : uint8_t { curves, x_lines };

/// What projecting one curve found besides its points.
struct RowCounts {
    uint32_t behind = 0;          ///< samples in front of the near plane's far side (no point)
    uint32_t values_clamped = 0;  ///< heights outside [value_min, value_max]
    uint32_t points_clamped = 0;  ///< projections beyond kPointLimit
};

namespace detail {
template <class A, class B> struct is_same_type { static constexpr bool value = false; };
template <class A> struct is_same_type<A, A> { static constexpr bool value = true; };

/// Number of significant bits of |x|.
inline int bit_length(const Int128& x) {
    const Int128 a = x.sign() < 0 ? -x : x;
    const uint64_t hi = static_cast<uint64_t>(a.hi);
    if (hi != 0) return 128 - clz64(hi);
    return 64 - clz64(a.lo);
}

/// round(x / 2^s) (ties toward +inf) for 0 <= s <= 120; the result must fit int64.
inline int64_t round_shift(const Int128& x, int s) {
    if (s == 0) return static_cast<int64_t>(x.lo);
    Int128 half;
    if (s <= 64) half.lo = uint64_t{1} << (s - 1);
    else half.hi = int64_t{1} << (s - 65);
    const Int128 y = x + half;
    if (s < 64) return static_cast<int64_t>(y.shr(s).lo);
    return y.hi >> (s - 64);  // s == 64: the high word itself
}

/// c . p + c0 2^30 for a world point p (raw Q16).
struct Form {
    int64_t c[3] = {0, 0, 0};
    int64_t c0 = 0;
    Int128 at(int64_t x, int64_t y, int64_t z) const {
        return mul128(c0, int64_t{1} << 30) + mul128(c[0], x) + mul128(c[1], y) + mul128(c[2], z);
    }
};

/// a + (b - a) t for t in [0, 2^16] (Q16).
inline HomPoint lerp(const HomPoint& a, const HomPoint& b, int32_t t_q16) {
    auto mix = [t_q16](int32_t p, int32_t q) {
        return p + static_cast<int32_t>((int64_t{q - p} * t_q16) >> 16);
    };
    return {mix(a.u, b.u), mix(a.v, b.v), mix(a.w, b.w)};
}

/// A height of type T as int32_t, saturated: a value of a wider type (int64_t) or an unsigned 32-bit one
/// beyond int32 becomes INT32_MIN or INT32_MAX, which the range check then clamps and counts (a plain
/// cast wrapped it into the declared range, drawn there with status ok).
template <class T>
constexpr int32_t height_value(T v) {
    if constexpr (static_cast<T>(-1) < 0) {
        if constexpr (sizeof(T) <= sizeof(int32_t)) return static_cast<int32_t>(v);
        else return v < INT32_MIN ? INT32_MIN : v > INT32_MAX ? INT32_MAX : static_cast<int32_t>(v);
    } else {
        if constexpr (sizeof(T) < sizeof(int32_t)) return static_cast<int32_t>(v);
        else return v > static_cast<T>(INT32_MAX) ? INT32_MAX : static_cast<int32_t>(v);
    }
}

/// Whether every value of T lies in [value_min, value_max] (no clamping needed).
template <class T>
constexpr bool in_type_range(int32_t value_min, int32_t value_max) {
    if constexpr (sizeof(T) > 2) {
        return false;
    } else {
        constexpr int32_t lo = static_cast<T>(-1) < 0 ? -(int32_t{1} << (8 * sizeof(T) - 1)) : 0;
        constexpr int32_t hi = static_cast<T>(-1) < 0 ? (int32_t{1} << (8 * sizeof(T) - 1)) - 1 : (int32_t{1} << (8 * sizeof(T))) - 1;
        return value_min <= lo && value_max >= hi;
    }
}

/// scale16(u, r, s) for any s (points very close to the near plane, or a far-off surface), clamped
/// to +-kPointLimit.
inline int32_t scale_slow(int32_t u, uint32_t r, int s, RowCounts& counts) {
    const int64_t p = int64_t{u >> 14} * r;
    if (s > 62) return p < 0 ? -1 : 0;
    int64_t q;
    if (s >= 0) {
        q = p >> s;
    } else {
        const int64_t room = int64_t{kPointLimit} >> min(-s, 40);
        q = (p >= room || p <= -room) ? (p < 0 ? -int64_t{kPointLimit} - 1 : int64_t{kPointLimit} + 1) : p * (int64_t{1} << -s);
    }
    if (q > kPointLimit || q < -kPointLimit) {
        ++counts.points_clamped;
        return q < 0 ? -kPointLimit : kPointLimit;
    }
    return static_cast<int32_t>(q);
}

}  // namespace detail

}  // namespace hider::horizon

// Floating horizons (Wright 1973; Rogers, "Procedural Elements", s. 4-2) over caller memory. Per
// column, `upper` is the topmost and `lower` the bottommost row any earlier curve reached (row 0 on
// top, so upper <= lower once set); a pixel of a later curve is visible above upper or below lower.
// Rows are stored clamped to [-1, height], which keeps every comparison with rows of the frame exact.
// Also the two small tables the drawer (drawer.hpp) uses: the slope reciprocals and the height ramp.
#pragma once
#include <hider/fixed.hpp>
#include <hider/frame.hpp>
#include <hider/horizon/point.hpp>
#include <hider/status.hpp>

namespace hider::horizon {

/// Upper and lower horizon, one int16 per column each, in caller memory. Build with make_horizon().
struct Horizon {
    int16_t* upper = nullptr;
    int16_t* lower = nullptr;
    int32_t width = 0, height = 0;
};

/// Views `upper` and `lower` (at least `width` entries each) as the horizons of a width x height frame
/// and resets them. invalid_argument for short or missing arrays or a size outside 1..kMaxFrameSide.
inline Status make_horizon(Span<int16_t> upper, Span<int16_t> lower, int32_t width, int32_t height, Horizon& out) {
    if (width < 1 || height < 1 || width > kMaxFrameSide || height > kMaxFrameSide) return Status::invalid_argument;
    if (upper.data() == nullptr || lower.data() == nullptr || upper.size() < static_cast<size_t>(width) ||
        lower.size() < static_cast<size_t>(width))
        return Status::invalid_argument;
    out = {upper.data(), lower.data(), width, height};
    for (int32_t c = 0; c < width; ++c) {
        out.upper[c] = INT16_MAX;  // nothing drawn yet: every row is above the upper horizon...
        out.lower[c] = INT16_MIN;  // ...and below the lower one
    }
    return Status::ok;
}

/// Forgets every curve drawn (another plot, or a pass that nothing before can hide).
inline void reset(const Horizon& h) {
    for (int32_t c = 0; c < h.width; ++c) {
        h.upper[c] = INT16_MAX;
        h.lower[c] = INT16_MIN;
    }
}

namespace detail {
/// ceil(2^24 / d) for d in [1, 256): t = (b - a) * kSlope[d] >> 9 is (b - a) / d in Q15, exactly 2^15 at
/// b - a = d and never above it. 1 KB of flash; saves a division per column boundary (a library call
/// on ARMv6-M) for segments shorter than 16 pixels, which is nearly all of them in a dense plot.
struct SlopeTable {
    uint32_t v[256];
    constexpr SlopeTable() : v() {
        for (uint32_t d = 1; d < 256; ++d) v[d] = ((uint32_t{1} << 24) + d - 1) / d;
    }
};
inline constexpr SlopeTable kSlope{};
}  // namespace detail

/// Maps a height value to a colour of a ramp of at most 256: ramp[(v - v_min) size / (v_max - v_min + 1)]
/// (clamped), the quotient from a scale made once (make_ramp), so a drawn run costs one 32-bit product.
struct ValueRamp {
    Span<const Rgb> ramp;
    int32_t v_min = 0, v_max = 0;
    int shift = 0;      ///< (v - v_min) >> shift is below 2^12
    uint32_t mul = 0;   ///< ceil(size 2^20 / reduced span)

    Rgb operator()(int32_t v) const {
        // clamped at both ends: a value past v_max (a height the plot clamps) overflowed the product
        const uint32_t t = static_cast<uint32_t>(clamp(v, v_min, v_max)) - static_cast<uint32_t>(v_min);
        const uint32_t i = ((t >> shift) * mul) >> 20;
        return ramp[min<size_t>(i, ramp.size() - 1)];
    }
};

/// The ramp for values in [v_min, v_max]. Precondition: 1 <= ramp.size() <= 256.
inline ValueRamp make_ramp(Span<const Rgb> ramp, int32_t v_min, int32_t v_max) {
    ValueRamp r;
    r.ramp = ramp;
    r.v_min = v_min;
    r.v_max = v_max;
    uint32_t span = static_cast<uint32_t>(v_max) - static_cast<uint32_t>(v_min);  // + 1 below, after the shift
    while ((span >> r.shift) >= (uint32_t{1} << 12)) ++r.shift;
    span = (span >> r.shift) + 1;
    r.mul = static_cast<uint32_t>(((uint64_t{ramp.size()} << 20) + span - 1) / span);  // t / span < 1: t mul < 2^28
    return r;
}

}  // namespace hider::horizon

// A point of a floating-horizon plot in screen space: 1/16 pixel from the frame's top-left corner.
#pragma once
#include <hider/base.hpp>

namespace hider::horizon {

constexpr int kPointFracBits = 4;                   ///< PlotPoint coordinates carry 4 fraction bits
constexpr int32_t kPointLimit = int32_t{1} << 24;   ///< |x|, |y| of a PlotPoint (projection clamps)
constexpr int32_t kNoPoint = INT32_MIN;             ///< PlotPoint::x of a point behind the near plane

/// A projected point: x, y in 1/16 pixel from the frame's top-left corner; pixel (c, r) covers
/// [16c, 16c + 16) x [16r, 16r + 16). x == kNoPoint marks a point that has no projection.
struct PlotPoint {
    int32_t x, y;
};

}  // namespace hider::horizon

// The length of a 3-vector of doubles, without the overflow and underflow of squaring (|v| near 1e154 or
// 1e-162), computed the same way by every C++ library. std::hypot(x, y, z) is not: libstdc++ scales by
// the largest component, libc++ (the web build's, macOS's) squares, so a model near those extremes
// rendered natively and failed or differed in the browser. This is libstdc++'s formula, so the native
// tools' results did not move.
#pragma once
#include <cmath>

namespace hider::tool {

inline double hypot3(double x, double y, double z) {
    x = std::fabs(x);
    y = std::fabs(y);
    z = std::fabs(z);
    const double a = x < y ? (y < z ? z : y) : (x < z ? z : x);
    if (!(a > 0.0)) return a == 0.0 ? 0.0 : a;  // zero, or NaN
    const double u = x / a, v = y / a, w = z / a;
    return a * std::sqrt(u * u + v * v + w * w);
}

}  // namespace hider::tool

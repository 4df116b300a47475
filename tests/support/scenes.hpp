// Deterministic hard scenes for checking hider against the double reference (support/reference.hpp).
// Random scenes draw from std::mt19937 through our own mapping (no std::*_distribution), ids run 1..n.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "support/reference.hpp"

namespace hider::ref {

struct RefScene {
    std::vector<RefTriangle> tris;
    RefCamera cam;     // 320x240, fovy 60
    std::string name;  // kind plus seed and count, for failure messages
};

/// `count` random interpenetrating triangles of mixed sizes (0.02..0.8) in the cube [-1, 1]^3, seen from outside.
RefScene soup(uint32_t seed, int count);

/// `count` long thin triangles (length 1.2..2.2, altitude/length 1/200 to 1/1000) crossing near the origin.
RefScene slivers(uint32_t seed, int count);

/// 32 triangles, eye at the origin looking down -Z: six random triangles hundreds of units across, a floor and a
/// tilted wall that cross the near plane (0.5) and pass behind the eye, and 24 small ones at d in [2, 8].
RefScene huge_triangles(uint32_t seed);

/// Three thin bars (12 triangles each, ids 1-12, 13-24, 25-36), each lying over the next where they cross: a cycle.
RefScene cyclic_bars();

/// Five triangles: two large ones crossing through each other (ids 1, 2), a quad (3, 4) pierced by a triangle (5).
RefScene piercing();

/// `count` interpenetrating closed boxes (12 triangles each, outward CCW winding) around the origin.
RefScene boxes(uint32_t seed, int count);

}  // namespace hider::ref

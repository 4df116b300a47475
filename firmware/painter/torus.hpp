// The painter examples' scene and storage: the baked torus at 160x128 (firmware/common/scenes/) with a
// polygon pool of its 1000 triangles plus 256 for Newell's cuts. RAM: pool 80,384 B + order 5,024 B +
// sort keys 2 x 10,048 B + vertex cache 6,000 B + colour band 5,120 B + coverage 320 B + PPM row 480 B.
#pragma once
#include "common/scenes/torus_160x128.hpp"
#include "painter/app.hpp"

namespace painter {

namespace torus = hider::scenes::torus_160x128;

/// Polygon pool: every triangle of the mesh (the torus is not clipped) plus room for cuts.
constexpr size_t kPolyCapacity = torus::kTriangleCount + 256;

using TorusStorage = Storage<torus::kVertexCount, kPolyCapacity, torus::kWidth>;

inline spin::Scene torus_scene() { return {torus::kCamera, torus::kWidth, torus::kHeight, torus::mesh()}; }

}  // namespace painter

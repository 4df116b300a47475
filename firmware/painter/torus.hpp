// The painter examples' scene and storage: the baked torus at 160x128 (firmware/common/scenes/) with a
// polygon pool of its 1000 triangles plus 256 for Newell's cuts (painter/app.hpp Storage; the sizes are
// in README.md's memory table).
#pragma once
#include "common/scenes/torus_160x128.hpp"
#include "painter/app.hpp"

namespace painter {

namespace torus = hider::scenes::torus_160x128;

/// Polygon pool: every triangle of the mesh (the torus is not clipped) plus room for cuts.
constexpr size_t kCutRoom = 256;
constexpr size_t kPolyCapacity = torus::kTriangleCount + kCutRoom;

using TorusStorage = Storage<torus::kVertexCount, kPolyCapacity, kCutRoom, torus::kWidth, torus::kHeight>;

inline spin::Scene torus_scene() { return {torus::kCamera, torus::kWidth, torus::kHeight, torus::mesh()}; }

}  // namespace painter

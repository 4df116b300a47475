// The BSP examples' scenes and storage (bsp/app.hpp): the torus at 160x128 without back-face culling in
// 16-row bands from one walk's draw list (its tree from tests/data/models/torus.obj), and the city seen from street level
// (tests/data/scenes/city-1-16-16-street.obj, culled, full frame) as a tree and as the z-buffered mesh.
#pragma once
#include "bsp/app.hpp"
#include "common/scenes/bsp_city_street_160x128.hpp"
#include "common/scenes/bsp_torus_160x128.hpp"
#include "common/scenes/city_street_160x128.hpp"

namespace bspfw {

namespace torus_tree = hider::bsp_data::bsp_torus_160x128;
namespace city_tree = hider::bsp_data::bsp_city_street_160x128;
namespace city_mesh = hider::scenes::city_street_160x128;

/// Rows per band of the torus: 160 x 16 RGB565 = 5 KB of colour, 8 bands.
constexpr int32_t kTorusRows = 16;

/// The torus's draw list holds at most one entry per node (order_bsp).
using TorusStorage =
    Storage<torus_tree::kVertexCount, torus_tree::kMaxDepth, torus_tree::kWidth, kTorusRows, false, false, torus_tree::kNodeCount>;
using CityStorage = Storage<city_tree::kVertexCount, city_tree::kMaxDepth, city_tree::kWidth, city_tree::kHeight, false, true>;
using CityZStorage = Storage<city_mesh::kVertexCount, 1, city_mesh::kWidth, city_mesh::kHeight, true, false>;

inline Scene torus_scene() {
    return {{torus_tree::kBlob, sizeof torus_tree::kBlob}, {}, torus_tree::kCamera, torus_tree::kWidth, torus_tree::kHeight, false};
}
inline Scene city_scene() {
    return {{city_tree::kBlob, sizeof city_tree::kBlob}, {}, city_tree::kCamera, city_tree::kWidth, city_tree::kHeight, true};
}
inline Scene city_mesh_scene() { return {{}, city_mesh::mesh(), city_mesh::kCamera, city_mesh::kWidth, city_mesh::kHeight, true}; }

}  // namespace bspfw

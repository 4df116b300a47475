// Host builder of lib/hider/ray/bvh.hpp's flat hierarchy: binned surface-area heuristic (16 bins on the
// axis of widest centroid spread, Wald 2007), leaves of at most kMaxLeaf triangles where a split pays,
// boxes exact in raw Q16 (the min and max of the vertices), nodes in pre-order. Deterministic.
#pragma once
#include <hider/ray/bvh.hpp>

#include <string>
#include <vector>

namespace hider::tool {

/// A hierarchy built on the host: owns its arrays; view() lends them to lib/.
struct BakedBvh {
    ray::BvhHeader header{};
    std::vector<ray::BvhNode> nodes;
    std::vector<uint32_t> triangles;

    ray::Bvh view() const { return {header, {nodes.data(), nodes.size()}, {triangles.data(), triangles.size()}}; }
};

struct BvhBuildOptions {
    uint32_t max_leaf = 4;   ///< a leaf holds at most this many triangles unless no split separates them
    uint16_t max_depth = 48; ///< deeper subtrees become one leaf (the walk's stack needs this many entries)
};

/// Builds the hierarchy of `mesh` (every index in range: check with validate() first). False with a
/// reason for an empty mesh. The result passes validate_bvh() with a stack of header.max_depth entries.
bool build_bvh(const Mesh& mesh, BakedBvh& out, std::string& error, const BvhBuildOptions& options = {});

}  // namespace hider::tool

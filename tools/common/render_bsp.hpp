// Host driver of the BSP walks (hider-render --algo bsp / bsp-front): the tree from a blob or built from
// the scene, vertex projection once per frame, then draw_bsp / draw_bsp_front per band.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/bsp_build.hpp"
#include "common/render.hpp"

namespace hider::tool {

/// Draws `scene`'s camera view of the tree in `blob` (or, when blob is empty, of a tree built from the
/// scene's own triangles with the default heuristic) with opt.algo bsp or bsp_front.
bool render_bsp(const Scene& scene, const std::vector<uint8_t>& blob, const RenderOptions& opt, RenderResult& out,
                std::string& error);

/// What bsp_load() refused in a blob, for a message: "checksum mismatch (corrupted)", "another BSP format
/// version (1; this hider reads 2): rebuild it with hider-bsp", "invalid node 17 (status bad data)".
std::string bsp_load_message(Status s, const BspLoadInfo& info);

/// A blob copied to 8-byte aligned memory (the walks read it in place).
class AlignedBlob {
public:
    explicit AlignedBlob(const std::vector<uint8_t>& bytes);
    Span<const uint8_t> span() const { return {reinterpret_cast<const uint8_t*>(words_.data()), size_}; }

private:
    std::vector<uint64_t> words_;
    size_t size_;
};

}  // namespace hider::tool

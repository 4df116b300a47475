// Host drivers of lib/hider/ray/: hider-render's --algo raycast for OBJ scenes (BVH built here, face
// shading like the other algorithms) and --scene for ray-traced text scenes, band by band like the
// z-buffer driver, into RGB888 bytes (render.hpp's RenderResult).
#pragma once
#include "common/ray_scene.hpp"
#include "common/render.hpp"

namespace hider::tool {

/// Ray casts `scene` (Shade::headlight or Shade::id) with a BVH built for its mesh. False with a
/// reason for an unusable option (depth shading) or a mesh lib/ rejects.
bool render_raycast(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error);

/// Ray traces `scene` at width x height in opt.format, opt.band_rows rows at a time (0: all).
bool render_ray_scene(const RayScene& scene, int width, int height, const RenderOptions& opt, RenderResult& out,
                      std::string& error);

}  // namespace hider::tool

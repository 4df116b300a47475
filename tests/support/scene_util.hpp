// Test glue between hider's fixed-point scenes and the double reference: the reference always sees the
// exact values hider works with (fixed positions and camera), so agreement tests measure the renderer.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/render.hpp"
#include "common/scene.hpp"
#include "support/reference.hpp"
#include "support/scenes.hpp"

namespace hider::test {

/// Builds a hider Scene from a generated reference scene (same ids, same camera); false + reason on failure.
bool scene_from_ref(const ref::RefScene& in, tool::Scene& out, std::string& error);

/// Loads tests/data/models/<name> with default framing at width x height (or a given camera).
tool::Scene load_model(const std::string& name, const tool::CameraArgs& cam = {});

/// The triangles and camera exactly as hider sees them, in double.
std::vector<ref::RefTriangle> ref_triangles(const tool::Scene& s);
ref::RefCamera ref_camera(const tool::Scene& s);

/// Generated reference scenes as hider sees them (scene_from_ref, REQUIREd), with their names.
std::vector<std::pair<std::string, tool::Scene>> scenes_from_ref(const std::vector<ref::RefScene>& scenes);

/// The face-id frame (RGB888, Shade::id; decode with tool::decode_ids) of one algorithm, REQUIREd to render.
tool::RenderResult render_ids(const tool::Scene& s, tool::Algo algo, bool cull, int depth_bits = 32, int band = 0);

/// Face-id image rendered by hider (z-buffer) for the scene.
std::vector<uint32_t> hider_ids(const tool::Scene& s, bool cull, int depth_bits = 16);

/// How many triangles cover each pixel centre (pipeline projection and clipping, rasterizer coverage,
/// no depth test). Both windings count unless cull is set.
std::vector<int> coverage_counts(const tool::Scene& s, bool cull);

/// What an algorithm's face-id image gets wrong where the z-buffer's shows a surface.
struct Defects {
    long holes = 0;   ///< inside the z-buffer's silhouette (the pixel and its 8 neighbours covered), empty here
    long cracks = 0;  ///< inside a face's area (all 8 neighbours show it in the z-buffer), another face here
};
Defects count_defects(const std::vector<uint32_t>& ids, const std::vector<uint32_t>& zbuffer_ids, int width, int height);

/// A generated scene (tools/common/gen_scenes.hpp) as hider sees it, faces kept whole.
tool::Scene generated_scene(const std::string& name);

/// Appends triangle a, b, c (0-based vertex indices, counter-clockwise seen from its front) to m, with
/// the next face id.
void add_face(tool::ObjModel& m, int a, int b, int c);

/// A closed UV sphere of `slices` x `stacks` (poles as fans, outward faces), framed by build_scene() at
/// width x height from the default camera: a convex surface, whose every plane has all others behind it.
tool::Scene uv_sphere(int slices, int stacks, int width, int height);

/// Writes an RGB888 image as a PNG-free PPM for inspection of failures (into HIDER_TEST_OUT).
void dump_ppm(const std::string& name, int width, int height, const std::vector<uint8_t>& rgb);

}  // namespace hider::test

// Host driver shared by hider-render, hider-bench and the tests: runs lib/ on a Scene with one of the
// algorithms, in one piece or band by band, and returns the frame as RGB888 bytes plus statistics.
#pragma once
#include <hider/raster/zbuffer.hpp>
#include <hider/sort/newell.hpp>
#include <hider/sort/painter.hpp>
#include <hider/sort/reverse.hpp>

#include <string>
#include <vector>

#include "common/scene.hpp"

namespace hider::tool {

enum class Algo { zbuffer, painter, newell, reverse, raycast, bsp, bsp_front };
enum class PixelFormat { rgb565, rgb888, grey8 };

/// Largest room for Newell's cuts the tools give or try (polygons).
constexpr size_t kMaxSplitPool = size_t{1} << 24;
/// The most words of NewellScratch::reorders hider-render tries before it gives up naming a size.
constexpr size_t kMaxReorders = size_t{1} << 16;

/// The room for cuts hider-render gives Newell by default for a mesh of `triangles` triangles.
size_t default_split_pool(size_t triangles);

/// Names accepted by --algo, in order, comma-separated (for messages).
std::string algo_names();
bool parse_algo(const std::string& name, Algo& out);

struct RenderOptions {
    Algo algo = Algo::zbuffer;
    Shade shade = Shade::headlight;
    bool cull = true;
    int depth_bits = 16;  ///< 16 or 32
    int band_rows = 0;    ///< 0 = whole frame at once
    bool window = false;  ///< zbuffer: draw only the frame's centred column window (centred_window()), background outside
    PixelFormat format = PixelFormat::rgb565;
    Rgb background{0, 0, 0};
    Rgb base{255, 255, 255};
    DepthKey painter_key = DepthKey::farthest;  ///< painter only
    size_t split_pool = 0;  ///< newell/reverse: extra polygons for cuts; 0 = default_split_pool()
    size_t reorders = kNewellReorders;  ///< newell/reverse: words of NewellScratch::reorders (two a pair)
};

/// What the ray caster or ray tracer did (render_ray.hpp).
struct RayCounts {
    uint64_t rays = 0, hits = 0, shadow_rays = 0;
    uint64_t boxes = 0, triangles = 0;  ///< BVH box and triangle tests
};

struct RenderResult {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  ///< width * height * 3, row 0 first
    FrameStats stats;
    uint32_t pixels_covered = 0;  ///< distinct pixels written at least once
    NewellStats newell;           ///< newell and reverse only
    size_t polygons = 0;          ///< object-space algorithms: polygons drawn after cuts
    size_t pool = 0;              ///< newell and reverse: the room for cuts it had (polygons)
    size_t pool_needed = 0;       ///< when cuts were dropped: the room that would have held them (0: more than kMaxSplitPool)
    size_t reorders_needed = 0;   ///< when pairs were unresolved: the reorders words that resolve them all (0: none
                                  ///< up to reorders_tried does; some pair is a piercing one no line cuts)
    size_t reorders_tried = 0;    ///< the most reorders words a sizing run had
    RayCounts ray;                ///< raycast and ray-traced scenes only
};

/// Renders `scene` with lib/ only. Returns false with a reason for unusable options.
bool render(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error);

/// Newell's face of each triangle (NewellOptions::face_ids) as render() passes it: mesh.ids' face where
/// all that face's vertices lie exactly on one plane of the fixed-point grid, else a face of its own.
/// (An OBJ quad with decimal coordinates off the axes is seldom exactly flat on the grid: its triangles
/// are then ordered like any others, at the cost of a few pair tests.)
std::vector<uint32_t> flat_faces(const Mesh& mesh);

/// Face id per pixel decoded from an RGB888 id render (0 = background).
std::vector<uint32_t> decode_ids(const RenderResult& r);

}  // namespace hider::tool

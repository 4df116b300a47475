// Host driver of the BSP walks (see render_bsp.hpp).
#include "common/render_bsp.hpp"

#include <hider/bsp/walk.hpp>

#include <cstring>

#include "host/ppm.hpp"

namespace hider::tool {
namespace {

/// Pixels covered by at least one triangle the walk may draw (an independent count for the overdraw):
/// of the faces it draws (bsp_walk_faces(): front faces when culling, else those the eye's cell sees).
template <class Frame>
uint32_t covered_pixels(const View& view, const BspTree& tree, const std::vector<ScreenVertex>& verts, bool cull,
                        const Vec3q16& eye, const Frame& whole) {
    std::vector<uint8_t> hit(static_cast<size_t>(whole.width) * whole.height, 0);
    uint32_t n = 0;
    FrameStats st;
    std::vector<uint32_t> stack(bsp_stack_entries(tree.max_depth));
    DrawOptions walk;
    walk.cull = cull;
    const BspFaces faces = bsp_walk_faces(view, eye, tree, walk, {stack.data(), stack.size()});
    for (const BspNode& node : tree.nodes) {
        const int side = detail::eye_side(tree, node, eye);
        if (side == 0) continue;
        for (uint32_t t = node.first; t < node.first + node.count; ++t) {
            const BspTriangle& tri = tree.triangles[t];
            const bool front = (side > 0) != ((tri.face & kBspFaceBack) != 0);  // the eye on its front side
            if (!bsp_draws(faces, front)) continue;
            for_each_clipped(view, tree.vertices, {verts.data(), verts.size()}, tri.v[0], tri.v[1], tri.v[2], st,
                             [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
                                 TriangleRaster tr;
                                 if (!tr.setup(a, b, c, whole.width, whole.height)) return;
                                 tr.spans(std::max(0, tr.first_row()), std::min(whole.height, tr.end_row()),
                                          [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
                                              for (int32_t x = x0; x < x1; ++x) {
                                                  uint8_t& h = hit[static_cast<size_t>(y) * whole.width + x];
                                                  n += h == 0;
                                                  h = 1;
                                              }
                                          });
                             });
        }
    }
    return n;
}

template <class Format>
bool draw_with(const Scene& scene, const BspTree& tree, const RenderOptions& opt, RenderResult& out, std::string& error) {
    View view;
    const Status vs = make_view(scene.camera, scene.width, scene.height, view);
    if (vs != Status::ok) {
        error = std::string("camera rejected: ") + status_name(vs);
        return false;
    }
    std::vector<ScreenVertex> verts(tree.vertices.size());
    DrawOptions draw;
    draw.cull = opt.cull;
    draw.shade = opt.shade;
    draw.base = opt.base;
    (void)project_vertices(view, tree.vertices, {verts.data(), verts.size()}, &draw.depth_range);
    std::vector<uint32_t> stack(bsp_stack_entries(tree.max_depth));
    const int rows = opt.band_rows > 0 ? opt.band_rows : scene.height;
    std::vector<typename Format::Pixel> color(static_cast<size_t>(scene.width) * rows);
    std::vector<uint32_t> coverage(static_cast<size_t>(coverage_words(scene.width)) * rows);
    out.width = scene.width;
    out.height = scene.height;
    out.rgb.clear();
    out.stats = FrameStats{};
    out.stats.triangles_in = static_cast<uint32_t>(tree.triangles.size());
    for (int y0 = 0; y0 < scene.height; y0 += rows) {
        const int y1 = std::min(scene.height, y0 + rows);
        const auto band = band_view<Format, uint16_t>(color.data(), nullptr, scene.width, scene.height, y0, y1);
        clear(band, opt.background);
        const FrameStats st = opt.algo == Algo::bsp_front
                                  ? draw_bsp_front(view, scene.camera.eye, tree, {verts.data(), verts.size()}, band, draw,
                                                   {stack.data(), stack.size()}, {coverage.data(), coverage.size()})
                                  : draw_bsp(view, scene.camera.eye, tree, {verts.data(), verts.size()}, band, draw,
                                             {stack.data(), stack.size()});
        if (st.status != Status::ok) {
            error = std::string("BSP walk: ") + status_name(st.status);
            return false;
        }
        out.stats.merge(st);
        port::append_rgb888(band, out.rgb);
    }
    const auto whole = band_view<Format, uint16_t>(nullptr, nullptr, scene.width, scene.height, 0, scene.height);
    out.pixels_covered = covered_pixels(view, tree, verts, opt.cull, scene.camera.eye, whole);
    return true;
}

}  // namespace

AlignedBlob::AlignedBlob(const std::vector<uint8_t>& bytes) : words_((bytes.size() + 7) / 8), size_(bytes.size()) {
    if (!bytes.empty()) std::memcpy(words_.data(), bytes.data(), bytes.size());
}

std::string bsp_load_message(Status s, const BspLoadInfo& info) {
    std::string m = bsp_problem_text(info.problem);
    switch (info.problem) {
        case BspProblem::version:
            m += " (" + std::to_string(info.value) + "; this hider reads " + std::to_string(kBspVersion) +
                 "): rebuild it with hider-bsp";
            break;
        case BspProblem::vertex_range: m = "vertex " + std::to_string(info.index) + " outside the BSP world range"; break;
        case BspProblem::node: m += " " + std::to_string(info.index); break;
        case BspProblem::triangle: m += " " + std::to_string(info.index); break;
        case BspProblem::shape: m += " (at node " + std::to_string(info.index) + ")"; break;
        case BspProblem::depth:
            m += " (header " + std::to_string(info.value) + ", tree " + (info.index > info.value ? "at least " : "") +
                 std::to_string(info.index) + ")";
            break;
        case BspProblem::size: m += " (the header's counts give " + std::to_string(info.value) + " bytes)"; break;
        default: break;
    }
    return m + " (status " + status_name(s) + ")";
}

bool render_bsp(const Scene& scene, const std::vector<uint8_t>& blob, const RenderOptions& opt, RenderResult& out,
                std::string& error) {
    std::vector<uint8_t> built;
    if (blob.empty()) {
        BspBuilt tree;
        BspStats stats;
        if (!build_bsp(scene.positions, scene.tris, scene.ids, BspOptions{}, tree, stats, error)) return false;
        built = bsp_blob(tree, BspFit{scene.centre, scene.scale});
    }
    const AlignedBlob aligned(blob.empty() ? built : blob);
    BspTree tree;
    std::vector<uint32_t> probe(bsp_stack_entries(1u << 16));  // load measures the depth with it
    BspLoadInfo info;
    const Status ls = bsp_load(aligned.span(), {probe.data(), probe.size()}, tree, &info);
    if (ls != Status::ok) {
        error = "BSP tree rejected: " + bsp_load_message(ls, info);
        return false;
    }
    switch (opt.format) {
        case PixelFormat::rgb565: return draw_with<Rgb565Format>(scene, tree, opt, out, error);
        case PixelFormat::rgb888: return draw_with<Rgb888Format>(scene, tree, opt, out, error);
        case PixelFormat::grey8: return draw_with<Grey8Format>(scene, tree, opt, out, error);
    }
    return false;
}

}  // namespace hider::tool

// Host driver: vertex projection once per frame, then the chosen algorithm per band.
#include "common/render.hpp"

#include "host/ppm.hpp"

namespace hider::tool {
namespace {

template <class Format, class Depth>
bool render_with(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error) {
    View view;
    const Status vs = make_view(scene.camera, scene.width, scene.height, view);
    if (vs != Status::ok) {
        error = std::string("camera rejected: ") + status_name(vs);
        return false;
    }
    const Mesh mesh = scene.mesh();
    const Status ms = validate(mesh);
    if (ms != Status::ok) {
        error = std::string("mesh rejected: ") + status_name(ms);
        return false;
    }
    std::vector<ScreenVertex> verts(mesh.positions.size());
    DrawOptions draw;
    draw.cull = opt.cull;
    draw.shade = opt.shade;
    draw.base = opt.base;
    (void)project_vertices(view, mesh.positions, {verts.data(), verts.size()}, &draw.depth_range);
    const int rows = opt.band_rows > 0 ? opt.band_rows : scene.height;
    std::vector<typename Format::Pixel> color(static_cast<size_t>(scene.width) * rows);
    std::vector<Depth> depth(static_cast<size_t>(scene.width) * rows);
    out.width = scene.width;
    out.height = scene.height;
    out.rgb.clear();
    out.rgb.reserve(static_cast<size_t>(scene.width) * scene.height * 3);
    out.stats = FrameStats{};
    for (int y0 = 0; y0 < scene.height; y0 += rows) {
        const int y1 = std::min(scene.height, y0 + rows);
        const auto band = band_view<Format, Depth>(color.data(), depth.data(), scene.width, scene.height, y0, y1);
        clear(band, opt.background);
        const FrameStats st = draw_zbuffer<true>(view, mesh, {verts.data(), verts.size()}, band, draw);
        if (y0 == 0) {
            out.stats = st;
        } else {  // triangles are looked at once per band; keep the per-frame meaning of those counts
            FrameStats px{};
            px.fragments = st.fragments;
            px.pixels_written = st.pixels_written;
            px.status = st.status;
            out.stats.merge(px);
        }
        port::append_rgb888(band, out.rgb);
    }
    return true;
}

template <class Format>
bool render_format(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error) {
    if (opt.depth_bits == 16) return render_with<Format, uint16_t>(scene, opt, out, error);
    return render_with<Format, uint32_t>(scene, opt, out, error);
}

}  // namespace

std::string algo_names() { return "zbuffer"; }

bool parse_algo(const std::string& name, Algo& out) {
    if (name == "zbuffer") { out = Algo::zbuffer; return true; }
    return false;
}

bool render(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error) {
    if (opt.depth_bits != 16 && opt.depth_bits != 32) {
        error = "depth bits must be 16 or 32";
        return false;
    }
    if (opt.band_rows < 0) {
        error = "band rows must be >= 1";
        return false;
    }
    switch (opt.format) {
        case PixelFormat::rgb565: return render_format<Rgb565Format>(scene, opt, out, error);
        case PixelFormat::rgb888: return render_format<Rgb888Format>(scene, opt, out, error);
        case PixelFormat::grey8: return render_format<Grey8Format>(scene, opt, out, error);
    }
    return false;
}

std::vector<uint32_t> decode_ids(const RenderResult& r) {
    std::vector<uint32_t> ids(static_cast<size_t>(r.width) * r.height);
    for (size_t i = 0; i < ids.size(); ++i)
        ids[i] = (uint32_t{r.rgb[3 * i]} << 16) | (uint32_t{r.rgb[3 * i + 1]} << 8) | r.rgb[3 * i + 2];
    return ids;
}

}  // namespace hider::tool

// Host driver: vertex projection once per frame, then the chosen algorithm per band.
#include "common/render.hpp"

#include "common/render_ray.hpp"
#include "host/ppm.hpp"

namespace hider::tool {
namespace {

/// Pixels covered by at least one of the polygons (an independent count for the overdraw figure).
uint32_t count_covered(const std::vector<ScreenPoly>& polys, int width, int height) {
    std::vector<uint8_t> hit(static_cast<size_t>(width) * height, 0);
    uint32_t n = 0;
    for (const ScreenPoly& p : polys) {
        TriangleRaster tr;
        if (!tr.setup(p.v[0], p.v[1], p.v[2], width, height)) continue;
        tr.spans(std::max(0, tr.first_row()), std::min(height, tr.end_row()), [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
            for (int32_t x = x0; x < x1; ++x) {
                uint8_t& h = hit[static_cast<size_t>(y) * width + x];
                n += h == 0;
                h = 1;
            }
        });
    }
    return n;
}

template <class Format, class Depth>
bool render_sorted(const Scene& scene, const RenderOptions& opt, const View& view, const Mesh& mesh,
                   const std::vector<ScreenVertex>& verts, const DrawOptions& draw, RenderResult& out) {
    // Storage the application would declare statically on a device.
    const size_t extra = opt.algo == Algo::painter ? 0 : (opt.split_pool != 0 ? opt.split_pool : mesh.tris.size() * 16 + 1024);
    std::vector<ScreenPoly> poly_store(mesh.tris.size() * 7 + extra);  // a clipped triangle gives up to 7 pieces
    std::vector<uint32_t> order_store(poly_store.size());
    BoundedList<ScreenPoly> polys(poly_store.data(), poly_store.size());
    FrameStats st;
    build_polys(view, mesh, {verts.data(), verts.size()}, opt.cull, polys, st);
    const size_t built = polys.size();
    if (opt.split_pool != 0) {  // exactly the requested room for cuts
        polys = BoundedList<ScreenPoly>(poly_store.data(), built + opt.split_pool);
        for (size_t i = 0; i < built; ++i) polys.push_back(poly_store[i]);
    }
    std::vector<SortKey> keys(built), scratch(built);
    BoundedList<uint32_t> order(order_store.data(), order_store.size());
    for (size_t i = 0; i < built; ++i) order.push_back(0);
    const Status so = painter_order({polys.data(), built}, opt.algo == Algo::painter ? opt.painter_key : DepthKey::farthest,
                  {keys.data(), keys.size()}, {scratch.data(), scratch.size()}, {order.data(), built});
    if (so != Status::ok) st.status = so;
    if (opt.algo != Algo::painter) {
        const Status ns = newell_order(polys, order, out.newell);
        if (ns != Status::ok) st.status = ns;
    }
    out.polygons = order.size();
    const int rows = opt.band_rows > 0 ? opt.band_rows : scene.height;
    std::vector<typename Format::Pixel> color(static_cast<size_t>(scene.width) * rows);
    std::vector<uint32_t> coverage(static_cast<size_t>(coverage_words(scene.width)) * rows);
    for (int y0 = 0; y0 < scene.height; y0 += rows) {
        const int y1 = std::min(scene.height, y0 + rows);
        const auto band = band_view<Format, Depth>(color.data(), nullptr, scene.width, scene.height, y0, y1);
        clear(band, opt.background);
        const FrameStats bs = opt.algo == Algo::reverse
                                  ? paint_front_to_back(view, mesh, {polys.data(), polys.size()}, {order.data(), order.size()},
                                                        band, draw, {coverage.data(), coverage.size()})
                                  : paint_in_order<true>(view, mesh, {polys.data(), polys.size()},
                                                         {order.data(), order.size()}, band, draw);
        FrameStats px{};
        px.fragments = bs.fragments;
        px.pixels_written = bs.pixels_written;
        px.status = bs.status;
        st.merge(px);
        port::append_rgb888(band, out.rgb);
    }
    st.triangles_drawn = static_cast<uint32_t>(order.size());
    out.stats = st;
    out.pixels_covered = count_covered(std::vector<ScreenPoly>(polys.data(), polys.data() + polys.size()), scene.width, scene.height);
    return true;
}

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
    out.width = scene.width;
    out.height = scene.height;
    out.rgb.clear();
    out.rgb.reserve(static_cast<size_t>(scene.width) * scene.height * 3);
    out.stats = FrameStats{};
    out.newell = NewellStats{};
    out.pixels_covered = 0;
    if (opt.algo != Algo::zbuffer) return render_sorted<Format, Depth>(scene, opt, view, mesh, verts, draw, out);
    const int rows = opt.band_rows > 0 ? opt.band_rows : scene.height;
    std::vector<typename Format::Pixel> color(static_cast<size_t>(scene.width) * rows);
    std::vector<Depth> depth(static_cast<size_t>(scene.width) * rows);
    for (int y0 = 0; y0 < scene.height; y0 += rows) {
        const int y1 = std::min(scene.height, y0 + rows);
        const auto band = band_view<Format, Depth>(color.data(), depth.data(), scene.width, scene.height, y0, y1);
        clear(band, opt.background);
        const FrameStats st = draw_zbuffer<true>(view, mesh, {verts.data(), verts.size()}, band, draw);
        if (y0 == 0) {
            out.stats = st;
        } else {  // per-triangle counts (in, clipped, outside) repeat in every band; the rest add up
            FrameStats add{};
            add.status = st.status;
            add.triangles_drawn = st.triangles_drawn;
            add.triangles_culled = st.triangles_culled;
            add.fragments = st.fragments;
            add.pixels_written = st.pixels_written;
            out.stats.merge(add);
        }
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < scene.width; ++x) out.pixels_covered += band.depth_row(y)[x] != DepthTraits<Depth>::kClear;
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

std::string algo_names() { return "zbuffer, painter, newell, reverse, raycast"; }

bool parse_algo(const std::string& name, Algo& out) {
    if (name == "zbuffer") { out = Algo::zbuffer; return true; }
    if (name == "painter") { out = Algo::painter; return true; }
    if (name == "newell") { out = Algo::newell; return true; }
    if (name == "reverse") { out = Algo::reverse; return true; }
    if (name == "raycast") { out = Algo::raycast; return true; }
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
    if (opt.algo == Algo::raycast) return render_raycast(scene, opt, out, error);
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

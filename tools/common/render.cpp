// Host driver: vertex projection once per frame, then the chosen algorithm per band.
#include "common/render.hpp"

#include "common/render_ray.hpp"
#include "common/render_bsp.hpp"
#include "host/ppm.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace hider::tool {
namespace {

/// Pixels covered by at least one of the polygons (an independent count for the overdraw figure).
uint32_t count_covered(Span<const ScreenPoly> polys, Span<const PieceCut> cuts, int width, int height) {
    std::vector<uint8_t> hit(static_cast<size_t>(width) * height, 0);
    FrameView<Grey8Format> whole;
    whole.width = width;
    whole.height = height;
    whole.y0 = 0;
    whole.y1 = height;
    const BandBounds bb = band_bounds(whole);
    uint32_t n = 0;
    for (const ScreenPoly& p : polys)
        with_poly_raster(p, cuts, bb, whole, [&](const auto& r, int32_t y0, int32_t y1) {
            return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
                for (int32_t x = x0; x < x1; ++x) {
                    uint8_t& h = hit[static_cast<size_t>(y) * width + x];
                    n += h == 0;
                    h = 1;
                }
            });
        });
    return n;
}

/// Storage of one sorted render, what an application would declare statically on a device.
struct SortedStore {
    std::vector<ScreenPoly> polys;
    std::vector<PieceCut> cuts;
    std::vector<uint32_t> order, heap, heap_pos, links, cells, chain, reorders, faces;
    std::vector<SortKey> keys, scratch;
};

/// The polygons of `mesh` and their order for opt.algo, with `extra` polygons of room for Newell's
/// cuts (two cut records each). Fills the lists over `store`; returns the first non-ok status.
Status order_polygons(const RenderOptions& opt, const View& view, const Mesh& mesh, const std::vector<ScreenVertex>& verts,
                      size_t extra, SortedStore& store, BoundedList<ScreenPoly>& polys, BoundedList<PieceCut>& cuts,
                      BoundedList<uint32_t>& order, FrameStats& st, NewellStats& ns) {
    store.polys.resize(mesh.tris.size() * 7);  // a clipped triangle gives up to 7 pieces
    polys = BoundedList<ScreenPoly>(store.polys.data(), store.polys.size());
    build_polys(view, mesh, {verts.data(), verts.size()}, opt.cull, polys, st);
    const size_t built = polys.size();
    if (opt.algo == Algo::painter) {
        store.keys.resize(built);
        store.scratch.resize(built);
        store.order.resize(built);
        order = BoundedList<uint32_t>(store.order.data(), built);
        for (size_t i = 0; i < built; ++i) order.push_back(0);
        const Status so = painter_order({polys.data(), built}, opt.painter_key, {store.keys.data(), built},
                                        {store.scratch.data(), built}, {order.data(), built});
        cuts = BoundedList<PieceCut>();
        return so != Status::ok ? so : st.status;
    }
    const size_t cap = built + extra;
    store.polys.resize(std::max(store.polys.size(), cap));
    BoundedList<ScreenPoly> pool(store.polys.data(), cap);
    for (size_t i = 0; i < built; ++i) pool.push_back(store.polys[i]);
    polys = pool;
    store.cuts.resize(2 * extra);
    cuts = BoundedList<PieceCut>(store.cuts.data(), store.cuts.size());
    store.order.resize(cap);
    store.heap.resize(cap);
    store.heap_pos.resize(cap);
    store.chain.resize(cap);
    store.reorders.resize(opt.reorders);
    store.links.resize(2 * cap);
    store.cells.resize(grid_cells(view.width, view.height));
    order = BoundedList<uint32_t>(store.order.data(), cap);
    store.keys.resize(built);
    store.scratch.resize(built);
    const NewellScratch scratch{{store.keys.data(), built},       {store.scratch.data(), built},
                                {store.heap.data(), cap},        {store.heap_pos.data(), cap},
                                {store.links.data(), 2 * cap},   {store.cells.data(), store.cells.size()},
                                {store.chain.data(), cap},       {store.reorders.data(), opt.reorders}};
    NewellOptions nopt;
    store.faces = flat_faces(mesh);  // the triangles of a flat face need no order among themselves
    nopt.face_ids = {store.faces.data(), store.faces.size()};
    const Status s = newell_order(view, polys, cuts, scratch, order, ns, nopt);
    return s != Status::ok ? s : st.status;
}

/// Newell's statistics for the order order_polygons() finds with `extra` polygons of room (sizing runs).
NewellStats trial_order(const RenderOptions& opt, const View& view, const Mesh& mesh, const std::vector<ScreenVertex>& verts,
                        size_t extra) {
    SortedStore store;
    BoundedList<ScreenPoly> polys;
    BoundedList<PieceCut> cuts;
    BoundedList<uint32_t> order;
    FrameStats st;
    NewellStats ns;
    order_polygons(opt, view, mesh, verts, extra, store, polys, cuts, order, st, ns);
    return ns;
}

template <class Format, class Depth>
bool render_sorted(const Scene& scene, const RenderOptions& opt, const View& view, const Mesh& mesh,
                   const std::vector<ScreenVertex>& verts, const DrawOptions& draw, RenderResult& out) {
    const size_t extra = opt.split_pool != 0 ? opt.split_pool : default_split_pool(mesh.tris.size());
    SortedStore store;
    BoundedList<ScreenPoly> polys;
    BoundedList<PieceCut> cuts;
    BoundedList<uint32_t> order;
    FrameStats st;
    st.status = order_polygons(opt, view, mesh, verts, extra, store, polys, cuts, order, st, out.newell);
    out.pool = extra;
    out.pool_needed = 0;
    out.reorders_needed = 0;
    out.reorders_tried = opt.reorders;
    const NewellStats& ns = out.newell;
    if (opt.algo != Algo::painter && ns.unresolved != 0 && ns.dropped == 0 && ns.too_deep == 0 && !ns.budget_exhausted) {
        // How many reorders words would order every pair by its pixels: the same view with more (not
        // when a full pool, the cut limit or the budget left pairs unresolved: their warnings say so).
        for (size_t more = std::max<size_t>(2 * opt.reorders, 64); more <= kMaxReorders; more *= 4) {
            RenderOptions o2 = opt;
            o2.reorders = more;
            out.reorders_tried = more;
            const NewellStats n2 = trial_order(o2, view, mesh, verts, extra);
            if (n2.unresolved == 0) {
                out.reorders_needed = n2.reorders_peak;  // a run that needed no more than it held
                break;
            }
        }
    }
    if (opt.algo != Algo::painter && out.newell.dropped != 0) {
        // How large the pool would have had to be: the same order with room to spare.
        for (size_t more = std::max<size_t>(2 * extra, 1024); more <= kMaxSplitPool; more *= 2) {
            const NewellStats n2 = trial_order(opt, view, mesh, verts, more);
            if (n2.dropped == 0) {
                out.pool_needed = n2.splits;  // one polygon per cut
                break;
            }
        }
    }
    out.polygons = order.size();
    const int rows = opt.band_rows > 0 ? opt.band_rows : scene.height;
    std::vector<typename Format::Pixel> color(static_cast<size_t>(scene.width) * rows);
    std::vector<uint32_t> coverage(static_cast<size_t>(coverage_words(scene.width)) * rows);
    const Span<const ScreenPoly> ps{polys.data(), polys.size()};
    const Span<const PieceCut> cs{cuts.data(), cuts.size()};
    const Span<const uint32_t> os{order.data(), order.size()};
    for (int y0 = 0; y0 < scene.height; y0 += rows) {
        const int y1 = std::min(scene.height, y0 + rows);
        const auto band = band_view<Format, Depth>(color.data(), nullptr, scene.width, scene.height, y0, y1);
        clear(band, opt.background);
        const FrameStats bs = opt.algo == Algo::reverse
                                  ? paint_front_to_back(view, mesh, ps, cs, os, band, draw, {coverage.data(), coverage.size()})
                                  : paint_in_order<true>(view, mesh, ps, cs, os, band, draw);
        FrameStats px{};
        px.fragments = bs.fragments;
        px.pixels_written = bs.pixels_written;
        px.status = bs.status;
        st.merge(px);
        port::append_rgb888(band, out.rgb);
    }
    out.stats = st;
    out.pixels_covered = count_covered(ps, cs, scene.width, scene.height);
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
    // With opt.window, bands of the frame's centred column window through the narrowed view, copied into
    // full-width rows of the background.
    ColumnWindow window{0, scene.width};
    View drawn = view;
    if (opt.window) {
        window = centred_window({verts.data(), verts.size()}, scene.width);
        if (window_view(view, window, drawn) != Status::ok) {
            error = "internal: centred_window() gave a window window_view() refuses";
            return false;
        }
    }
    std::vector<typename Format::Pixel> color(static_cast<size_t>(window.width) * rows), full_color;
    std::vector<Depth> depth(color.size());
    if (window.width != scene.width) full_color.resize(static_cast<size_t>(scene.width) * rows);
    for (int y0 = 0; y0 < scene.height; y0 += rows) {
        const int y1 = std::min(scene.height, y0 + rows);
        const auto band = band_view<Format, Depth>(color.data(), depth.data(), window.width, scene.height, y0, y1);
        clear(band, opt.background);
        const FrameStats st = draw_zbuffer<true>(drawn, mesh, {verts.data(), verts.size()}, band, draw);
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
            for (int x = 0; x < window.width; ++x) out.pixels_covered += band.depth_row(y)[x] != DepthTraits<Depth>::kClear;
        if (window.width == scene.width) {
            port::append_rgb888(band, out.rgb);
            continue;
        }
        const auto full = band_view<Format, Depth>(full_color.data(), nullptr, scene.width, scene.height, y0, y1);
        clear(full, opt.background);
        for (int y = y0; y < y1; ++y) std::copy(band.row(y), band.row(y) + window.width, full.row(y) + window.x0);
        port::append_rgb888(full, out.rgb);
    }
    // draw_zbuffer counts the triangles (or clipped pieces) it sets up and culls, not those of zero area
    // or with no pixel centre: the buckets come from build_polys, which puts each mesh triangle in exactly
    // one (as for the sorted algorithms). Without clipping the z-buffer's own counts must agree.
    std::vector<ScreenPoly> scratch(mesh.tris.size() * 7);  // a clipped triangle gives up to 7 pieces
    BoundedList<ScreenPoly> polys(scratch.data(), scratch.size());
    FrameStats buckets;
    build_polys(view, mesh, {verts.data(), verts.size()}, opt.cull, polys, buckets);
    if (out.stats.triangles_clipped == 0 &&
        (buckets.triangles_culled != out.stats.triangles_culled || buckets.triangles_drawn != out.stats.triangles_drawn)) {
        error = "internal: the z-buffer's triangle counts differ from build_polys' (drawn " +
                std::to_string(out.stats.triangles_drawn) + " / " + std::to_string(buckets.triangles_drawn) + ", culled " +
                std::to_string(out.stats.triangles_culled) + " / " + std::to_string(buckets.triangles_culled) + ")";
        return false;
    }
    out.stats.triangles_drawn = buckets.triangles_drawn;
    out.stats.triangles_culled = buckets.triangles_culled;
    out.stats.triangles_degenerate = buckets.triangles_degenerate;
    out.stats.triangles_outside = buckets.triangles_outside;
    return true;
}

template <class Format>
bool render_format(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error) {
    if (opt.depth_bits == 16) return render_with<Format, uint16_t>(scene, opt, out, error);
    return render_with<Format, uint32_t>(scene, opt, out, error);
}

}  // namespace

size_t default_split_pool(size_t triangles) { return triangles * 16 + 1024; }

std::string algo_names() { return "zbuffer, painter, newell, reverse, raycast, bsp, bsp-front"; }

bool parse_algo(const std::string& name, Algo& out) {
    if (name == "zbuffer") { out = Algo::zbuffer; return true; }
    if (name == "painter") { out = Algo::painter; return true; }
    if (name == "newell") { out = Algo::newell; return true; }
    if (name == "reverse") { out = Algo::reverse; return true; }
    if (name == "raycast") { out = Algo::raycast; return true; }
    if (name == "bsp") { out = Algo::bsp; return true; }
    if (name == "bsp-front") { out = Algo::bsp_front; return true; }
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
    if (opt.algo == Algo::bsp || opt.algo == Algo::bsp_front) return render_bsp(scene, {}, opt, out, error);
    switch (opt.format) {
        case PixelFormat::rgb565: return render_format<Rgb565Format>(scene, opt, out, error);
        case PixelFormat::rgb888: return render_format<Rgb888Format>(scene, opt, out, error);
        case PixelFormat::grey8: return render_format<Grey8Format>(scene, opt, out, error);
    }
    return false;
}

std::vector<uint32_t> flat_faces(const Mesh& mesh) {
    if (mesh.ids.empty()) return {};
    struct Face {
        __int128 n[3] = {0, 0, 0}, d = 0;  // n . p = d for each of its vertices p
        bool has_plane = false, flat = true;
    };
    std::unordered_map<uint32_t, Face> faces;
    auto pos = [&](uint16_t v) {
        const Vec3q16& p = mesh.positions[v];
        return std::array<__int128, 3>{p.x.raw(), p.y.raw(), p.z.raw()};
    };
    for (int pass = 0; pass < 2; ++pass)
        for (size_t t = 0; t < mesh.tris.size(); ++t) {
            Face& f = faces[mesh.ids[t]];
            const auto a = pos(mesh.tris[t].v[0]), b = pos(mesh.tris[t].v[1]), c = pos(mesh.tris[t].v[2]);
            if (pass == 0 && !f.has_plane) {  // the first triangle of the face with a plane (|coordinates| < 2^29)
                const __int128 u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                f.n[0] = u[1] * w[2] - u[2] * w[1];
                f.n[1] = u[2] * w[0] - u[0] * w[2];
                f.n[2] = u[0] * w[1] - u[1] * w[0];
                f.d = f.n[0] * a[0] + f.n[1] * a[1] + f.n[2] * a[2];
                f.has_plane = f.n[0] != 0 || f.n[1] != 0 || f.n[2] != 0;
            }
            if (pass == 1 && f.has_plane)
                for (const auto& p : {a, b, c}) f.flat = f.flat && f.n[0] * p[0] + f.n[1] * p[1] + f.n[2] * p[2] == f.d;
        }
    std::vector<uint32_t> out(mesh.tris.size());
    std::unordered_map<uint32_t, uint32_t> number;  // only equality matters: faces renumbered from 0
    uint32_t next = 0;
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        if (!faces[mesh.ids[t]].flat) {
            out[t] = next++;
            continue;
        }
        const auto it = number.emplace(mesh.ids[t], next).first;
        next += it->second == next;
        out[t] = it->second;
    }
    return out;
}

std::vector<uint32_t> decode_ids(const RenderResult& r) {
    std::vector<uint32_t> ids(static_cast<size_t>(r.width) * r.height);
    for (size_t i = 0; i < ids.size(); ++i)
        ids[i] = (uint32_t{r.rgb[3 * i]} << 16) | (uint32_t{r.rgb[3 * i + 1]} << 8) | r.rgb[3 * i + 2];
    return ids;
}

}  // namespace hider::tool

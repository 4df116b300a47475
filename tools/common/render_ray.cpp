// Host drivers of the ray caster and the ray tracer (see render_ray.hpp).
#include "common/render_ray.hpp"

#include <hider/ray/cast.hpp>

#include "common/bvh_build.hpp"
#include "host/ppm.hpp"

namespace hider::tool {
namespace {

void add(RayCounts& c, const ray::TraceStats& s) {
    c.rays += s.rays;
    c.hits += s.hits;
    c.shadow_rays += s.shadow_rays;
    c.boxes += s.bvh.boxes;
    c.triangles += s.bvh.triangles;
}

/// Runs `row_fn(y, pixels)` for every row, band by band in buffers of opt.band_rows rows.
template <class Format, class RowFn>
void render_rows(int width, int height, const RenderOptions& opt, RenderResult& out, RowFn row_fn) {
    const int rows = opt.band_rows > 0 ? opt.band_rows : height;
    std::vector<typename Format::Pixel> color(static_cast<size_t>(width) * rows);
    out.width = width;
    out.height = height;
    out.rgb.clear();
    out.rgb.reserve(static_cast<size_t>(width) * height * 3);
    for (int y0 = 0; y0 < height; y0 += rows) {
        const int y1 = std::min(height, y0 + rows);
        const auto band = band_view<Format, uint16_t>(color.data(), nullptr, width, height, y0, y1);
        for (int y = y0; y < y1; ++y) row_fn(y, band.row(y));
        port::append_rgb888(band, out.rgb);
    }
}

template <class Format>
void cast_all(const Scene& scene, const ray::PrimaryRays& rays, const ray::Bvh& bvh, const RenderOptions& opt,
              std::vector<ray::BvhStackEntry>& stack, RenderResult& out) {
    DrawOptions draw;
    draw.cull = opt.cull;
    draw.shade = opt.shade;
    draw.base = opt.base;
    const Mesh mesh = scene.mesh();
    render_rows<Format>(scene.width, scene.height, opt, out, [&](int y, typename Format::Pixel* row) {
        add(out.ray, ray::cast_row<Format>(rays, mesh, bvh, draw, opt.background, y, row, {stack.data(), stack.size()}));
    });
}

template <class Format>
void trace_all(const RayScene& scene, const ray::Scene& s, const ray::PrimaryRays& rays, int width, int height,
               const RenderOptions& opt, std::vector<ray::BvhStackEntry>& stack, RenderResult& out) {
    std::vector<ray::SphereRect> rects(scene.spheres.size());
    if (ray::sphere_rects(s, rays, {rects.data(), rects.size()}) != Status::ok) rects.clear();  // cannot fail: sized above
    render_rows<Format>(width, height, opt, out, [&](int y, typename Format::Pixel* row) {
        add(out.ray, ray::trace_row<Format>(s, rays, y, row, {stack.data(), stack.size()}, {rects.data(), rects.size()}));
    });
}

}  // namespace

bool render_raycast(const Scene& scene, const RenderOptions& opt, RenderResult& out, std::string& error) {
    if (opt.shade == Shade::depth) {
        error = "--shade depth is not available with --algo raycast (use headlight or id)";
        return false;
    }
    const Mesh mesh = scene.mesh();
    const Status ms = validate(mesh);
    if (ms != Status::ok) {
        error = std::string("mesh rejected: ") + status_name(ms);
        return false;
    }
    BakedBvh bvh;
    if (!build_bvh(mesh, bvh, error)) return false;
    std::vector<ray::BvhStackEntry> stack(bvh.header.max_depth);
    const Status bs = ray::validate_bvh(bvh.view(), mesh, {stack.data(), stack.size()});
    if (bs != Status::ok) {
        error = std::string("bvh rejected: ") + status_name(bs);
        return false;
    }
    ray::PrimaryRays rays;
    const Status vs = ray::make_primary_rays(scene.camera, scene.width, scene.height, rays);
    if (vs != Status::ok) {
        error = std::string("camera rejected: ") + status_name(vs);
        return false;
    }
    out = RenderResult{};
    switch (opt.format) {
        case PixelFormat::rgb565: cast_all<Rgb565Format>(scene, rays, bvh.view(), opt, stack, out); break;
        case PixelFormat::rgb888: cast_all<Rgb888Format>(scene, rays, bvh.view(), opt, stack, out); break;
        case PixelFormat::grey8: cast_all<Grey8Format>(scene, rays, bvh.view(), opt, stack, out); break;
    }
    out.stats.triangles_in = static_cast<uint32_t>(mesh.tris.size());
    out.stats.pixels_written = static_cast<uint32_t>(out.ray.hits);
    out.stats.fragments = static_cast<uint32_t>(out.ray.hits);
    out.pixels_covered = static_cast<uint32_t>(out.ray.hits);
    return true;
}

bool render_ray_scene(const RayScene& scene, int width, int height, const RenderOptions& opt, RenderResult& out,
                      std::string& error) {
    if (opt.band_rows < 0) {
        error = "band rows must be >= 1";
        return false;
    }
    ray::PrimaryRays rays;
    const Status vs = ray::make_primary_rays(scene.camera, width, height, rays);
    if (vs != Status::ok) {
        error = std::string("camera rejected: ") + status_name(vs);
        return false;
    }
    const ray::Scene s = scene.view();
    std::vector<ray::BvhStackEntry> stack(scene.stack_depth());
    const Status ss = ray::validate_scene(s, {stack.data(), stack.size()});
    if (ss != Status::ok) {
        error = std::string("scene rejected: ") + status_name(ss);
        return false;
    }
    out = RenderResult{};
    switch (opt.format) {
        case PixelFormat::rgb565: trace_all<Rgb565Format>(scene, s, rays, width, height, opt, stack, out); break;
        case PixelFormat::rgb888: trace_all<Rgb888Format>(scene, s, rays, width, height, opt, stack, out); break;
        case PixelFormat::grey8: trace_all<Grey8Format>(scene, s, rays, width, height, opt, stack, out); break;
    }
    out.stats.pixels_written = static_cast<uint32_t>(width) * static_cast<uint32_t>(height);
    return true;
}

}  // namespace hider::tool

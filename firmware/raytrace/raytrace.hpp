// Ray tracing straight into a display, one row at a time: the demo scene (firmware/common/scenes/
// raytrace_demo.hpp, baked from tests/data/scenes/spheres.txt) is traced row by row into a single RGB565
// row buffer that goes to a port::BandSink after each row, so the frame never exists in RAM. Shared by
// the raytrace firmware and its host reference (tools/firmware-hosts/raytrace_reference.cpp).
#pragma once
#include <hider/ray/trace.hpp>

#include "common/bench.hpp"
#include "common/scenes/raytrace_demo.hpp"
#include "display/sink.hpp"
#include "spin/ppm_sink.hpp"

namespace raytrace {

namespace demo = hider::scenes::raytrace_demo;

/// Memory the application declares: one row of pixels, the BVH walk's stack and the spheres' rectangles.
struct Buffers {
    hider::Span<uint16_t> row;                     ///< >= width RGB565 pixels
    hider::Span<hider::ray::BvhStackEntry> stack;  ///< >= demo::kStackDepth entries
    hider::Span<hider::ray::SphereRect> rects;      ///< >= the scene's spheres
};

/// What one frame did, summed over its rows.
struct Result {
    hider::Status status = hider::Status::ok;
    hider::ray::TraceStats stats{};
};

/// Traces the demo scene at width x height into `sink`, one row per write_rows call; each row's tracing
/// (not the sink) is bracketed by bench_begin()/bench_end(). invalid_argument for a short row buffer or a
/// refused sink call; the scene's own status from validate_scene() / make_primary_rays().
inline Result trace_frame(int32_t width, int32_t height, const Buffers& buf, const hider::port::BandSink& sink) {
    Result r;
    const hider::ray::Scene scene = demo::scene();
    hider::ray::PrimaryRays rays;
    if (!hider::port::is_complete(sink) || buf.row.size() < static_cast<size_t>(width) || width > UINT16_MAX || height > UINT16_MAX) {
        r.status = hider::Status::invalid_argument;
        return r;
    }
    r.status = hider::ray::validate_scene(scene, buf.stack);
    if (r.status == hider::Status::ok) r.status = hider::ray::make_primary_rays(demo::kCamera, width, height, rays);
    if (r.status == hider::Status::ok) r.status = hider::ray::sphere_rects(scene, rays, buf.rects);
    if (r.status != hider::Status::ok) return r;
    if (!sink.begin_frame(sink.user, static_cast<uint16_t>(width), static_cast<uint16_t>(height))) {
        r.status = hider::Status::invalid_argument;
        return r;
    }
    bool sent = true;
    for (int32_t y = 0; y < height && sent; ++y) {
        bench_begin();
        const hider::ray::TraceStats st =
            hider::ray::trace_row<hider::Rgb565Format>(scene, rays, y, buf.row.data(), buf.stack, buf.rects);
        bench_end();
        r.stats.merge(st);
        sent = sink.write_rows(sink.user, static_cast<uint16_t>(y), 1, buf.row.data(), static_cast<uint32_t>(width));
    }
    const bool ended = sink.end_frame(sink.user);
    if (!(sent && ended)) r.status = hider::Status::invalid_argument;
    return r;
}

/// The raytrace program: the demo frame into the PPM file `path` through spin::PpmSink. Returns the exit
/// status (0 ok, 1 failure, with a message). Io as in spin/app.hpp.
template <class Io>
int run(Io& io, const Buffers& buf, hider::Span<uint8_t> ppm_row, const char* path) {
    if (!io.open(path)) {
        io.print("raytrace: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    spin::PpmSink<Io> ppm(io, ppm_row);
    const Result r = trace_frame(demo::kWidth, demo::kHeight, buf, ppm.sink());
    const bool closed = io.close();
    if (r.status != hider::Status::ok || ppm.status() != hider::port::BandStatus::ok || !closed) {
        io.print("raytrace: failed: ");
        io.print(hider::status_name(r.status));
        io.print("\n");
        return 1;
    }
    io.print(path);
    io.print(": rays ");
    io.print_u32(r.stats.rays);
    io.print(", shadow rays ");
    io.print_u32(r.stats.shadow_rays);
    io.print(", hits ");
    io.print_u32(r.stats.hits);
    io.print("\n");
    return 0;
}

}  // namespace raytrace

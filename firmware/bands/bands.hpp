// Band-by-band rendering for RAM-starved chips: the frame's vertices are projected once into a
// ScreenVertex cache, then draw_zbuffer_binned() (lib/hider/raster/binned.hpp) draws the frame band by
// band through one band-sized colour and depth buffer, each band handed to a port::BandSink as a display
// driver takes it. Triangles are binned once; a triangle continuing into the next band resumes from its
// carried set-up. Gives exactly the bytes of the full-frame render (spin/render.hpp). Shared by the bands
// and bands320 firmware and their host reference.
#pragma once
#include <hider/raster/binned.hpp>

#include "common/bench.hpp"
#include "display/sink.hpp"
#include "spin/ppm_sink.hpp"
#include "spin/render.hpp"

namespace bands {

/// Buffers a band renderer needs, declared by the application.
struct BandBuffers {
    hider::Span<hider::ScreenVertex> verts;  ///< one per mesh vertex
    hider::Span<uint16_t> color;             ///< >= width * rows RGB565
    hider::Span<uint16_t> depth;             ///< >= width * rows
    int32_t rows;                            ///< rows per band
    hider::BinnedScratch scratch;            ///< bins and carried set-ups (binned.hpp)
};

/// Renders frame `frame` of `s` band by band into `sink` (begin_frame, write_rows per band, end_frame).
/// Everything but the sink calls is bracketed by bench_begin()/bench_end(). Returns the frame's
/// statistics; invalid_argument for unusable buffers or a refused sink call. `carry` receives the
/// carried-slot figures.
inline hider::FrameStats render_in_bands(const spin::Scene& s, uint32_t frame, const BandBuffers& buf,
                                         const hider::port::BandSink& sink, hider::BinnedStats& carry) {
    auto failed = [](hider::Status why) {
        hider::FrameStats st;
        st.status = why;
        return st;
    };
    const size_t band_px = static_cast<size_t>(s.width) * static_cast<size_t>(buf.rows);
    if (!hider::port::is_complete(sink) || buf.rows < 1 || buf.color.size() < band_px || buf.depth.size() < band_px ||
        s.width > UINT16_MAX || s.height > UINT16_MAX)
        return failed(hider::Status::invalid_argument);
    if (!sink.begin_frame(sink.user, static_cast<uint16_t>(s.width), static_cast<uint16_t>(s.height)))
        return failed(hider::Status::invalid_argument);
    hider::View view;
    bench_begin();
    hider::Status status = spin::frame_view(s, frame, view);
    if (status == hider::Status::ok) status = hider::project_vertices(view, s.mesh.positions, buf.verts);
    // Initialised from the call (no second FrameStats on the stack beside the one it returns).
    hider::FrameStats total =
        status != hider::Status::ok
            ? failed(status)
            : hider::draw_zbuffer_binned(
                  view, s.mesh, buf.verts,
                  hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), buf.depth.data(), s.width, s.height, 0, buf.rows),
                  spin::draw_options(), spin::kBackground, buf.scratch,
                  [&sink](const spin::Frame& band) {
                      bench_end();  // the sink's time is the display's, not the renderer's
                      const bool sent = sink.write_rows(sink.user, static_cast<uint16_t>(band.y0), static_cast<uint16_t>(band.rows()),
                                                        band.color, static_cast<uint32_t>(band.stride));
                      bench_begin();
                      return sent;
                  },
                  &carry);
    bench_end();
    const bool ended = sink.end_frame(sink.user);
    if (total.status == hider::Status::ok && !ended) total.status = hider::Status::invalid_argument;
    return total;
}

/// The bands program: frame 0 of `s` band by band into the PPM file `path` through spin::PpmSink (rows
/// converted `ppm_chunk.size() / 3` pixels at a time). Returns the exit status (0 ok, 1 failure, with a
/// message). Io as in spin/app.hpp.
template <class Io>
int run(Io& io, const spin::Scene& s, const BandBuffers& buf, hider::Span<uint8_t> ppm_chunk, const char* path) {
    if (!io.open(path)) {
        io.print("bands: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    spin::PpmSink<Io> ppm(io, ppm_chunk, static_cast<uint16_t>(s.width));
    hider::BinnedStats carry;
    const hider::FrameStats st = render_in_bands(s, 0, buf, ppm.sink(), carry);
    const bool closed = io.close();
    if (!st.ok() || ppm.status() != hider::port::BandStatus::ok || !closed) {
        io.print("bands: failed: ");
        io.print(hider::status_name(st.status));
        io.print(", sink status ");
        io.print_u32(static_cast<uint32_t>(ppm.status()));
        io.print("\n");
        return 1;
    }
    io.print(path);
    io.print(": ");
    io.print_u32(static_cast<uint32_t>((s.height + buf.rows - 1) / buf.rows));
    io.print(" bands, triangles drawn ");
    io.print_u32(st.triangles_drawn);
    io.print(", carried ");
    io.print_u32(carry.carried);
    io.print(", set up again ");
    io.print_u32(carry.set_up_again);
    io.print(", slots used ");
    io.print_u32(carry.carried_high_water);
    io.print(" of ");
    io.print_u32(static_cast<uint32_t>(buf.scratch.carried.size()));
    io.print("\n");
    return 0;
}

}  // namespace bands

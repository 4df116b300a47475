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
    int32_t rows;                            ///< rows per band of the frame's width
    hider::BinnedScratch scratch;            ///< bins (head: one per band of `rows`) and carried set-ups (binned.hpp)
};

/// How render_in_bands() cut the frame: its column window and the rows per band.
struct BandLayout {
    hider::ColumnWindow window;
    int32_t rows = 0;
};

/// The frame's centred column window (centred_window()) and the rows of it the band memory holds (at
/// least cut.rows, which fit the full width); narrows `view` to the window. Out of line: its locals stay
/// off the stack under the band loop.
__attribute__((noinline)) inline hider::Status window_frame(const spin::Scene& s, hider::Span<const hider::ScreenVertex> verts,
                                                           size_t memory_px, hider::View& view, BandLayout& cut) {
    cut.window = hider::centred_window({verts.data(), s.mesh.positions.size()}, s.width);
    cut.rows = hider::min(s.height, static_cast<int32_t>(memory_px / static_cast<size_t>(cut.window.width)));
    return hider::window_view(view, cut.window, view);
}

/// Renders frame `frame` of `s` band by band into `sink` (begin_frame, write_rows or write_columns per
/// band, end_frame). When the sink takes windows (BandSink::write_columns), the bands hold only the
/// frame's centred column window (centred_window(): the background lies outside it) and are as tall as
/// the band memory allows for its width (min(color, depth) / window width rows, at least `buf.rows`);
/// otherwise `buf.rows` rows of the full width. Everything but the sink calls is bracketed by
/// bench_begin()/bench_end(). Returns the frame's statistics; invalid_argument for unusable buffers or a
/// refused sink call. `carry` receives the carried-slot figures, `cut` the window and rows.
__attribute__((always_inline)) inline hider::FrameStats render_in_bands(const spin::Scene& s, uint32_t frame,
                                                                        const BandBuffers& buf,
                                                                        const hider::port::BandSink& sink,
                                                                        hider::BinnedStats& carry, BandLayout& cut) {
    auto failed = [](hider::Status why) {
        hider::FrameStats st;
        st.status = why;
        return st;
    };
    cut.window = {0, s.width};
    cut.rows = buf.rows;
    const size_t memory_px = hider::min(buf.color.size(), buf.depth.size());
    if (!hider::port::is_complete(sink) || buf.rows < 1 || memory_px < static_cast<size_t>(s.width) * static_cast<size_t>(buf.rows) ||
        s.width > UINT16_MAX || s.height > UINT16_MAX)
        return failed(hider::Status::invalid_argument);
    if (!sink.begin_frame(sink.user, static_cast<uint16_t>(s.width), static_cast<uint16_t>(s.height)))
        return failed(hider::Status::invalid_argument);
    hider::View view;
    bench_begin();
    hider::Status status = spin::frame_view(s, frame, view);
    if (status == hider::Status::ok) status = hider::project_vertices(view, s.mesh.positions, buf.verts);
    if (status == hider::Status::ok && sink.write_columns != nullptr)
        status = window_frame(s, buf.verts, memory_px, view, cut);
    // Initialised from the call (no second FrameStats on the stack beside the one it returns).
    hider::FrameStats total =
        status != hider::Status::ok
            ? failed(status)
            : hider::draw_zbuffer_binned(
                  view, s.mesh, buf.verts,
                  hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), buf.depth.data(), cut.window.width,
                                                                  s.height, 0, cut.rows),
                  spin::draw_options(), spin::kBackground, buf.scratch,
                  [&sink, &cut](const spin::Frame& band) {
                      bench_end();  // the sink's time is the display's, not the renderer's
                      const uint16_t y0 = static_cast<uint16_t>(band.y0), rows = static_cast<uint16_t>(band.rows());
                      const uint32_t stride = static_cast<uint32_t>(band.stride);
                      const bool sent =
                          cut.window.x0 == 0  // the whole width
                              ? sink.write_rows(sink.user, y0, rows, band.color, stride)
                              : sink.write_columns(sink.user, y0, rows, static_cast<uint16_t>(cut.window.x0),
                                                   static_cast<uint16_t>(cut.window.width),
                                                   hider::Rgb565Format::pack(spin::kBackground), band.color, stride);
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
/// converted `ppm_chunk.size() / 3` pixels at a time), in bands of its column window (kWindow false: of
/// the full width, as through a sink without BandSink::write_columns). Returns the exit status (0 ok, 1
/// failure, with a message). Io as in spin/app.hpp.
template <bool kWindow = true, class Io>
int run(Io& io, const spin::Scene& s, const BandBuffers& buf, hider::Span<uint8_t> ppm_chunk, const char* path) {
    if (!io.open(path)) {
        io.print("bands: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    spin::PpmSink<Io> ppm(io, ppm_chunk, static_cast<uint16_t>(s.width));
    hider::BinnedStats carry;
    BandLayout cut;
    const hider::FrameStats st = render_in_bands(s, 0, buf, ppm.sink(kWindow), carry, cut);
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
    io.print_u32(static_cast<uint32_t>((s.height + cut.rows - 1) / cut.rows));
    io.print(" bands of ");
    io.print_u32(static_cast<uint32_t>(cut.rows));
    io.print(" rows, columns ");
    io.print_u32(static_cast<uint32_t>(cut.window.x0));
    io.print(" + ");
    io.print_u32(static_cast<uint32_t>(cut.window.width));
    io.print(", triangles drawn ");
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

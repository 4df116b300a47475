// Band-by-band rendering for RAM-starved chips: the frame's vertices are projected once into a
// ScreenVertex cache, then each band of kBandRows rows is cleared, drawn (draw_zbuffer on a band_view)
// and handed to a port::BandSink, as a display driver takes it. Gives exactly the bytes of the
// full-frame render (spin/render.hpp). Shared by the bands firmware and its host reference.
#pragma once
#include "common/bench.hpp"
#include "display/sink.hpp"
#include "spin/ppm_sink.hpp"
#include "spin/render.hpp"

namespace bands {

/// Rows per band: 160 x 8 x (2 B colour + 2 B depth) = 5 KB, which with the 6 KB vertex cache fits
/// the 16 KB small machines; 128 rows = 16 bands.
constexpr int32_t kBandRows = 8;

/// Buffers a band renderer needs, declared by the application.
struct BandBuffers {
    hider::Span<hider::ScreenVertex> verts;  ///< one per mesh vertex
    hider::Span<uint16_t> color;             ///< >= width * rows RGB565
    hider::Span<uint16_t> depth;             ///< >= width * rows
    int32_t rows;                            ///< rows per band
};

/// Renders frame `frame` of `s` band by band into `sink` (begin_frame, write_rows per band, end_frame).
/// Projection and each band's draw are bracketed by bench_begin()/bench_end() (sink time excluded).
/// Returns the statistics summed over the bands (triangle counts then count band setups, pixel counts
/// are the frame's); invalid_argument for unusable buffers or a refused sink call.
inline hider::FrameStats render_in_bands(const spin::Scene& s, uint32_t frame, const BandBuffers& buf,
                                         const hider::port::BandSink& sink) {
    hider::FrameStats total;
    const size_t band_px = static_cast<size_t>(s.width) * static_cast<size_t>(buf.rows);
    if (!hider::port::is_complete(sink) || buf.rows < 1 || buf.color.size() < band_px || buf.depth.size() < band_px ||
        s.width > UINT16_MAX || s.height > UINT16_MAX) {
        total.status = hider::Status::invalid_argument;
        return total;
    }
    hider::View view;
    bench_begin();
    total.status = spin::frame_view(s, frame, view);
    if (total.status == hider::Status::ok) total.status = hider::project_vertices(view, s.mesh.positions, buf.verts);
    bench_end();
    if (total.status != hider::Status::ok) return total;
    if (!sink.begin_frame(sink.user, static_cast<uint16_t>(s.width), static_cast<uint16_t>(s.height))) {
        total.status = hider::Status::invalid_argument;
        return total;
    }
    bool sent = true;
    for (int32_t y0 = 0; y0 < s.height && sent; y0 += buf.rows) {
        const int32_t y1 = hider::min(s.height, y0 + buf.rows);
        const spin::Frame band =
            hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), buf.depth.data(), s.width, s.height, y0, y1);
        bench_begin();
        const hider::FrameStats st = spin::draw_band(view, s.mesh, buf.verts, band);
        bench_end();
        total.merge(st);  // triangle counts are per band: a triangle spanning k bands is set up k times
        sent = sink.write_rows(sink.user, static_cast<uint16_t>(y0), static_cast<uint16_t>(y1 - y0), buf.color.data(),
                               static_cast<uint32_t>(s.width));
    }
    const bool ended = sink.end_frame(sink.user);
    if (total.status == hider::Status::ok && !(sent && ended)) total.status = hider::Status::invalid_argument;
    return total;
}

/// The bands program: frame 0 of `s` band by band into the PPM file `path` through spin::PpmSink.
/// Returns the exit status (0 ok, 1 failure, with a message). Io as in spin/app.hpp.
template <class Io>
int run(Io& io, const spin::Scene& s, const BandBuffers& buf, hider::Span<uint8_t> ppm_row, const char* path) {
    if (!io.open(path)) {
        io.print("bands: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    spin::PpmSink<Io> ppm(io, ppm_row);
    const hider::FrameStats st = render_in_bands(s, 0, buf, ppm.sink());
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
    io.print(" bands, triangle setups ");
    io.print_u32(st.triangles_drawn);
    io.print("\n");
    return 0;
}

}  // namespace bands

// The painter examples, for firmware and host alike: a baked scene drawn without back-face culling by
// one of the object-space algorithms of lib/hider/sort/ (painter by farthest depth, Newell's order
// painted back to front, or that order front to back with a coverage mask), band by band with no
// depth buffer, each band streamed through spin::PpmSink. Same driver sequence as tools/common/render.cpp.
#pragma once
#include <hider/sort/newell.hpp>
#include <hider/sort/painter.hpp>
#include <hider/sort/reverse.hpp>

#include "common/bench.hpp"
#include "common/bits.hpp"
#include "display/sink.hpp"
#include "spin/ppm_sink.hpp"
#include "spin/render.hpp"

namespace painter {

/// Which order the polygons are painted in.
enum class Algo : uint8_t {
    painter,  ///< farthest-vertex key, back to front
    newell,   ///< Newell's order (with cuts), back to front
    reverse,  ///< Newell's order, front to back, each pixel written once (coverage bits)
};

/// Rows per band: 160 x 16 RGB565 = 5 KB of colour, 8 bands for 128 rows.
constexpr int32_t kBandRows = 16;

/// Name of the algorithm's output file.
constexpr const char* output_name(Algo a) {
    return a == Algo::painter ? "painter.ppm" : (a == Algo::newell ? "newell.ppm" : "reverse.ppm");
}

/// hider-render's defaults (headlight, white) without back-face culling, so both sides of the torus
/// are sorted and Newell finds overlaps to resolve.
inline hider::DrawOptions draw_options() {
    hider::DrawOptions opt;
    opt.cull = false;
    return opt;
}

/// Caller-owned storage of one render (statics on a device); Storage below declares it.
struct Buffers {
    hider::Span<hider::ScreenVertex> verts;  ///< one per mesh vertex
    hider::Span<hider::ScreenPoly> polys;    ///< pool: the built triangles plus room for Newell's cuts
    hider::Span<hider::PieceCut> cuts;       ///< two per cut Newell may make
    hider::NewellScratch newell;             ///< sort keys (shared with keys/scratch below), heap, grid, chain, reorders
    hider::Span<uint32_t> order;             ///< >= polys.size()
    hider::Span<hider::SortKey> keys;        ///< >= polys.size()
    hider::Span<hider::SortKey> scratch;     ///< >= polys.size()
    hider::Span<uint16_t> color;             ///< >= width * rows RGB565
    hider::Span<uint32_t> coverage;          ///< >= coverage_words(width) * rows (reverse painter)
    int32_t rows;                            ///< rows per band
};

/// Storage for a scene of kVertices vertices in a kWidth x kHeight frame, with a pool of kPolys polygons
/// of which kCutRoom are room for Newell's cuts.
template <size_t kVertices, size_t kPolys, size_t kCutRoom, int32_t kWidth, int32_t kHeight, int32_t kRows = kBandRows>
struct Storage {
    hider::ScreenVertex verts[kVertices];
    hider::ScreenPoly polys[kPolys];
    hider::PieceCut cuts[2 * kCutRoom];
    uint32_t heap[kPolys];
    uint32_t heap_pos[kPolys];
    uint32_t links[2 * kPolys];
    uint32_t cells[hider::grid_cells(kWidth, kHeight)];
    uint32_t chain[kPolys];
    uint32_t reorders[hider::kNewellReorders];
    uint32_t order[kPolys];
    hider::SortKey keys[kPolys];
    hider::SortKey scratch[kPolys];
    uint16_t color[kWidth * kRows];
    uint32_t coverage[hider::coverage_words(kWidth) * kRows];
    uint8_t ppm_row[kWidth * 3];

    Buffers buffers() {
        return {verts, polys, cuts, {keys, scratch, heap, heap_pos, links, cells, chain, reorders}, order, keys, scratch, color, coverage, kRows};
    }
};

/// What one render did. `stats` sums the bands (triangle counts are per band setup).
struct Result {
    hider::FrameStats stats;
    hider::NewellStats newell;
    uint32_t polygons_built = 0;  ///< screen triangles from build_polys
    uint32_t polygons = 0;        ///< in the painted order (after Newell's cuts)
    uint32_t covered = 0;         ///< reverse: coverage bits set at the end of each band, summed
    uint32_t coverage_mismatches = 0;  ///< reverse: bands whose pixels_written differs from their bits set
    bool sink_ok = true;          ///< every sink call accepted
};

namespace detail {

/// View, projection, screen triangles and the painting order of `algo` into polys/cuts/order.
inline hider::Status build_order(const spin::Scene& s, Algo algo, const Buffers& buf, hider::View& view,
                                 hider::BoundedList<hider::ScreenPoly>& polys, hider::BoundedList<hider::PieceCut>& cuts,
                                 hider::BoundedList<uint32_t>& order, Result& r) {
    hider::Status st = hider::make_view(s.camera, s.width, s.height, view);
    if (st == hider::Status::ok) st = hider::project_vertices(view, s.mesh.positions, buf.verts);
    if (st != hider::Status::ok) return st;
    hider::FrameStats fs;  // a full pool (capacity_exceeded) still orders and draws what it holds
    hider::build_polys(view, s.mesh, buf.verts, draw_options().cull, polys, fs);
    const size_t built = polys.size();
    r.polygons_built = static_cast<uint32_t>(built);
    if (algo != Algo::painter) {
        st = hider::newell_order(view, polys, cuts, buf.newell, order, r.newell);
    } else {
        for (size_t i = 0; i < built; ++i) (void)order.push_back(0);  // room; painter_order fills it
        st = hider::painter_order({polys.data(), built}, hider::DepthKey::farthest, {buf.keys.data(), built},
                                  {buf.scratch.data(), built}, {order.data(), built});
    }
    r.polygons = static_cast<uint32_t>(order.size());
    return fs.status != hider::Status::ok ? fs.status : st;
}

/// Clears and paints rows [y0, y1) in the order; for the reverse painter also checks on the spot that
/// the pixels it wrote are exactly the coverage bits it set (outside the measured region).
inline hider::FrameStats paint_band(const spin::Scene& s, Algo algo, const Buffers& buf, const hider::View& view,
                                    const hider::BoundedList<hider::ScreenPoly>& polys,
                                    const hider::BoundedList<hider::PieceCut>& cuts,
                                    const hider::BoundedList<uint32_t>& order, int32_t y0, int32_t y1, Result& r) {
    const auto band = hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), nullptr, s.width, s.height, y0, y1);
    const hider::Span<const hider::ScreenPoly> p{polys.data(), polys.size()};
    const hider::Span<const hider::PieceCut> c{cuts.data(), cuts.size()};
    const hider::Span<const uint32_t> o{order.data(), order.size()};
    bench_begin();
    hider::clear(band, spin::kBackground);
    const hider::FrameStats st = algo == Algo::reverse
                                     ? hider::paint_front_to_back(view, s.mesh, p, c, o, band, draw_options(), buf.coverage)
                                     : hider::paint_in_order<true>(view, s.mesh, p, c, o, band, draw_options());
    bench_end();
    if (algo == Algo::reverse) {
        const uint32_t set = ::bits_set(buf.coverage.data(), static_cast<size_t>(hider::coverage_words(s.width)) * band.rows());
        r.covered += set;
        if (set != st.pixels_written) ++r.coverage_mismatches;
    }
    return st;
}

}  // namespace detail

/// Renders `s` with `algo` band by band into `sink` (begin_frame, write_rows per band, end_frame).
/// The frame work (view through ordering, then each band's clear and paint) is bracketed by
/// bench_begin()/bench_end(); the sink and the coverage check are not. Borrows everything for the call.
inline Result render_in_bands(const spin::Scene& s, Algo algo, const Buffers& buf, const hider::port::BandSink& sink) {
    Result r;
    const size_t pool = buf.polys.size();
    if (!hider::port::is_complete(sink) || buf.rows < 1 || s.width > UINT16_MAX || s.height > UINT16_MAX ||
        buf.order.size() < pool || buf.keys.size() < pool || buf.scratch.size() < pool ||
        buf.color.size() < static_cast<size_t>(s.width) * static_cast<size_t>(buf.rows) ||
        buf.coverage.size() < static_cast<size_t>(hider::coverage_words(s.width)) * static_cast<size_t>(buf.rows)) {
        r.stats.status = hider::Status::invalid_argument;
        return r;
    }
    hider::BoundedList<hider::ScreenPoly> polys(buf.polys.data(), pool);
    hider::BoundedList<hider::PieceCut> cuts(buf.cuts.data(), buf.cuts.size());
    hider::BoundedList<uint32_t> order(buf.order.data(), pool);
    hider::View view;
    bench_begin();
    r.stats.status = detail::build_order(s, algo, buf, view, polys, cuts, order, r);
    bench_end();
    if (!r.stats.ok() && r.stats.status != hider::Status::capacity_exceeded) return r;  // a full pool still draws
    r.sink_ok = sink.begin_frame(sink.user, static_cast<uint16_t>(s.width), static_cast<uint16_t>(s.height));
    for (int32_t y0 = 0; y0 < s.height && r.sink_ok; y0 += buf.rows) {
        const int32_t y1 = hider::min(s.height, y0 + buf.rows);
        r.stats.merge(detail::paint_band(s, algo, buf, view, polys, cuts, order, y0, y1, r));
        r.sink_ok = sink.write_rows(sink.user, static_cast<uint16_t>(y0), static_cast<uint16_t>(y1 - y0), buf.color.data(),
                                    static_cast<uint32_t>(s.width));
    }
    const bool ended = sink.end_frame(sink.user);
    r.sink_ok = r.sink_ok && ended;
    return r;
}

/// Prints the counts of a render on the console (Io as in spin/app.hpp).
template <class Io>
void print_result(Io& io, Algo algo, const Result& r) {
    io.print(output_name(algo));
    io.print(": polygons built ");
    io.print_u32(r.polygons_built);
    io.print(", painted ");
    io.print_u32(r.polygons);
    io.print(", triangle setups ");
    io.print_u32(r.stats.triangles_drawn);
    io.print(", fragments ");
    io.print_u32(static_cast<uint32_t>(r.stats.fragments));  // a 160x128 frame stays far below 2^32
    io.print(", pixels written ");
    io.print_u32(static_cast<uint32_t>(r.stats.pixels_written));
    io.print("\n");
    if (algo != Algo::painter) {
        io.print("newell: pair tests ");
        io.print_u32(static_cast<uint32_t>(r.newell.pair_tests));
        io.print(", moves ");
        io.print_u32(r.newell.moves);
        io.print(", splits ");
        io.print_u32(r.newell.splits);
        io.print(", cycles ");
        io.print_u32(r.newell.cycles);
        io.print(", unresolved ");
        io.print_u32(r.newell.unresolved);
        io.print(", dropped ");
        io.print_u32(r.newell.dropped);
        io.print("\n");
    }
    if (algo == Algo::reverse) {
        io.print("reverse: pixels written ");
        io.print_u32(static_cast<uint32_t>(r.stats.pixels_written));
        io.print(", covered ");
        io.print_u32(r.covered);
        io.print(r.coverage_mismatches == 0 ? " (equal in every band)\n" : " (DIFFERENT)\n");
    }
}

/// The painter program: `s` drawn with `algo` into the PPM file output_name(algo). Returns the exit
/// status: 0 ok; 1 when a status is not ok, the sink or the file failed, or the reverse painter's
/// pixels written differ from its coverage bits set.
template <class Io>
int run(Io& io, const spin::Scene& s, Algo algo, const Buffers& buf, hider::Span<uint8_t> ppm_row) {
    const char* path = output_name(algo);
    if (!io.open(path)) {
        io.print("painter: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    spin::PpmSink<Io> ppm(io, ppm_row);
    const Result r = render_in_bands(s, algo, buf, ppm.sink());
    const bool closed = io.close();
    print_result(io, algo, r);
    return spin::stream_verdict(io, "painter", r.stats.status, r.sink_ok, ppm, closed, r.coverage_mismatches);
}

}  // namespace painter

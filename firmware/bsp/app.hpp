// The BSP examples, for firmware and host alike: a tree baked into flash by hider-bsp
// (firmware/common/scenes/bsp_*.hpp), checked once by bsp_load(), then drawn without a depth buffer:
// back to front (draw_bsp, or order_bsp once per frame and draw_bsp_list per band) or front to back with
// coverage bits (draw_bsp_front), band by band, each band streamed through spin::PpmSink. The z-buffer
// run draws the scene's mesh (hider-bake) the usual way, so the host can compare the two and the
// instruction counts show what the tree saves.
// Measured region (bench_begin..bench_end): view set-up and projection (for a tree walked per band:
// marking its vertices unprojected, since the walks project a vertex when a triangle first needs it; for
// the list: all of them, then its walk), then each band's clear and draw; bsp_load() and the sink are
// outside it.
#pragma once
#include <hider/bsp/order.hpp>
#include <hider/raster/zbuffer.hpp>

#include "common/bench.hpp"
#include "common/bits.hpp"
#include "display/sink.hpp"
#include "spin/ppm_sink.hpp"

namespace bspfw {

/// What draws the frame.
enum class Algo : uint8_t {
    back_to_front,  ///< draw_bsp: far subtree, the node, near subtree; every pixel painted over
    listed,         ///< the same order from one walk a frame (order_bsp), each band drawn from the list
    front_to_back,  ///< draw_bsp_front: each pixel written once, covered subtrees skipped
    zbuffer,        ///< the scene's mesh through draw_zbuffer (16-bit depth band)
};

/// Background colour of every frame.
constexpr hider::Rgb kBackground{0, 0, 0};

/// A scene as the examples draw it: a baked tree (or a baked mesh for Algo::zbuffer) and the camera.
struct Scene {
    hider::Span<const uint8_t> blob;  ///< the tree, 8-byte aligned (flash)
    hider::Mesh mesh;                 ///< the source mesh, for Algo::zbuffer
    hider::Camera camera;
    int32_t width, height;
    bool cull;  ///< back-face culling
};

/// Caller-owned storage of one render (statics on a device); Storage below declares it.
struct Buffers {
    hider::Span<hider::ScreenVertex> verts;  ///< one per tree (or mesh) vertex
    hider::Span<uint32_t> stack;             ///< bsp_stack_entries(the tree's depth)
    hider::Span<uint16_t> color;             ///< width * rows RGB565
    hider::Span<uint16_t> depth;             ///< width * rows (Algo::zbuffer only)
    hider::Span<uint32_t> coverage;          ///< coverage_words(width) * rows (Algo::front_to_back only)
    hider::Span<hider::BspDrawEntry> list;   ///< order_bsp's list (Algo::listed only): up to one per node
    hider::Span<uint8_t> ppm_row;            ///< 3 * width
    int32_t rows;                            ///< rows per band
};

/// Storage for kVertices vertices, a tree kDepth nodes deep and kRows-row bands kWidth wide; the depth
/// and coverage arrays only when the algorithm needs them, a draw list of kList entries (Algo::listed).
template <size_t kVertices, uint32_t kDepth, int32_t kWidth, int32_t kRows, bool kDepthBand, bool kCoverage, size_t kList = 1>
struct Storage {
    hider::ScreenVertex verts[kVertices];
    uint32_t stack[hider::bsp_stack_entries(kDepth)];
    uint16_t color[kWidth * kRows];
    uint16_t depth[kDepthBand ? kWidth * kRows : 1];
    uint32_t coverage[kCoverage ? hider::coverage_words(kWidth) * kRows : 1];
    hider::BspDrawEntry list[kList];
    uint8_t ppm_row[kWidth * 3];

    Buffers buffers() { return {verts, stack, color, depth, coverage, list, ppm_row, kRows}; }
};

/// What one render did: the bands' statistics summed, and for front to back the coverage check.
struct Result {
    hider::FrameStats stats;
    uint32_t covered = 0;              ///< front to back: coverage bits set at the end of each band, summed
    uint32_t coverage_mismatches = 0;  ///< front to back: bands whose pixels written differ from their bits set
    bool sink_ok = true;               ///< every sink call accepted
};

/// The options every example draws with: the defaults, culling as the scene says.
inline hider::DrawOptions opt_of(const Scene& s) {
    hider::DrawOptions opt;
    opt.cull = s.cull;
    return opt;
}

namespace detail {

/// Clears and draws rows [y0, y1) (inside the measured region); for front to back then checks that the
/// pixels written are exactly the coverage bits set (outside it).
inline hider::FrameStats draw_band(const Scene& s, Algo algo, const hider::BspTree& tree, const Buffers& buf,
                                   const hider::View& view, hider::Span<const hider::BspDrawEntry> list, int32_t y0,
                                   int32_t y1, Result& r) {
    const hider::DrawOptions opt = opt_of(s);
    hider::FrameStats st;
    bench_begin();
    if (algo == Algo::zbuffer) {
        const auto band = hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), buf.depth.data(), s.width,
                                                                          s.height, y0, y1);
        hider::clear(band, kBackground);
        st = hider::draw_zbuffer<false>(view, s.mesh, {buf.verts.data(), buf.verts.size()}, band, opt);
    } else {
        const auto band = hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), nullptr, s.width, s.height, y0, y1);
        hider::clear(band, kBackground);
        if (algo == Algo::listed)
            st = hider::draw_bsp_list(view, tree, {buf.verts.data(), buf.verts.size()}, list, band, opt);
        else
            st = algo == Algo::front_to_back
                     ? hider::draw_bsp_front(view, s.camera.eye, tree, buf.verts, band, opt, buf.stack, buf.coverage)
                     : hider::draw_bsp(view, s.camera.eye, tree, buf.verts, band, opt, buf.stack);
    }
    bench_end();
    if (algo == Algo::front_to_back) {
        const uint32_t set = ::bits_set(buf.coverage.data(), static_cast<size_t>(hider::coverage_words(s.width)) * (y1 - y0));
        r.covered += set;
        if (set != st.pixels_written) ++r.coverage_mismatches;
    }
    return st;
}

}  // namespace detail

/// Renders `s` with `algo` band by band into `sink` (begin_frame, write_rows per band, end_frame).
/// Borrows everything for the call. A blob that bsp_load() refuses (or storage too small) ends the
/// render before the sink is called, with the status in stats.
inline Result render_in_bands(const Scene& s, Algo algo, const Buffers& buf, const hider::port::BandSink& sink) {
    Result r;
    const size_t band_pixels = static_cast<size_t>(s.width) * static_cast<size_t>(buf.rows > 0 ? buf.rows : 0);
    if (!hider::port::is_complete(sink) || buf.rows < 1 || s.width > UINT16_MAX || s.height > UINT16_MAX ||
        buf.color.size() < band_pixels || (algo == Algo::zbuffer && buf.depth.size() < band_pixels)) {
        r.stats.status = hider::Status::invalid_argument;
        return r;
    }
    hider::BspTree tree;
    if (algo != Algo::zbuffer) {
        r.stats.status = hider::bsp_load(s.blob, buf.stack, tree);
        if (!r.stats.ok()) return r;
    }
    const hider::Span<const hider::Vec3q16> positions = algo == Algo::zbuffer ? s.mesh.positions : tree.vertices;
    hider::View view;
    hider::BoundedList<hider::BspDrawEntry> list(buf.list.data(), buf.list.size());
    bench_begin();
    r.stats.status = hider::make_view(s.camera, s.width, s.height, view);
    if (r.stats.ok()) {
        if (algo == Algo::zbuffer) {
            r.stats.status = hider::project_vertices(view, positions, buf.verts);
        } else if (buf.verts.size() < positions.size()) {
            r.stats.status = hider::Status::invalid_argument;
        } else {
            hider::mark_unprojected(buf.verts);  // the walks project each vertex when first drawn
            if (algo == Algo::listed)  // one walk a frame, projecting what its list will draw
                r.stats.merge(hider::order_bsp(view, s.camera.eye, tree, buf.verts, opt_of(s), buf.stack, list));
        }
    }
    bench_end();
    // A full draw list (capacity_exceeded) still gives a whole frame, without its nearest nodes; the status
    // stays in the result. Any other status ends the render.
    auto drawable = [&r] { return r.stats.ok() || r.stats.status == hider::Status::capacity_exceeded; };
    if (!drawable()) return r;
    r.sink_ok = sink.begin_frame(sink.user, static_cast<uint16_t>(s.width), static_cast<uint16_t>(s.height));
    for (int32_t y0 = 0; y0 < s.height && r.sink_ok && drawable(); y0 += buf.rows) {
        const int32_t y1 = hider::min(s.height, y0 + buf.rows);
        r.stats.merge(detail::draw_band(s, algo, tree, buf, view, {list.data(), list.size()}, y0, y1, r));
        r.sink_ok = sink.write_rows(sink.user, static_cast<uint16_t>(y0), static_cast<uint16_t>(y1 - y0), buf.color.data(),
                                    static_cast<uint32_t>(s.width));
    }
    const bool ended = sink.end_frame(sink.user);
    r.sink_ok = r.sink_ok && ended;
    return r;
}

/// Prints the counts of a render on the console (Io as in spin/app.hpp).
template <class Io>
void print_result(Io& io, const char* path, const Result& r) {
    io.print(path);
    io.print(": triangles drawn ");
    io.print_u32(r.stats.triangles_drawn);
    io.print(", culled ");
    io.print_u32(r.stats.triangles_culled);
    io.print(", fragments ");
    io.print_u32(static_cast<uint32_t>(r.stats.fragments));  // a 160x128 frame stays far below 2^32
    io.print(", pixels written ");
    io.print_u32(static_cast<uint32_t>(r.stats.pixels_written));
    io.print(", nodes visited ");
    io.print_u32(r.stats.nodes_visited);
    io.print(", subtrees skipped ");
    io.print_u32(r.stats.subtrees_skipped);
    io.print("\n");
}

/// The program: `s` drawn with `algo` into the PPM file `path`. Returns the exit status: 0 ok; 1 when a
/// status is not ok, the sink or the file failed, or front to back wrote a pixel other than once.
template <class Io>
int run(Io& io, const Scene& s, Algo algo, const Buffers& buf, const char* path) {
    if (!io.open(path)) {
        io.print("bsp: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    spin::PpmSink<Io> ppm(io, buf.ppm_row);
    const Result r = render_in_bands(s, algo, buf, ppm.sink());
    const bool closed = io.close();
    print_result(io, path, r);
    return spin::stream_verdict(io, "bsp", r.stats.status, r.sink_ok, ppm, closed, r.coverage_mismatches);
}

}  // namespace bspfw

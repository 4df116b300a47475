// The measured regions of hider-bench: extern "C" noinline functions that callgrind toggles on
// (--toggle-collect=hider_bench_frame / _span / _sort / _newell). They run lib/ code only: no
// allocation, no I/O. Everything they touch is prepared by the caller and passed in one job struct.
#pragma once
#include <hider/raster/zbuffer.hpp>
#include <hider/sort/newell.hpp>
#include <hider/sort/painter.hpp>

namespace hider::tool::bench {

/// One frame of lib/ work: inputs set once by the caller, outputs written by hider_bench_frame.
struct FrameJob {
    Camera camera{};
    int32_t width = 0, height = 0;
    Mesh mesh{};                  ///< validated once by the caller
    Span<ScreenVertex> verts;     ///< >= mesh.positions.size(), preallocated
    uint16_t* color = nullptr;    ///< width * height RGB565 pixels
    uint16_t* depth16 = nullptr;  ///< width * height, used when depth_bits == 16
    uint32_t* depth32 = nullptr;  ///< width * height, used when depth_bits == 32
    int depth_bits = 16;
    DrawOptions draw{};
    Rgb background{0, 0, 0};
    Status status = Status::ok;  ///< out: make_view / project_vertices result
    FrameStats stats{};          ///< out: draw_zbuffer result
};

/// One call of the z-buffer span on pixels [x0, x1) of a row with a flat RGB565 colour (the paired span
/// for 16-bit depth, span_depth_test<false> for 32-bit).
struct SpanJob {
    uint16_t* color = nullptr;
    uint16_t* depth16 = nullptr;  ///< used when depth32 is null
    uint32_t* depth32 = nullptr;
    int32_t x0 = 0, x1 = 0;
    uint32_t z_q32 = 0, dz_q32 = 0;
    uint16_t pixel = 0;
};

/// One painter_order call: back-to-front order of polys by farthest depth (key fill + radix sort).
struct SortJob {
    Span<const ScreenPoly> polys;
    Span<SortKey> keys;     ///< >= polys.size()
    Span<SortKey> scratch;  ///< >= polys.size()
    Span<uint32_t> order;   ///< >= polys.size(); out
};

/// One newell_order call: polys (cuts append), cuts and order are filled in place.
struct NewellJob {
    View view{};
    BoundedList<ScreenPoly>* polys = nullptr;
    BoundedList<PieceCut>* cuts = nullptr;
    NewellScratch scratch{};
    BoundedList<uint32_t>* order = nullptr;
    NewellStats stats{};         ///< out
    Status status = Status::ok;  ///< out
};

}  // namespace hider::tool::bench

/// make_view, project_vertices, clear (colour + depth), draw_zbuffer<false>: exactly one frame.
extern "C" __attribute__((noinline)) void hider_bench_frame(hider::tool::bench::FrameJob* job);

/// One z-buffer span call as described by `job`.
extern "C" __attribute__((noinline)) void hider_bench_span(const hider::tool::bench::SpanJob* job);

/// painter_order(job->polys, DepthKey::farthest, ...) into job->order.
extern "C" __attribute__((noinline)) void hider_bench_sort(const hider::tool::bench::SortJob* job);

/// newell_order(job->view, *job->polys, *job->cuts, job->scratch, *job->order, job->stats) -> job->status.
extern "C" __attribute__((noinline)) void hider_bench_newell(hider::tool::bench::NewellJob* job);

// The code callgrind counts: lib/ calls only. Kept in its own file so nothing from the driver
// (parsing, printing, allocation) can be inlined into the measured functions.
#include "measured.hpp"

namespace {

using namespace hider;
using hider::tool::bench::FrameJob;

template <class Depth>
FrameStats draw_frame(const View& view, const FrameJob& job, Depth* depth) {
    const auto frame = frame_view<Rgb565Format, Depth>(job.color, depth, job.width, job.height);
    clear(frame, job.background);
    return draw_zbuffer<false>(view, job.mesh, job.verts, frame, job.draw);
}

}  // namespace

extern "C" __attribute__((noinline)) void hider_bench_frame(FrameJob* job) {
    View view;
    job->status = make_view(job->camera, job->width, job->height, view);
    if (job->status != Status::ok) return;
    job->status = project_vertices(view, job->mesh.positions, job->verts);
    if (job->status != Status::ok) return;
    job->stats = job->depth_bits == 32 ? draw_frame(view, *job, job->depth32) : draw_frame(view, *job, job->depth16);
}

extern "C" __attribute__((noinline)) void hider_bench_span(const hider::tool::bench::SpanJob* job) {
    const FlatShader<uint16_t> shader{job->pixel};
    if (job->depth32 != nullptr) {
        (void)span_depth_test<false>(job->color, job->depth32, job->x0, job->x1, job->z_q32, job->dz_q32, shader);
    } else {  // what draw_zbuffer runs for RGB565 + 16-bit depth
        const PairedSpan<uint16_t, FlatShader<uint16_t>> span{
            job->dz_q32,
            static_cast<intptr_t>(reinterpret_cast<uintptr_t>(job->color) - reinterpret_cast<uintptr_t>(job->depth16)), shader};
        (void)span_depth_test_paired<false>(job->depth16 + job->x0, job->x1 - job->x0, job->z_q32, span);
    }
}

extern "C" __attribute__((noinline)) void hider_bench_sort(const hider::tool::bench::SortJob* job) {
    if (painter_order(job->polys, DepthKey::farthest, job->keys, job->scratch, job->order) != Status::ok) __builtin_trap();
}

extern "C" __attribute__((noinline)) void hider_bench_newell(hider::tool::bench::NewellJob* job) {
    job->status = newell_order(job->view, *job->polys, *job->cuts, job->scratch, *job->order, job->stats);
}

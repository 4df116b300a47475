// Random small scenes shared by the kernelcheck firmware and its host twin: each case is a view of a frame
// up to 24 x 24 pixels (random camera, field of view, near and far) and kDrawTriangles triangles over
// kVertexBatch positions placed around it (mostly on screen, some past the guard band or behind the eye,
// so some triangles are clipped; in odd cases all on screen), with random normals, culled or not. run_draw_cases() draws each case
// into kernelcheck's buffers with draw_flat_kernel() through `draw` (on Cortex-M the assembly draw loop)
// and through `twin` (the C++ loop) and folds the frame and the statistics into one digest per case.
#pragma once
#include <hider/raster/zbuffer.hpp>

#include "kernelcheck/vertex_cases.hpp"

namespace kernelcheck {

constexpr int kDrawCases = 80;
constexpr int kDrawTriangles = 40;
constexpr uint32_t kDrawSeed = 0x1B873593u;

struct DrawCase {
    hider::View view;
    hider::Vec3q16 p[kVertexBatch];
    hider::Tri tris[kDrawTriangles];
    hider::Normal14 normals[kDrawTriangles];
    bool cull;
};

/// One case; on_screen keeps every vertex in front of the eye and inside the guard band (no triangle
/// clipped: the Cortex-M3 loops' path without a clip test).
inline void make_draw_case(Rng& rng, DrawCase& c, bool on_screen = false) {
    using hider::Q16;
    for (;;) {
        hider::Camera cam;
        auto coord = [&rng](int32_t limit) { return Q16::from_raw(rng.range(-limit, limit)); };
        cam.eye = {coord(1 << 24), coord(1 << 24), coord(1 << 24)};
        cam.target = {coord(1 << 24), coord(1 << 24), coord(1 << 24)};
        cam.up = {Q16::from_raw(0), Q16::from_raw(65536), Q16::from_raw(0)};
        cam.fovy = hider::Angle::from_bam(0x08000000u + rng.next() % 0x60000000u);
        const int32_t near = hider::kMinNearRaw + rng.range(0, 1 << 20);
        const int32_t far = near + rng.range(1 << 16, 1 << 28);
        cam.near = Q16::from_raw(near);
        cam.far = Q16::from_raw(far);
        const int32_t width = rng.range(1, 24);
        const int32_t height = rng.range(1, 24);
        if (hider::make_view(cam, width, height, c.view) == hider::Status::ok) break;
    }
    const hider::View& v = c.view;
    for (hider::Vec3q16& p : c.p) {
        uint32_t kind = rng.next() % 8;
        if (on_screen && kind < 2) kind = 2;
        int64_t w = v.near_raw + static_cast<int64_t>(rng.next() % static_cast<uint32_t>(v.far_raw - v.near_raw + 1));
        if (kind == 0) w = -w / 4;  // behind the eye
        // Subpixel screen positions: mostly over the frame, some past the guard band.
        const int32_t reach = kind == 1 ? hider::kGuardBand + 2000 : 16 * (v.width + v.height) / 2 + 40;
        const int32_t sx = rng.range(-reach, reach);
        const int32_t sy = rng.range(-reach, reach);
        const int64_t wp = w < 1 ? 1 : w;
        p = world_of(v, int64_t{sx} * 256 * wp / v.k_q8, int64_t{-sy} * 256 * wp / v.k_q8, w);
    }
    for (hider::Tri& t : c.tris)
        for (uint16_t& i : t.v) i = static_cast<uint16_t>(rng.next() % kVertexBatch);
    for (hider::Normal14& n : c.normals) {
        n.x = static_cast<int16_t>(rng.range(-16384, 16384));
        n.y = static_cast<int16_t>(rng.range(-16384, 16384));
        n.z = static_cast<int16_t>(rng.range(-16384, 16384));
    }
    c.cull = (rng.next() & 3u) != 0;
}

/// Draws every case through `draw` (into out[kDrawCases]) and `twin` (a function of (view, mesh, verts,
/// frame, opt, stats)); returns the first case whose digests differ, or -1. The frame lives in b.
template <class Draw, class Twin>
int run_draw_cases(Draw&& draw, Twin&& twin, Buffers& b, uint32_t* out) {
    static_assert(24 * 24 <= kMaxRows * kWidth, "the largest case frame fits the buffers");
    Rng rng{kDrawSeed};
    int first_difference = -1;
    static DrawCase c;
    static hider::ScreenVertex verts[kVertexBatch];
    for (int i = 0; i < kDrawCases; ++i) {
        make_draw_case(rng, c, (i & 1) != 0);  // odd cases: every vertex projected
        (void)hider::project_vertices(c.view, {c.p, kVertexBatch}, {verts, kVertexBatch});
        hider::Mesh mesh;
        mesh.positions = {c.p, kVertexBatch};
        mesh.tris = {c.tris, kDrawTriangles};
        mesh.normals = {c.normals, kDrawTriangles};
        const auto frame = hider::frame_view<hider::Rgb565Format>(b.color, b.depth, c.view.width, c.view.height);
        hider::DrawOptions opt;
        opt.cull = c.cull;
        opt.base = {static_cast<uint8_t>(rng.next()), static_cast<uint8_t>(rng.next()), static_cast<uint8_t>(rng.next())};
        uint32_t digests[2];
        for (int pass = 0; pass < 2; ++pass) {
            hider::clear(frame, {1, 2, 3});
            hider::FrameStats st;
            if (pass == 0) draw(c.view, mesh, verts, frame, opt, st);
            else twin(c.view, mesh, verts, frame, opt, st);
            Fnv fnv;
            const uint32_t n = static_cast<uint32_t>(c.view.width * c.view.height);
            for (uint32_t k = 0; k < n; ++k) fnv.add(b.color[k] | (uint32_t{b.depth[k]} << 16));
            const uint32_t counts[] = {st.triangles_in, st.triangles_drawn, st.triangles_culled, st.triangles_clipped,
                                       st.triangles_outside};
            for (uint32_t x : counts) fnv.add(x);
            digests[pass] = fnv.h;
        }
        out[i] = digests[0];
        if (digests[1] != digests[0] && first_difference < 0) first_difference = i;
    }
    return first_difference;
}

}  // namespace kernelcheck

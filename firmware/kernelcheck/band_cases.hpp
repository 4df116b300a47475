// Random small scenes drawn band by band, shared by the kernelcheck firmware and its host twin. Each
// case is a draw case (draw_cases.hpp: a frame up to 24 x 24, 40 random triangles, some clipped), a
// quarter of its triangles repeating an earlier one so that depths tie, every other case with two
// triangles wholly above or below the frame (place_off_frame()), culled or not, drawn by the band
// renderer (binned.hpp; a quarter shaded by depth: the generic bands) in bands of 1 to 6 rows, rows 0 to
// 3 elements longer than the frame's width (the
// band buffer's stride: the pads must stay as they are), with 0 to 5 carried slots: set-ups are carried,
// resumed, refused a slot and set up again. run_band_cases() draws each case through `draw` (on ARMv7-M
// with the assembly band loop and binning pass, on ARMv6-M with the assembly resumes and binning pass, on
// RV32 with the assembly resumes) and `twin` (the C++ loops) and digests every band, the frame's statistics
// and the carried-slot figures.
#pragma once
#include <hider/raster/binned.hpp>

#include "kernelcheck/draw_cases.hpp"

namespace kernelcheck {

constexpr int kBandCases = 100;
constexpr uint32_t kBandSeed = 0x2545F491u;
constexpr int32_t kMaxBandRows = 6;
constexpr size_t kMaxSlots = 5;

/// What a band draw needs besides the scene: the frame's first `rows` rows of b as the band buffer.
struct BandSetup {
    hider::FrameView<hider::Rgb565Format, uint16_t> buffers;
    hider::DrawOptions opt;
    hider::BinnedScratch scratch;
};

/// Moves the last three positions of c wholly above (or below) the frame, in front of the eye and wide
/// of its side columns but inside the guard band, and links two triangles to them, one of each winding:
/// binned into the first (last) band by the clamp of their first row, where they find no row.
inline void place_off_frame(Rng& rng, DrawCase& c, bool below) {
    const hider::View& v = c.view;
    const int64_t w = v.near_raw + static_cast<int64_t>(rng.next() % static_cast<uint32_t>(v.far_raw - v.near_raw + 1));
    const int32_t side = below ? 1 : -1;
    const int32_t reach_x = 8 * v.width + 16;  // subpixels from the frame's centre: past its side columns
    const int32_t off_y = 8 * v.height + 16;   // past its top or bottom row
    const int32_t sx[3] = {-reach_x - rng.range(0, 64), reach_x + rng.range(0, 64), rng.range(-reach_x, reach_x)};
    const int32_t sy[3] = {side * (off_y + rng.range(0, 64)), side * (off_y + rng.range(0, 64)),
                           side * (off_y + 64 + rng.range(0, 256))};
    for (int k = 0; k < 3; ++k)
        c.p[kVertexBatch - 3 + k] = world_of(v, int64_t{sx[k]} * 256 * w / v.k_q8, int64_t{-sy[k]} * 256 * w / v.k_q8, w);
    constexpr uint16_t a = kVertexBatch - 3, b = kVertexBatch - 2, d = kVertexBatch - 1;
    c.tris[rng.next() % kDrawTriangles] = {{a, b, d}};
    c.tris[rng.next() % kDrawTriangles] = {{a, d, b}};
}

/// Draws every case through `draw` and `twin` (functions of (view, mesh, verts, setup, done, binned
/// stats) returning the FrameStats), digests into out[kBandCases]; returns the first case whose digests
/// differ, or -1.
template <class Draw, class Twin>
int run_band_cases(Draw&& draw, Twin&& twin, Buffers& b, uint32_t* out) {
    static_assert(24 * kMaxBandRows <= kMaxRows * kWidth, "the largest band fits the buffers");
    Rng rng{kBandSeed};
    int first_difference = -1;
    static DrawCase c;
    static hider::ScreenVertex verts[kVertexBatch];
    static uint16_t next[kDrawTriangles];
    static uint16_t head[24 + 1];  // one past the most bands: a list head the binning must never write
    static hider::KernelTriangle carried[kMaxSlots];
    static uint8_t slots[3 * kMaxSlots];
    for (int i = 0; i < kBandCases; ++i) {
        make_draw_case(rng, c);
        // A quarter of the triangles repeat an earlier one (another normal, so another colour): depths tie,
        // and the first in mesh order must win in every band, carried or not.
        for (int k = 0; k < kDrawTriangles / 4; ++k) {
            const uint32_t to = 1 + rng.next() % (kDrawTriangles - 1);
            c.tris[to] = c.tris[rng.next() % to];
        }
        if ((i & 1) != 0) place_off_frame(rng, c, (i & 2) != 0);
        c.cull = (rng.next() & 1u) != 0;  // half of them draw back faces too
        (void)hider::project_vertices(c.view, {c.p, kVertexBatch}, {verts, kVertexBatch});
        hider::Mesh mesh;
        mesh.positions = {c.p, kVertexBatch};
        mesh.tris = {c.tris, kDrawTriangles};
        mesh.normals = {c.normals, kDrawTriangles};
        const int32_t rows = rng.range(1, kMaxBandRows);
        const size_t slot_count = rng.next() % (kMaxSlots + 1);
        BandSetup s;
        s.buffers = hider::band_view<hider::Rgb565Format, uint16_t>(b.color, b.depth, c.view.width, c.view.height, 0,
                                                                     hider::min(rows, c.view.height));
        s.buffers.stride = c.view.width + rng.range(0, 3);  // 0 to 3 spare elements a row, never written
        s.opt.cull = c.cull;
        s.opt.base = {static_cast<uint8_t>(rng.next()), static_cast<uint8_t>(rng.next()), static_cast<uint8_t>(rng.next())};
        if (i % 8 == 3 || i % 8 == 5) s.opt.shade = hider::Shade::depth;  // the generic bands, off-frame triangles below, above
        const size_t bands = static_cast<size_t>((c.view.height + s.buffers.y1 - 1) / s.buffers.y1);
        s.scratch = {{next, kDrawTriangles}, {head, bands}, {carried, slot_count}, {slots, 3 * slot_count}};
        uint32_t digests[2];
        for (int pass = 0; pass < 2; ++pass) {
            Fnv fnv;
            for (int32_t k = 0; k < kMaxRows * kWidth; ++k) {  // the pads keep these: digested with the rows
                b.color[k] = 0x5A5A;
                b.depth[k] = 0xA5A5;
            }
            auto done = [&](const hider::FrameView<hider::Rgb565Format, uint16_t>& band) {
                fnv.add(static_cast<uint32_t>(band.y0) | static_cast<uint32_t>(band.stride) << 16);
                for (int32_t y = band.y0; y < band.y1; ++y)
                    for (int32_t x = 0; x < band.stride; ++x) fnv.add(band.row(y)[x] | (uint32_t{band.depth_row(y)[x]} << 16));
                return true;
            };
            for (size_t k = bands; k < 25; ++k) head[k] = 0x5A5A;  // past the scratch: must stay as it is
            hider::BinnedStats bs;
            const hider::FrameStats st = pass == 0 ? draw(c.view, mesh, verts, s, done, bs) : twin(c.view, mesh, verts, s, done, bs);
            const uint32_t counts[] = {static_cast<uint32_t>(st.status), st.triangles_in, st.triangles_drawn,
                                       st.triangles_culled, st.triangles_clipped, st.triangles_outside,
                                       bs.carried, bs.set_up_again, bs.carried_high_water};
            for (uint32_t x : counts) fnv.add(x);
            for (size_t k = bands; k < 25; ++k) fnv.add(head[k]);
            digests[pass] = fnv.h;
        }
        out[i] = digests[0];
        if (digests[1] != digests[0] && first_difference < 0) first_difference = i;
    }
    return first_difference;
}

}  // namespace kernelcheck

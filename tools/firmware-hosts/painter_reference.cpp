// Host twin of painter_plain, painter_newell and painter_reverse: the same scene, storage and band
// renderer (painter/app.hpp) compiled for the host, writing painter.ppm, newell.ppm and reverse.ppm
// into the current directory. Then checks on the host that one 128-row band gives the same bytes as
// the 16-row bands, and that Newell's and the reverse painter's frames agree with a z-buffer render
// of the same scene (draw_zbuffer, 32-bit depth; written as zbuffer.ppm) on >= 99.9% of the pixels
// (the 16-bit z-buffer, zbuffer16.ppm, is reported only). Exit 0 ok, 1 on a failure.
#include <cstdio>
#include <vector>

#include "painter/torus.hpp"
#include "spin/app.hpp"
#include "capture_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

using spin::CaptureIo;

painter::TorusStorage g_storage;
const spin::Scene kScene = painter::torus_scene();
constexpr int32_t kPixels = painter::torus::kWidth * painter::torus::kHeight;

/// The PPM bytes of `algo` drawn in bands of `rows` rows; writes the file too when `disk`. Empty on failure.
std::vector<uint8_t> render(painter::Algo algo, int32_t rows, bool disk) {
    CaptureIo io;
    io.disk = disk;
    io.quiet = !disk;
    std::vector<uint16_t> color(static_cast<size_t>(kScene.width) * rows);
    std::vector<uint32_t> coverage(static_cast<size_t>(hider::coverage_words(kScene.width)) * rows);
    painter::Buffers buf = g_storage.buffers();
    buf.color = {color.data(), color.size()};
    buf.coverage = {coverage.data(), coverage.size()};
    buf.rows = rows;
    if (painter::run(io, kScene, algo, buf, g_storage.ppm_row) != 0) return {};
    return io.bytes;
}

/// PPM bytes of the z-buffered frame of the same view, options and projection (full frame, `Depth`
/// bits of depth), also written as `path`. Empty on failure.
template <class Depth>
std::vector<uint8_t> zbuffer_ppm(const char* path) {
    static uint16_t color[kPixels];
    static Depth depth[kPixels];
    hider::View view;
    if (hider::make_view(kScene.camera, kScene.width, kScene.height, view) != hider::Status::ok ||
        hider::project_vertices(view, kScene.mesh.positions, g_storage.verts) != hider::Status::ok)
        return {};
    const auto frame = hider::frame_view<hider::Rgb565Format, Depth>(color, depth, kScene.width, kScene.height);
    hider::clear(frame, spin::kBackground);
    const hider::FrameStats st = hider::draw_zbuffer<false>(view, kScene.mesh, g_storage.verts, frame, painter::draw_options());
    CaptureIo io;
    io.disk = true;
    if (!st.ok() || !spin::write_frame_ppm(io, path, color, kScene.width, kScene.height, g_storage.ppm_row)) return {};
    return io.bytes;
}

}  // namespace

int main() {
    const painter::Algo algos[] = {painter::Algo::painter, painter::Algo::newell, painter::Algo::reverse};
    std::vector<uint8_t> banded[3];
    for (int k = 0; k < 3; ++k) {
        banded[k] = render(algos[k], painter::kBandRows, true);
        if (banded[k].empty()) return 1;
        if (render(algos[k], kScene.height, false) != banded[k]) {
            std::fprintf(stderr, "painter_reference: %s: one full-height band differs from %d-row bands\n",
                         painter::output_name(algos[k]), static_cast<int>(painter::kBandRows));
            return 1;
        }
    }
    const std::vector<uint8_t> zbuffer = zbuffer_ppm<uint32_t>("zbuffer.ppm");
    const std::vector<uint8_t> zbuffer16 = zbuffer_ppm<uint16_t>("zbuffer16.ppm");
    if (zbuffer.empty() || zbuffer16.empty()) {
        std::fputs("painter_reference: z-buffer render failed\n", stderr);
        return 1;
    }
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
        const int32_t diff = spin::pixel_mismatches(banded[k], zbuffer, kPixels);
        const bool must_agree = algos[k] != painter::Algo::painter;  // the plain painter's errors are expected
        const bool agrees = int64_t{kPixels - diff} * 1000 >= int64_t{kPixels} * 999;
        std::printf("%s vs z-buffer: %d of %d pixels differ (%.3f%% equal)%s; vs 16-bit z-buffer: %d\n",
                    painter::output_name(algos[k]), static_cast<int>(diff), static_cast<int>(kPixels),
                    100.0 * (kPixels - diff) / kPixels,
                    must_agree ? (agrees ? ", >= 99.9%: ok" : ", below 99.9%: FAIL") : "",
                    static_cast<int>(spin::pixel_mismatches(banded[k], zbuffer16, kPixels)));
        ok = ok && (agrees || !must_agree);
    }
    return ok ? 0 : 1;
}

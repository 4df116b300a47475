// Host twin of bsp_torus, bsp_city and bsp_city_zbuffer: the same scenes, storage and band renderer
// (bsp/app.hpp) compiled for the host, writing bsp_torus.ppm, bsp_city.ppm and bsp_city_zbuffer.ppm into
// the current directory. Then checks on the host: the torus in one 128-row band, the torus walked in each
// band (draw_bsp) and the city in 8-row bands give the same bytes as the firmware's bands; the trees agree with a z-buffer render of their
// source mesh on >= 99.9% of the pixels (the torus against the baked torus mesh without culling, 32-bit
// depth; the city against bsp_city_zbuffer); front to back wrote each pixel once (checked per band by
// run()). Prints the counts. Exit 0 ok, 1 on a failure.
#include <cstdio>
#include <vector>

#include "bsp/scenes.hpp"
#include "common/scenes/torus_160x128.hpp"
#include "capture_io.hpp"

extern "C" void bench_begin() {}
extern "C" void bench_end() {}

namespace {

using spin::CaptureIo;

bspfw::TorusStorage g_torus;
bspfw::CityStorage g_city;
bspfw::CityZStorage g_city_z;

/// The PPM bytes of `algo` drawing `s` in bands of `rows` rows (storage `buf` with its band arrays
/// replaced); writes the file `path` too when `disk`. Empty on failure.
std::vector<uint8_t> render(const bspfw::Scene& s, bspfw::Algo algo, bspfw::Buffers buf, int32_t rows, const char* path, bool disk) {
    CaptureIo io;
    io.disk = disk;
    io.quiet = !disk;
    std::vector<uint16_t> color(static_cast<size_t>(s.width) * rows), depth(static_cast<size_t>(s.width) * rows);
    std::vector<uint32_t> coverage(static_cast<size_t>(hider::coverage_words(s.width)) * rows);
    buf.color = {color.data(), color.size()};
    buf.depth = {depth.data(), depth.size()};
    buf.coverage = {coverage.data(), coverage.size()};
    buf.rows = rows;
    if (bspfw::run(io, s, algo, buf, path) != 0) return {};
    return io.bytes;
}

bool agrees(const char* what, const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int32_t pixels) {
    const int32_t diff = spin::pixel_mismatches(a, b, pixels);
    const bool ok = int64_t{pixels - diff} * 1000 >= int64_t{pixels} * 999;
    std::printf("%s: %d of %d pixels differ (%.3f%% equal)%s\n", what, static_cast<int>(diff), static_cast<int>(pixels),
                100.0 * (pixels - diff) / pixels, ok ? ", >= 99.9%: ok" : ", below 99.9%: FAIL");
    return ok;
}

bool same(const char* what, const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    if (!a.empty() && a == b) return true;
    std::fprintf(stderr, "bsp_reference: %s differ\n", what);
    return false;
}

}  // namespace

int main() {
    namespace bf = bspfw;
    const bf::Scene torus = bf::torus_scene(), city = bf::city_scene(), city_mesh = bf::city_mesh_scene();
    const auto torus_ppm = render(torus, bf::Algo::listed, g_torus.buffers(), bf::kTorusRows, "bsp_torus.ppm", true);
    const auto city_ppm = render(city, bf::Algo::front_to_back, g_city.buffers(), city.height, "bsp_city.ppm", true);
    const auto city_z_ppm = render(city_mesh, bf::Algo::zbuffer, g_city_z.buffers(), city.height, "bsp_city_zbuffer.ppm", true);
    if (torus_ppm.empty() || city_ppm.empty() || city_z_ppm.empty()) return 1;
    bool ok = same("bsp_torus in one band and in 16-row bands",
                   render(torus, bf::Algo::listed, g_torus.buffers(), torus.height, "", false), torus_ppm);
    ok = same("bsp_torus from its draw list and walked in each band",
              render(torus, bf::Algo::back_to_front, g_torus.buffers(), bf::kTorusRows, "", false), torus_ppm) && ok;
    ok = same("bsp_city in 8-row bands and in one band", render(city, bf::Algo::front_to_back, g_city.buffers(), 8, "", false),
              city_ppm) && ok;
    ok = same("bsp_city back to front and front to back", render(city, bf::Algo::back_to_front, g_city.buffers(), 8, "", false),
              city_ppm) && ok;

    // A draw list one entry short: the whole frame is still streamed, the status says capacity_exceeded
    // and the run fails; only the nearest node's pixels are missing.
    {
        CaptureIo io;
        io.quiet = true;
        bf::Buffers buf = g_torus.buffers();
        std::vector<uint16_t> color(static_cast<size_t>(torus.width) * bf::kTorusRows);
        buf.color = {color.data(), color.size()};
        buf.rows = bf::kTorusRows;
        hider::View view;
        std::vector<hider::BspDrawEntry> all(buf.list.size());
        hider::BspTree tree;
        if (hider::bsp_load(torus.blob, buf.stack, tree) != hider::Status::ok ||
            hider::make_view(torus.camera, torus.width, torus.height, view) != hider::Status::ok ||
            hider::project_vertices(view, tree.vertices, buf.verts) != hider::Status::ok)
            return 1;
        hider::BoundedList<hider::BspDrawEntry> full(all.data(), all.size());
        if (!hider::order_bsp(view, torus.camera.eye, tree, buf.verts, bf::opt_of(torus), buf.stack, full).ok()) return 1;
        const size_t needed = full.size();
        buf.list = {buf.list.data(), needed - 1};
        const int failed = bf::run(io, torus, bf::Algo::listed, buf, "short_list.ppm");
        const int32_t pixels = torus.width * torus.height;
        const int32_t diff = io.bytes.size() == torus_ppm.size() ? spin::pixel_mismatches(io.bytes, torus_ppm, pixels) : -1;
        const bool short_ok = failed == 1 && diff > 0 && diff < pixels / 100;
        std::printf("bsp_torus with a list of %zu entries for %zu: run %s, %d pixels differ from the whole list%s\n",
                    needed - 1, needed, failed == 1 ? "failed" : "passed", static_cast<int>(diff), short_ok ? ": ok" : ": FAIL");
        ok = short_ok && ok;
    }

    // The torus mesh z-buffered without culling (the tree's source, same camera).
    namespace tm = hider::scenes::torus_160x128;
    static bf::Storage<tm::kVertexCount, 1, tm::kWidth, tm::kHeight, true, false> torus_z;
    bf::Scene torus_mesh{{}, tm::mesh(), tm::kCamera, tm::kWidth, tm::kHeight, false};
    const auto torus_z_ppm = render(torus_mesh, bf::Algo::zbuffer, torus_z.buffers(), tm::kHeight, "bsp_torus_zbuffer.ppm", true);
    ok = agrees("bsp_torus vs its mesh z-buffered", torus_ppm, torus_z_ppm, torus.width * torus.height) && ok;
    ok = agrees("bsp_city vs bsp_city_zbuffer", city_ppm, city_z_ppm, city.width * city.height) && ok;
    return ok ? 0 : 1;
}

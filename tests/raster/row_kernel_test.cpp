// The z-buffer's fast path on the host: draw_zbuffer<false> sends flat RGB565 triangles over 16-bit depth
// through the row kernel (row_kernel.hpp, the portable loop here), the others through the paired span;
// draw_zbuffer<true> (what hider-render and the goldens use) counts fragments and never takes the kernel.
// Both must write exactly the same bytes on every shipped model, culled or not, whole or in bands.
#include <hider/raster/zbuffer.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

namespace {

struct Frame565 {
    std::vector<uint16_t> color, depth;
    FrameStats stats;
};

/// Draws `s` band by band (rows = 0: whole frame) with draw_zbuffer<kCount>, RGB565 over 16-bit depth.
template <bool kCount>
Frame565 draw(const tool::Scene& s, const DrawOptions& opt, int rows) {
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    const Mesh mesh = s.mesh();
    std::vector<ScreenVertex> verts(mesh.positions.size());
    REQUIRE(project_vertices(view, mesh.positions, {verts.data(), verts.size()}) == Status::ok);
    const int band_rows = rows > 0 ? rows : s.height;
    Frame565 out;
    out.color.assign(static_cast<size_t>(s.width) * s.height, 0);
    out.depth.assign(out.color.size(), 0);
    for (int y0 = 0; y0 < s.height; y0 += band_rows) {
        const int y1 = std::min(s.height, y0 + band_rows);
        const size_t at = static_cast<size_t>(y0) * s.width;
        const auto band = band_view<Rgb565Format, uint16_t>(&out.color[at], &out.depth[at], s.width, s.height, y0, y1);
        clear(band, Rgb{3, 4, 5});
        const FrameStats st = draw_zbuffer<kCount>(view, mesh, {verts.data(), verts.size()}, band, opt);
        REQUIRE(st.ok());
        out.stats.triangles_drawn += st.triangles_drawn;
        out.stats.triangles_culled += st.triangles_culled;
    }
    return out;
}

std::vector<std::string> shipped_models() {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(std::string(HIDER_TEST_DATA) + "/models"))
        if (e.path().extension() == ".obj") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST_CASE("the row-kernel path gives exactly the bytes of the counting path on every shipped model") {
    const std::vector<std::string> models = shipped_models();
    REQUIRE(models.size() >= 9);
    for (const std::string& name : models) {
        tool::CameraArgs cam;
        if (name == "torus.obj") {  // the benchmark view (firmware/spin): the whole torus inside the columns
            cam.eye = tool::Vec3d{0, 0, -2.5};
            cam.target = tool::Vec3d{0, 0, 0};
            cam.fov_deg = 73.7398;
            cam.near = 0.25;
        }
        const tool::Scene s = test::load_model(name, cam);
        const bool big = s.tris.size() > 20000;
        for (bool cull : {true, false})
            for (Shade shade : {Shade::headlight, Shade::id}) {  // id: a different colour per triangle shows order
                DrawOptions opt;
                opt.cull = cull;
                opt.shade = shade;
                const Frame565 counted = draw<true>(s, opt, 0);
                long covered = 0;
                for (uint16_t d : counted.depth) covered += d != 0xFFFF;
                CHECK_MESSAGE(covered > 2000, name);
                for (int rows : {0, 1, 8, 61}) {
                    if (big && rows == 1) continue;  // 240 walks of 69,451 triangles: slow under the sanitizers
                    CAPTURE(name);
                    CAPTURE(cull);
                    CAPTURE(rows);
                    CAPTURE(static_cast<int>(shade));
                    const Frame565 fast = draw<false>(s, opt, rows);
                    CHECK(fast.color == counted.color);
                    CHECK(fast.depth == counted.depth);
                    CHECK(fast.stats.triangles_culled == counted.stats.triangles_culled);
                    CHECK(fast.stats.triangles_drawn == counted.stats.triangles_drawn);
                }
            }
    }
}

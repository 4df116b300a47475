// hider-bench carry: what carrying a triangle from band to band asks of a carried record, on the torus's
// standard view at 320x240 (the frame of firmware/spin320 and bands320), by band height: the triangles the
// row kernel draws, those that continue past the band that set them up, and those whose rows reach the
// middle vertex only in a later band (a record without the lower short edge would set that edge up
// there, division included). Counted on the host from the kernel set-ups of the whole frame.
#include <cinttypes>
#include <cstdio>

#include <hider/raster/kernel_triangle.hpp>

#include "bench.hpp"

namespace hider::tool::bench {

int carry_command(const Args& args) {
    std::string models = default_models_dir();
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--models") models = option_value(args, i);
        else fail("carry: unknown option '" + args[i] + "'");
    }
    const std::string path = models + "/torus.obj";
    ObjModel model;
    ObjError err;
    if (!load_obj(path, model, err)) fail(format(err));
    Scene scene;
    std::string why;
    if (!build_scene(model, camera_from(torus_view("320x240")), scene, why)) fail(path + ": " + why);
    const Mesh mesh = scene.mesh();
    View view;
    std::vector<ScreenVertex> verts(mesh.positions.size());
    if (make_view(scene.camera, scene.width, scene.height, view) != Status::ok ||
        project_vertices(view, mesh.positions, {verts.data(), verts.size()}) != Status::ok)
        fail(path + ": the view or the projection failed");
    const KernelBand band = kernel_band(scene.width, scene.height, 0, scene.height, 2 * scene.width);
    // Rows of every triangle the kernel draws (culled as the frame culls): first, middle, end.
    struct Rows {
        int32_t top, mid, end;
    };
    std::vector<Rows> drawn;
    uint32_t generic = 0;
    for (const Tri& t : mesh.tris) {
        const ScreenVertex &a = verts[t.v[0]], &b = verts[t.v[1]], &c = verts[t.v[2]];
        if (a.z == 0 || b.z == 0 || c.z == 0) fail(path + ": a vertex is clipped (not the standard view?)");
        const int32_t area = TriangleRaster::signed_area(a, b, c);
        if (area >= 0) continue;  // culled, or no area
        KernelTriangle kt;
        const KernelSetup s = kernel_setup_portable(a, b, c, area, band, kt);
        if (s == KernelSetup::generic) ++generic;
        if (s != KernelSetup::kernel || kt.row >= kt.end) continue;
        drawn.push_back({kt.row, kt.mid, kt.end});
    }
    std::printf("Carried set-ups of the torus at 320x240 (standard view, culled): %zu triangles drawn by the row kernel "
                "(%" PRIu32 " generic)\n\n",
                drawn.size(), generic);
    std::printf("| rows per band | continue past their first band | reach the middle row in a later band |\n");
    std::printf("|---:|---:|---:|\n");
    for (int32_t rows : {3, 4, 5, 6, 8, 16}) {
        uint32_t carried = 0, later_mid = 0;
        for (const Rows& r : drawn) {
            const int32_t band_end = (r.top / rows + 1) * rows;
            carried += r.end > band_end;
            later_mid += r.mid >= band_end && r.mid < r.end;
        }
        std::printf("| %d | %" PRIu32 " | %" PRIu32 " |\n", rows, carried, later_mid);
    }
    return 0;
}

}  // namespace hider::tool::bench

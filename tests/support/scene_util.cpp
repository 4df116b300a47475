// Test glue between fixed-point scenes and the double reference.
#include "support/scene_util.hpp"

#include <cmath>

#include <doctest/doctest.h>

#include <hider/raster/zbuffer.hpp>

#include "common/gen_scenes.hpp"
#include "host/ppm.hpp"

namespace hider::test {

bool scene_from_ref(const ref::RefScene& in, tool::Scene& out, std::string& error) {
    tool::ObjModel model;
    for (const ref::RefTriangle& t : in.tris) {
        tool::ObjFace f;
        for (const ref::Vec3d& v : t.v) {
            f.v.push_back(static_cast<int32_t>(model.vertices.size()));
            model.vertices.push_back({v.x, v.y, v.z});
        }
        f.id = t.id;
        model.faces.push_back(f);
    }
    tool::CameraArgs cam;
    cam.eye = tool::Vec3d{in.cam.eye.x, in.cam.eye.y, in.cam.eye.z};
    cam.target = tool::Vec3d{in.cam.target.x, in.cam.target.y, in.cam.target.z};
    cam.up = tool::Vec3d{in.cam.up.x, in.cam.up.y, in.cam.up.z};
    cam.fov_deg = in.cam.fovy_deg;
    cam.near = in.cam.near;
    cam.far = in.cam.far;
    cam.width = in.cam.width;
    cam.height = in.cam.height;
    return tool::build_scene(model, cam, out, error);
}

tool::Scene load_model(const std::string& name, const tool::CameraArgs& cam) {
    tool::ObjModel model;
    tool::ObjError err;
    tool::Scene s;
    const bool loaded = tool::load_obj(std::string(HIDER_TEST_DATA) + "/models/" + name, model, err);
    REQUIRE_MESSAGE(loaded, tool::format(err));
    std::string why;
    const bool built = tool::build_scene(model, cam, s, why);
    REQUIRE_MESSAGE(built, why);
    return s;
}

std::vector<ref::RefTriangle> ref_triangles(const tool::Scene& s) {
    std::vector<ref::RefTriangle> out;
    out.reserve(s.tris.size());
    for (size_t i = 0; i < s.tris.size(); ++i) {
        ref::RefTriangle t{};
        for (int k = 0; k < 3; ++k) {
            const Vec3q16& p = s.positions[s.tris[i].v[k]];
            t.v[k] = {tool::to_double(p.x), tool::to_double(p.y), tool::to_double(p.z)};
        }
        t.id = s.ids[i];
        out.push_back(t);
    }
    return out;
}

ref::RefCamera ref_camera(const tool::Scene& s) {
    const Camera& c = s.camera;
    auto v = [](const Vec3q16& p) { return ref::Vec3d{tool::to_double(p.x), tool::to_double(p.y), tool::to_double(p.z)}; };
    return {v(c.eye), v(c.target), v(c.up), c.fovy.bam() / 4294967296.0 * 360.0, tool::to_double(c.near),
            tool::to_double(c.far), s.width, s.height};
}

std::vector<std::pair<std::string, tool::Scene>> scenes_from_ref(const std::vector<ref::RefScene>& scenes) {
    std::vector<std::pair<std::string, tool::Scene>> out;
    for (const ref::RefScene& rs : scenes) {
        tool::Scene s;
        std::string why;
        REQUIRE_MESSAGE(scene_from_ref(rs, s, why), why);
        out.push_back({rs.name, s});
    }
    return out;
}

tool::RenderResult render_ids(const tool::Scene& s, tool::Algo algo, bool cull, int depth_bits, int band) {
    tool::RenderOptions opt;
    opt.algo = algo;
    opt.cull = cull;
    opt.shade = Shade::id;
    opt.format = tool::PixelFormat::rgb888;
    opt.depth_bits = depth_bits;
    opt.band_rows = band;
    tool::RenderResult r;
    std::string why;
    const bool ok = tool::render(s, opt, r, why);
    REQUIRE_MESSAGE(ok, why);
    return r;
}

std::vector<uint32_t> hider_ids(const tool::Scene& s, bool cull, int depth_bits) {
    return tool::decode_ids(render_ids(s, tool::Algo::zbuffer, cull, depth_bits));
}

std::vector<int> coverage_counts(const tool::Scene& s, bool cull) {
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    const Mesh mesh = s.mesh();
    std::vector<ScreenVertex> verts(mesh.positions.size());
    REQUIRE(project_vertices(view, mesh.positions, {verts.data(), verts.size()}) == Status::ok);
    std::vector<int> counts(static_cast<size_t>(s.width) * s.height, 0);
    FrameStats st;
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        for_each_clipped(view, mesh, {verts.data(), verts.size()}, t, st,
                               [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
                                   const int32_t area = TriangleRaster::signed_area(a, b, c);
                                   if (area == 0 || (cull && area > 0)) return;
                                   TriangleRaster tr;
                                   tr.setup(a, b, c, s.width, s.height);
                                   tr.spans(max(0, tr.first_row()), min(s.height, tr.end_row()),
                                            [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
                                                for (int32_t x = x0; x < x1; ++x) ++counts[static_cast<size_t>(y) * s.width + x];
                                            });
                               });
    }
    return counts;
}

Defects count_defects(const std::vector<uint32_t>& ids, const std::vector<uint32_t>& z, int w, int h) {
    Defects d;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const uint32_t c = z[static_cast<size_t>(y) * w + x], got = ids[static_cast<size_t>(y) * w + x];
            if (c == 0 || got == c) continue;
            // Inside the silhouette: every neighbour covered; inside the face: every neighbour that face.
            bool covered = x > 0 && y > 0 && x + 1 < w && y + 1 < h, same = covered;
            for (int dy = -1; dy <= 1 && covered; ++dy)
                for (int dx = -1; dx <= 1 && covered; ++dx) {
                    const uint32_t n = z[static_cast<size_t>(y + dy) * w + x + dx];
                    covered = n != 0;
                    same = same && n == c;
                }
            if (got == 0) d.holes += covered;
            else d.cracks += same;
        }
    return d;
}

tool::Scene generated_scene(const std::string& name) {
    tool::gen::GenScene g;
    std::string why;
    const bool known = tool::gen::by_name(name, g, why);
    REQUIRE_MESSAGE(known, why);
    tool::Scene s;
    const bool built = tool::build_scene(tool::gen::obj_model(g), tool::gen::camera_args(g), s, why);
    REQUIRE_MESSAGE(built, why);
    return s;
}

void add_face(tool::ObjModel& m, int a, int b, int c) {
    tool::ObjFace f;
    f.v = {a, b, c};
    f.id = static_cast<uint32_t>(m.faces.size() + 1);
    m.faces.push_back(f);
}

tool::Scene uv_sphere(int slices, int stacks, int width, int height) {
    tool::ObjModel m;
    const double pi = 3.14159265358979323846;
    m.vertices.push_back({0, 1, 0});
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const double th = pi * i / stacks, ph = 2 * pi * j / slices;
            m.vertices.push_back({std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)});
        }
    m.vertices.push_back({0, -1, 0});
    const int south = static_cast<int>(m.vertices.size()) - 1;
    auto at = [&](int i, int j) { return 1 + (i - 1) * slices + (j % slices); };
    for (int j = 0; j < slices; ++j) add_face(m, 0, at(1, j + 1), at(1, j));
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            add_face(m, at(i, j), at(i, j + 1), at(i + 1, j + 1));
            add_face(m, at(i, j), at(i + 1, j + 1), at(i + 1, j));
        }
    for (int j = 0; j < slices; ++j) add_face(m, south, at(stacks - 1, j), at(stacks - 1, j + 1));
    tool::CameraArgs cam;
    cam.width = width;
    cam.height = height;
    tool::Scene s;
    std::string why;
    const bool built = tool::build_scene(m, cam, s, why);
    REQUIRE_MESSAGE(built, why);
    return s;
}

void dump_ppm(const std::string& name, int width, int height, const std::vector<uint8_t>& rgb) {
    std::string err;
    port::write_ppm(std::string(HIDER_TEST_OUT) + "/" + name + ".ppm", width, height, rgb, err);
}

}  // namespace hider::test

// Red-team pass over check_view_range() (88166bf): three placements it judges wrongly.
//  1. with_model() composes the translation with apply(), which wraps modulo 2^32 like the points: a
//     model 44,000 units behind the eye composes to a translation 25,536 units in front of it, which the
//     check (seeing only the composed transform) accepts, and the mesh is drawn there with status ok.
//  2. A view z of exactly INT32_MIN (2^15 units in front) passes the exact test (it is an int32), but
//     to_view_point() negates it (w = -z: signed overflow), so the vertex counts as behind the near plane
//     and the clipper draws a wedge across the frame with status ok.
//  3. compose()'s floored products give an entry of -2^30 - 1 for a camera at (100, 0, -100) looking at
//     the origin and a model turned 45 degrees about y (rotation_y()), which the check refuses as "no
//     rotation": an ordinary scene inside the world range draws nothing (invalid_argument).
#include <hider/raster/zbuffer.hpp>

#include <vector>

#include <doctest/doctest.h>

#include "support/reference.hpp"

using namespace hider;

namespace {

Vec3q16 units(int32_t x, int32_t y, int32_t z) { return {Q16::from_int(x), Q16::from_int(y), Q16::from_int(z)}; }
ref::Vec3d to_d(const Vec3q16& p) { return {p.x.raw() / 65536.0, p.y.raw() / 65536.0, p.z.raw() / 65536.0}; }

/// Placed position in double (rotation exactly as the model's Q30 entries, then the translation).
ref::Vec3d placed_d(const Transform& t, const Vec3q16& p) {
    const ref::Vec3d q = to_d(p), tr = to_d(t.trans);
    const double v[3] = {q.x, q.y, q.z}, o[3] = {tr.x, tr.y, tr.z};
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = o[i] + (t.rot.m[i][0].raw() * v[0] + t.rot.m[i][1].raw() * v[1] + t.rot.m[i][2].raw() * v[2]) / 1073741824.0;
    return {r[0], r[1], r[2]};
}

struct Drawn {
    Status projected = Status::ok;
    FrameStats st;
    std::vector<uint32_t> ids, want;
};

/// The z-buffer's face ids of `mesh` under `model` against the double reference's.
Drawn draw_placed(const Camera& cam, const Mesh& mesh, const Transform& model, double fovy_deg, double near, double far) {
    constexpr int W = 48, H = 36;
    Drawn d;
    View view;
    REQUIRE(make_view(cam, W, H, view) == Status::ok);
    const View placed = with_model(view, model);
    std::vector<ScreenVertex> verts(mesh.positions.size());
    d.projected = project_vertices(placed, mesh.positions, {verts.data(), verts.size()});
    std::vector<Rgb888> px(W * H);
    std::vector<uint32_t> depth(W * H);
    const auto f = frame_view<Rgb888Format, uint32_t>(px.data(), depth.data(), W, H);
    clear(f, Rgb{0, 0, 0});
    DrawOptions opt;
    opt.shade = Shade::id;
    opt.cull = false;
    d.st = draw_zbuffer(placed, mesh, {verts.data(), verts.size()}, f, opt);
    for (const Rgb888& c : px) d.ids.push_back((uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b);
    std::vector<ref::RefTriangle> rt;
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        ref::RefTriangle r{};
        for (int k = 0; k < 3; ++k) r.v[k] = placed_d(model, mesh.positions[mesh.tris[t].v[k]]);
        r.id = static_cast<uint32_t>(t + 1);
        rt.push_back(r);
    }
    const ref::RefCamera rc{to_d(cam.eye), to_d(cam.target), to_d(cam.up), fovy_deg, near, far, W, H};
    d.want = ref::render_ids(rt, rc, false);
    return d;
}

long painted(const std::vector<uint32_t>& ids) {
    long n = 0;
    for (const uint32_t v : ids) n += v != 0;
    return n;
}

Camera camera(Vec3q16 eye, Vec3q16 target, int fovy_deg, int far) {
    Camera cam;
    cam.eye = eye;
    cam.target = target;
    cam.up = units(0, 1, 0);
    cam.fovy = Angle::from_degrees(Q16::from_int(fovy_deg));
    cam.near = Q16::from_int(1);
    cam.far = Q16::from_int(far);
    return cam;
}

}  // namespace

TEST_CASE("with_model(): a translation that wraps in compose() is not taken for a placement in front of the eye") {
    // A 2,000-unit square 4,000 units along +z in the model; the eye at z = -8,000 looks down -z and the
    // model moves the square 32,000 units along +z: 44,000 units behind the eye. compose() wraps that
    // translation (40,000 units, past 2^15) to 25,536 units in front, where every vertex is an int32.
    const Vec3q16 pos[4] = {units(-1000, -1000, 4000), units(1000, -1000, 4000), units(1000, 1000, 4000), units(-1000, 1000, 4000)};
    const Tri tris[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    const Mesh mesh{{pos, 4}, {tris, 2}, {}, {}};
    REQUIRE(validate(mesh) == Status::ok);
    Transform model;
    model.trans = units(0, 0, 32000);
    const Drawn d = draw_placed(camera(units(0, 0, -8000), units(0, 0, -8100), 10, 32000), mesh, model, 10.0, 1.0, 32000.0);
    REQUIRE(painted(d.want) == 0);  // behind the eye
    CHECK(d.st.ok());
    CHECK(d.projected == Status::out_of_range);  // was ok
    CHECK(painted(d.ids) == 0);                  // was 400 pixels of the square
}

TEST_CASE("check_view_range(): a view z of INT32_MIN, which to_view_point() cannot negate, is refused or drawn right") {
    // One vertex exactly 2^15 units ahead (view z = INT32_MIN raw, beyond the far plane), two 24,768 units
    // ahead: the far plane should cut the tip off; the negated INT32_MIN put it behind the near plane.
    const Vec3q16 pos[3] = {units(0, 0, 0), units(-1000, -1000, 8000), units(1000, -1000, 8000)};
    const Tri tris[1] = {{{0, 1, 2}}};
    const Mesh mesh{{pos, 3}, {tris, 1}, {}, {}};
    REQUIRE(validate(mesh) == Status::ok);
    Transform model;
    model.trans = {Q16::from_int(0), Q16::from_int(0), Q16::from_raw(INT32_MIN)};
    const Drawn d = draw_placed(camera(units(0, 0, 0), units(0, 0, -100), 10, 32000), mesh, model, 10.0, 1.0, 32000.0);
    CHECK(d.st.ok());
    if (d.projected == Status::ok) {
        const ref::Agreement ag = ref::compare_ids(d.ids, d.want, 48, 36);
        CHECK(ag.off_edge_mismatch == 0);  // was 232 (a wedge below the triangle)
    } else {
        CHECK(d.projected == Status::out_of_range);
        CHECK(painted(d.ids) == 0);
    }
}

TEST_CASE("with_model(): a rotation composed with the view's is not refused for an entry one raw unit past +-1") {
    // A cube at the origin seen from (100, 0, -100), the model turned 45 degrees about y: compose()
    // floors an entry to -2^30 - 1, and check_view_range() called that no rotation (invalid_argument).
    std::vector<Vec3q16> pos;
    for (int k = 0; k < 8; ++k) pos.push_back(units(k & 1 ? 20 : -20, k & 2 ? 20 : -20, k & 4 ? 20 : -20));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<Tri> tris;
    for (const auto& q : quads) {
        tris.push_back({{uint16_t(q[0]), uint16_t(q[1]), uint16_t(q[2])}});
        tris.push_back({{uint16_t(q[0]), uint16_t(q[2]), uint16_t(q[3])}});
    }
    const Mesh mesh{{pos.data(), pos.size()}, {tris.data(), tris.size()}, {}, {}};
    Transform model;
    model.rot = rotation_y(Angle::from_bam(0x20000000u));  // 45 degrees
    REQUIRE(validate(mesh, model) == Status::ok);
    const Camera cam = camera(units(100, 0, -100), units(0, 0, 0), 60, 1000);
    View view;
    REQUIRE(make_view(cam, 48, 36, view) == Status::ok);
    CHECK(check_view_range(with_model(view, model).to_view, kWorldLimitBits) == Status::ok);  // was invalid_argument
    const Drawn d = draw_placed(cam, mesh, model, 60.0, 1.0, 1000.0);
    CHECK(d.projected == Status::ok);
    CHECK(d.st.ok());
    CHECK(painted(d.ids) > 50);  // was 0 (100 before 88166bf)
    CHECK(ref::compare_ids(d.ids, d.want, 48, 36).off_edge_mismatch == 0);
}

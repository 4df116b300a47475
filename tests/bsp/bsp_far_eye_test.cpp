// draw_bsp() under a far with_model() placement that check_view_range() accepts (every view coordinate
// about 20,000 units, the tree's cube within int32) but whose eye in the tree's coordinates,
// apply_inverse(model, eye) as walk.hpp asks, lies 34,641 units from the tree's origin along its x axis:
// past 2^15 units, so it wraps to the other side of the tree. The side tests ordered the box from the
// wrong side (50 of 163 pixels showed a far face, status ok); check_bsp_view() now refuses the eye.
#include <hider/bsp/walk.hpp>
#include <hider/raster/zbuffer.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "bsp/bsp_blobs.hpp"
#include "bsp/bsp_exercise.hpp"
#include "common/bsp_build.hpp"
#include "support/reference.hpp"

using namespace hider;

namespace {

Vec3q16 units(int32_t x, int32_t y, int32_t z) { return {Q16::from_int(x), Q16::from_int(y), Q16::from_int(z)}; }

std::vector<uint32_t> ids_of(const std::vector<Rgb888>& px) {
    std::vector<uint32_t> ids(px.size());
    for (size_t i = 0; i < px.size(); ++i) ids[i] = (uint32_t{px[i].r} << 16) | (uint32_t{px[i].g} << 8) | px[i].b;
    return ids;
}

}  // namespace

TEST_CASE("draw_bsp under a far placement: the eye in the tree's coordinates past 2^15 units is refused or ordered right") {
    // A closed box, 3,800 x 3,000 x 2,400 units, one id per triangle.
    std::vector<Vec3q16> pos;
    for (int k = 0; k < 8; ++k) pos.push_back(units(k & 1 ? 1900 : -1900, k & 2 ? 1500 : -1500, k & 4 ? 1200 : -1200));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<Tri> tris;
    std::vector<uint32_t> ids;
    for (const auto& q : quads) {
        tris.push_back({{uint16_t(q[0]), uint16_t(q[1]), uint16_t(q[2])}});
        ids.push_back(static_cast<uint32_t>(tris.size()));
        tris.push_back({{uint16_t(q[0]), uint16_t(q[2]), uint16_t(q[3])}});
        ids.push_back(static_cast<uint32_t>(tris.size()));
    }
    tool::BspBuilt built;
    tool::BspStats stats;
    std::string why;
    REQUIRE_MESSAGE(tool::build_bsp(pos, tris, ids, tool::BspOptions{}, built, stats, why), why);
    const std::vector<uint8_t> bytes = tool::bsp_blob(built, tool::BspFit{});
    std::vector<uint64_t> store;
    const Span<const uint8_t> blob = test::aligned_copy(bytes.data(), bytes.size(), store);
    std::vector<uint32_t> load_stack(4096);
    BspTree tree;
    REQUIRE(bsp_load(blob, {load_stack.data(), load_stack.size()}, tree) == Status::ok);
    std::vector<Tri> tt;
    std::vector<uint32_t> faces;
    for (const BspTriangle& t : tree.triangles) {
        tt.push_back({{uint16_t(t.v[0]), uint16_t(t.v[1]), uint16_t(t.v[2])}});
        faces.push_back(t.face & kBspFaceMask);
    }
    const Mesh mesh{tree.vertices, {tt.data(), tt.size()}, {}, {faces.data(), faces.size()}};

    constexpr int W = 320, H = 240;
    Camera cam;
    cam.eye = units(0, 0, 0);
    cam.target = units(0, 0, -100);
    cam.up = units(0, 1, 0);
    cam.fovy = Angle::from_degrees(Q16::from_int(120));
    cam.near = Q16::from_int(1);
    cam.far = Q16::from_int(32767);
    View view;
    REQUIRE(make_view(cam, W, H, view) == Status::ok);
    // The model's x axis along (-1, -1, -1) / sqrt(3), its origin at (-20000, -20000, -20000): the eye lies
    // along the tree's +x axis, 20,000 sqrt(3) = 34,641 units away.
    const double s = std::sqrt(1.0 / 3), h = std::sqrt(0.5);
    const double d[3] = {-s, -s, -s}, e1[3] = {h, -h, 0};
    const double e2[3] = {d[1] * e1[2] - d[2] * e1[1], d[2] * e1[0] - d[0] * e1[2], d[0] * e1[1] - d[1] * e1[0]};
    Transform model;
    for (int i = 0; i < 3; ++i) {
        const double col[3] = {d[i], e1[i], e2[i]};
        for (int j = 0; j < 3; ++j) model.rot.m[i][j] = Q30::from_raw(static_cast<int32_t>(std::lround(col[j] * 1073741823.0)));
    }
    model.trans = units(-20000, -20000, -20000);
    const View placed = with_model(view, model);
    REQUIRE(check_view_range(placed.to_view, kBspWorldLimitBits) == Status::ok);  // no view coordinate wraps

    std::vector<ScreenVertex> verts(tree.vertices.size());
    REQUIRE(project_vertices(placed, tree.vertices, {verts.data(), verts.size()}) == Status::ok);
    DrawOptions opt;
    opt.shade = Shade::id;
    opt.cull = false;
    std::vector<Rgb888> z(W * H), b(W * H);
    std::vector<uint32_t> depth(W * H);
    const auto zf = frame_view<Rgb888Format, uint32_t>(z.data(), depth.data(), W, H);
    clear(zf, Rgb{0, 0, 0});
    REQUIRE(draw_zbuffer(placed, mesh, {verts.data(), verts.size()}, zf, opt).ok());
    const std::vector<uint32_t> zids = ids_of(z);
    long painted = 0;
    for (const uint32_t v : zids) painted += v != 0;
    REQUIRE(painted > 100);

    const Vec3q16 eye = apply_inverse(model, cam.eye);  // as walk.hpp asks; 34,641 units wrap to -30,895
    std::vector<uint32_t> stack(bsp_stack_entries(tree.max_depth));
    const auto bf = frame_view<Rgb888Format, uint16_t>(b.data(), nullptr, W, H);
    clear(bf, Rgb{0, 0, 0});
    std::vector<ScreenVertex> walk_verts(tree.vertices.size());
    mark_unprojected({walk_verts.data(), walk_verts.size()});
    const FrameStats st = draw_bsp(placed, eye, tree, {walk_verts.data(), walk_verts.size()}, bf, opt, {stack.data(), stack.size()});
    // The view puts that eye 2^32 raw units from its origin: check_bsp_view() refuses it, nothing drawn
    // (was 50 of the 163 pixels wrong, status ok).
    CHECK(st.status == Status::invalid_argument);
    CHECK(st.nodes_visited == 0);
    long drawn = 0;
    for (const uint32_t v : ids_of(b)) drawn += v != 0;
    CHECK(drawn == 0);
}

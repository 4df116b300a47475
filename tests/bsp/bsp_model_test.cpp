// A BSP tree drawn under a model transform (with_model()): the walk's eye must be the camera's eye in
// the tree's coordinates, apply_inverse(model, eye); then the walk gives the z-buffer's picture of the
// turned tree. The world eye ordered suzanne wrongly on up to 69 of 5,992 off-edge pixels of a 96 x 72
// frame with status ok; check_bsp_view() refuses it (invalid_argument).
#include <hider/bsp/walk.hpp>
#include <hider/raster/zbuffer.hpp>

#include <vector>

#include <doctest/doctest.h>

#include "bsp/bsp_blobs.hpp"
#include "bsp/bsp_exercise.hpp"
#include "support/reference.hpp"

using namespace hider;

namespace {

std::vector<uint32_t> ids_of(const std::vector<Rgb888>& px) {
    std::vector<uint32_t> ids(px.size());
    for (size_t i = 0; i < px.size(); ++i) ids[i] = (uint32_t{px[i].r} << 16) | (uint32_t{px[i].g} << 8) | px[i].b;
    return ids;
}

}  // namespace

TEST_CASE("draw_bsp under with_model() with the eye in the tree's coordinates equals the z-buffer") {
    const std::vector<uint8_t> bytes = test::blob_of_obj("models/suzanne.obj");
    std::vector<uint64_t> store;
    const Span<const uint8_t> blob = test::aligned_copy(bytes.data(), bytes.size(), store);
    std::vector<uint32_t> load_stack(4096);
    BspTree tree;
    REQUIRE(bsp_load(blob, {load_stack.data(), load_stack.size()}, tree) == Status::ok);
    REQUIRE(tree.vertices.size() <= kMaxMeshVertices);
    std::vector<Tri> tris;
    std::vector<uint32_t> faces;
    for (const BspTriangle& t : tree.triangles) {
        tris.push_back({{uint16_t(t.v[0]), uint16_t(t.v[1]), uint16_t(t.v[2])}});
        faces.push_back(t.face & kBspFaceMask);
    }
    const Mesh mesh{tree.vertices, {tris.data(), tris.size()}, {}, {faces.data(), faces.size()}};
    constexpr int W = 96, H = 72;
    Camera cam;
    cam.eye = {Q16::from_int(900), Q16::from_int(500), Q16::from_int(1400)};
    cam.target = {};
    cam.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
    cam.fovy = Angle::from_degrees(Q16::from_int(45));
    cam.near = Q16::from_int(1);
    cam.far = Q16::from_int(10000);
    View view;
    REQUIRE(make_view(cam, W, H, view) == Status::ok);
    long world_eye_refused = 0;
    for (uint32_t k = 0; k < 8; ++k) {
        Transform model;
        model.rot = rotation_y(Angle::from_bam(k << 29));
        model.trans = {Q16::from_int(30), Q16::from_int(0), Q16::from_int(-20)};
        REQUIRE(validate(mesh, model) == Status::ok);
        const View turned = with_model(view, model);
        std::vector<ScreenVertex> verts(tree.vertices.size());
        REQUIRE(project_vertices(turned, tree.vertices, {verts.data(), verts.size()}) == Status::ok);
        DrawOptions opt;
        opt.shade = Shade::id;
        std::vector<Rgb888> z(W * H), b(W * H);
        std::vector<uint32_t> depth(W * H);
        const auto zf = frame_view<Rgb888Format, uint32_t>(z.data(), depth.data(), W, H);
        clear(zf, Rgb{0, 0, 0});
        REQUIRE(draw_zbuffer(turned, mesh, {verts.data(), verts.size()}, zf, opt).ok());
        std::vector<uint32_t> stack(bsp_stack_entries(tree.max_depth));
        const auto bf = frame_view<Rgb888Format, uint16_t>(b.data(), nullptr, W, H);
        clear(bf, Rgb{0, 0, 0});
        CAPTURE(k);
        REQUIRE(draw_bsp(turned, apply_inverse(model, cam.eye), tree, {verts.data(), verts.size()}, bf, opt,
                         {stack.data(), stack.size()}).ok());
        CHECK(ref::compare_ids(ids_of(b), ids_of(z), W, H).off_edge_mismatch == 0);
        // The world eye, which ordered the turned tree wrongly with status ok, is refused: the view does
        // not put it at its origin (check_bsp_view()).
        const FrameStats world = draw_bsp(turned, cam.eye, tree, {verts.data(), verts.size()}, bf, opt, {stack.data(), stack.size()});
        world_eye_refused += world.status == Status::invalid_argument;
    }
    CHECK(world_eye_refused == 8);
}

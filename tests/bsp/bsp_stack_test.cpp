// The walks' stack: bsp_stack_entries(depth) = depth + 1 entries, one per level. Every walk (back to
// front, front to back, the one-walk list, the eye's cell) and bsp_load() run with exactly that many
// entries inside a guarded buffer: nothing past it is written, and the walks proper (culled, so without
// the cell search) use at most depth - 1. Scenes: a UV sphere built without axis splits, whose convex
// surface makes the tree a chain as deep as most of its polygons, and with them; the torus and teapot, and
// random soups; cameras outside, inside and on a tree vertex.
#include <algorithm>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include <hider/bsp/order.hpp>
#include <hider/bsp/walk.hpp>

#include "common/bsp_build.hpp"
#include "common/render_bsp.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

constexpr uint32_t kSentinel = 0xA5A5A5A5u;  // no walk writes it: its index bits exceed every tree here
constexpr size_t kGuard = 16;

/// The entries written below the end of `buf`'s first `used` (sentinel-filled) entries: one past the
/// highest index written; and whether the guard beyond them is intact.
size_t high_water(const std::vector<uint32_t>& buf, size_t used) {
    size_t hw = 0;
    for (size_t i = 0; i < used; ++i)
        if (buf[i] != kSentinel) hw = i + 1;
    return hw;
}
bool guard_intact(const std::vector<uint32_t>& buf, size_t used) {
    return std::all_of(buf.begin() + static_cast<std::ptrdiff_t>(used), buf.end(), [](uint32_t v) { return v == kSentinel; });
}

struct Walks {
    size_t walk_high = 0;  ///< the most entries any culled walk used
};

/// Every walk of `tree` from `cam` into a small frame, each with a fresh guarded stack of exactly
/// bsp_stack_entries(depth) entries.
void walk_all(const tool::Scene& s, const BspTree& tree, const Camera& cam, Walks& w) {
    View view;
    REQUIRE(make_view(cam, s.width, s.height, view) == Status::ok);
    const size_t entries = bsp_stack_entries(tree.max_depth);
    std::vector<ScreenVertex> verts(tree.vertices.size());
    std::vector<uint16_t> color(static_cast<size_t>(s.width) * s.height);
    std::vector<uint32_t> coverage(static_cast<size_t>(coverage_words(s.width)) * s.height);
    std::vector<BspDrawEntry> list_room(tree.nodes.size());
    const auto frame = band_view<Rgb565Format, uint16_t>(color.data(), nullptr, s.width, s.height, 0, s.height);
    for (bool cull : {true, false})
        for (int which = 0; which < 4; ++which) {
            INFO("cull ", cull, " walk ", which);
            DrawOptions opt;
            opt.cull = cull;
            mark_unprojected({verts.data(), verts.size()});
            std::vector<uint32_t> buf(entries + kGuard, kSentinel);
            const Span<uint32_t> stack{buf.data(), entries};
            FrameStats st;
            BoundedList<BspDrawEntry> list(list_room.data(), list_room.size());
            clear(frame, Rgb{0, 0, 0});
            switch (which) {
                case 0: st = draw_bsp(view, cam.eye, tree, {verts.data(), verts.size()}, frame, opt, stack); break;
                case 1:
                    st = draw_bsp_front(view, cam.eye, tree, {verts.data(), verts.size()}, frame, opt, stack,
                                        {coverage.data(), coverage.size()});
                    break;
                case 2: st = order_bsp(view, cam.eye, tree, {verts.data(), verts.size()}, opt, stack, list); break;
                default: (void)bsp_visible_faces(view, cam.eye, tree, stack); break;
            }
            CHECK(st.status == Status::ok);
            CHECK(guard_intact(buf, entries));
            const size_t hw = high_water(buf, entries);
            if (cull && which < 3) {  // the walk alone: one entry per level above the deepest node at most
                CHECK(hw + 1 <= tree.max_depth);
                w.walk_high = std::max(w.walk_high, hw);
            }
        }
}

/// Builds and loads `s`'s tree with `opt` (the load with exactly depth + 1 entries, guarded), then walks it from
/// its camera, from inside (the centroid of its first triangle) and from its first vertex.
Walks check_scene(const std::string& name, const tool::Scene& s, const tool::BspOptions& opt = {}) {
    INFO(name);
    tool::BspBuilt built;
    tool::BspStats bs;
    std::string why;
    REQUIRE_MESSAGE(tool::build_bsp(s.positions, s.tris, s.ids, opt, built, bs, why), why);
    const tool::AlignedBlob blob(tool::bsp_blob(built, tool::BspFit{s.centre, s.scale}));
    const uint32_t depth = built.max_depth;
    REQUIRE(bsp_stack_entries(depth) == size_t{depth} + 1);
    BspTree tree;
    {
        std::vector<uint32_t> buf(bsp_stack_entries(depth) + kGuard, kSentinel);
        REQUIRE(bsp_load(blob.span(), {buf.data(), bsp_stack_entries(depth)}, tree) == Status::ok);
        CHECK(guard_intact(buf, bsp_stack_entries(depth)));
        CHECK(bsp_load(blob.span(), {buf.data(), bsp_stack_entries(depth) - 1}, tree) == Status::capacity_exceeded);
        REQUIRE(bsp_load(blob.span(), {buf.data(), bsp_stack_entries(depth)}, tree) == Status::ok);
    }
    Walks w;
    walk_all(s, tree, s.camera, w);
    Camera c = s.camera;
    const Vec3q16 p = tree.vertices[tree.triangles[0].v[0]], q = tree.vertices[tree.triangles[0].v[1]],
                  r = tree.vertices[tree.triangles[0].v[2]];
    c.eye = {Q16::from_raw((p.x.raw() + q.x.raw() + r.x.raw()) / 3), Q16::from_raw((p.y.raw() + q.y.raw() + r.y.raw()) / 3),
             Q16::from_raw((p.z.raw() + q.z.raw() + r.z.raw()) / 3)};
    c.target = {};
    walk_all(s, tree, c, w);
    c.eye = p;
    c.target = {p.x + Q16::from_int(3), p.y + Q16::from_int(1), p.z - Q16::from_int(5)};
    walk_all(s, tree, c, w);
    MESSAGE(name, ": depth ", depth, ", most entries a walk used ", w.walk_high);
    return w;
}

}  // namespace

TEST_CASE("BSP walks and load fit in depth + 1 stack entries (one per level)") {
    // The convex sphere (without axis splits, the default): a chain of nodes; seen from outside, about half of them
    // wait for their back subtree, so the bound is really reached for, not met by a shallow tree.
    const tool::Scene ball = test::uv_sphere(24, 12, 64, 48);
    const tool::BspOptions chain;
    const Walks w = check_scene("sphere 24x12, one chain", ball, chain);
    CHECK(w.walk_high * 4 > ball.tris.size());
    tool::BspOptions split;
    split.max_chain = 64;
    check_scene("sphere 24x12, axis splits", ball, split);
    for (const char* name : {"boxes-6-10", "soup-3-60", "stacked-2-8"}) check_scene(name, test::generated_scene(name));
}

TEST_CASE("BSP walks fit in depth + 1 stack entries on the torus and teapot" * doctest::test_suite("slow")) {
    for (const char* name : {"torus.obj", "teapot.obj"}) check_scene(name, test::load_model(name));
}

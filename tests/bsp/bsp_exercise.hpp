// Arbitrary bytes through bsp_load() and, when it accepts them, through both walks and the one-walk list
// (order.hpp) into a small frame from a few fixed cameras (one of them on a vertex of the tree, so on
// some node's plane). Shared by the doctest suite (corrupt blobs, tests/bsp/bsp_load_test.cpp) and the
// libFuzzer target (tests/fuzz/bsp_load_fuzz.cpp), so an input one of them finds replays in the other.
// Every buffer is a std::vector of exactly the size lib/ is promised, so under ASan a read or write past
// it is caught.
#pragma once
#include <hider/bsp/order.hpp>
#include <hider/bsp/walk.hpp>

#include <cstring>
#include <vector>

namespace hider::test {

/// What one input did: the load status and, for an accepted tree, what the walks reported.
struct BspExercise {
    Status load = Status::bad_data;
    uint32_t depth = 0;             ///< the measured depth of an accepted tree
    int walks = 0;                  ///< walks run (both orders, every camera, full frame and a band)
    int walk_failures = 0;          ///< walks that did not return ok on a tree bsp_load accepted
    int overdraw_failures = 0;      ///< front-to-back walks that wrote more pixels than their band holds
    uint64_t triangles_drawn = 0;
};

/// A blob copied into 8-byte aligned memory of exactly its size rounded up to 8 (the tail is zero and
/// outside the span handed to bsp_load).
inline Span<const uint8_t> aligned_copy(const uint8_t* data, size_t size, std::vector<uint64_t>& storage) {
    storage.assign((size + 7) / 8, 0);
    if (size != 0) std::memcpy(storage.data(), data, size);
    return {reinterpret_cast<const uint8_t*>(storage.data()), size};
}

/// bsp_load() with a load stack of exactly `stack_entries` entries.
inline Status load_bsp(Span<const uint8_t> blob, size_t stack_entries, BspTree& tree) {
    std::vector<uint32_t> stack(stack_entries);
    return bsp_load(blob, {stack.data(), stack.size()}, tree);
}

namespace detail {

inline Camera bsp_camera(Vec3q16 eye, Vec3q16 target) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
    c.fovy = Angle::from_bam(0x15555555u);  // 30 degrees
    c.near = Q16::from_ratio(1, 16);
    c.far = Q16::from_int(8192);
    return c;
}

/// Both walks of `tree` from `cam`, and the one-walk list (order_bsp, then draw_bsp_list per band),
/// full frame and one band, into a 40 x 30 RGB565 frame.
inline void walk_bsp_both(const BspTree& tree, const Camera& cam, bool cull, Shade shade, BspExercise& out) {
    constexpr int32_t kW = 40, kH = 30;
    View view;
    if (make_view(cam, kW, kH, view) != Status::ok) return;
    std::vector<ScreenVertex> verts(tree.vertices.size());
    DrawOptions opt;
    opt.cull = cull;
    opt.shade = shade;
    if (project_vertices(view, tree.vertices, {verts.data(), verts.size()}, &opt.depth_range) != Status::ok) {
        ++out.walk_failures;
        return;
    }
    std::vector<uint32_t> stack(bsp_stack_entries(tree.max_depth));
    std::vector<BspDrawEntry> entries(tree.nodes.size());  // one per node: never too few
    BoundedList<BspDrawEntry> list(entries.data(), entries.size());
    const FrameStats ordered = order_bsp(view, cam.eye, tree, {verts.data(), verts.size()}, opt, {stack.data(), stack.size()}, list);
    ++out.walks;
    out.walk_failures += ordered.status != Status::ok;
    const int32_t bands[2][2] = {{0, kH}, {11, 18}};
    for (const auto& b : bands) {
        const int32_t rows = b[1] - b[0];
        std::vector<uint16_t> color(static_cast<size_t>(kW) * rows);
        std::vector<uint32_t> coverage(static_cast<size_t>(coverage_words(kW)) * rows);
        const auto frame = band_view<Rgb565Format, uint16_t>(color.data(), nullptr, kW, kH, b[0], b[1]);
        clear(frame, Rgb{0, 0, 0});
        for (bool front : {false, true}) {
            const FrameStats st =
                front ? draw_bsp_front(view, cam.eye, tree, {verts.data(), verts.size()}, frame, opt, {stack.data(), stack.size()},
                                       {coverage.data(), coverage.size()})
                      : draw_bsp(view, cam.eye, tree, {verts.data(), verts.size()}, frame, opt, {stack.data(), stack.size()});
            ++out.walks;
            out.walk_failures += st.status != Status::ok;
            out.overdraw_failures += front && st.pixels_written > uint64_t{kW} * static_cast<uint64_t>(rows);
            out.triangles_drawn += st.triangles_drawn;
        }
        const FrameStats st = draw_bsp_list(view, tree, {verts.data(), verts.size()}, {list.data(), list.size()}, frame, opt);
        ++out.walks;
        out.walk_failures += st.status != Status::ok;
        out.triangles_drawn += st.triangles_drawn;
    }
}

}  // namespace detail

/// Walks an accepted tree from three cameras: outside the world's +-512 unit fit looking at the origin
/// (culling, headlight), at the origin looking down -z (no culling, face ids), and on the tree's first
/// vertex (depth shading), so eye-in-plane nodes are met.
inline void walk_bsp_cameras(const BspTree& tree, BspExercise& out) {
    const Vec3q16 origin{};
    const Vec3q16 outside{Q16::from_int(300), Q16::from_int(400), Q16::from_int(1500)};
    const Vec3q16 down_z{Q16::from_int(0), Q16::from_int(0), Q16::from_int(-1)};
    detail::walk_bsp_both(tree, detail::bsp_camera(outside, origin), true, Shade::headlight, out);
    detail::walk_bsp_both(tree, detail::bsp_camera(origin, down_z), false, Shade::id, out);
    if (!tree.vertices.empty()) {
        const Vec3q16 v = tree.vertices[0];
        const Vec3q16 ahead{v.x + Q16::from_int(1), v.y, v.z - Q16::from_int(2)};
        detail::walk_bsp_both(tree, detail::bsp_camera(v, ahead), false, Shade::depth, out);
    }
}

/// Loads `data` (copied to aligned memory) with a stack for trees up to `max_depth` deep and walks it
/// when accepted.
inline BspExercise exercise_bsp(const uint8_t* data, size_t size, uint32_t max_depth = 64) {
    BspExercise r;
    std::vector<uint64_t> storage;
    BspTree tree;
    r.load = load_bsp(aligned_copy(data, size, storage), bsp_stack_entries(max_depth), tree);
    if (r.load != Status::ok) return r;
    r.depth = tree.max_depth;
    walk_bsp_cameras(tree, r);
    return r;
}

}  // namespace hider::test

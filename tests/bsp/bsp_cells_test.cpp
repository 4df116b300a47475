// Labelled cells (BspNode::cells, hider-bsp's label_cells, bsp_visible_faces): the compiler labels the
// cells of closed surfaces only; a walk that then draws one side of the faces gives exactly the bytes of
// the same tree drawn with both sides, from random eyes outside, inside the solid and close enough for the
// near plane to cut the surface, whole frame and bands, back to front, front to back and from the list
// (up to a silhouette pixel a front face's rounding leaves to a back face); and the z-buffer's face ids
// with no hole and no crack. A tree with its labels swapped (a planted fault) is caught by the same
// comparison. bsp_load refuses labels where none can be.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include <hider/bsp/order.hpp>

#include "common/bsp_build.hpp"
#include "common/gen_scenes.hpp"
#include "common/render.hpp"
#include "common/render_bsp.hpp"
#include "support/reference.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

struct Built {
    tool::BspBuilt built;
    tool::BspStats stats;
};

Built build(const tool::Scene& s) {
    Built b;
    std::string why;
    REQUIRE_MESSAGE(tool::build_bsp(s.positions, s.tris, s.ids, tool::BspOptions{}, b.built, b.stats, why), why);
    return b;
}

struct Loaded {
    tool::AlignedBlob blob;
    BspTree tree;
};

Loaded load(const tool::BspBuilt& built, const tool::Scene& s) {
    Loaded l{tool::AlignedBlob(tool::bsp_blob(built, tool::BspFit{s.centre, s.scale})), {}};
    std::vector<uint32_t> probe(bsp_stack_entries(1u << 16));
    REQUIRE(bsp_load(l.blob.span(), {probe.data(), probe.size()}, l.tree) == Status::ok);
    return l;
}

/// RGB565 face-id frame of a tree drawn in bands of `rows` by draw_bsp (0), draw_bsp_front (1) or the list (2).
std::vector<uint16_t> frame(const tool::Scene& s, const BspTree& tree, int how, int rows, FrameStats& st) {
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(tree.vertices.size());
    mark_unprojected({verts.data(), verts.size()});
    std::vector<uint32_t> stack(bsp_stack_entries(tree.max_depth));
    std::vector<BspDrawEntry> entries(tree.nodes.size());
    BoundedList<BspDrawEntry> list(entries.data(), entries.size());
    DrawOptions opt;
    opt.shade = Shade::id;
    opt.cull = false;
    if (how == 2) {
        st = order_bsp(view, s.camera.eye, tree, {verts.data(), verts.size()}, opt, {stack.data(), stack.size()}, list);
        REQUIRE(st.status == Status::ok);
    }
    std::vector<uint16_t> rgb;
    std::vector<uint32_t> cov(static_cast<size_t>(coverage_words(s.width)) * static_cast<size_t>(rows));
    for (int y0 = 0; y0 < s.height; y0 += rows) {
        const int y1 = std::min(s.height, y0 + rows);
        std::vector<uint16_t> color(static_cast<size_t>(s.width) * static_cast<size_t>(rows));
        const auto band = band_view<Rgb565Format, uint16_t>(color.data(), nullptr, s.width, s.height, y0, y1);
        clear(band, Rgb{0, 0, 0});
        FrameStats b;
        if (how == 0)
            b = draw_bsp(view, s.camera.eye, tree, {verts.data(), verts.size()}, band, opt, {stack.data(), stack.size()});
        else if (how == 1)
            b = draw_bsp_front(view, s.camera.eye, tree, {verts.data(), verts.size()}, band, opt, {stack.data(), stack.size()},
                               {cov.data(), cov.size()});
        else
            b = draw_bsp_list(view, tree, {verts.data(), verts.size()}, {list.data(), list.size()}, band, opt);
        REQUIRE(b.status == Status::ok);
        st.merge(b);
        rgb.insert(rgb.end(), color.begin(), color.begin() + static_cast<long>(s.width) * (y1 - y0));
    }
    return rgb;
}

/// Counts of one comparison run.
struct Tally {
    int faces[3] = {0, 0, 0};  ///< cameras by bsp_visible_faces(): both, front, back
    uint64_t differing = 0;    ///< pixels where the labelled tree differs from the unlabelled one
    uint64_t skipped = 0;      ///< triangles the labelled walks left out
    uint64_t worst = 0;        ///< most pixels differing in one frame
    long holes = 0, cracks = 0;  ///< against the z-buffer (test::count_defects), the unlabelled tree's too
};

/// The box of the tree's vertices, raw: lo[k], hi[k].
struct Box {
    int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
};
Box box_of(const BspTree& tree) {
    Box b;
    for (const Vec3q16& p : tree.vertices)
        for (int k = 0; k < 3; ++k) {
            const int32_t c = k == 0 ? p.x.raw() : (k == 1 ? p.y.raw() : p.z.raw());
            b.lo[k] = std::min(b.lo[k], c);
            b.hi[k] = std::max(b.hi[k], c);
        }
    return b;
}

/// Random cameras around and inside the box (1.6 times it), looking at its middle half; near planes
/// short (1/400 of its width) and, every third camera, deep (1/6: into the surface).
std::vector<Camera> random_cameras(const Camera& own, const Box& box, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    auto coord = [&](int k, double widen) {
        const double mid = (static_cast<double>(box.lo[k]) + box.hi[k]) / 2, half = (static_cast<double>(box.hi[k]) - box.lo[k]) / 2 * widen;
        return Q16::from_raw(static_cast<int32_t>(std::uniform_real_distribution<double>(mid - half, mid + half)(rng)));
    };
    std::vector<Camera> cams;
    for (int c = 0; c < count; ++c) {
        Camera cam = own;
        cam.eye = {coord(0, 1.6), coord(1, 1.6), coord(2, 1.6)};
        cam.target = {coord(0, 0.5), coord(1, 0.5), coord(2, 0.5)};
        cam.near = Q16::from_raw(std::max(kMinNearRaw, (box.hi[0] - box.lo[0]) / (c % 3 == 2 ? 6 : 400)));
        cams.push_back(cam);
    }
    return cams;
}

/// Eyes a 25th of the box's width behind triangles of the tree (inside a solid's wall, such as the torus's
/// tube), looking along an edge of the triangle or across the wall; a near plane of 1/400 of the width.
std::vector<Camera> inside_cameras(const Camera& own, const BspTree& tree, const Box& box, int count) {
    std::vector<Camera> cams;
    const double depth = (static_cast<double>(box.hi[0]) - box.lo[0]) / 25.0;
    auto q = [](double c) { return Q16::from_raw(static_cast<int32_t>(std::lround(c))); };
    for (int k = 0; k < count; ++k) {
        const BspTriangle& tri = tree.triangles[static_cast<size_t>(k) * tree.triangles.size() / static_cast<size_t>(count)];
        double v[3][3];
        for (int i = 0; i < 3; ++i) {
            const Vec3q16& p = tree.vertices[tri.v[i]];
            v[i][0] = p.x.raw();
            v[i][1] = p.y.raw();
            v[i][2] = p.z.raw();
        }
        const double e1[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
        const double e2[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), el = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        for (int look = 0; look < 2; ++look) {
            double eye[3], to[3];
            for (int i = 0; i < 3; ++i) {
                eye[i] = (v[0][i] + v[1][i] + v[2][i]) / 3 - n[i] / len * depth;
                to[i] = eye[i] + (look == 0 ? e1[i] / el : -n[i] / len) * depth * 10;
            }
            Camera cam = own;
            cam.eye = {q(eye[0]), q(eye[1]), q(eye[2])};
            cam.target = {q(to[0]), q(to[1]), q(to[2])};
            cam.near = Q16::from_raw(std::max(kMinNearRaw, (box.hi[0] - box.lo[0]) / 400));
            cams.push_back(cam);
        }
    }
    return cams;
}

/// The labelled tree `built` of `s` against the same tree without labels, from each camera, pixel for pixel with
/// each walk, whole frame and 7-row bands; and hider-render's bsp of the labelled tree against the
/// z-buffer without culling. `swapped`: the labels exchanged (a planted fault; then only counted).
Tally compare(const std::string& name, tool::Scene s, const Built& built, const std::vector<Camera>& cameras, bool swapped = false) {
    s.width = 160;  // frames of a small display: enough pixels for silhouettes, a quarter of the time
    s.height = 120;
    Built b = built;
    tool::BspBuilt plain = b.built;
    for (BspNode& n : plain.nodes) n.cells = 0;
    if (swapped)
        for (BspNode& n : b.built.nodes)
            n.cells = static_cast<uint16_t>(((n.cells & 3u) << 2) | ((n.cells >> 2) & 3u));
    const Loaded labelled = load(b.built, s), unlabelled = load(plain, s);
    const std::vector<uint8_t> labelled_blob = tool::bsp_blob(b.built, tool::BspFit{s.centre, s.scale});
    Tally t;
    for (size_t c = 0; c < cameras.size(); ++c) {
        s.camera = cameras[c];
        View view;
        if (make_view(s.camera, s.width, s.height, view) != Status::ok) continue;
        std::vector<uint32_t> stack(bsp_stack_entries(labelled.tree.max_depth));
        const BspFaces faces = bsp_visible_faces(view, s.camera.eye, labelled.tree, {stack.data(), stack.size()});
        ++t.faces[static_cast<int>(faces)];
        std::vector<uint16_t> whole_without;
        for (int how = 0; how < 3; ++how)
            for (int rows : {s.height, 7}) {
                FrameStats a, u;
                const std::vector<uint16_t> with = frame(s, labelled.tree, how, rows, a);
                const std::vector<uint16_t> without = frame(s, unlabelled.tree, how, rows, u);
                uint64_t diff = 0;
                for (size_t i = 0; i < with.size(); ++i) diff += with[i] != without[i];
                t.differing += diff;
                t.worst = std::max(t.worst, diff);
                if (how == 0 && rows == s.height) {
                    whole_without = without;
                    t.skipped += a.triangles_culled;
                }
                if (swapped) continue;
                // A front face turned edge-on by the 1/16-pixel rounding of its vertices can leave a
                // silhouette pixel that only a back face covered: single pixels, off any face's area.
                INFO(name << " camera " << c << " walk " << how << " rows " << rows);
                CHECK(diff <= 2);
                CHECK(u.triangles_culled == 0);
                CHECK((faces != BspFaces::both) == (a.triangles_culled > 0));  // one side left out, or none
            }
        if (swapped) continue;
        tool::RenderOptions ro;
        ro.shade = Shade::id;
        ro.format = tool::PixelFormat::rgb888;
        ro.depth_bits = 32;
        ro.cull = false;
        tool::RenderResult zr, br;
        std::string why;
        ro.algo = tool::Algo::zbuffer;
        REQUIRE_MESSAGE(tool::render(s, ro, zr, why), why);
        ro.algo = tool::Algo::bsp;
        REQUIRE_MESSAGE(tool::render_bsp(s, labelled_blob, ro, br, why), why);  // hider-render's bsp of this tree
        const std::vector<uint32_t> ids = tool::decode_ids(br), z = tool::decode_ids(zr);
        const ref::Agreement agree = ref::compare_ids(ids, z, s.width, s.height);
        const test::Defects d = test::count_defects(ids, z, s.width, s.height);
        INFO(name << " camera " << c << " against the z-buffer");
        // Holes the labels made: empty here, covered around it by the z-buffer, drawn by the unlabelled
        // tree. (A face's outline moved by a cut point's rounding can leave the same hole in both: it is
        // the BSP's, counted in t.holes, not the labels'.)
        long made = 0;
        for (int y = 1; y + 1 < s.height; ++y)
            for (int x = 1; x + 1 < s.width; ++x) {
                const size_t i = static_cast<size_t>(y) * static_cast<size_t>(s.width) + static_cast<size_t>(x);
                if (ids[i] != 0 || whole_without[i] == 0) continue;
                bool covered = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) covered = covered && z[i + static_cast<size_t>(dy * s.width + dx)] != 0;
                made += covered;
            }
        CHECK(made == 0);
        CHECK(agree.rate() >= 0.999);
        CHECK(d.cracks == 0);
        t.holes += d.holes;
        t.cracks += d.cracks;
    }
    MESSAGE(name << ": " << cameras.size() << " cameras, faces both/front/back " << t.faces[0] << "/" << t.faces[1] << "/"
                 << t.faces[2] << ", triangles left out " << t.skipped << ", pixels differing " << t.differing << " (at most "
                 << t.worst << " in a frame), holes " << t.holes << ", cracks " << t.cracks << " against the z-buffer");
    return t;
}

/// Cameras per comparison: under ASan a quarter (the frames run ten times slower there; the plain host
/// build checks them all).
int cameras(int n) {
#if defined(__SANITIZE_ADDRESS__)
    return (n + 3) / 4;
#else
    return n;
#endif
}

}  // namespace

TEST_CASE("hider-bsp labels the cells of closed surfaces, and of no open one") {
    const Built torus = build(test::load_model("torus.obj"));
    CHECK(torus.stats.cells_note.empty());
    CHECK(torus.stats.cells_labelled == torus.built.nodes.size() + 1);  // every empty child: N + 1 of them
    CHECK(torus.stats.winding_low == 0);
    CHECK(torus.stats.winding_high == 1);
    size_t lowest = 0, highest = 0;
    for (const BspNode& n : torus.built.nodes)
        for (int c = 0; c < 2; ++c) {
            lowest += (n.cells & (kBspCellLowest << c)) != 0;
            highest += (n.cells & (kBspCellHighest << c)) != 0;
            if (n.child[c] != kBspNone) CHECK((n.cells & ((kBspCellLowest | kBspCellHighest) << c)) == 0);
        }
    CHECK(lowest > 0);
    CHECK(highest > 0);
    for (const char* open : {"suzanne.obj"}) {
        const Built b = build(test::load_model(open));
        INFO(open);
        CHECK(b.stats.cells_labelled == 0);
        CHECK(b.stats.cells == tool::BspCells::open);
        for (const BspNode& n : b.built.nodes) CHECK(n.cells == 0);
    }
    const Built soup = build(test::generated_scene("soup-1-300"));
    CHECK(soup.stats.cells_labelled == 0);
    CHECK(!soup.stats.cells_note.empty());
}

TEST_CASE("a labelled tree draws one side of the faces and the same bytes as both, from outside, inside and with the near plane in the surface") {
    // The torus (winding numbers 0..1: outside, inside the tube) and interpenetrating boxes (0..4: where
    // boxes overlap, cells of the middle numbers draw both sides).
    const tool::Scene torus = test::load_model("torus.obj");
    const Built tb = build(torus);
    const Loaded tl = load(tb.built, torus);
    const Box box = box_of(tl.tree);
    for (uint32_t seed : {1u, 2u}) {
        const Tally t = compare("torus seed " + std::to_string(seed), torus, tb, random_cameras(torus.camera, box, cameras(24), seed));
        CHECK(t.faces[1] > 0);  // outside the solid
        CHECK(t.faces[0] > 0);  // too near a surface, or the near plane through it
        CHECK(t.skipped > 0);
    }
    // Random eyes seldom fall inside the tube: these stand in its wall, 1/25 of the torus's width deep.
    const Tally inside = compare("torus, eyes inside the tube", torus, tb, inside_cameras(torus.camera, tl.tree, box, cameras(12)));
    CHECK(inside.faces[2] >= cameras(12));  // back faces only, from most of them
    const tool::Scene boxes = test::generated_scene("boxes-6-10");
    const Built bb = build(boxes);
    REQUIRE_MESSAGE(bb.stats.cells == tool::BspCells::labelled, bb.stats.cells_note);
    CHECK(bb.stats.winding_low == 0);
    CHECK(bb.stats.winding_high >= 2);  // boxes overlap
    const Loaded bl = load(bb.built, boxes);
    const Tally t = compare("boxes-6-10", boxes, bb, random_cameras(boxes.camera, box_of(bl.tree), cameras(24), 3));
    CHECK(t.faces[1] > 0);
}

TEST_CASE("swapped labels (a planted fault) change the picture") {
    const tool::Scene torus = test::load_model("torus.obj");
    const Built tb = build(torus);
    const Loaded tl = load(tb.built, torus);
    const Box box = box_of(tl.tree);
    std::vector<Camera> cams = random_cameras(torus.camera, box, cameras(6), 5);
    const std::vector<Camera> inside = inside_cameras(torus.camera, tl.tree, box, cameras(3));
    cams.insert(cams.end(), inside.begin(), inside.end());
    const Tally t = compare("torus, labels swapped", torus, tb, cams, true);
    CHECK(t.faces[1] > 0);  // outside cells now labelled highest: back faces only
    CHECK(t.faces[2] > 0);
    CHECK(t.differing > 100);
}

TEST_CASE("bsp_load refuses cell labels on a child that is not empty, two labels, or unknown bits") {
    tool::Scene s = test::generated_scene("cyclic-bars");  // a small tree (its bars touch: not labelled)
    const Built b = build(s);
    size_t inner = 0, leaf = 0;  // a node with a front child, one with an empty front child
    for (size_t i = 0; i < b.built.nodes.size(); ++i) {
        if (b.built.nodes[i].child[0] != kBspNone) inner = i;
        else leaf = i;
    }
    auto status_with = [&](size_t node, uint16_t cells) {
        tool::BspBuilt t = b.built;
        t.nodes[node].cells = cells;
        tool::AlignedBlob blob(tool::bsp_blob(t, tool::BspFit{s.centre, s.scale}));
        std::vector<uint32_t> stack(bsp_stack_entries(1u << 16));
        BspTree tree;
        return bsp_load(blob.span(), {stack.data(), stack.size()}, tree);
    };
    CHECK(status_with(leaf, kBspCellLowest) == Status::ok);
    CHECK(status_with(leaf, kBspCellHighest) == Status::ok);
    CHECK(status_with(inner, kBspCellLowest) == Status::bad_data);
    CHECK(status_with(inner, kBspCellHighest) == Status::bad_data);
    CHECK(status_with(leaf, kBspCellLowest | kBspCellHighest) == Status::bad_data);
    size_t back_inner = 0, back_leaf = 0;  // the same for the back child: bits 1 and 3
    for (size_t i = 0; i < b.built.nodes.size(); ++i) {
        if (b.built.nodes[i].child[1] != kBspNone) back_inner = i;
        else back_leaf = i;
    }
    CHECK(status_with(back_leaf, kBspCellLowest << 1) == Status::ok);
    CHECK(status_with(back_leaf, kBspCellHighest << 1) == Status::ok);
    CHECK(status_with(back_inner, kBspCellLowest << 1) == Status::bad_data);
    CHECK(status_with(back_inner, kBspCellHighest << 1) == Status::bad_data);
    CHECK(status_with(back_leaf, (kBspCellLowest | kBspCellHighest) << 1) == Status::bad_data);
    CHECK(status_with(leaf, 0x10) == Status::bad_data);
}

TEST_CASE("a labelled BSP tree of spot (a real closed mesh, 15,076 tree triangles) draws the bytes of both sides" *
          doctest::test_suite("slow")) {
#if defined(__SANITIZE_ADDRESS__)
    MESSAGE("spot: checked by the host build, not under ASan (its tree takes minutes there)");
#else
    const tool::Scene spot = test::load_model("spot.obj");
    const Built b = build(spot);
    REQUIRE_MESSAGE(b.stats.cells == tool::BspCells::labelled, b.stats.cells_note);
    const Loaded l = load(b.built, spot);
    const Box box = box_of(l.tree);
    std::vector<Camera> cams = random_cameras(spot.camera, box, 16, 7);
    const std::vector<Camera> inside = inside_cameras(spot.camera, l.tree, box, 4);
    cams.insert(cams.end(), inside.begin(), inside.end());
    const Tally t = compare("spot", spot, b, cams);
    CHECK(t.faces[1] > 0);
#endif
}

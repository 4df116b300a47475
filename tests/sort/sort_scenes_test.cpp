// Newell and the reverse painter on interpenetrating scenes they were not tuned on: random soups of
// several seeds and sizes, crossing sticks, boxes stacked into each other, a ground grid through the
// near plane, a city from above, with and without culling. Against the z-buffer (32-bit depth) they
// must give the same face-id image on >= 99.9% of off-edge pixels with no hole (a pixel the z-buffer
// covers left empty) and no crack (a pixel inside a face's area, all of whose neighbours show that face in
// the z-buffer, showing another face); the reverse painter writes every pixel once.
#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "common/gen_scenes.hpp"
#include "support/scene_util.hpp"

using namespace hider;
using hider::test::render_ids;

namespace {

/// Generated scene g framed from inside: the eye within half a unit of its target on each axis, looking
/// within 2 units of it (offsets from rng, the same on every library), in a frame of width x height.
bool scene_from_inside(const tool::gen::GenScene& g, std::mt19937& rng, int width, int height, tool::Scene& s) {
    auto u = [&rng] { return (static_cast<int>(rng() % 1001) - 500) / 1000.0; };
    tool::CameraArgs args = tool::gen::camera_args(g);
    args.width = width;
    args.height = height;
    const tool::gen::P3 c = g.target;
    const double ex = u(), ey = u(), ez = u(), tx = u(), ty = u(), tz = u();
    args.eye = tool::Vec3d{c.x + ex, c.y + ey, c.z + ez};
    args.target = tool::Vec3d{c.x + 4 * tx, c.y + 4 * ty, c.z + 4 * tz};
    std::string why;
    return tool::build_scene(tool::gen::obj_model(g), args, s, why);
}

/// Newell and the reverse painter against the z-buffer on one scene; returns Newell's statistics.
NewellStats check_ids(const tool::Scene& s, const std::string& name, bool cull) {
    NewellStats newell;
    const tool::RenderResult z = render_ids(s, tool::Algo::zbuffer, cull);
    const std::vector<uint32_t> zi = tool::decode_ids(z);
    for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) {
        const tool::RenderResult r = render_ids(s, algo, cull);
        const std::vector<uint32_t> ri = tool::decode_ids(r);
        const ref::Agreement a = ref::compare_ids(ri, zi, s.width, s.height);
        const test::Defects d = test::count_defects(ri, zi, s.width, s.height);
        const std::string what = name + (algo == tool::Algo::newell ? " newell" : " reverse") + (cull ? " cull" : " no-cull");
        INFO(what);
        MESSAGE(what << ": " << a.off_edge_mismatch << " of " << a.off_edge << " off-edge pixels differ, holes " << d.holes
                     << ", cracks " << d.cracks << "; polygons " << r.polygons << ", cuts " << r.newell.splits << ", pair tests "
                     << r.newell.pair_tests << ", unresolved " << r.newell.unresolved << ", too deep " << r.newell.too_deep);
        CHECK(a.rate() >= 0.999);
        CHECK(d.holes == 0);
        CHECK(d.cracks == 0);
        CHECK(r.stats.status == Status::ok);
        if (algo == tool::Algo::reverse) CHECK(r.stats.pixels_written == r.pixels_covered);  // overdraw 1.00
        if (algo == tool::Algo::newell) newell = r.newell;
    }
    return newell;
}

/// Pixels where `ids` shows a face farther than the nearest one, judged on the snapped screen triangles
/// every algorithm draws (exact planes through the projected, clipped vertices, in long double) at the
/// pixel centres strictly inside every triangle that covers them (centres on an edge are skipped).
long wrong_on_snapped_planes(const tool::Scene& s, bool cull, const std::vector<uint32_t>& ids) {
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    const Mesh mesh = s.mesh();
    std::vector<ScreenVertex> verts(mesh.positions.size());
    project_vertices(view, mesh.positions, {verts.data(), verts.size()});
    struct T {
        ScreenVertex a, b, c;
        uint32_t id;
    };
    std::vector<T> tris;
    FrameStats st;
    for (size_t t = 0; t < mesh.tris.size(); ++t)
        for_each_clipped(view, mesh, {verts.data(), verts.size()}, t, st, [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
            const int32_t area = TriangleRaster::signed_area(a, b, c);
            if (area != 0 && !(cull && area > 0)) tris.push_back({a, b, c, s.ids[t]});
        });
    auto edge = [](const ScreenVertex& p, const ScreenVertex& q, double x, double y) {
        return (double(q.x) - p.x) * (y - p.y) - (double(q.y) - p.y) * (x - p.x);
    };
    auto depth = [](const T& t, double x, double y) {
        const long double x1 = t.b.x - t.a.x, y1 = t.b.y - t.a.y, z1 = static_cast<long double>(t.b.z) - t.a.z;
        const long double x2 = t.c.x - t.a.x, y2 = t.c.y - t.a.y, z2 = static_cast<long double>(t.c.z) - t.a.z;
        const long double nx = y1 * z2 - z1 * y2, ny = z1 * x2 - x1 * z2, nz = x1 * y2 - y1 * x2;
        return static_cast<long double>(t.a.z) - (nx * (x - t.a.x) + ny * (y - t.a.y)) / nz;
    };
    long wrong = 0;
    for (int py = 0; py < s.height; ++py)
        for (int px = 0; px < s.width; ++px) {
            const double x = (px + 0.5 - s.width / 2.0) * 16, y = (py + 0.5 - s.height / 2.0) * 16;
            bool on_edge = false;
            long double best = 1e30L, shown = 1e30L;
            const uint32_t id = ids[static_cast<size_t>(py) * static_cast<size_t>(s.width) + static_cast<size_t>(px)];
            for (const T& t : tris) {
                const double e0 = edge(t.a, t.b, x, y), e1 = edge(t.b, t.c, x, y), e2 = edge(t.c, t.a, x, y);
                on_edge = on_edge || e0 == 0 || e1 == 0 || e2 == 0;
                if (!((e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0))) continue;
                const long double d = depth(t, x, y);
                best = d < best ? d : best;
                if (t.id == id) shown = d < shown ? d : shown;
            }
            if (!on_edge && best < 1e30L && shown > best && shown < 1e30L) ++wrong;
        }
    return wrong;
}

void check_scene(const std::string& name) {
    const tool::Scene s = test::generated_scene(name);
    for (bool cull : {true, false}) check_ids(s, name, cull);
}

}  // namespace

TEST_CASE("Newell and the reverse painter match the z-buffer on random interpenetrating soups") {
    for (const char* name : {"dense-1-150", "dense-2-150", "dense-3-50", "dense-4-300", "soup-5-500"}) check_scene(name);
}

TEST_CASE("Newell and the reverse painter match the z-buffer on stacks of nearly parallel triangles") {
    // 2 to 11 random triangles 2 units wide on one tilted plane, lifted 1e-4, 3e-4 or 1e-3 units apart
    // (gap x layer), seen from 4 units. Once a third triangle has cut one of a pair, the pair's pieces
    // lie within the rounding slack of each other's plane at every corner; taken for "wholly farther",
    // a piece went before a nearer one (a red team's stacks: 37 of 400 frames at 160x120, up to 128
    // off-edge pixels, status ok). Against the 32-bit z-buffer: no off-edge difference, hole or crack.
    std::mt19937 rng(20261204u);
    auto u = [&rng](double a, double b) { return a + (b - a) * (static_cast<double>(rng()) / 4294967296.0); };
    long z_wrong = 0, flagged = 0;
    for (int seed = 0; seed < 60; ++seed) {
        tool::ObjModel m;
        const int n = 2 + seed % 10;
        const double gap = seed % 3 == 0 ? 1e-4 : (seed % 3 == 1 ? 3e-4 : 1e-3);
        const double nx = u(-0.5, 0.5), ny = u(-0.5, 0.5);
        for (int i = 0; i < n; ++i) {
            tool::ObjFace f;
            for (int k = 0; k < 3; ++k) {
                const double x = u(-1, 1), y = u(-1, 1);
                f.v.push_back(static_cast<int32_t>(m.vertices.size()));
                m.vertices.push_back({x, y, -(nx * x + ny * y) * 0.5 + gap * i});
            }
            f.id = static_cast<uint32_t>(i + 1);
            m.faces.push_back(f);
        }
        tool::CameraArgs args;
        args.width = 160;
        args.height = 120;
        args.eye = tool::Vec3d{u(-1, 1), u(-1, 1), 4};
        args.target = tool::Vec3d{0, 0, 0};
        tool::Scene s;
        std::string why;
        REQUIRE_MESSAGE(tool::build_scene(m, args, s, why), why);
        for (const bool cull : {false, true}) {
            const std::vector<uint32_t> zi = tool::decode_ids(render_ids(s, tool::Algo::zbuffer, cull));
            z_wrong += wrong_on_snapped_planes(s, cull, zi);
            for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) {
                const tool::RenderResult r = render_ids(s, algo, cull);
                const std::vector<uint32_t> ids = tool::decode_ids(r);
                const ref::Agreement a = ref::compare_ids(ids, zi, s.width, s.height);
                const test::Defects d = test::count_defects(ids, zi, s.width, s.height);
                INFO("seed " << seed << std::string(algo == tool::Algo::newell ? " newell" : " reverse") << std::string(cull ? " cull" : " no-cull"));
                const long wrong = wrong_on_snapped_planes(s, cull, ids);
                if (r.stats.status == Status::ok) {  // never silently wrong
                    CHECK(wrong == 0);
                    CHECK(a.off_edge_mismatch == 0);
                    CHECK(d.holes == 0);
                    CHECK(d.cracks == 0);
                } else {
                    MESSAGE("status " << std::string(status_name(r.stats.status)) << ": " << wrong << " pixels from a farther layer, "
                                      << a.off_edge_mismatch << " off edges, " << d.cracks << " cracks");
                    ++flagged;
                }
            }
        }
    }
    CHECK(z_wrong == 0);  // the referee agrees with the z-buffer
    // A stack whose order the cuts cannot settle says so (unresolved pairs: capacity_exceeded); the old
    // side test drew 10 of these 60 stacks wrong with status ok. Now 2 (4 frames, without culling) say so.
    MESSAGE(flagged << " of 240 frames returned a status other than ok");
    CHECK(flagged <= 4);
}

TEST_CASE("Newell and the reverse painter match the z-buffer on sticks, stacked boxes, a ground grid and a city") {
    for (const char* name : {"mikado-1-24", "mikado-2-40", "stacked-1-8", "stacked-2-12", "grid-1-20-10", "city-1-10-10-above",
                             "boxes-7-20"})
        check_scene(name);
}

namespace {
/// Newell and the reverse painter give the z-buffer's face on every off-edge pixel of generated scene
/// `name` (a scene of a sweep that once differed), with the status ok; returns Newell's statistics.
NewellStats check_off_edge_exact(const char* name, bool cull) {
    const tool::Scene s = test::generated_scene(name);
    const std::vector<uint32_t> zi = tool::decode_ids(render_ids(s, tool::Algo::zbuffer, cull));
    NewellStats newell;
    for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) {
        const tool::RenderResult r = render_ids(s, algo, cull);
        const ref::Agreement a = ref::compare_ids(tool::decode_ids(r), zi, s.width, s.height);
        INFO(name << (algo == tool::Algo::newell ? " newell" : " reverse") << (cull ? " cull" : " no-cull"));
        CHECK(a.off_edge > 30000);
        CHECK(a.off_edge_mismatch == 0);
        CHECK(r.stats.status == Status::ok);
        CHECK(r.newell.unresolved == 0);
        if (algo == tool::Algo::newell) newell = r.newell;
    }
    return newell;
}
}  // namespace

TEST_CASE("Newell and the reverse painter agree with the z-buffer on every off-edge pixel where outlines drifted") {
    // Found by a sweep of random scenes: a piece's outline clipped from already rounded points drifted
    // along a later cut meeting it at a shallow angle, and Newell misordered pixels with the status ok
    // (stacked-142-8 culled: 1 pixel; boxes-169-10 with back faces: 50). Outlines now keep exact edges.
    for (const auto& [name, cull] : {std::pair<const char*, bool>{"stacked-142-8", true}, {"boxes-169-10", false}}) check_off_edge_exact(name, cull);
}

TEST_CASE("Newell orders by their shared pixels the pairs of a cycle no cut breaks, and separates pieces on exact edges") {
    // Found by sweeps (every one without culling): cycles of pieces of two boxes that no plane cuts
    // (boxes-143-6: 1 off-edge pixel, boxes-143-10: 2, boxes-387-10: 4), left in the order found with
    // the status ok; and pieces taken for disjoint on the grid points of an edge two cuts made a subpixel
    // long, which pointed the wrong way (stacked-56-12: 47 pixels, the cycles there were harmless).
    // Each must now give the z-buffer's faces, with every uncut pair of a cycle ordered by its pixels.
    for (const char* name : {"boxes-143-6", "boxes-143-10", "boxes-387-10", "stacked-56-12"}) {
        const NewellStats n = check_off_edge_exact(name, false);
        CHECK(n.pixel_ordered > 0);
    }
}

TEST_CASE("Newell and the reverse painter agree with the z-buffer where a cut line passed a pixel centre") {
    // Found by sweeps: a cut line through two grid points passed a pixel centre on the wrong side of the
    // exact crossing of the two planes, and that pixel went to the wrong face with the status ok (1 or 2
    // pixels each). crossing_line() now checks the centres next to the line and moves its ends.
    for (const auto& [name, cull] : {std::pair<const char*, bool>{"soup-159-200", true}, {"soup-245-200", false}, {"stacked-49-12", true},
                                     {"stacked-60-12", true}, {"stacked-183-8", true}, {"dense-44-100", false}})
        check_off_edge_exact(name, cull);
}

TEST_CASE("A cut whose crossing passes a pixel centre by a hair is exact: the line pivots where the crossing passes it") {
    // Found by sweeps: crossings within 0.0003 to 0.1 subpixel of a pixel centre over their length
    // (stacked-349-8 nearly along a column of centres, boxes-211-10 along a row), where no line through the box borders or
    // through grid points near the crossing beyond the box passed every centre on its side, so the cut
    // was reported inexact and the frame capacity_exceeded. The pivots of crossing_line() now find a line.
    for (const auto& [name, cull] : {std::pair<const char*, bool>{"stacked-349-8", true}, {"boxes-211-10", true}, {"stacked-47-12", true},
                                     {"stacked-355-8", false}}) {
        const NewellStats n = check_off_edge_exact(name, cull);
        CHECK(n.inexact_cuts == 0);
    }
}

TEST_CASE("Newell and the reverse painter render band by band exactly on soups and sticks seen from inside") {
    // A piece's box decides which bands draw it (with_poly_raster) and which pairs Newell tests, so it
    // must hold every pixel the piece draws; the fuzzer found a cut chain whose rounded box did not, as a
    // row lost at a band's first row. Random soups and piercing sticks, eyes inside them, small frames:
    // 1-, 2- and 3-row bands give the whole frame's bytes. Without piece_box(), mikado-203 loses a row.
#if defined(__SANITIZE_ADDRESS__)
    const uint32_t first = 181, last = 220;  // under ASan a tenth of the seeds (those with mikado-203)
#else
    const uint32_t first = 1, last = 400;
#endif
    int frames = 0, cuts = 0;
    for (uint32_t seed = first; seed <= last; ++seed) {
        tool::gen::GenScene g = seed % 2 == 0 ? tool::gen::soup(seed, 40) : tool::gen::mikado(seed, 30);
        std::mt19937 rng(seed);
        tool::Scene s;
        if (!scene_from_inside(g, rng, 40, 30, s)) continue;
        for (bool cull : {true, false})
            for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) {
                const tool::RenderResult whole = render_ids(s, algo, cull);
                cuts += static_cast<int>(whole.newell.splits);
                ++frames;
                for (int band : {1, 2, 3}) {
                    const std::string what = g.name + (algo == tool::Algo::newell ? " newell" : " reverse") +
                                             (cull ? " cull" : " no-cull") + " band " + std::to_string(band);
                    INFO(what);
                    CHECK(render_ids(s, algo, cull, 32, band).rgb == whole.rgb);
                }
            }
    }
    MESSAGE(frames << " frames, " << cuts << " cuts");
    CHECK(frames >= static_cast<int>(last - first + 1) * 3);
    CHECK(cuts > static_cast<int>(last - first + 1) * 50);
}

TEST_CASE("Newell's cycle search skips pairs a search of the chain tried in vain: a fuzzer's 37 triangles at 24x17" *
          doctest::test_suite("slow")) {  // 4 s under ASan
    // obj_render_fuzz found this input (a mangled cyclic_bars.obj) slow: 16 s under ASan. In a frame this
    // small nearly every pair overlaps, a chain of moves closed 3,634 cycles that no cut breaks and its
    // pixels ordered, and each one searched every pair of the cycle again: 1,041,204 pair tests. The pairs
    // of the longest earlier search of the same chain that found no cut are now skipped (their polygons are
    // unchanged): 458,298, with the moves, cuts, cycles and pixel orders of the full search (500d174), so
    // the same order. Since the parts of a clipped triangle have planes of their own and the fans of its
    // quads that are not flat on the grid are ordered among themselves: 1,638 cycles, 291,510 pair tests
    // and the same pixels. The eye is the fuzzer's: inside the model's box, looking at its first vertex.
    tool::ObjModel model;
    tool::ObjError err;
    REQUIRE(tool::load_obj(std::string(HIDER_TEST_DATA) + "/obj/newell_cycles_fuzz.obj", model, err));
    tool::Vec3d lo = model.vertices[0], hi = lo;
    for (const auto& v : model.vertices)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], v[k]);
            hi[k] = std::max(hi[k], v[k]);
        }
    tool::CameraArgs args;
    args.width = 24;
    args.height = 17;
    args.eye = tool::Vec3d{lo[0] + (hi[0] - lo[0]) * 0.4, lo[1] + (hi[1] - lo[1]) * 0.55, lo[2] + (hi[2] - lo[2]) * 0.45};
    args.target = model.vertices[0];
    tool::Scene s;
    std::string why;
    REQUIRE_MESSAGE(tool::build_scene(model, args, s, why), why);
    // Where faces 23 and 28 (which share an edge) meet, the 32-bit z-buffer gets 13 pixels wrong against
    // the exact reference and Newell 8, all on edges; one that Newell gets right lies amid the z-buffer's
    // wrong face (a crack by count_defects against the z-buffer). So Newell is held to the reference, and
    // to the z-buffer off edges only.
    const std::vector<uint32_t> exact = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), false);
    const std::vector<uint32_t> zi = tool::decode_ids(render_ids(s, tool::Algo::zbuffer, false));
    const ref::Agreement z_to_exact = ref::compare_ids(zi, exact, s.width, s.height);
    MESSAGE("the z-buffer: " << z_to_exact.total_mismatch << " pixels differ from the exact reference, "
                             << test::count_defects(zi, exact, s.width, s.height).cracks << " of them cracks");
    std::vector<uint8_t> newell_rgb;
    for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) {
        const tool::RenderResult r = render_ids(s, algo, false);
        const std::vector<uint32_t> ids = tool::decode_ids(r);
        const ref::Agreement to_exact = ref::compare_ids(ids, exact, s.width, s.height);
        const ref::Agreement to_z = ref::compare_ids(ids, zi, s.width, s.height);
        const test::Defects d = test::count_defects(ids, exact, s.width, s.height);
        INFO(std::string(algo == tool::Algo::newell ? "newell" : "reverse"));
        MESSAGE(to_exact.total_mismatch << " pixels differ from the exact reference (" << to_exact.off_edge_mismatch
                                        << " of " << to_exact.off_edge << " off edges), " << to_z.total_mismatch
                                        << " from the z-buffer; pair tests " << r.newell.pair_tests);
        CHECK(to_exact.off_edge > 150);
        CHECK(to_exact.off_edge_mismatch == 0);
        CHECK(to_z.off_edge_mismatch == 0);
        CHECK(d.holes == 0);
        CHECK(d.cracks == 0);
        CHECK(r.stats.status == Status::ok);
        CHECK(r.newell.unresolved == 0);
        CHECK(r.newell.cycles == 1078);
        CHECK(r.newell.moves == 5297);
        CHECK(r.newell.splits == 446);
        CHECK(r.newell.pixel_ordered == 886);
        CHECK(r.newell.pair_tests < 300000);  // 1,041,204 with the full search, 458,298 with the memo alone
        if (algo == tool::Algo::newell) newell_rgb = r.rgb;
        else CHECK(r.rgb == newell_rgb);
        if (algo == tool::Algo::reverse) CHECK(r.stats.pixels_written == r.pixels_covered);
    }
}

TEST_CASE("Newell and the reverse painter match the exact reference in tiny frames with the eye among the triangles" *
          doctest::test_suite("slow")) {  // 3 s under ASan
    // Frames of 16x12 to 32x24 (where nearly every pair overlaps, as in the fuzzer's slow input) inside
    // random soups, dense soups and piercing sticks, 200 seeds, culled and not. Against the exact reference:
    // no off-edge difference and no hole, and no more cracks than the 32-bit z-buffer has against it (its
    // snapped vertices are Newell's too: dense-23-40 at 32x24 has one such pixel, in both).
    int frames = 0;
    long zbuffer_cracks = 0, newell_cracks = 0;
    uint64_t most_tests = 0;
    for (uint32_t seed = 1; seed <= 200; ++seed) {
        const tool::gen::GenScene g = seed % 3 == 0   ? tool::gen::soup(seed, 40)
                                      : seed % 3 == 1 ? tool::gen::mikado(seed, 30)
                                                      : tool::gen::dense_soup(seed, 40);
        std::mt19937 rng(seed * 7 + 1);
        const int sizes[3][2] = {{24, 17}, {16, 12}, {32, 24}};
        tool::Scene s;
        if (!scene_from_inside(g, rng, sizes[seed % 3][0], sizes[seed % 3][1], s)) continue;
        for (bool cull : {true, false}) {
            const std::vector<uint32_t> exact = ref::render_ids(test::ref_triangles(s), test::ref_camera(s), cull);
            const std::vector<uint32_t> zi = tool::decode_ids(render_ids(s, tool::Algo::zbuffer, cull));
            const long z_cracks = test::count_defects(zi, exact, s.width, s.height).cracks;
            zbuffer_cracks += z_cracks;
            ++frames;
            for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) {
                const tool::RenderResult r = render_ids(s, algo, cull);
                const std::vector<uint32_t> ids = tool::decode_ids(r);
                const test::Defects d = test::count_defects(ids, exact, s.width, s.height);
                INFO(g.name << " " << s.width << "x" << s.height << (algo == tool::Algo::newell ? " newell" : " reverse")
                            << (cull ? " cull" : " no-cull"));
                CHECK(ref::compare_ids(ids, exact, s.width, s.height).off_edge_mismatch == 0);
                CHECK(ref::compare_ids(ids, zi, s.width, s.height).off_edge_mismatch == 0);
                CHECK(d.holes == 0);
                CHECK(d.cracks <= z_cracks);
                CHECK(r.stats.status == Status::ok);
                if (algo == tool::Algo::reverse) CHECK(r.stats.pixels_written == r.pixels_covered);
                if (algo == tool::Algo::newell) {
                    newell_cracks += d.cracks;
                    most_tests = std::max<uint64_t>(most_tests, r.newell.pair_tests);
                }
            }
        }
    }
    MESSAGE(frames << " frames; cracks against the exact reference: z-buffer " << zbuffer_cracks << ", Newell " << newell_cracks
                   << "; most pair tests in one frame " << most_tests);
    CHECK(frames >= 380);
}

TEST_CASE("Newell and the reverse painter order near-parallel surfaces as the z-buffer does") {
    // A small triangle 3e-5 to 1e-3 units in front of or behind a large one on a parallel plane (a model 2
    // units wide, random slopes and placements): closer than half a subpixel's depth slope at these sizes.
    // A rounding slack on whole triangles took such pairs for coplanar and drew whichever came later (35
    // of these 90 frames wrong, on up to 6% of their off-edge pixels); only a piece's cut points are rounded.
    int frames = 0, moved = 0;
    for (uint32_t seed = 1; seed <= 30; ++seed) {
        std::mt19937 rng(seed);
        auto u = [&rng](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() % 100001) / 100000.0; };
        const double a = u(-0.9, 0.9), b = u(-0.9, 0.9);
        const double gaps[] = {3e-5, 1e-4, 3e-4, 1e-3};
        const double gap = gaps[rng() % 4] * (rng() % 2 == 0 ? 1.0 : -1.0);
        const double scale = u(0.2, 0.6), cx = u(-0.2, 0.2), cy = u(-0.3, 0.0);
        const double big[3][2] = {{-1, -1}, {1, -1}, {0, 1}};
        std::ostringstream obj;
        obj.precision(17);
        for (const auto& v : big) obj << "v " << v[0] << ' ' << v[1] << ' ' << a * v[0] + b * v[1] << '\n';
        for (const auto& v : big) {
            const double x = cx + scale * v[0], y = cy + scale * v[1];
            obj << "v " << x << ' ' << y << ' ' << a * x + b * y + gap << '\n';
        }
        obj << "f 1 2 3\nf 4 5 6\n";
        std::istringstream in(obj.str());
        tool::ObjModel model;
        tool::ObjError err;
        REQUIRE(tool::parse_obj(in, "near-parallel", model, err));
        for (const int width : {160, 320, 640}) {
            tool::CameraArgs args;
            args.width = width;
            args.height = width * 3 / 4;
            tool::Scene s;
            std::string why;
            REQUIRE_MESSAGE(tool::build_scene(model, args, s, why), why);
            const std::string name = "near-parallel seed " + std::to_string(seed) + " gap " + std::to_string(gap) + " " +
                                     std::to_string(width) + " px";
            moved += static_cast<int>(check_ids(s, name, false).moves);
            ++frames;
        }
    }
    CHECK(frames == 90);
    CHECK(moved > 0);  // the small triangle in front waits for the large one behind it
}

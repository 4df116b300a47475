// Building blocks of the object-space algorithms: the exact 128-bit arithmetic, the O(n) radix sort,
// plane-side classification and splitting, and Newell's pool at capacity N and N - 1.
#include <hider/int128.hpp>
#include <hider/sort/newell.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

TEST_CASE("mul128 and Int128 sums are exact (checked against unsigned __int128 on the host)") {
    std::mt19937_64 rng(5);
    for (int i = 0; i < 100000; ++i) {
        const auto a = static_cast<int64_t>(rng()) >> (rng() % 63), b = static_cast<int64_t>(rng()) >> (rng() % 63);
        const auto c = static_cast<int64_t>(rng()) >> (rng() % 63), d = static_cast<int64_t>(rng()) >> (rng() % 63);
        const __int128 want = static_cast<__int128>(a) * b - static_cast<__int128>(c) * d;
        const Int128 got = mul128(a, b) - mul128(c, d);
        CHECK(got.lo == static_cast<uint64_t>(want));
        CHECK(got.hi == static_cast<int64_t>(want >> 64));
        CHECK(got.sign() == (want > 0) - (want < 0));
    }
    CHECK(mul128(INT64_MIN, INT64_MIN).hi == int64_t{1} << 62);
    CHECK(mul128(INT64_MIN, -1).fits64() == false);
    CHECK(mul128(-3, 5).fits64());
}

TEST_CASE("radix_sort sorts 32-bit keys ascending and stably in O(n)") {
    std::mt19937 rng(9);
    for (size_t n : {0u, 1u, 2u, 100u, 70000u}) {
        std::vector<SortKey> keys(n), scratch(n);
        for (size_t i = 0; i < n; ++i) keys[i] = {static_cast<uint32_t>(rng() % (n < 100 ? 7u : 0xFFFFFFFFu)), static_cast<uint32_t>(i)};
        std::vector<SortKey> want = keys;
        std::stable_sort(want.begin(), want.end(), [](SortKey a, SortKey b) { return a.key < b.key; });
        radix_sort({keys.data(), n}, {scratch.data(), n});
        bool same = true;
        for (size_t i = 0; i < n; ++i) same = same && keys[i].key == want[i].key && keys[i].index == want[i].index;
        CHECK(same);
    }
}

TEST_CASE("a plane classifies its own vertices as on it and cuts a straddling triangle into two exact pieces") {
    auto sv = [](int x, int y, uint32_t z) { ScreenVertex v; v.x = static_cast<int16_t>(x); v.y = static_cast<int16_t>(y); v.z = z; return v; };
    ScreenPoly wall{{sv(-800, -800, 1u << 30), sv(800, -800, 1u << 30), sv(0, 800, 1u << 30)}, 0, 0, 0, 0, 0, 0, 3, kNotMoved, kNoCut, 0};
    update_extents(wall);
    const ScreenPlane pl = plane_of(wall);
    for (const ScreenVertex& v : wall.v) CHECK(side(pl, v).sign() == 0);
    CHECK(side(pl, sv(5, 5, (1u << 30) + 1)).sign() > 0);  // farther
    CHECK(side(pl, sv(5, 5, (1u << 30) - 1)).sign() < 0);
    const Int128 slack = rounding_slack(pl);
    CHECK(classify(pl, slack, sv(5, 5, (1u << 30) + 4)) > 0);
    CHECK(classify(pl, slack, sv(5, 5, (1u << 30) - 4)) < 0);
    CHECK(classify(pl, slack, sv(5, 5, (1u << 30) + 3)) == 0);  // within the rounding slack of a cut point
    ScreenPoly stick{{sv(-400, 0, 1u << 29), sv(400, 0, 3u << 29), sv(0, 300, 3u << 29)}, 0, 0, 0, 0, 0, 0, 7, kNotMoved, kNoCut, kPolyFront};
    update_extents(stick);
    Outline whole;
    outline_of(stick, {}, whole);
    CHECK(side_of(pl, whole) == 0);
    std::vector<PieceCut> cuts;
    ScreenPoly far{}, near{};
    PieceCut far_cut{}, near_cut{};
    REQUIRE(cut_polygon(stick, {}, pl, wall.tri, far, near, far_cut, near_cut) == CutResult::cut);
    far.cut = 0;
    near.cut = 1;
    cuts = {far_cut, near_cut};
    CHECK(far.cut == 0);
    CHECK(near.cut == 1);
    CHECK(known_side(far, {cuts.data(), cuts.size()}, wall.tri) == 1);
    CHECK(known_side(near, {cuts.data(), cuts.size()}, wall.tri) == -1);
    CHECK(known_side(far, {cuts.data(), cuts.size()}, 99) == 0);
    const ScreenPoly pieces[2] = {far, near};
    for (int k = 0; k < 2; ++k) {
        CHECK(pieces[k].tri == 7);
        CHECK(pieces[k].flags == kPolyFront);
        Outline o;
        outline_of(pieces[k], {cuts.data(), cuts.size()}, o);
        CHECK(o.count >= 3);
        CHECK(side_of(pl, o) == (k == 0 ? 1 : -1));  // each piece lies on one side of the plane
    }
    // The two pieces cover exactly the stick's pixels, each once (a 100x50 frame around it).
    const int w = 100, h = 50;
    std::vector<int> count(w * h, 0), want(w * h, 0);
    FrameView<Grey8Format> frame;
    frame.width = w;
    frame.height = h;
    frame.y0 = 0;
    frame.y1 = h;
    const BandBounds bb = band_bounds(frame);
    auto cover = [&](const ScreenPoly& p, std::vector<int>& c) {
        with_poly_raster(p, {cuts.data(), cuts.size()}, bb, frame, [&](const auto& r, int32_t y0, int32_t y1) {
            return r.spans(y0, y1, [&](int32_t y, int32_t x0, int32_t x1, uint32_t) { for (int32_t x = x0; x < x1; ++x) ++c[y * w + x]; });
        });
    };
    cover(stick, want);
    cover(far, count);
    cover(near, count);
    CHECK(count == want);
    CHECK(std::count(want.begin(), want.end(), 1) > 100);
}

TEST_CASE("Newell's cut pool at capacity N finishes the frame exactly; at N - 1 it reports the drop") {
    tool::Scene s;
    std::string why;
    REQUIRE(test::scene_from_ref(ref::piercing(), s, why));
    tool::RenderOptions opt;
    opt.algo = tool::Algo::newell;
    opt.shade = Shade::id;
    opt.format = tool::PixelFormat::rgb888;
    tool::RenderResult big;
    REQUIRE(tool::render(s, opt, big, why));
    REQUIRE(big.stats.status == Status::ok);
    const size_t built = big.polygons - (big.polygons - s.tris.size() > 0 ? 0 : 0);
    (void)built;
    // The pool must hold every extra piece: polygons after cuts minus polygons before them.
    tool::RenderOptions probe = opt;
    probe.algo = tool::Algo::painter;
    tool::RenderResult painter;
    REQUIRE(tool::render(s, probe, painter, why));
    const size_t needed = big.polygons - painter.polygons;
    REQUIRE(needed > 0);
    opt.split_pool = needed;
    tool::RenderResult exact;
    REQUIRE(tool::render(s, opt, exact, why));
    CHECK(exact.stats.status == Status::ok);
    CHECK(exact.newell.dropped == 0);
    CHECK(exact.rgb == big.rgb);
    opt.split_pool = needed - 1;
    tool::RenderResult short_pool;
    REQUIRE(tool::render(s, opt, short_pool, why));
    CHECK(short_pool.stats.status == Status::capacity_exceeded);
    CHECK(short_pool.newell.dropped >= 1);
    CHECK(short_pool.rgb.size() == big.rgb.size());  // the frame still finishes
}

TEST_CASE("build_polys fills its list to capacity and counts what it drops") {
    const tool::Scene s = test::load_model("torus.obj");
    View view;
    REQUIRE(make_view(s.camera, s.width, s.height, view) == Status::ok);
    std::vector<ScreenVertex> verts(s.positions.size());
    REQUIRE(project_vertices(view, s.mesh().positions, {verts.data(), verts.size()}) == Status::ok);
    std::vector<ScreenPoly> store(4000);
    BoundedList<ScreenPoly> all(store.data(), store.size());
    FrameStats st;
    build_polys(view, s.mesh(), {verts.data(), verts.size()}, true, all, st);
    REQUIRE(st.status == Status::ok);
    const size_t n = all.size();
    BoundedList<ScreenPoly> exact(store.data(), n);
    FrameStats st_exact;
    build_polys(view, s.mesh(), {verts.data(), verts.size()}, true, exact, st_exact);
    CHECK(st_exact.status == Status::ok);
    CHECK(exact.size() == n);
    CHECK(exact.dropped() == 0);
    BoundedList<ScreenPoly> short_list(store.data(), n - 1);
    FrameStats st_short;
    build_polys(view, s.mesh(), {verts.data(), verts.size()}, true, short_list, st_short);
    CHECK(st_short.status == Status::capacity_exceeded);
    CHECK(short_list.size() == n - 1);
    CHECK(short_list.dropped() == 1);
    CHECK(short_list.high_water() == n - 1);
}

TEST_CASE("newell_order refuses an order list or scratch smaller than the polygon pool") {
    View view;
    view.width = 32;
    view.height = 32;
    std::vector<ScreenPoly> store(10);
    std::vector<PieceCut> cut_store(10);
    std::vector<uint32_t> ord(10), heap(10), pos(10), links(20), cells(grid_cells(32, 32)), chain(10);
    BoundedList<ScreenPoly> polys(store.data(), store.size());
    BoundedList<PieceCut> cuts(cut_store.data(), cut_store.size());
    NewellScratch scratch{{heap.data(), 10}, {pos.data(), 10}, {links.data(), 20}, {cells.data(), cells.size()}, {chain.data(), 10}};
    NewellStats ns;
    BoundedList<uint32_t> order(ord.data(), ord.size());
    CHECK(newell_order(view, polys, cuts, scratch, order, ns) == Status::ok);
    BoundedList<uint32_t> short_order(ord.data(), 5);
    CHECK(newell_order(view, polys, cuts, scratch, short_order, ns) == Status::invalid_argument);
    NewellScratch short_heap = scratch;
    short_heap.heap = {heap.data(), 9};
    CHECK(newell_order(view, polys, cuts, short_heap, order, ns) == Status::invalid_argument);
    NewellScratch short_links = scratch;
    short_links.links = {links.data(), 19};
    CHECK(newell_order(view, polys, cuts, short_links, order, ns) == Status::invalid_argument);
    NewellScratch short_cells = scratch;
    short_cells.cells = {cells.data(), cells.size() - 1};
    CHECK(newell_order(view, polys, cuts, short_cells, order, ns) == Status::invalid_argument);
    NewellScratch short_chain = scratch;
    short_chain.chain = {chain.data(), 9};
    CHECK(newell_order(view, polys, cuts, short_chain, order, ns) == Status::invalid_argument);
}

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

TEST_CASE("a plane classifies its own vertices as on it and splits a straddling triangle into pieces") {
    auto sv = [](int x, int y, uint32_t z) { ScreenVertex v; v.x = static_cast<int16_t>(x); v.y = static_cast<int16_t>(y); v.z = z; return v; };
    ScreenPoly wall{{sv(-800, -800, 1u << 30), sv(800, -800, 1u << 30), sv(0, 800, 1u << 30)}, 0, 0, 0, 0, 0, 0, 0, kNotMoved, 0};
    update_extents(wall);
    const ScreenPlane pl = plane_of(wall);
    for (const ScreenVertex& v : wall.v) CHECK(side(pl, v).sign() == 0);
    CHECK(side(pl, sv(5, 5, (1u << 30) + 1)).sign() > 0);  // farther
    CHECK(side(pl, sv(5, 5, (1u << 30) - 1)).sign() < 0);
    ScreenPoly stick{{sv(-400, 0, 1u << 29), sv(400, 0, 3u << 29), sv(0, 300, 3u << 29)}, 0, 0, 0, 0, 0, 0, 7, kNotMoved, kPolyFront};
    update_extents(stick);
    CHECK(side_of(pl, stick) == 0);
    ScreenPoly pieces[3];
    const int n = split_by_plane(stick, pl, pieces);
    CHECK(n == 3);
    for (int k = 0; k < n; ++k) {
        CHECK(pieces[k].tri == 7);
        CHECK(pieces[k].flags == kPolyFront);
        CHECK(side_of(pl, pieces[k]) != 0);  // every piece lies on one side (within the rounding slack)
        CHECK((TriangleRaster::signed_area(pieces[k].v[0], pieces[k].v[1], pieces[k].v[2]) > 0) ==
              (TriangleRaster::signed_area(stick.v[0], stick.v[1], stick.v[2]) > 0));  // winding kept
    }
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

TEST_CASE("newell_order refuses an order list smaller than the polygon pool") {
    std::vector<ScreenPoly> store(10);
    std::vector<uint32_t> ord(5);
    BoundedList<ScreenPoly> polys(store.data(), store.size());
    BoundedList<uint32_t> order(ord.data(), ord.size());
    NewellStats ns;
    CHECK(newell_order(polys, order, ns) == Status::invalid_argument);
}

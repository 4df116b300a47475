// The object-space algorithms against the z-buffer: Newell and the reverse painter give the same
// face-id image on >= 99.9% of off-edge pixels for every model and for scenes built to break the plain
// painter (cyclic overlap, piercing, interpenetrating boxes, soups), which the plain painter gets wrong.
// The reverse painter writes every pixel at most once; every algorithm renders band by band exactly.
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

namespace {

tool::RenderResult run(const tool::Scene& s, tool::Algo algo, bool cull, int band = 0) {
    tool::RenderOptions opt;
    opt.algo = algo;
    opt.cull = cull;
    opt.shade = Shade::id;
    opt.format = tool::PixelFormat::rgb888;
    opt.band_rows = band;
    tool::RenderResult r;
    std::string why;
    const bool ok = tool::render(s, opt, r, why);
    REQUIRE_MESSAGE(ok, why);
    return r;
}

const char* name_of(tool::Algo a) {
    switch (a) {
        case tool::Algo::zbuffer: return "zbuffer";
        case tool::Algo::painter: return "painter";
        case tool::Algo::newell: return "newell";
        case tool::Algo::reverse: return "reverse";
        case tool::Algo::raycast: return "raycast";
        case tool::Algo::bsp: return "bsp";
        case tool::Algo::bsp_front: return "bsp-front";
    }
    return "?";
}

/// Pixels where `ids` differs from the z-buffer although the z-buffer shows the same face on all 8
/// neighbours: isolated holes from T-junctions at Newell's cuts (the off-edge metric cannot see them).
long interior_holes(const std::vector<uint32_t>& ids, const std::vector<uint32_t>& z, int w, int h) {
    long n = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const uint32_t c = z[static_cast<size_t>(y) * w + x];
            if (c == 0 || ids[static_cast<size_t>(y) * w + x] == c) continue;
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) interior = interior && z[static_cast<size_t>(y + dy) * w + x + dx] == c;
            n += interior;
        }
    return n;
}

/// Agreement of algo with the z-buffer; also checks the reverse painter's single writes.
double agreement(const tool::Scene& s, const std::string& name, tool::Algo algo, bool cull) {
    const tool::RenderResult z = run(s, tool::Algo::zbuffer, cull);
    const tool::RenderResult r = run(s, algo, cull);
    const ref::Agreement a = ref::compare_ids(tool::decode_ids(r), tool::decode_ids(z), s.width, s.height);
    const long holes = interior_holes(tool::decode_ids(r), tool::decode_ids(z), s.width, s.height);
    MESSAGE(name << " " << std::string(name_of(algo)) << std::string(cull ? " cull" : " no-cull") << ": interior holes " << holes
                 << " of " << r.pixels_covered << " covered");
    CHECK(holes * 2000 <= static_cast<long>(r.pixels_covered));  // below 0.05% (T-junctions; README)
    MESSAGE(name << " " << std::string(name_of(algo)) << std::string(cull ? " cull" : " no-cull") << ": off-edge " << a.off_edge
                 << ", mismatched " << a.off_edge_mismatch << ", splits " << r.newell.splits << ", moves "
                 << r.newell.moves << ", unresolved " << r.newell.unresolved << ", overdraw "
                 << (r.pixels_covered ? double(r.stats.pixels_written) / r.pixels_covered : 0.0));
    CHECK(r.stats.status == Status::ok);
    if (algo == tool::Algo::reverse) CHECK(r.stats.pixels_written == r.pixels_covered);  // overdraw exactly 1.00
    return a.rate();
}

std::vector<std::pair<std::string, tool::Scene>> hard_scenes() {
    return test::scenes_from_ref({ref::cyclic_bars(), ref::piercing(), ref::boxes(6, 10), ref::soup(1, 300),
                                  ref::huge_triangles(4)});
}

}  // namespace

TEST_CASE("Newell and the reverse painter match the z-buffer on the scenes that break the painter") {
    for (const auto& [name, s] : hard_scenes())
        for (bool cull : {true, false})
            for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) CHECK(agreement(s, name, algo, cull) >= 0.999);
}

TEST_CASE("Newell and the reverse painter match the z-buffer on every test model" * doctest::test_suite("slow")) {
    for (const char* name : {"torus.obj", "teapot.obj", "suzanne.obj", "spot.obj", "cow.obj", "fandisk.obj",
                             "beetle.obj", "woody.obj", "stanford-bunny.obj"}) {
        const tool::Scene s = test::load_model(name);
        for (bool cull : {true, false})
            for (tool::Algo algo : {tool::Algo::newell, tool::Algo::reverse}) CHECK(agreement(s, name, algo, cull) >= 0.999);
    }
}

TEST_CASE("the plain painter differs from the z-buffer on cyclic overlap and on piercing polygons") {
    for (const ref::RefScene& rs : {ref::cyclic_bars(), ref::piercing()}) {
        tool::Scene s;
        std::string why;
        REQUIRE(test::scene_from_ref(rs, s, why));
        for (DepthKey key : {DepthKey::farthest, DepthKey::barycenter}) {
            tool::RenderOptions opt;
            opt.algo = tool::Algo::painter;
            opt.painter_key = key;
            opt.shade = Shade::id;
            opt.format = tool::PixelFormat::rgb888;
            tool::RenderResult r;
            REQUIRE(tool::render(s, opt, r, why));
            const ref::Agreement a = ref::compare_ids(tool::decode_ids(r), tool::decode_ids(run(s, tool::Algo::zbuffer, true)), s.width, s.height);
            MESSAGE(rs.name << " painter key " << std::string(key == DepthKey::farthest ? "farthest" : "barycenter") << ": "
                            << a.off_edge_mismatch << " off-edge pixels differ from the z-buffer");
            CHECK(a.off_edge_mismatch > 20);  // Newell and the reverse painter mismatch 0 here: this is the error
        }
    }
}

TEST_CASE("painter, Newell and the reverse painter render band by band exactly like the full frame") {
    const tool::Scene torus = test::load_model("torus.obj");
    std::vector<std::pair<std::string, tool::Scene>> scenes = hard_scenes();
    scenes.push_back({"torus", torus});
    for (const auto& [name, s] : scenes)
        for (tool::Algo algo : {tool::Algo::painter, tool::Algo::newell, tool::Algo::reverse})
            for (int band : {1, 7, 32}) {
                const std::string& scene_name = name;  // INFO cannot capture a structured binding (clang)
                INFO(scene_name, " ", name_of(algo), " band ", band);
                CHECK(run(s, algo, false, band).rgb == run(s, algo, false).rgb);
            }
}

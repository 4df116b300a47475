// Newell and the reverse painter on interpenetrating scenes they were not tuned on: random soups of
// several seeds and sizes, crossing sticks, boxes stacked into each other, a ground grid through the
// near plane, a city from above, with and without culling. Against the z-buffer (32-bit depth) they
// must give the same face-id image on >= 99.9% of off-edge pixels with no hole (a pixel the z-buffer
// covers left empty) and no crack (a pixel inside a face's area, all of whose neighbours show that face in
// the z-buffer, showing another face); the reverse painter writes every pixel once.
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/gen_scenes.hpp"
#include "support/scene_util.hpp"

using namespace hider;

namespace {

tool::RenderResult render_ids(const tool::Scene& s, tool::Algo algo, bool cull, int depth_bits = 32, int band = 0) {
    tool::RenderOptions opt;
    opt.algo = algo;
    opt.cull = cull;
    opt.shade = Shade::id;
    opt.format = tool::PixelFormat::rgb888;
    opt.depth_bits = depth_bits;
    opt.band_rows = band;
    tool::RenderResult r;
    std::string why;
    const bool ok = tool::render(s, opt, r, why);
    REQUIRE_MESSAGE(ok, why);
    return r;
}


void check_scene(const std::string& name) {
    const tool::Scene s = test::generated_scene(name);
    for (bool cull : {true, false}) {
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
        }
    }
}

}  // namespace

TEST_CASE("Newell and the reverse painter match the z-buffer on random interpenetrating soups") {
    for (const char* name : {"dense-1-150", "dense-2-150", "dense-3-50", "dense-4-300", "soup-5-500"}) check_scene(name);
}

TEST_CASE("Newell and the reverse painter match the z-buffer on sticks, stacked boxes, a ground grid and a city") {
    for (const char* name : {"mikado-1-24", "mikado-2-40", "stacked-1-8", "stacked-2-12", "grid-1-20-10", "city-1-10-10-above",
                             "boxes-7-20"})
        check_scene(name);
}

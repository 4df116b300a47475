// Which polygons Newell takes for one plane. The parts of one clipped triangle (near plane, guard band)
// lie in slightly different planes (rounded clip vertices), so a side found against one part must not
// stand for another's: where it did, the crossing line of two clipped triangles that pierce each other
// moved by up to a pixel (170 pixels of a 320x240 frame in the first scene below, 2 to 7 in the others),
// with status ok. And the triangles of an OBJ polygon are left unordered among themselves only when
// the polygon is flat. Each frame is compared with the z-buffer's (32-bit depth).
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "support/scene_util.hpp"

using namespace hider;

namespace {

Q16 q(double v) { return Q16::from_raw(static_cast<int32_t>(std::llround(v * 65536.0))); }
Vec3q16 q3(const double (&p)[3]) { return {q(p[0]), q(p[1]), q(p[2])}; }

struct TwoTriangles {
    double eye[3], target[3];
    uint32_t fovy_bam;
    double near, far;
    int width, height;
    bool cull;
    double v[6][3];
};

tool::Scene scene_of(const TwoTriangles& t) {
    tool::Scene s;
    for (const auto& p : t.v) s.positions.push_back(q3(p));
    s.tris = {Tri{{0, 1, 2}}, Tri{{3, 4, 5}}};
    s.ids = {1, 2};
    s.camera.eye = q3(t.eye);
    s.camera.target = q3(t.target);
    s.camera.up = {Q16{}, Q16::from_raw(65536), Q16{}};
    s.camera.fovy = Angle::from_bam(t.fovy_bam);
    s.camera.near = q(t.near);
    s.camera.far = q(t.far);
    s.width = t.width;
    s.height = t.height;
    return s;
}

/// Pixels where algo's face differs from the z-buffer's (32-bit depth); REQUIREs status ok.
long differing(const tool::Scene& s, tool::Algo algo, bool cull, const std::vector<uint32_t>& z) {
    const tool::RenderResult r = test::render_ids(s, algo, cull);
    REQUIRE(r.stats.status == Status::ok);
    const std::vector<uint32_t> ids = tool::decode_ids(r);
    long n = 0;
    for (size_t i = 0; i < ids.size(); ++i) n += ids[i] != z[i];
    return n;
}

uint64_t next(uint64_t& x) {  // splitmix64
    uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
double uniform(uint64_t& x, double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next(x) >> 11) / 9007199254740992.0; }

}  // namespace

TEST_CASE("clipped piercing pairs: Newell and reverse show the z-buffer's face on every pixel") {
    // Found by random scenes with the eye inside (world units, exact Q16 values, up = +y).
    const TwoTriangles found[] = {
        {{30.30267333984375, 13.985595703125, 75.055877685546875},
         {315.97055053710938, 106.5081787109375, 185.88092041015625}, 742240228, 22.663589477539062, 953.43043518066406,
         320, 240, true,
         {{271.96673583984375, -4.8370361328125, 494.6192626953125},
          {86.993865966796875, 392.31564331054688, 230.45770263671875},
          {93.277084350585938, -241.91796875, -44.178512573242188},
          {112.45263671875, 364.26394653320312, 181.41961669921875},
          {94.177215576171875, -80.033828735351562, 49.753952026367188},
          {152.02432250976562, 154.14045715332031, 284.9276123046875}}},
        {{-153.25276184082031, 22.848739624023438, -82.943923950195312},
         {-172.65628051757812, 265.3350830078125, 38.434219360351562}, 1236132458, 13.354949951171875, 956.80525207519531,
         160, 120, false,
         {{-371.06111145019531, 158.79222106933594, 112.37985229492188},
          {-27.982666015625, 27.40277099609375, -33.862136840820312},
          {-76.03253173828125, -78.77294921875, -107.12081909179688},
          {-237.23672485351562, 118.92189025878906, -41.6722412109375},
          {-269.56765747070312, 29.749984741210938, -22.350143432617188},
          {101.17143249511719, -107.91435241699219, 327.28700256347656}}},
        {{-4.1197357177734375, 9.425567626953125, 51.848846435546875},
         {-77.448699951171875, -25.486312866210938, 332.35166931152344}, 895541081, 37.737808227539062, 895.04180908203125,
         160, 120, true,
         {{-90.430526733398438, -162.13687133789062, 422.56385803222656},
          {-12.72149658203125, 216.95623779296875, 202.54707336425781},
          {183.64016723632812, -384.54617309570312, 218.77626037597656},
          {111.14674377441406, 134.76425170898438, 486.80558776855469},
          {137.64366149902344, -138.69717407226562, 108.94358825683594},
          {-68.850982666015625, 56.963134765625, 374.55809020996094}}},
        {{44.754196166992188, 62.839035034179688, -27.941146850585938},
         {-52.356231689453125, -236.88735961914062, -118.14402770996094}, 882545590, 3.2927398681640625, 950.54965209960938,
         160, 120, true,
         {{-318.81394958496094, -423.92404174804688, 260.75625610351562},
          {-270.44300842285156, -35.676177978515625, 483.15071105957031},
          {-109.99851989746094, -323.81636047363281, 130.55006408691406},
          {-277.03108215332031, -124.61744689941406, 512},
          {-101.34963989257812, -489.00001525878906, 97.2152099609375},
          {-273.24334716796875, 211.0872802734375, 202.90414428710938}}},
    };
    for (const TwoTriangles& t : found) {
        const tool::Scene s = scene_of(t);
        const tool::RenderResult zr = test::render_ids(s, tool::Algo::zbuffer, t.cull);
        REQUIRE(zr.stats.triangles_clipped >= 1);
        const std::vector<uint32_t> z = tool::decode_ids(zr);
        CHECK(differing(s, tool::Algo::newell, t.cull, z) == 0);
        CHECK(differing(s, tool::Algo::reverse, t.cull, z) == 0);
    }
}

TEST_CASE("clipped piercing pairs: soups around the eye") {
    // 40 triangles in a cube with the eye inside and a near plane 0.003..0.2 of the cube: most triangles
    // are clipped by the near plane or the guard band into several parts, and many pierce each other.
    long frames = 0, clipped = 0, cut = 0, off_newell = 0, off_reverse = 0, bad_newell = 0, bad_reverse = 0;
    for (uint64_t seed = 1; seed <= 300; ++seed) {
        uint64_t x = seed * 7919;
        tool::ObjModel m;
        for (int i = 0; i < 40; ++i) {
            const double c[3] = {uniform(x, -1, 1), uniform(x, -1, 1), uniform(x, -1, 1)}, r = uniform(x, 0.2, 1.2);
            for (int k = 0; k < 3; ++k) m.vertices.push_back({c[0] + r * uniform(x, -1, 1), c[1] + r * uniform(x, -1, 1),
                                                              c[2] + r * uniform(x, -1, 1)});
            const auto n = static_cast<int32_t>(m.vertices.size());
            m.faces.push_back({{n - 3, n - 2, n - 1}, static_cast<uint32_t>(i + 1), i + 1});
        }
        tool::CameraArgs cam;
        const tool::Vec3d eye{uniform(x, -0.5, 0.5), uniform(x, -0.5, 0.5), uniform(x, -0.5, 0.5)};
        cam.eye = eye;
        cam.target = tool::Vec3d{eye[0] + uniform(x, -1, 1), eye[1] + uniform(x, -1, 1), eye[2] + uniform(x, -1, 1)};
        cam.fov_deg = uniform(x, 40, 110);
        cam.near = std::pow(10.0, uniform(x, -2.5, -0.7));
        cam.far = 10;
        cam.width = 160;
        cam.height = 120;
        tool::Scene s;
        std::string why;
        REQUIRE_MESSAGE(tool::build_scene(m, cam, s, why), why);
        const bool cull = (seed & 1) != 0;
        const tool::RenderResult zr = test::render_ids(s, tool::Algo::zbuffer, cull);
        const std::vector<uint32_t> z = tool::decode_ids(zr);
        ++frames;
        clipped += zr.stats.triangles_clipped;
        const tool::RenderResult nr = test::render_ids(s, tool::Algo::newell, cull);
        cut += nr.newell.splits;
        const long dn = differing(s, tool::Algo::newell, cull, z), dr = differing(s, tool::Algo::reverse, cull, z);
        off_newell += dn;
        off_reverse += dr;
        bad_newell += dn != 0;
        bad_reverse += dr != 0;
    }
    MESSAGE("frames ", frames, ", clipped ", clipped, ", cut ", cut, "; pixels off: newell ", off_newell, " in ", bad_newell,
            ", reverse ", off_reverse, " in ", bad_reverse);
    CHECK(clipped >= 10 * frames);
    CHECK(cut >= 10 * frames);
    // Parts named by their mesh triangle alone: 10 pixels in 5 frames. Now 2 pixels in one frame (seed 203),
    // within the documented slack of a piece: a piece of triangle 6 cut along part 0 of clipped triangle 25
    // reaches under 1/10 subpixel past part 1's plane (nearly the same plane), which the slack of half a
    // subpixel's depth slope takes for 'on it'; the pixel centres lie 0.07 and 0.08 subpixel from the crossing.
    CHECK(bad_newell <= 1);
    CHECK(bad_reverse <= 1);
    CHECK(off_newell <= 2);
    CHECK(off_reverse <= 2);
}

TEST_CASE("a folded OBJ polygon: its triangles are ordered like any others") {
    // Quads and a pentagon whose vertices do not lie on one plane, seen so that one fan triangle hides
    // another: taken for one flat face, Newell left them in depth order and drew 38 of 210 pixels wrong.
    const char* models[] = {
        "v -1 -1 0\nv 1 -1 1.5\nv 1 1 0\nv -1 1 1.5\nf 1 2 3 4\n",
        "v -1 -1 0\nv 1 -1 1.5\nv 1 1 0\nv -1 1 1.5\nf 1 2 3\nf 1 3 4\n",  // the same, as two faces
        "v -1 -1 0\nv 1 -1 1.2\nv 1.3 0.5 -0.4\nv 0 1.4 1.1\nv -1.3 0.5 -0.6\nf 1 2 3 4 5\n",
    };
    for (const char* text : models) {
        for (bool cull : {false, true}) {
            std::istringstream in(text);
            tool::ObjModel m;
            tool::ObjError err;
            REQUIRE(tool::parse_obj(in, "folded.obj", m, err));
            tool::CameraArgs cam;
            cam.eye = tool::Vec3d{0, -4, 2};
            cam.target = tool::Vec3d{0, 0, 0.5};
            cam.width = 64;
            cam.height = 48;
            tool::Scene s;
            std::string why;
            REQUIRE_MESSAGE(tool::build_scene(m, cam, s, why), why);
            tool::RenderResult r[3];
            const tool::Algo algos[3] = {tool::Algo::zbuffer, tool::Algo::newell, tool::Algo::reverse};
            for (int a = 0; a < 3; ++a) {
                tool::RenderOptions opt;
                opt.algo = algos[a];
                opt.cull = cull;
                opt.depth_bits = 32;
                opt.format = tool::PixelFormat::rgb888;  // headlight: one id, but each triangle its own shade
                REQUIRE_MESSAGE(tool::render(s, opt, r[a], why), why);
                REQUIRE(r[a].stats.status == Status::ok);
            }
            const std::string model = text;
            CAPTURE(model);
            CAPTURE(cull);
            CHECK(r[0].stats.triangles_drawn >= (cull ? 1u : 2u));
            CHECK(r[1].rgb == r[0].rgb);
            CHECK(r[2].rgb == r[0].rgb);
        }
    }
}

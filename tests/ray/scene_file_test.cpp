// The ray-tracing scene format (tools/common/ray_scene.*, README.md "Scene files (`hider-render --scene`)"): every kind of
// malformed line is reported as "file:line: what" and rejected, good files load exactly, and
// hider-render --scene keeps the tools' error contract (exit 2, one stderr line, no output file).
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/ray_scene.hpp"

using namespace hider;

namespace {

const char* kCamera = "camera eye 0 2 8 target 0 0 0\n";

std::string scratch() {
    const std::string d = std::string(HIDER_TEST_OUT) + "/scene_file";
    std::filesystem::create_directories(d);
    return d;
}

/// Parses `text` as "t.txt"; returns the error ("" on success).
std::string parse_error(const std::string& text, tool::RayScene* out = nullptr) {
    std::istringstream in(text);
    tool::RayScene s;
    std::string error;
    const bool ok = tool::parse_ray_scene(in, "t.txt", scratch(), s, error);
    if (ok && out != nullptr) *out = std::move(s);
    return ok ? std::string() : error;
}

struct BadCase {
    std::string text;  ///< scene text; the faulty line is the last one unless stated
    std::string where;  ///< "t.txt:N: "
    std::string what;   ///< part of the message
};

}  // namespace

TEST_CASE("every malformed scene line is reported with file, line and what is wrong") {
    const std::string c = kCamera;
    const std::vector<BadCase> cases = {
        {c + "spheer 0 0 0 1\n", "t.txt:2: ", "unknown keyword 'spheer'"},
        {c + "sphere 0 0 0\n", "t.txt:2: ", "sphere: missing radius"},
        {c + "sphere 0 0 x 1\n", "t.txt:2: ", "bad number 'x' for centre z"},
        {c + "sphere 0 0 0 1e999\n", "t.txt:2: ", "bad number '1e999' for radius"},
        {c + "\n# comment\nsphere 0 0 0 -1\n", "t.txt:4: ", "radius must be > 0 (got -1)"},
        {c + "sphere 0 0 0 0\n", "t.txt:2: ", "radius must be > 0"},
        {c + "sphere 0 0 0 1e-9\n", "t.txt:2: ", "below the fixed-point resolution"},
        {c + "plane 0 0 0 1\n", "t.txt:2: ", "plane: normal is the zero vector"},
        {c + "sphere 0 0 0 1 reflect 1.5\n", "t.txt:2: ", "reflectivity 1.5 outside [0, 1]"},
        {c + "plane 0 1 0 0 reflect -0.1\n", "t.txt:2: ", "reflectivity -0.1 outside [0, 1]"},
        {c + "sphere 9000 0 0 1\n", "t.txt:2: ", "does not fit the world cube"},
        {c + "sphere 8191.5 0 0 1\n", "t.txt:2: ", "does not fit the world cube"},
        {c + "plane 0 1 0 20000\n", "t.txt:2: ", "outside the world (|offset| < 16384)"},
        // Values that fail only once rounded to Q16 (lib/'s validate_scene() would refuse the scene
        // with no line), and a normal whose squares overflow double:
        {c + "sphere 8191.5 0 0 0.4999999\n", "t.txt:2: ", "does not fit the world cube"},
        {c + "plane 0 1 0 16383.9999999\n", "t.txt:2: ", "outside the world (|offset| < 16384)"},
        {c + "plane 1e-300 0 0 1\n", "t.txt:2: ", "plane: offset 1e+300 (along the unit normal) outside the world"},
        {c + "max-distance 1e-9\n", "t.txt:2: ", "max-distance: 1e-09 is below the fixed-point resolution"},
        {c + "triangle 0 0 0 1 0 0 0 1e5 0\n", "t.txt:2: ", "triangle: vertex 3 y 100000 is outside the world cube"},
        // A triangle on a line or a point (a red team's: accepted without a word, as a mesh of such is not):
        {c + "triangle 0 0 0 1 1 1 2 2 2\n", "t.txt:2: ", "triangle: no area at the fixed-point resolution (2^-16)"},
        {c + "triangle 0 0 0 0 0 0 0 0 0\n", "t.txt:2: ", "triangle: no area"},
        // A byte a message cannot show is written as \xNN (a NUL was invisible: "bad number '1'"):
        {c + std::string("sphere 0 0 0 1\0 2\n", 18), "t.txt:2: ", "sphere: bad number '1\\x00' for radius"},
        {c + "triangle 0 0 0 1e-6 0 0 0 1e-6 0\n", "t.txt:2: ", "triangle: no area"},
        {c + "light point 0 9000 0\n", "t.txt:2: ", "light: position y 9000 is outside the world cube"},
        {c + "light directional 0 0 0\n", "t.txt:2: ", "light: direction is the zero vector"},
        {c + "light spot 0 1 0\n", "t.txt:2: ", "expected 'point' or 'directional' (got 'spot')"},
        {c + "light point 0 1 0 colour 1 1 1\n", "t.txt:2: ", "unknown attribute 'colour'"},
        {c + "sphere 0 0 0 1 color 1.2 0 0\n", "t.txt:2: ", "color red 1.2 outside [0, 1]"},
        {c + "sphere 0 0 0 1 shiny 3\n", "t.txt:2: ", "unknown attribute 'shiny'"},
        {c + "plane 0 1 0 0 checker 0 0 0 0\n", "t.txt:2: ", "checker size 0 outside (0, 8192)"},
        {c + "background 0 0 0 1\n", "t.txt:2: ", "background: unexpected '1'"},
        {c + "ambient 0.1 0.1\n", "t.txt:2: ", "ambient: missing ambient blue"},
        {c + "bounces 2.5\n", "t.txt:2: ", "bounces: 2.5 out of range"},
        {c + "bounces 17\n", "t.txt:2: ", "bounces: 17 out of range (whole number 0..16)"},
        {c + "max-distance 0\n", "t.txt:2: ", "max-distance: 0 out of range"},
        {c + "max-distance 32767.99999999\n", "t.txt:2: ", "max-distance: 32768 out of range"},  // rounds to 2^31 raw
        {c + "size 0 10\n", "t.txt:2: ", "size: 0x10 out of range"},
        {c + "mesh\n", "t.txt:2: ", "mesh: missing file name"},
        {c + "mesh no_such.obj\n", "t.txt:2: ", "no_such.obj: cannot open file"},
        {c + "mesh m.obj scale -2\n", "t.txt:2: ", "mesh: scale must be > 0"},
        {"sphere 0 0 0 1\n", "t.txt: ", "no camera line"},
        {c + "camera eye 0 0 1 target 0 0 0\n", "t.txt:2: ", "camera: given twice (first on line 1)"},
        {"camera eye 0 0 1\n", "t.txt:1: ", "camera: missing target"},
        {"camera eye 1 1 1 target 1 1 1\n", "t.txt:1: ", "camera: eye and target coincide"},
        {"camera eye 0 5 0 target 0 0 0\n", "t.txt:1: ", "camera: up is parallel to the view direction"},
        {"camera eye 0 0 5 target 0 0 0 fov 180\n", "t.txt:1: ", "camera: fov 180 outside [0.5, 179.5] degrees"},
        {"camera eye 0 0 5 target 0 0 0 zoom 2\n", "t.txt:1: ", "camera: unknown field 'zoom'"},
        {"camera eye 0 0 9000 target 0 0 0\n", "t.txt:1: ", "camera: eye z 9000 is outside the world cube"},
        // A field given twice is refused, not overridden (like a second camera line).
        {"camera eye 0 0 5 eye 0 0 6 target 0 0 0\n", "t.txt:1: ", "camera: eye given twice"},
        {"camera eye 0 0 5 target 0 0 0 fov 40 fov 50\n", "t.txt:1: ", "camera: fov given twice"},
        {c + "sphere 0 0 0 1 color 1 0 0 color 0 1 0\n", "t.txt:2: ", "sphere: color given twice"},
        {c + "plane 0 1 0 0 reflect 0.5 checker 1 0 0 0 reflect 0.2\n", "t.txt:2: ", "plane: reflect given twice"},
        {c + "light point 0 1 0 color 1 1 1 color 0 0 0\n", "t.txt:2: ", "light: color given twice"},
        {c + "mesh m.obj scale 2 scale 3\n", "t.txt:2: ", "mesh: scale given twice"},
        {c + "sphere 0 0 0 1 " + std::string(5000, ' ') + "\n", "t.txt:2: ", "line longer than 4096 bytes"},
        {c + "#" + std::string(4096, 'x'), "t.txt:2: ", "line longer than 4096 bytes"},  // 4,097 bytes, no newline
        {c + "#" + std::string(4095, 'x') + "\n" + std::string(10000, '\0'), "t.txt:3: ", "line longer than 4096 bytes"},
    };
    for (const BadCase& b : cases) {
        INFO("scene text: ", b.text.substr(0, 200));
        const std::string error = parse_error(b.text);
        INFO("error: ", error);
        CHECK(error.rfind(b.where, 0) == 0);
        CHECK(error.find(b.what) != std::string::npos);
    }
}

TEST_CASE("a mesh line reports the OBJ's own file and line, and a mesh moved out of the world") {
    const std::string dir = scratch();
    std::ofstream(dir + "/bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 x\nf 1 2 3\n";
    std::ofstream(dir + "/m.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::string error = parse_error(std::string(kCamera) + "mesh bad.obj\n");
    CHECK(error.rfind("t.txt:2: mesh: ", 0) == 0);
    CHECK(error.find("bad.obj:3: ") != std::string::npos);
    error = parse_error(std::string(kCamera) + "mesh m.obj translate 8191.5 0 0\n");
    CHECK(error.find("transformed vertex x 8192.5 is outside the world cube") != std::string::npos);
    tool::RayScene s;
    CHECK(parse_error(std::string(kCamera) + "mesh m.obj scale 2 rotate 0 0 90 translate 1 0 0 color 1 0 0\n", &s).empty());
    REQUIRE(s.meshes.size() == 1);
    // x' = -2 y + 1, y' = 2 x: vertex 2 (1, 0, 0) lands on (1, 2, 0).
    CHECK(s.meshes[0].positions[1].x == Q16::from_int(1));
    CHECK(s.meshes[0].positions[1].y == Q16::from_int(2));
    CHECK(s.surfaces[s.meshes[0].surface].color == Rgb{255, 0, 0});
}

TEST_CASE("a good scene file loads every value exactly") {
    tool::RayScene s;
    const std::string text =
        "# a comment line\n"
        "size 64 48\r\n"
        "camera eye 0 1 5 target 0 0 0 up 0 1 0 fov 40   # trailing comment\n"
        "background 0.5 0.25 1\nambient 0.1 0.2 0.3\nbounces 3\nmax-distance 50\n"
        "sphere 1 2 3 0.5 color 1 0 0 reflect 0.5\n"
        "plane 0 2 0 -2 checker 0.25 0 0 1\n"
        "triangle 0 0 0 1 0 0 0 1 0 color 0 1 0\n"
        "light point 1 5 1 color 1 1 0.5\n"
        "light directional 0 1 0\n";
    REQUIRE(parse_error(text, &s).empty());
    CHECK(s.width == 64);
    CHECK(s.height == 48);
    CHECK(s.background == Rgb{128, 64, 255});
    CHECK(s.ambient == Rgb{26, 51, 77});
    CHECK(s.bounces == 3);
    CHECK(s.max_distance == Q16::from_int(50));
    REQUIRE(s.spheres.size() == 1);
    CHECK(s.spheres[0].centre == Vec3q16{Q16::from_int(1), Q16::from_int(2), Q16::from_int(3)});
    CHECK(s.spheres[0].radius == Q16::from_ratio(1, 2));
    CHECK(s.surfaces[s.spheres[0].surface].reflect_q15 == hider::ray::kReflectOne / 2);
    REQUIRE(s.planes.size() == 1);
    CHECK(s.planes[0].normal.y == Q30::from_raw(Q30::kOne));
    CHECK(s.planes[0].offset == Q16::from_int(-1));  // 2y = -2 is y = -1
    CHECK(s.surfaces[s.planes[0].surface].checker_size == Q16::from_ratio(1, 4));
    REQUIRE(s.meshes.size() == 1);  // the loose triangles
    CHECK(s.meshes[0].tris.size() == 1);
    CHECK(s.surfaces[s.meshes[0].surfaces[0]].color == Rgb{0, 255, 0});
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].color == Rgb{255, 255, 128});
    CHECK(s.lights[1].direction.y == Q30::from_raw(Q30::kOne));
    CHECK(s.sphere_bound.radius == Q16::from_ratio(1, 2));
}

TEST_CASE("values at the edge of the fixed-point range load, and a huge normal is still a direction") {
    tool::RayScene s;
    // 8191 + 0.99999 rounds to 2^29 - 1 raw: inside; a normal whose squares overflow double.
    REQUIRE(parse_error(std::string(kCamera) + "sphere 8191 0 0 0.99999\nplane 1e300 0 0 5e299\nmax-distance 1e-4\n", &s).empty());
    REQUIRE(s.spheres.size() == 1);
    CHECK(s.spheres[0].centre.x.raw() + s.spheres[0].radius.raw() == (int32_t{1} << 29) - 1);
    REQUIRE(s.planes.size() == 1);
    CHECK(s.planes[0].normal.x == Q30::from_raw(Q30::kOne));
    CHECK(s.planes[0].offset == Q16::from_ratio(1, 2));
    CHECK(s.max_distance.raw() == 7);  // 1e-4 x 65536 = 6.55
}

namespace {

struct Run {
    int code = -1;
    std::string out, err;
};

Run render(const std::vector<std::string>& args) {
    const std::string dir = scratch();
    std::string cmd = HIDER_RENDER_EXE;
    for (const std::string& a : args) cmd += " '" + a + "'";
    cmd += " >" + dir + "/out.txt 2>" + dir + "/err.txt";
    const int status = std::system(cmd.c_str());
    Run r;
    r.code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream o(dir + "/out.txt"), e(dir + "/err.txt");
    r.out.assign(std::istreambuf_iterator<char>(o), std::istreambuf_iterator<char>());
    r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
    return r;
}

}  // namespace

TEST_CASE("hider-render --scene: errors exit 2 with one line and no output; the demo renders") {
    const std::string dir = scratch(), out = dir + "/scene.ppm";
    std::ofstream(dir + "/bad.txt") << kCamera << "sphere 0 0 0 -1\n";
    auto check_error = [&](const std::vector<std::string>& args, const std::string& part) {
        std::filesystem::remove(out);
        const Run r = render(args);
        INFO("stderr: ", r.err);
        CHECK(r.code == 2);
        CHECK(r.out.empty());
        CHECK(r.err.rfind("hider-render: ", 0) == 0);
        CHECK(r.err.find(part) != std::string::npos);
        CHECK(r.err.find('\n') == r.err.size() - 1);
        CHECK_FALSE(std::filesystem::exists(out));
    };
    check_error({"--scene", dir + "/bad.txt", "-o", out}, dir + "/bad.txt:2: sphere: radius must be > 0 (got -1)");
    check_error({"--scene", dir + "/missing.txt", "-o", out}, "missing.txt: cannot open");
    const std::string demo = std::string(HIDER_TEST_DATA) + "/scenes/spheres.txt";
    check_error({"--scene", demo, "-o", out, "--eye", "1,2,3"}, "--eye does not apply to --scene");
    check_error({"--scene", demo, "-o", out, "--algo", "painter"}, "--algo must be raycast");
    check_error({"model.obj", "--scene", demo, "-o", out}, "either a model or --scene");
    std::filesystem::remove(out);
    const Run ok = render({"--scene", demo, "-o", out, "--size", "40x32", "--stats"});
    CHECK(ok.code == 0);
    CHECK(ok.out.rfind("rays ", 0) == 0);
    std::ifstream f(out, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    CHECK(bytes.rfind("P6\n40 32\n255\n", 0) == 0);
    CHECK(bytes.size() == std::string("P6\n40 32\n255\n").size() + 40 * 32 * 3);
}

TEST_CASE("a mesh scaled below the fixed-point resolution is refused, not drawn as nothing") {
    // A red team's scene: `mesh ... scale 1e-6` rendered 0 of 64 pixels with exit 0, while a sphere of
    // radius 1e-6 is refused. Every triangle of the icosphere rounds to no area.
    const std::string ball = std::string(HIDER_TEST_DATA) + "/obj/ico3.obj";
    const std::string e = parse_error("mesh " + ball + " scale 1e-6\n");
    CHECK(e.find("t.txt:1: mesh: " + ball + ": all 1280 triangles have no area at the fixed-point resolution (2^-16) after scale 1e-06") == 0);
    // At 1e-3 the triangles keep their area (a few raw units a side): accepted.
    const std::string accepted = parse_error("camera eye 0 0 0.01 target 0 0 0 fov 10\nmesh " + ball + " scale 1e-3\n");
    CHECK_MESSAGE(accepted.empty(), accepted);
}

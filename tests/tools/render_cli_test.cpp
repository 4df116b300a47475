// Tests for the hider-render command line: runs the real binary (HIDER_RENDER_EXE) through /bin/sh and
// checks its contract. Errors: exit 2, a first stderr line "hider-render: <file:line: what | reason>"
// (only usage errors print more: the usage text), nothing on stdout and no output file. Success: exit 0
// and a P6 file "P6\n<W> <H>\n255\n" + W*H*3 bytes. Fixtures: tests/data/bad/ (one error each, line
// numbers stated in their first line) and small models written at test time into HIDER_TEST_OUT.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <hider/bsp/format.hpp>
#include <hider/screen.hpp>

#include "bsp/bsp_blobs.hpp"
#include "common/gen_scenes.hpp"

namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

const std::string kExe = HIDER_RENDER_EXE;
const std::string kBspExe = HIDER_BSP_EXE;
const std::string kBad = std::string(HIDER_TEST_DATA) + "/bad/";

/// Scratch directory of this file's tests (created on first use).
const std::string& scratch() {
    static const std::string dir = [] {
        const std::string d = std::string(HIDER_TEST_OUT) + "/render_cli";
        std::error_code ec;
        fs::create_directories(d, ec);
        return d;
    }();
    return dir;
}

std::string scratch_path(const std::string& name) { return scratch() + "/" + name; }

/// The default output path every run checks for (removed before each run).
std::string out_ppm() { return scratch_path("out.ppm"); }

bool exists(const std::string& path) {
    std::error_code ec;
    return fs::exists(fs::symlink_status(path, ec));
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Writes `text` to a scratch file and returns its path.
std::string write_model(const std::string& name, const std::string& text) {
    const std::string path = scratch_path(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

std::string shell_quoted(const std::string& s) {
    std::string q = "'";
    for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

struct Run {
    std::string command;          ///< as given to the shell, for failure messages
    int code = -1;                ///< exit status; -1 if the process did not exit normally
    std::string out, err;         ///< stdout, stderr
    bool output_created = false;  ///< whether the output path exists after the run
};

/// Runs `exe` with `args` (after the shell commands in `prefix`, if any). `output` is removed before the
/// run and looked for after it; it should be the path given with -o, if any.
Run run_tool(const std::string& exe, const Args& args, const std::string& output, const std::string& prefix = "") {
    const std::string out_file = scratch_path("stdout.txt"), err_file = scratch_path("stderr.txt");
    std::error_code ec;
    fs::remove(output, ec);
    std::string cmd = shell_quoted(exe);
    for (const std::string& a : args) cmd += " " + shell_quoted(a);
    Run r;
    r.command = cmd;
    const std::string line = prefix + cmd + " >" + shell_quoted(out_file) + " 2>" + shell_quoted(err_file);
    const int status = std::system(line.c_str());
    r.code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(out_file);
    r.err = read_file(err_file);
    r.output_created = exists(output);
    return r;
}

/// Runs hider-render (see run_tool).
Run run(const Args& args, const std::string& output = out_ppm(), const std::string& prefix = "") {
    return run_tool(kExe, args, output, prefix);
}

/// hider-render MODEL -o out.ppm EXTRA...
Run render(const std::string& model, const Args& extra = {}) {
    Args args{model, "-o", out_ppm()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

enum class Usage { no, yes };

/// Checks the error contract on `r`: exit 2, empty stdout, no output file, one stderr line that starts
/// "hider-render: " and contains every part; with Usage::yes the usage text follows that line instead.
void check_error(const Run& r, const std::vector<std::string>& parts, Usage usage = Usage::no) {
    INFO("command: ", r.command);
    INFO("stderr: ", r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.output_created);
    const std::string line = first_line(r.err);
    CHECK(line.rfind("hider-render: ", 0) == 0);
    for (const std::string& part : parts) {
        INFO("expected in the first line: ", part);
        CHECK(contains(line, part));
    }
    const std::string rest = r.err.size() > line.size() ? r.err.substr(line.size() + 1) : std::string();
    if (usage == Usage::yes) {
        CHECK(rest.rfind("usage: hider-render MODEL.obj", 0) == 0);
    } else {
        CHECK(r.err == line + "\n");  // exactly one line
    }
}

/// A counter-clockwise (front-facing from +z) triangle around the origin; the default camera frames it.
const std::string kTriangle = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";

std::string triangle_model() { return write_model("triangle.obj", kTriangle); }

/// Looks down -z at the origin from z = 5, so the centre pixel sees (0, 0, 0).
const Args kFrontCamera{"--eye", "0,0,5", "--target", "0,0,0"};

Args with(Args a, const Args& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

/// A P6 file as hider-render writes it: exact header, then exactly w*h*3 bytes (else `ok` is false).
struct Image {
    bool ok = false;
    int width = 0, height = 0;
    std::string rgb;

    /// Pixel (x, y) as 0xRRGGBB, or 0xFFFFFFFF outside the image.
    uint32_t at(int x, int y) const {
        if (x < 0 || y < 0 || x >= width || y >= height) return 0xFFFFFFFFu;
        const size_t i = (static_cast<size_t>(y) * width + x) * 3;
        const auto byte = [&](size_t k) { return static_cast<uint32_t>(static_cast<unsigned char>(rgb[i + k])); };
        return byte(0) << 16 | byte(1) << 8 | byte(2);
    }
};

Image read_image(const std::string& path, int width, int height) {
    const std::string bytes = read_file(path);
    const std::string header = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    Image img;
    img.ok = bytes.rfind(header, 0) == 0 && bytes.size() == header.size() + static_cast<size_t>(width) * height * 3;
    if (img.ok) {
        img.width = width;
        img.height = height;
        img.rgb = bytes.substr(header.size());
    }
    return img;
}

/// Number of pixels equal to `rgb`.
int count_pixels(const Image& img, uint32_t rgb) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) n += img.at(x, y) == rgb;
    return n;
}

}  // namespace

// ---- OBJ errors: "file:line: what" from tools/common/obj.cpp -------------------------------------------

TEST_CASE("A bad number in a v line names the token, the file and the line") {
    const std::string path = kBad + "bad_number.obj";
    check_error(render(path), {path + ":3: ", "bad number", "'1.5.2'", "y coordinate"});
}

TEST_CASE("A face index past the last vertex is rejected with the file, the line and the vertex count") {
    const std::string path = kBad + "index_out_of_range.obj";
    check_error(render(path), {path + ":5: ", "vertex index 7 out of range", "3 vertices"});
}

TEST_CASE("A face index of 0 is rejected with the file and the line") {
    const std::string path = kBad + "index_zero.obj";
    check_error(render(path), {path + ":5: ", "vertex index 0 is invalid"});
}

TEST_CASE("A face with fewer than three vertices is rejected with the file and the line") {
    const std::string path = kBad + "face_two_vertices.obj";
    check_error(render(path), {path + ":5: ", "face has 2 vertices", "at least 3"});
}

TEST_CASE("A malformed face token is quoted in the error with the file and the line") {
    const std::string path = kBad + "face_malformed.obj";
    check_error(render(path), {path + ":5: ", "malformed face vertex", "'3x'"});
}

TEST_CASE("A model with vertices but no faces is rejected as having no faces") {
    const std::string path = kBad + "no_faces.obj";
    check_error(render(path), {path + ": no faces"});
}

TEST_CASE("A model without vertices is rejected, whether it holds only ignored lines or no bytes at all") {
    const std::string comments = kBad + "no_vertices.obj";
    check_error(render(comments), {comments + ": no vertices"});
    const std::string empty = write_model("empty.obj", "");
    check_error(render(empty), {empty + ": no vertices"});
}

TEST_CASE("A missing model file is reported with its path and the system's reason") {
    const std::string path = kBad + "does_not_exist.obj";
    CHECK_FALSE(exists(path));
    check_error(render(path), {path + ": ", "cannot open file", "No such file"});
}

TEST_CASE("A directory given as the model is reported as a file that cannot be opened") {
    check_error(render(scratch()), {scratch() + ": ", "cannot open file"});
}

TEST_CASE("A nan or inf coordinate is rejected with the axis, the token, the file and the line") {
    const std::string nan = kBad + "nan_coordinate.obj";
    check_error(render(nan), {nan + ":3: ", "y coordinate", "'nan'", "not finite"});
    const std::string inf = kBad + "inf_coordinate.obj";
    check_error(render(inf), {inf + ":4: ", "z coordinate", "'-inf'", "not finite"});
}

// ---- Scene fitting: "model: reason" from tools/common/scene.cpp ------------------------------------------

TEST_CASE("A model whose extent overflows double is rejected as too large to represent") {
    // +-1e308 are finite doubles, but their distance is not: no scale maps this box into fixed point.
    const std::string path = kBad + "huge_extent.obj";
    const Run r = render(path);
    check_error(r, {path + ": "});
    CHECK((contains(r.err, "too large") || contains(r.err, "cannot be represented")));
}

TEST_CASE("A model with more vertices than a hider mesh holds is rejected with both counts") {
    std::string text;
    for (int i = 0; i < 65537; ++i) text += "v " + std::to_string(i % 256) + " " + std::to_string(i / 256) + " 0\n";
    const std::string path = write_model("too_many_vertices.obj", text + "f 1 2 257\n");
    check_error(render(path), {path + ": ", "65537 vertices", "65536"});
}

TEST_CASE("A near plane too small for the scene is rejected, and the minimum it names is accepted") {
    const std::string model = triangle_model();
    const Run r = render(model, with(kFrontCamera, {"--near", "1e-9"}));
    check_error(r, {model + ": ", "near plane 1e-09 is too small", "hider needs near >= "});
    const std::string key = "near >= ";
    const size_t at = r.err.find(key);
    const double minimum = at == std::string::npos ? 0.0 : std::strtod(r.err.c_str() + at + key.size(), nullptr);
    INFO("stated minimum: ", minimum);
    CHECK(minimum > 1e-9);
    char above[32], below[32];
    std::snprintf(above, sizeof above, "%.9g", minimum * 1.01);
    std::snprintf(below, sizeof below, "%.9g", minimum * 0.99);
    const Run ok = render(model, with(kFrontCamera, {"--near", above, "--size", "8x6"}));
    INFO("stderr: ", ok.err);
    CHECK(ok.code == 0);
    CHECK(ok.output_created);
    check_error(render(model, with(kFrontCamera, {"--near", below})), {"is too small", "hider needs near >= "});
}

TEST_CASE("An up vector parallel to the view direction is rejected") {
    const std::string model = triangle_model();
    check_error(render(model, {"--eye", "0,0,5", "--target", "0,0,0", "--up", "0,0,1"}),
                {model + ": ", "up vector is parallel to the view direction"});
    check_error(render(model, {"--eye", "0,0,5", "--target", "0,0,0", "--up", "0,0,-3"}), {"up vector is parallel"});
}

TEST_CASE("A zero up vector is rejected") {
    const std::string model = triangle_model();
    check_error(render(model, {"--up", "0,0,0"}), {model + ": ", "up vector is zero"});
}

TEST_CASE("An eye equal to the target is rejected") {
    const std::string model = triangle_model();
    check_error(render(model, {"--eye", "1,2,3", "--target", "1,2,3"}), {model + ": ", "eye and target coincide"});
}

TEST_CASE("A far plane that is not beyond the near plane is rejected with both values") {
    const std::string model = triangle_model();
    check_error(render(model, {"--near", "5", "--far", "5"}), {model + ": ", "far plane (5)", "greater than near (5)"});
    check_error(render(model, {"--near", "5", "--far", "2"}), {model + ": ", "far plane (2)", "greater than near (5)"});
}

TEST_CASE("A near plane too small for the fixed-point range names the option it came from") {
    const std::string model = triangle_model();
    // Given: only the limit. Derived from a tiny --far: says so, with that far plane.
    check_error(render(model, {"--near", "1e-9"}), {model + ": ", "near plane 1e-09 is too small for a scene", "hider needs near >="});
    check_error(render(model, {"--far", "0.0001"}),
                {model + ": ", "near plane 1e-07 (not given: derived from the far plane 0.0001; give --near) is too small"});
}

TEST_CASE("A non-positive near plane is rejected") {
    const std::string model = triangle_model();
    check_error(render(model, {"--near", "0"}), {model + ": ", "near plane must be > 0"});
    check_error(render(model, {"--near", "-1"}), {"near plane must be > 0", "-1"});
}

TEST_CASE("A field of view of 0 or 200 degrees is rejected with the accepted range") {
    const std::string model = triangle_model();
    check_error(render(model, {"--fov", "0"}), {"--fov 0 out of range", "0.5..179.5"});
    check_error(render(model, {"--fov", "200"}), {"--fov 200 out of range", "0.5..179.5"});
}

// ---- Option errors: plain reasons from tools/hider-render/main.cpp --------------------------------------

TEST_CASE("Camera numbers that do not parse or are not finite are rejected with the option and the token") {
    const std::string model = triangle_model();
    check_error(render(model, {"--fov", "wide"}), {"--fov: bad number 'wide'"});
    check_error(render(model, {"--fov", "nan"}), {"--fov: bad number 'nan'"});
    check_error(render(model, {"--near", "1cm"}), {"--near: bad number '1cm'"});
    check_error(render(model, {"--far", "inf"}), {"--far: bad number 'inf'"});
}

TEST_CASE("An unknown --algo is rejected with the list of available algorithms") {
    check_error(render(triangle_model(), {"--algo", "scanline"}),
                {"unknown algo 'scanline'", "available: zbuffer, painter, newell, reverse"});
    check_error(render(triangle_model(), {"--painter-key", "nearest"}), {"unknown painter key 'nearest'", "farthest", "barycenter"});
    check_error(render(triangle_model(), {"--pool", "0"}), {"--pool needs a polygon count"});
    check_error(render(triangle_model(), {"--reorders", "3"}), {"--reorders needs an even word count 0..65536", "'3'"});
    check_error(render(triangle_model(), {"--reorders", "65538"}), {"--reorders needs an even word count"});
}

TEST_CASE("An unknown --shade is rejected with the list of available shades") {
    check_error(render(triangle_model(), {"--shade", "phong"}),
                {"unknown shade 'phong'", "available:", "headlight", "id", "depth"});
}

TEST_CASE("An unknown --format is rejected with the list of available formats") {
    check_error(render(triangle_model(), {"--format", "rgb444"}),
                {"unknown format 'rgb444'", "available:", "rgb565", "rgb888", "grey8"});
}

TEST_CASE("A --size that is zero, too large, missing a side or not numbers is rejected") {
    const std::string model = triangle_model();
    for (const std::string size : {"0x10", "2000x10", "1025x1", "10x-1"}) {
        INFO("--size ", size);
        check_error(render(model, {"--size", size}), {"--size " + size + " out of range", "1..1024"});
    }
    for (const std::string size : {"10", "axb", "10x", "x10", "10x10x10", ""}) {
        INFO("--size ", size);
        check_error(render(model, {"--size", size}), {"--size needs WxH", "'" + size + "'"});
    }
}

TEST_CASE("A --depth-bits other than 16 or 32 is rejected") {
    for (const std::string bits : {"24", "8", "x"}) {
        INFO("--depth-bits ", bits);
        check_error(render(triangle_model(), {"--depth-bits", bits}), {"--depth-bits must be 16 or 32", "'" + bits + "'"});
    }
}

TEST_CASE("A --band that is not a positive row count is rejected") {
    for (const std::string rows : {"0", "-1", "x", "1025", "3.5"}) {
        INFO("--band ", rows);
        check_error(render(triangle_model(), {"--band", rows}), {"--band needs a row count", "'" + rows + "'"});
    }
}

TEST_CASE("A --eye without exactly three comma-separated numbers is rejected") {
    const std::string model = triangle_model();
    check_error(render(model, {"--eye", "1,2"}), {"--eye needs x,y,z", "'1,2'"});
    check_error(render(model, {"--eye", "1,2,3,4"}), {"--eye needs x,y,z", "'1,2,3,4'"});
    check_error(render(model, {"--eye", "1,2,x"}), {"--eye: bad number 'x'"});
    check_error(render(model, {"--eye", "1,,3"}), {"--eye: bad number ''"});
    check_error(render(model, {"--target", "0,nan,0"}), {"--target: bad number 'nan'"});
    check_error(render(model, {"--up", "0 1 0"}), {"--up needs x,y,z"});
}

TEST_CASE("An unknown option is rejected with the usage") {
    check_error(render(triangle_model(), {"--frobnicate"}), {"unknown option '--frobnicate'"}, Usage::yes);
    check_error(render(triangle_model(), {"-x"}), {"unknown option '-x'"}, Usage::yes);
}

TEST_CASE("A missing -o is rejected with the usage") {
    check_error(run({triangle_model(), "--size", "8x6"}), {"no output given (-o OUT.ppm)"}, Usage::yes);
}

TEST_CASE("A missing model is rejected with the usage") {
    check_error(run({"-o", out_ppm()}), {"no model given"}, Usage::yes);
    check_error(run({}), {"no model given"}, Usage::yes);
}

TEST_CASE("An option at the end without its value is rejected with the usage") {
    const std::string model = triangle_model();
    for (const std::string opt : {"--size", "--eye", "--fov", "--near", "--algo", "--band", "--shade"}) {
        INFO("option ", opt);
        check_error(render(model, {opt}), {opt + " needs a value"}, Usage::yes);
    }
    check_error(run({model, "-o"}), {"-o needs a value"}, Usage::yes);
}

TEST_CASE("Two models are rejected and both are named") {
    const std::string a = triangle_model();
    const std::string b = kBad + "no_faces.obj";
    check_error(render(a, {b}), {"more than one model given", "'" + a + "'", "'" + b + "'"});
}

TEST_CASE("An output path in a missing directory is reported with the path and creates nothing") {
    const std::string out = scratch_path("no_such_dir/out.ppm");
    const Run r = run({triangle_model(), "-o", out}, out);
    check_error(r, {out + ": ", "No such file or directory"});
}

// ---- Success ---------------------------------------------------------------------------------------------

TEST_CASE("A tiny valid model renders a P6 file of the requested size and exits 0") {
    const Run r = render(triangle_model(), {"--size", "7x5"});
    INFO("stderr: ", r.err);
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    CHECK(r.out.empty());
    CHECK(r.output_created);
    const std::string bytes = read_file(out_ppm());
    CHECK(bytes.substr(0, 11) == "P6\n7 5\n255\n");
    CHECK(bytes.size() == 11 + 7 * 5 * 3);
    const Image img = read_image(out_ppm(), 7, 5);
    CHECK(img.ok);
    CHECK(img.at(3, 2) != 0u);  // the default camera frames the model: its centre is lit
}

TEST_CASE("Id shading writes the 1-based f-line index, and a degenerate first face draws nothing") {
    const std::string model = write_model("ids.obj",
                                          "# face 1: three collinear vertices on a line through the centre\n"
                                          "v -1 -1 0\nv 0 0 0\nv 1 1 0\n"
                                          "# face 2: counter-clockwise seen from +z, covers the centre\n"
                                          "v -2 -2 0\nv 2 -2 0\nv 0 2 0\n"
                                          "f 1 2 3\n"
                                          "f 4 5 6\n");
    for (const Args& camera : {kFrontCamera, Args{}}) {
        INFO("camera: ", camera.empty() ? std::string("default") : std::string("--eye 0,0,5"));
        const Run r = render(model, with(camera, {"--size", "7x5", "--shade", "id"}));
        INFO("stderr: ", r.err);
        CHECK(r.code == 0);
        const Image img = read_image(out_ppm(), 7, 5);
        CHECK(img.ok);
        CHECK(img.at(3, 2) == 0x000002u);        // the centre pixel: bytes (0, 0, 2)
        CHECK(count_pixels(img, 0x000001u) == 0);  // the degenerate face covers nothing
        CHECK(count_pixels(img, 0x000000u) + count_pixels(img, 0x000002u) == 7 * 5);
    }
}

TEST_CASE("Id shading counts f lines, not triangles: a quad before a face does not shift its id") {
    const std::string model = write_model("quad_ids.obj",
                                          "# face 1: a quad (two triangles) in the top-left corner, face 2 the centre\n"
                                          "v -3 1 0\nv -2 1 0\nv -2 2 0\nv -3 2 0\n"
                                          "v -1 -1 0\nv 1 -1 0\nv 0 1 0\n"
                                          "f 1 2 3 4\n"
                                          "f 5 6 7\n");
    const Run r = render(model, with(kFrontCamera, {"--size", "21x15", "--shade", "id", "--stats"}));
    INFO("stderr: ", r.err);
    CHECK(r.code == 0);
    CHECK(contains(r.out, "triangles 3 drawn 3"));
    const Image img = read_image(out_ppm(), 21, 15);
    CHECK(img.ok);
    CHECK(img.at(10, 7) == 0x000002u);
    CHECK(count_pixels(img, 0x000001u) > 0);
    CHECK(count_pixels(img, 0x000003u) == 0);
}

TEST_CASE("A face turned away from the camera is culled unless --no-cull is given") {
    const std::string model = write_model("back_face.obj", "v -1 -1 0\nv 0 1 0\nv 1 -1 0\nf 1 2 3\n");
    const Args args = with(kFrontCamera, {"--size", "7x5", "--shade", "id", "--stats"});
    const Run culled = render(model, args);
    CHECK(culled.code == 0);
    CHECK(contains(culled.out, "triangles 1 drawn 0 culled 1"));
    CHECK(read_image(out_ppm(), 7, 5).at(3, 2) == 0x000000u);
    const Run drawn = render(model, with(args, {"--no-cull"}));
    CHECK(drawn.code == 0);
    CHECK(contains(drawn.out, "triangles 1 drawn 1 culled 0"));
    CHECK(read_image(out_ppm(), 7, 5).at(3, 2) == 0x000001u);
}

TEST_CASE("An output name ending in .png writes a PNG file instead of a PPM") {
    const std::string out = scratch_path("out.png");
    const Run r = run({triangle_model(), "-o", out, "--size", "7x5"}, out);
    INFO("stderr: ", r.err);
    CHECK(r.code == 0);
    CHECK(r.output_created);
    CHECK(read_file(out).substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_CASE("--help prints the usage on stdout and exits 0 without writing anything") {
    for (const std::string opt : {"--help", "-h"}) {
        INFO("option ", opt);
        const Run r = run({opt});
        CHECK(r.code == 0);
        CHECK(r.err.empty());
        CHECK(r.out.rfind("usage: hider-render MODEL.obj", 0) == 0);
        CHECK(contains(r.out, "--algo"));
        CHECK_FALSE(r.output_created);
    }
}

// ---- Regressions: each of these once failed (fov range, misnamed camera errors, huge and tiny scales) ----

TEST_CASE("A field of view inside the accepted 0.5..179.5 range is never blamed on the up vector") {
    // make_view() once refused fovy below 1 degree and above 179, and build_scene() reported every
    // invalid_argument from it as a parallel up vector.
    const std::string model = triangle_model();
    for (const std::string fov : {"0.5", "0.7", "179.3", "179.5"}) {
        INFO("--fov ", fov);
        const Run r = render(model, {"--fov", fov, "--size", "8x6"});
        INFO("stderr: ", r.err);
        CHECK_FALSE(contains(r.err, "up vector"));
        CHECK((r.code == 0 || contains(r.err, "field of view")));
    }
}

TEST_CASE("Near and far planes that round to the same fixed-point value are never blamed on the up vector") {
    const std::string model = triangle_model();
    const Run r = render(model, {"--near", "1", "--far", "1.00000001"});
    INFO("stderr: ", r.err);
    CHECK_FALSE(contains(r.err, "up vector"));
    CHECK((r.code == 0 || (r.code == 2 && contains(r.err, "far"))));
}

TEST_CASE("An eye far away is never reported as a bad near plane the user did not give") {
    // Today both fail with "near plane must be > 0 (got inf)": length() squares 1e300, and at 1.79e308
    // the default far plane (distance * 1.01) overflows.
    const std::string model = triangle_model();
    for (const std::string eye : {"0,0,1e300", "0,0,1.79e308"}) {
        INFO("--eye ", eye);
        const Run r = render(model, {"--eye", eye, "--size", "8x6"});
        INFO("stderr: ", r.err);
        CHECK_FALSE(contains(r.err, "near plane"));
        CHECK((r.code == 0 || contains(r.err, "too large") || contains(r.err, "cannot be represented")));
    }
}

TEST_CASE("A model in tiny units is framed like the same model in unit size") {
    // length() in scene.cpp squares coordinates: at 1e-300 the bounding radius underflows to 0, the default
    // eye lands 2 units away and the model renders as an empty frame (exit 0).
    const std::string tiny = write_model("tiny.obj", "v -1e-300 -1e-300 0\nv 1e-300 -1e-300 0\nv 0 1e-300 0\nf 1 2 3\n");
    const Run r = render(tiny, {"--size", "7x5", "--shade", "id"});
    CHECK(r.code == 0);
    CHECK(read_image(out_ppm(), 7, 5).at(3, 2) == 0x000001u);
}

TEST_CASE("A write that fails midway leaves no partial output file") {
    // port::write_ppm() truncates the file, and on a failed write returns an error but leaves the bytes
    // written so far. A 1-block file size limit makes the write fail with EFBIG (SIGXFSZ ignored).
    const Run r = run({triangle_model(), "-o", out_ppm(), "--size", "100x100"}, out_ppm(), "trap '' XFSZ; ulimit -f 1; ");
    check_error(r, {out_ppm() + ": ", "write failed"});
}

namespace {

/// A generated scene written as OBJ into the scratch directory, and its camera options.
std::pair<std::string, Args> generated(const std::string& name) {
    hider::tool::gen::GenScene g;
    std::string why;
    REQUIRE_MESSAGE(hider::tool::gen::by_name(name, g, why), why);
    const std::string path = scratch_path(name + ".obj");
    std::ofstream out(path);
    hider::tool::gen::write_obj(g, out);
    out.close();
    Args cam;
    std::istringstream flags(hider::tool::gen::camera_flags(g));
    for (std::string w; flags >> w;) cam.push_back(w);
    return {path, cam};
}

}  // namespace

TEST_CASE("A full Newell pool is a warning naming the pool and the size it needed; --strict makes it exit 2") {
    const auto [model, cam] = generated("dense-1-150");
    const Run small = render(model, with(cam, {"--no-cull", "--algo", "newell", "--pool", "100"}));
    INFO("stderr: ", small.err);
    CHECK(small.code == 0);
    CHECK(small.output_created);
    CHECK(contains(small.err, "hider-render: warning: Newell's cut pool of 100 polygons is full"));
    const size_t at = small.err.find("needs a pool of ");
    REQUIRE(at != std::string::npos);
    const long needed = std::atol(small.err.c_str() + at + 16);
    CHECK(needed > 100);
    // The pairs the dropped cuts leave unresolved are not blamed on the pixel-ordered pairs' room.
    CHECK(contains(small.err, "pairs left uncut in an order some of their shared pixels disagree with (see the other warnings)"));
    CHECK_FALSE(contains(small.err, "--reorders"));
    const Run strict = render(model, with(cam, {"--no-cull", "--algo", "reverse", "--pool", "100", "--strict"}));
    CHECK(strict.code == 2);
    CHECK(contains(strict.err, "hider-render: error: Newell's cut pool of 100 polygons is full"));
    CHECK_FALSE(strict.output_created);  // an error leaves no image (it wrote the incomplete one before)
    // The size it names is enough: no warning, exit 0 even with --strict.
    const Run enough = render(model, with(cam, {"--no-cull", "--algo", "newell", "--pool", std::to_string(needed), "--strict"}));
    INFO("stderr with the named pool: ", enough.err);
    CHECK(enough.code == 0);
    CHECK(enough.err.empty());
    // The default pool holds it.
    const Run dflt = render(model, with(cam, {"--no-cull", "--algo", "newell", "--strict"}));
    CHECK(dflt.code == 0);
    CHECK(dflt.err.empty());
}

TEST_CASE("Pairs Newell cannot order for want of reorders words are a warning naming the size; --strict exits 2") {
    // boxes-69-10 without culling holds cycles no cut breaks, which Newell orders by their pixels and
    // keeps in NewellScratch::reorders (README.md, "Newell").
    const auto [model, cam] = generated("boxes-69-10");
    const Run none = render(model, with(cam, {"--no-cull", "--algo", "newell", "--reorders", "0", "--stats"}));
    INFO("stderr: ", none.err);
    CHECK(none.code == 0);
    CHECK(none.output_created);
    CHECK(contains(none.out, "status capacity exceeded"));
    CHECK(contains(none.err, "hider-render: warning: "));
    CHECK(contains(none.err, " pairs left uncut in an order some of their shared pixels disagree with: the 0 words"));
    const size_t at = none.err.find("needs --reorders ");
    REQUIRE(at != std::string::npos);
    const long needed = std::atol(none.err.c_str() + at + 17);
    CHECK(needed >= 2);
    CHECK(needed % 2 == 0);
    const Run strict = render(model, with(cam, {"--no-cull", "--algo", "reverse", "--reorders", "0", "--strict"}));
    CHECK(strict.code == 2);
    CHECK(contains(strict.err, "hider-render: error: "));
    // The size it names is enough, and --stats reports it as the peak: no warning, exit 0 with --strict.
    const Run enough = render(model, with(cam, {"--no-cull", "--algo", "newell", "--reorders", std::to_string(needed), "--strict", "--stats"}));
    INFO("stderr with the named size: ", enough.err);
    CHECK(enough.code == 0);
    CHECK(enough.err.empty());
    CHECK(contains(enough.out, "unresolved 0 "));
    CHECK(contains(enough.out, "reorders-peak " + std::to_string(needed) + "\n"));
    // So does the default (kNewellReorders words).
    const Run dflt = render(model, with(cam, {"--no-cull", "--algo", "newell", "--strict"}));
    CHECK(dflt.code == 0);
    CHECK(dflt.err.empty());
}

TEST_CASE("An inexact Newell cut is a warning; --strict makes it exit 2") {
    // In mikado-43-30 without culling one cut's crossing passes two pixel centres on opposite sides
    // within a few thousandths of a subpixel, and no line through grid points that crossing_line() tries
    // puts both on their sides (README.md, "Newell"): the frame is drawn, the cut reported. Should
    // crossing_line() learn to place this one, the test needs another scene whose cut stays inexact.
    const auto [model, cam] = generated("mikado-43-30");
    const Run r = render(model, with(cam, {"--no-cull", "--algo", "newell", "--stats"}));
    INFO("stderr: ", r.err);
    CHECK(r.code == 0);
    CHECK(r.output_created);
    CHECK(contains(r.out, "status capacity exceeded"));
    const size_t at = r.out.find("inexact-cuts ");
    REQUIRE(at != std::string::npos);
    const long n = std::atol(r.out.c_str() + at + 13);
    CHECK(n >= 1);
    CHECK(contains(r.err, "hider-render: warning: " + std::to_string(n) +
                              " cuts along a line that leaves a pixel centre on the wrong side of the plane\n"));
    const Run strict = render(model, with(cam, {"--no-cull", "--algo", "reverse", "--strict"}));
    CHECK(strict.code == 2);
    CHECK(contains(strict.err, "hider-render: error: "));
    CHECK(contains(strict.err, " cuts along a line that leaves a pixel centre on the wrong side of the plane"));
}

TEST_CASE("A far plane beyond the scene is clamped, and the default near plane does not follow it") {
    const std::string torus = std::string(HIDER_TEST_DATA) + "/models/torus.obj";
    for (const char* far : {"5000", "1e308"}) {
        const Run r = render(torus, {"--far", far, "--stats"});
        INFO("--far ", far, " stderr: ", r.err);
        CHECK(r.code == 0);
        CHECK(contains(r.out, "triangles 1000 drawn 456 "));  // as with the default far plane
    }
    check_error(render(torus, {"--near", "1e308"}), {"near plane (1e+308) lies beyond the whole scene"});
}

TEST_CASE("Coordinates near the double range are named, never printed as nan") {
    const std::string torus = std::string(HIDER_TEST_DATA) + "/models/torus.obj";
    const Run r = render(torus, {"--target", "1e308,1e308,1e308"});
    check_error(r, {"default eye", "give --eye"});
    CHECK_FALSE(contains(r.err, "nan"));
    const Run eye = render(triangle_model(), {"--eye", "-1.7e308,0,1.7e308"});
    CHECK_FALSE(contains(eye.err, "nan"));
}

TEST_CASE("The output format follows the extension, case-insensitively; unknown extensions are refused") {
    const std::string torus = std::string(HIDER_TEST_DATA) + "/models/torus.obj";
    const std::string upper = scratch_path("OUT.PNG");
    const Run png = run({torus, "-o", upper}, upper);
    CHECK(png.code == 0);
    CHECK(read_file(upper).substr(0, 4) == "\x89PNG");
    const std::string jpg = scratch_path("out.jpg");
    const Run bad = run({torus, "-o", jpg}, jpg);
    check_error(bad, {"unknown image format '.jpg'", "use .ppm or .png"});
    const std::string none = scratch_path("noext");
    check_error(run({torus, "-o", none}, none), {"unknown image format '(no extension)'"});
}

TEST_CASE("--help lists the algorithm names") {
    const Run r = run({"--help"});
    CHECK(r.code == 0);
    for (const char* algo : {"zbuffer", "painter", "newell", "reverse", "raycast"}) CHECK(contains(r.out, algo));
    CHECK(contains(r.out, "defaults: --size 320x240 --fov 60 --algo zbuffer --shade headlight --depth-bits 16 --format rgb565"));
    // ... and they are the defaults: the same bytes with and without them.
    const std::string torus = std::string(HIDER_TEST_DATA) + "/models/torus.obj";
    REQUIRE(render(torus).code == 0);
    const std::string plain = read_file(out_ppm());
    REQUIRE(render(torus, {"--size", "320x240", "--fov", "60", "--algo", "zbuffer", "--shade", "headlight", "--depth-bits", "16",
                           "--format", "rgb565", "--painter-key", "farthest"})
                .code == 0);
    CHECK(read_file(out_ppm()) == plain);
    // The painter's key too, without culling, where the two keys give different frames.
    REQUIRE(render(torus, {"--algo", "painter", "--no-cull"}).code == 0);
    const std::string painter = read_file(out_ppm());
    REQUIRE(render(torus, {"--algo", "painter", "--no-cull", "--painter-key", "farthest"}).code == 0);
    CHECK(read_file(out_ppm()) == painter);
    REQUIRE(render(torus, {"--algo", "painter", "--no-cull", "--painter-key", "barycenter"}).code == 0);
    CHECK(read_file(out_ppm()) != painter);
}

TEST_CASE("--stats counts every triangle in exactly one bucket for the z-buffer and the sorted algorithms") {
    // The benchmark view: 444 front faces, 554 back faces and 2 that cover no pixel centre.
    const std::string torus = std::string(HIDER_TEST_DATA) + "/models/torus.obj";
    for (const char* algo : {"zbuffer", "painter", "newell", "reverse"}) {
        const Run r = render(torus, {"--eye", "0,0,-2.5", "--target", "0,0,0", "--fov", "73.7398", "--near", "0.25", "--algo",
                                     algo, "--stats"});
        INFO(algo, " stdout: ", r.out);
        CHECK(contains(r.out, "triangles 1000 drawn 444 culled 554 degenerate 0 outside 2 "));
    }
    // Ray casting has no buckets to fill: it says so instead of printing "drawn 0".
    const Run ray = render(torus, {"--algo", "raycast", "--size", "64x48", "--stats"});
    INFO("raycast stdout: ", ray.out);
    CHECK(ray.code == 0);
    CHECK(contains(ray.out, "triangles 1000 (ray cast: no drawn, culled or clipped counts; rays below)\n"));
    CHECK_FALSE(contains(ray.out, " drawn "));
    CHECK(contains(ray.out, "\nrays 3072 hits "));  // one ray per pixel
    // A scene with zero-area and clipped triangles: the buckets still add up to the triangles in.
    const std::string model = write_model("buckets.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 0 0 5\nv 1 0 5\nv 0 1 5\n"
                                                         "f 1 2 3\nf 1 2 4\nf 3 2 1\nf 5 6 7\n");
    const Run r = render(model, {"--eye", "0.3,0.3,3", "--target", "0.3,0.3,0", "--near", "0.5", "--algo", "painter", "--stats"});
    INFO("stdout: ", r.out);
    unsigned in = 0, drawn = 0, culled = 0, degenerate = 0, outside = 0, clipped = 0;
    REQUIRE(std::sscanf(r.out.c_str(), "triangles %u drawn %u culled %u degenerate %u outside %u clipped %u", &in, &drawn, &culled,
                        &degenerate, &outside, &clipped) == 6);
    CHECK(in == 4);
    CHECK(degenerate == 1);  // f 1 2 4 is a line
    CHECK(culled == 1);      // f 3 2 1 runs clockwise
    CHECK(drawn + culled + degenerate + outside == in);
    // The z-buffer, whole frame and in bands, on that scene and on the city seen from the street (clipped
    // triangles, triangles between pixel centres): the buckets add up to the triangles in.
    const std::string city = std::string(HIDER_TEST_DATA) + "/scenes/city-1-16-16-street.obj";
    for (const std::string& m : {model, city})
        for (const char* band : {"240", "7"}) {
            Args args = {"--algo", "zbuffer", "--stats", "--band", band};
            if (m == city)
                for (const char* a : {"--eye", "12.25,0.3,25.1", "--target", "12.25,0.5,0", "--near", "0.5", "--far", "200"}) args.push_back(a);
            else
                for (const char* a : {"--eye", "0.3,0.3,3", "--target", "0.3,0.3,0", "--near", "0.5"}) args.push_back(a);
            const Run z = render(m, args);
            INFO(m, " band ", band, " stdout: ", z.out, " stderr: ", z.err);
            REQUIRE(z.code == 0);
            REQUIRE(std::sscanf(z.out.c_str(), "triangles %u drawn %u culled %u degenerate %u outside %u clipped %u", &in, &drawn,
                                &culled, &degenerate, &outside, &clipped) == 6);
            CHECK(drawn + culled + degenerate + outside == in);
            CHECK(drawn > 0);
        }
}

// ---- BSP trees: hider-bsp's .hbsp/.hpp output, and hider-render drawing a tree from a blob or an OBJ ----

namespace {

const std::string kTorus = std::string(HIDER_TEST_DATA) + "/models/torus.obj";

/// hider-bsp MODEL -o OUT EXTRA...
Run bsp_tool(const std::string& model, const std::string& out, const Args& extra = {}) {
    Args args{model, "-o", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_tool(kBspExe, args, out);
}

/// The torus compiled once into scratch/torus.hbsp.
const std::string& torus_blob() {
    static const std::string path = [] {
        const std::string p = scratch_path("torus.hbsp");
        const Run r = bsp_tool(kTorus, p);
        REQUIRE(r.code == 0);
        return p;
    }();
    return path;
}

/// Copies `bytes` into a scratch .hbsp file.
std::string write_blob(const std::string& name, const std::string& bytes) { return write_model(name, bytes); }

}  // namespace

TEST_CASE("A tree from hider-bsp and the same OBJ built in memory give byte-identical frames") {
    const Args cameras[] = {{}, {"--eye", "2.5,1.2,0.7", "--target", "0,0,0.1"}, {"--eye", "0.3,0.2,0.1", "--fov", "100"}};
    for (const std::string algo : {"bsp", "bsp-front"}) {
        for (const Args& camera : cameras) {
            INFO("algo ", algo, ", camera ", camera.empty() ? std::string("default") : camera[1]);
            const Args flags = with(camera, {"--algo", algo, "--size", "64x48", "--shade", "id", "--stats"});
            const Run from_blob = render(torus_blob(), flags);
            INFO("stderr: ", from_blob.err);
            REQUIRE(from_blob.code == 0);
            CHECK(contains(from_blob.out, "bsp nodes-visited "));
            const std::string blob_image = read_file(out_ppm());
            const Run from_obj = render(kTorus, flags);
            REQUIRE(from_obj.code == 0);
            CHECK(read_file(out_ppm()) == blob_image);
            CHECK(from_obj.out == from_blob.out);  // the same tree: the same walk
            const Image img = read_image(out_ppm(), 64, 48);
            REQUIRE(img.ok);
            CHECK(count_pixels(img, 0x000000u) < 64 * 48);  // the torus is in view
        }
    }
}

TEST_CASE("A tree past a mesh's 65,536 vertices renders from its blob as from its OBJ") {
    // dense-1-1000's 1,000 triangles cut into a tree of 73,524 vertices (the bunny's: 96,703). The walk
    // indexes them in 32 bits; hider-render refused the blob ("hider meshes hold at most 65536").
    const auto [model, cam] = generated("dense-1-1000");
    const std::string blob = scratch_path("dense1000.hbsp");
    const Run built = run_tool(kBspExe, {model, "-o", blob, "--stats"}, blob);
    REQUIRE(built.code == 0);
    const size_t at = built.out.find(" vertices ");
    REQUIRE(at != std::string::npos);
    CHECK(std::atol(built.out.c_str() + at + 10) > 65536);
    const Args flags = with(cam, {"--algo", "bsp", "--size", "96x72", "--shade", "id", "--no-cull"});
    const Run from_blob = render(blob, flags);
    INFO("stderr: ", from_blob.err);
    REQUIRE(from_blob.code == 0);
    const std::string blob_image = read_file(out_ppm());
    const Run from_obj = render(model, flags);
    REQUIRE(from_obj.code == 0);
    CHECK(read_file(out_ppm()) == blob_image);
}

TEST_CASE("hider-bsp's output is deterministic, and its .hpp holds the blob's bytes under the given name") {
    const std::string again = scratch_path("torus_again.hbsp");
    REQUIRE(bsp_tool(kTorus, again).code == 0);
    const std::string blob = read_file(torus_blob());
    CHECK(read_file(again) == blob);
    CHECK(blob.size() > 64);
    // The extension picks the form in any case, as hider-render's and hider-plot's do.
    const std::string upper = scratch_path("torus_upper.HBSP");
    REQUIRE(bsp_tool(kTorus, upper).code == 0);
    CHECK(read_file(upper) == blob);
    const std::string upper_hpp = scratch_path("torus_upper.Hpp");
    REQUIRE(bsp_tool(kTorus, upper_hpp, {"--name", "kUpper"}).code == 0);
    CHECK(contains(read_file(upper_hpp), "kUpper"));
    const std::string header = scratch_path("torus_tree.hpp");
    const Run r = bsp_tool(kTorus, header, {"--name", "kTorusTree"});
    CHECK(r.code == 0);
    const std::string src = read_file(header);
    CHECK(contains(src, "kTorusTree"));
    CHECK(contains(src, "torus.obj"));
    CHECK(contains(src, std::to_string(blob.size())));  // the byte count is stated
}

TEST_CASE("hider-bsp names a header's namespace after its file unless --name says otherwise") {
    const std::string header = scratch_path("torus_default_name.hpp");
    const Run r = bsp_tool(kTorus, header);
    INFO("stderr: ", r.err);
    REQUIRE(r.code == 0);
    const std::string src = read_file(header);
    CHECK(contains(src, "namespace hider::bsp_data::torus_default_name {"));
    CHECK_FALSE(contains(src, "bsp_data::tree"));
    // A file name that is no C++ name is refused before anything is written, and --name rescues it.
    const std::string dashed = scratch_path("torus-tree.hpp");
    const Run bad = bsp_tool(kTorus, dashed);
    CHECK(bad.code == 2);
    CHECK_FALSE(bad.output_created);
    CHECK(contains(bad.err, "its file name 'torus-tree' may hold only letters, digits and '_'"));
    CHECK(contains(bad.err, "give --name NAME"));
    const Run named = bsp_tool(kTorus, dashed, {"--name", "torus_tree"});
    REQUIRE(named.code == 0);
    CHECK(contains(read_file(dashed), "namespace hider::bsp_data::torus_tree {"));
    // A keyword as the file name is refused as --name would be.
    const Run keyword = bsp_tool(kTorus, scratch_path("class.hpp"));
    CHECK(keyword.code == 2);
    CHECK(contains(keyword.err, "is a C++ keyword"));
}

TEST_CASE("hider-bsp with camera options adds hider-render's camera in the tree's world to a .hpp, and refuses them for a blob") {
    const std::string header = scratch_path("torus_cam.hpp");
    const Run r = bsp_tool(kTorus, header, {"--name", "torus_view", "--size", "160x128", "--eye", "0,1,3", "--fov", "50"});
    INFO("stderr: ", r.err);
    CHECK(r.code == 0);
    const std::string src = read_file(header);
    CHECK(contains(src, "namespace hider::bsp_data::torus_view"));
    CHECK(contains(src, "kWidth = 160;"));
    CHECK(contains(src, "kHeight = 128;"));
    CHECK(contains(src, "inline constexpr Camera kCamera"));
    CHECK(contains(src, "--eye 0,1,3"));  // the options are recorded
    // The blob in the header is the one hider-bsp writes as .hbsp (the camera does not change the tree).
    CHECK(contains(src, "kBlob[" + std::to_string(read_file(torus_blob()).size()) + "]"));
    const Run blob = bsp_tool(kTorus, scratch_path("torus_cam.hbsp"), {"--eye", "0,1,3"});
    CHECK(blob.code == 2);
    CHECK_FALSE(blob.output_created);
    CHECK(contains(blob.err, "camera options need a .hpp output"));
    const Run bad = bsp_tool(kTorus, scratch_path("torus_bad.hpp"), {"--fov", "0"});
    CHECK(bad.code == 2);
    CHECK(contains(bad.err, "field of view 0 degrees out of range"));
}

TEST_CASE("hider-bsp --stats reports polygons, split ratio, nodes, depth, leaf size, bytes, build time and the cells") {
    const Run r = bsp_tool(kTorus, scratch_path("stats.hbsp"), {"--stats", "--candidates", "8", "--split-weight", "3"});
    INFO("stdout: ", r.out, "stderr: ", r.err);
    CHECK(r.code == 0);
    for (const std::string part : {"input triangles ", "polygons ", "split-ratio ", "nodes ", "depth ", "largest-node ", "bytes ",
                                   "build "})
        CHECK(contains(r.out, part));
    // The RAM a walk needs: one ScreenVertex per vertex and depth + 1 stack entries, from the printed counts.
    unsigned long vertices = 0, nodes = 0, depth = 0, ram = 0, per_vertex = 0, entries = 0, list_nodes = 0;
    const size_t at = r.out.find("vertices "), walk = r.out.find("walk RAM ");
    REQUIRE(at != std::string::npos);
    REQUIRE(walk != std::string::npos);
    REQUIRE(std::sscanf(r.out.c_str() + at, "vertices %lu nodes %lu depth %lu", &vertices, &nodes, &depth) == 3);
    REQUIRE(std::sscanf(r.out.c_str() + walk, "walk RAM %lu bytes (vertices %*u x %lu B, stack %lu x 4 B); order_bsp's list: up to %lu",
                        &ram, &per_vertex, &entries, &list_nodes) == 4);
    CHECK(per_vertex == sizeof(hider::ScreenVertex));
    CHECK(entries == depth + 1);
    CHECK(ram == vertices * sizeof(hider::ScreenVertex) + 4 * entries);
    CHECK(list_nodes == nodes);
    // The torus is a closed surface: its cells are labelled. Suzanne is open: they are not, and it says why.
    CHECK(contains(r.out, "cells labelled "));
    CHECK(contains(r.out, "winding numbers 0..1"));
    const Run open = bsp_tool(std::string(HIDER_TEST_DATA) + "/models/suzanne.obj", scratch_path("open.hbsp"), {"--stats"});
    CHECK(open.code == 0);
    CHECK(contains(open.out, "cells not labelled: the surface is not closed"));
}

TEST_CASE("hider-bsp reports OBJ errors with the file and the line, like hider-render, and bad options with exit 2") {
    const std::string path = kBad + "index_out_of_range.obj";
    const std::string out = scratch_path("bad.hbsp");
    const Run bad_obj = bsp_tool(path, out);
    CHECK(bad_obj.code == 2);
    CHECK_FALSE(bad_obj.output_created);
    CHECK(first_line(bad_obj.err) == "hider-bsp: " + first_line(render(path).err).substr(std::string("hider-render: ").size()));
    CHECK(contains(bad_obj.err, path + ":5: "));
    const Run bad_ext = bsp_tool(kTorus, scratch_path("tree.bin"));
    CHECK(bad_ext.code == 2);
    CHECK(contains(bad_ext.err, "use .hbsp"));
    const Run bad_weight = bsp_tool(kTorus, out, {"--split-weight", "-1"});
    CHECK(bad_weight.code == 2);
    CHECK(contains(bad_weight.err, "--split-weight"));
    const Run bad_name = bsp_tool(kTorus, scratch_path("t.hpp"), {"--name", "1tree"});
    CHECK(bad_name.code == 2);
    CHECK(contains(bad_name.err, "--name"));
    // Names that broke the header they named (it did not compile; found by a red-team pass).
    for (const std::string shadow : {"uint8_t", "ray", "hider", "NULL", "INT32_MAX", "linux"}) {
        const Run r = bsp_tool(kTorus, scratch_path("t.hpp"), {"--name", shadow});
        CHECK(r.code == 2);
        CHECK(contains(r.err, "--name '" + shadow + "' is "));
    }
    CHECK(bsp_tool(kTorus, scratch_path("t.hpp"), {"--name", "mesh"}).code == 0);  // a member's name is fine
    for (const char* chain : {"-1", "x", "100000001"}) {
        const Run bad_chain = bsp_tool(kTorus, out, {"--max-chain", chain});
        CHECK(bad_chain.code == 2);
        CHECK(contains(bad_chain.err, "--max-chain needs a whole number 0..100000000"));
    }
}

TEST_CASE("hider-render --stats: bsp-front's covered pixels are those of the faces its cell sees (overdraw 1.00)") {
    // The tree's cells are labelled, so the walk draws front faces only; a silhouette pixel that vertex
    // rounding leaves to a back face stays empty (README: one seen). The covered count took the back faces
    // too and said "written 41 covered 42 overdraw 0.98".
    const Run r = render(std::string(HIDER_TEST_DATA) + "/obj/fan60.obj",
                         {"--algo", "bsp-front", "--no-cull", "--size", "120x90", "--eye",
                          "7.7037584525322309,-11.959646377003907,-8.8491990435597643", "--target",
                          "-0.050681283977201674,5.849927619138505,-1.3652855266259536", "--near", "0.05", "--far", "400",
                          "--stats"});
    REQUIRE(r.code == 0);
    CHECK(contains(r.out, "written 41 covered 41 overdraw 1.00"));
    // With culling, from inside the torus's tube looking across its hole: the walk draws front faces
    // (bsp_walk_faces()), not the back faces the eye's cell would see; covered said 0.
    const Run inside = render(kTorus, {"--algo", "bsp-front", "--size", "64x48", "--eye", "1,0,0", "--target", "-1,0,0",
                                       "--near", "0.01", "--stats"});
    REQUIRE(inside.code == 0);
    CHECK(contains(inside.out, "written 1139 covered 1139 overdraw 1.00"));
}

TEST_CASE("hider-bsp refuses a model its tree cannot hold, and a failed run leaves the output file as it was") {
    // A triangle 2e-4 wide at x = 1e6: the blob keeps the fit's centre to 30 bits, whose rounding times the
    // scale put the vertices 3,000 world units out, past the tree's world. It was written (exit 0), and
    // every reader refused the tree ("bad data"). Now: exit 2, with the reason and what to do.
    const std::string far =
        write_model("far_off.obj", "v 1000000.0003800001 0 0\nv 1000000.00058 0.0001 0\nv 1000000.00048 0 0.0002\nf 1 2 3\n");
    const std::string out = scratch_path("far_off.hbsp");
    const Run r = bsp_tool(far, out);
    CHECK(r.code == 2);
    CHECK_FALSE(r.output_created);
    CHECK(contains(r.err, "far_off.obj: the model lies too far from the origin for its size"));
    CHECK(contains(r.err, "move the model nearer the origin"));
    const Run in_render = render(far, {"--algo", "bsp"});
    CHECK(in_render.code == 2);
    CHECK(contains(in_render.err, "too far from the origin"));
    // Every face without area: an empty tree is no use, and says so.
    const Run flat = bsp_tool(write_model("collinear.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 3 2 1\n"), out);
    CHECK(flat.code == 2);
    CHECK_FALSE(flat.output_created);
    CHECK(contains(flat.err, "no face with an area"));
    // A camera outside the tree's world fails after the output was named: an existing file stays.
    const std::string kept = scratch_path("kept.hpp");
    std::ofstream(kept, std::ios::binary) << "keep me";
    const Run cam = run_tool(kBspExe, {kTorus, "-o", kept, "--eye", "100,0,0"}, scratch_path("none"));
    CHECK(cam.code == 2);
    CHECK(contains(cam.err, "outside the tree's world"));
    CHECK(read_file(kept) == "keep me");
}

TEST_CASE("A write that fails midway leaves hider-bsp's existing output as it was, and nothing partial") {
    // hider-bsp (like hider-bake and hider-scenes) wrote in place: a failed write left a truncated file
    // over the good one. Outputs now go through a temporary file renamed over the output when whole.
    const std::string out = scratch_path("kept.hbsp");
    REQUIRE(bsp_tool(write_model("cube_small.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"), out).code == 0);
    const std::string good = read_file(out);
    REQUIRE(!good.empty());
    const Run r = run_tool(kBspExe, {kTorus, "-o", out}, scratch_path("none"), "trap '' XFSZ; ulimit -f 1; ");
    CHECK(r.code == 2);
    CHECK(contains(r.err, out + ": write failed"));
    CHECK(read_file(out) == good);
    CHECK_FALSE(exists(out + ".partial"));
}

#if !defined(__SANITIZE_ADDRESS__)  // ASan reserves far more address space than the limit below
TEST_CASE("A tool that runs out of memory says so and exits 2, without an output") {
    // The tools are built without exceptions: a failed allocation aborted (std::bad_alloc, exit 134).
    const Run r = run({std::string(HIDER_TEST_DATA) + "/models/stanford-bunny.obj", "-o", out_ppm(), "--algo", "bsp"}, out_ppm(),
                      "ulimit -v 50000; ");
    CHECK(r.code == 2);
    CHECK(r.err == "hider-render: out of memory\n");
    CHECK_FALSE(r.output_created);
}
#endif

TEST_CASE("hider-bsp warns when the planes cut the model into many times its triangles") {
    // 60 crossing triangles become 15,991 in the tree (a red-team model): written, with a warning.
    const std::string model = std::string(HIDER_TEST_DATA) + "/obj/crossing_triangles.obj";
    const Run r = bsp_tool(model, scratch_path("crossing.hbsp"));
    CHECK(r.code == 0);
    CHECK(contains(r.err, "hider-bsp: warning: " + model + ": the tree holds 15991 triangles for 60 in the model (split ratio 111.5, "));
    const Run torus = bsp_tool(kTorus, scratch_path("torus_quiet.hbsp"));  // split ratio 1.8
    CHECK(torus.code == 0);
    CHECK(torus.err.empty());
}

TEST_CASE("A face too small for the model's extent to keep an area on the grid is a warning naming its line") {
    // A 1e-3 triangle beside one of 1e6: fitted into +-512 world units it has no area left and drew
    // nothing, silently (a red-team pass). Its big neighbour and a face degenerate in the model itself
    // (three points on a line, line 9) are not named.
    const std::string m = write_model("tiny.obj", "v -1e6 -1e6 0\nv 1e6 -1e6 0\nv 0 1e6 0\nv 0 0 1\nv 0.001 0 1\nv 0 0.001 1\n"
                                                  "v 0 -1e6 0\nf 1 2 3\nf 1 7 2\nf 4 5 6\n");
    const Run r = render(m, {"--size", "32x32"});
    CHECK(r.code == 0);
    CHECK(r.output_created);
    CHECK(r.err == "hider-render: warning: " + m + ":10: face has an area in the model but none on the fixed-point grid: it is too "
                   "small for the model's extent and draws nothing\n");
    const Run tree = bsp_tool(m, scratch_path("tiny.hbsp"));
    CHECK(tree.code == 0);
    CHECK(contains(tree.err, "hider-bsp: warning: " + m + ":10: face has an area in the model but none on the fixed-point grid"));
    const Run from_obj = render(m, {"--size", "32x32", "--algo", "bsp"});
    CHECK(from_obj.code == 0);
    CHECK(contains(from_obj.err, "hider-render: warning: " + m + ":10: face has an area"));
    // The same small face in a model of its own size keeps its area: no warning.
    const std::string alone = write_model("alone.obj", "v 0 0 1\nv 0.001 0 1\nv 0 0.001 1\nf 1 2 3\n");
    const Run quiet = render(alone, {"--size", "32x32"});
    CHECK(quiet.code == 0);
    CHECK(quiet.err.empty());
}

TEST_CASE("A model whose every face lies on a line or a point is a warning, and every algorithm draws the background") {
    // Faces degenerate in the model itself: each is skipped without a word (as above), and when no face
    // is left the image was the background alone, silently.
    const std::string m = write_model("lines.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 4 4 1\n");
    for (const char* algo : {"zbuffer", "painter", "newell", "reverse", "raycast", "bsp", "bsp-front"}) {
        INFO("algorithm: ", std::string(algo));
        const Run r = render(m, {"--size", "16x12", "--algo", algo});
        CHECK(r.code == 0);
        CHECK(r.err == "hider-render: warning: " + m + ": no face has an area: the image shows only the background\n");
        const Image img = read_image(out_ppm(), 16, 12);
        REQUIRE(img.ok);
        CHECK(count_pixels(img, img.at(0, 0)) == 16 * 12);
    }
    // One face with an area among them: no warning, and it is drawn.
    const std::string one = write_model("lines_and_one.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    const Run r = render(one, {"--size", "16x12", "--no-cull"});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    const Image img = read_image(out_ppm(), 16, 12);
    REQUIRE(img.ok);
    CHECK(count_pixels(img, img.at(0, 0)) < 16 * 12);
}

TEST_CASE("A concave face whose fan from its first vertex paints outside it is a warning naming its line") {
    // Every tool fans an OBJ polygon from its first vertex. A V (notch at vertex 4) fanned from vertex 1
    // filled the notch, silently (a red-team pass). An L fanned from its inner corner is exact: no warning.
    const std::string v = write_model("notch.obj", "# a V\nv 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 0.5 0\nv 0 2 0\nf 1 2 3 4 5\n");
    const Run r = render(v, {"--size", "32x32"});
    CHECK(r.code == 0);
    CHECK(r.output_created);
    CHECK(r.err == "hider-render: warning: " + v + ":7: face is not convex from its first vertex: its fan covers area outside it (triangulate it)\n");
    const Run tree = bsp_tool(v, scratch_path("notch.hbsp"));
    CHECK(tree.code == 0);
    CHECK(contains(tree.err, "hider-bsp: warning: " + v + ":7: face is not convex"));
    const std::string l = write_model("ell.obj", "v 1 1 0\nv 0 1 0\nv 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 2 0\nf 1 2 3 4 5 6\n");
    const Run ok = render(l, {"--size", "32x32"});
    CHECK(ok.code == 0);
    CHECK(ok.err.empty());
    // A convex face with a vertex on its first edge: that fan triangle is degenerate, and the sign of its
    // rounding noise once decided (a reviewer: 724 of 2,000 such rectangles warned). And the V at the
    // extremes of double, where squared products over- or underflowed and the V passed unnoticed.
    const std::string mid = write_model("midpoint.obj", "v 0.1 0.9 0.66\nv 0.6 0.9 0.81\nv 1.1 0.9 0.96\nv 1.1 1.0 1.03\nv 0.1 1.0 0.73\nf 1 2 3 4 5\n");
    const Run quiet = render(mid, {"--size", "32x32"});
    CHECK(quiet.code == 0);
    CHECK(quiet.err.empty());
    for (const std::string scale : {"e-40", "e40"}) {
        const std::string big = write_model("notch" + scale + ".obj", "v 0" + scale + " 0 0\nv 2" + scale + " 0 0\nv 2" + scale + " 2" + scale +
                                                                          " 0\nv 1" + scale + " 0.5" + scale + " 0\nv 0 2" + scale + " 0\nf 1 2 3 4 5\n");
        const Run far = render(big, {"--size", "32x32"});
        CHECK(contains(far.err, ":6: face is not convex"));
    }
}

TEST_CASE("hider-bsp --max-chain: off by default, N splits the chains across an axis, and --stats says how often") {
    auto depth_and_splits = [](const Args& extra) {
        const Run r = bsp_tool(kTorus, scratch_path("chain.hbsp"), extra);
        INFO("stdout: ", r.out, "stderr: ", r.err);
        REQUIRE(r.code == 0);
        unsigned long depth = 0, splits = 0;
        const size_t at = r.out.find("depth ");
        REQUIRE(at != std::string::npos);
        REQUIRE(std::sscanf(r.out.c_str() + at, "depth %lu largest-node %*u axis-splits %lu", &depth, &splits) == 2);
        return std::make_pair(depth, splits);
    };
    const auto plain = depth_and_splits({"--stats"}), off = depth_and_splits({"--stats", "--max-chain", "0"}),
               on = depth_and_splits({"--stats", "--max-chain", "256"}), fine = depth_and_splits({"--stats", "--max-chain", "16"});
    CHECK(plain == off);
    CHECK(off.second == 0);
    CHECK(on.second > 0);
    CHECK(fine.second > on.second);
    CHECK(on.first < off.first);
    CHECK(fine.first < on.first);
}

TEST_CASE("A corrupt, truncated or empty .hbsp is rejected with exit 2 and no image") {
    const std::string good = read_file(torus_blob());
    std::string flipped = good;
    flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
    std::string newer = good;  // the version field (bytes 4-5) of a later format
    newer[4] = static_cast<char>(hider::kBspVersion + 1);
    newer[5] = 0;
    std::string padded = kTriangle;
    padded.resize(80, ' ');
    // Each refusal names what bsp_load() found (BspLoadInfo), not only "bad data".
    const std::string cases[][3] = {
        {"flipped.hbsp", flipped, "checksum mismatch (corrupted) (status bad data)"},
        {"truncated.hbsp", good.substr(0, good.size() - 7), "sizes disagree with the blob's length (cut or padded) (the header's counts give " +
                                                                std::to_string(good.size()) + " bytes) (status bad data)"},
        {"empty.hbsp", "", "shorter than a BSP header (status bad data)"},
        {"header_only.hbsp", good.substr(0, 64), "sizes disagree with the blob's length"},
        {"obj_text.hbsp", padded, "not a hider BSP blob (no HBSP magic) (status bad data)"},
        {"newer.hbsp", newer,
         "another BSP format version (" + std::to_string(hider::kBspVersion + 1) + "; this hider reads " +
             std::to_string(hider::kBspVersion) + "): rebuild it with hider-bsp (status bad data)"}};
    for (const auto& c : cases) {
        INFO("case ", c[0]);
        const std::string path = write_blob(c[0], c[1]);
        check_error(render(path, {"--algo", "bsp"}), {path + ": not a valid BSP tree: ", c[2]});
    }
    const std::string missing = scratch_path("missing.hbsp");
    check_error(render(missing, {"--algo", "bsp-front"}), {missing + ": cannot open"});
    // A valid tree deeper than the tool's walk stack: its own message, not "not a valid BSP tree".
    const std::vector<uint8_t> chain = hider::test::chain_blob(hider::tool::kToolMaxBspDepth + 1);
    const std::string deep = write_blob("deep.hbsp", std::string(chain.begin(), chain.end()));
    check_error(render(deep, {"--algo", "bsp"}), {deep + ": the tree is deeper than the 65536 levels hider-render walks"});
}

TEST_CASE("A .hbsp whose world transform is out of range (checksum intact) is refused, not misread") {
    // The header's centre and scale are scale * 2^exponent; any int32 exponent must read as a number or
    // be refused (UBSan saw INT32_MIN - 30 overflow before the exponent was clamped).
    const std::string good = read_file(torus_blob());
    using hider::BspHeader;
    using hider::BspScaled;
    REQUIRE(good.size() > sizeof(BspHeader));
    const int32_t exponents[] = {INT32_MIN, INT32_MAX, -5000, 5000};
    for (int field = 0; field < 4; ++field)  // centre x, y, z, then scale
        for (const int32_t e : exponents) {
            std::string bytes = good;
            BspHeader h;
            std::memcpy(&h, bytes.data(), sizeof h);
            BspScaled& v = field < 3 ? h.centre[field] : h.scale;
            v.exponent = e;
            if (v.mantissa_q30 == 0) v.mantissa_q30 = 1 << 29;  // a centre of 0 would ignore its exponent
            std::memcpy(bytes.data(), &h, sizeof h);
            h.checksum = hider::bsp_checksum(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
            std::memcpy(bytes.data(), &h, sizeof h);
            const std::string path = write_blob("transform.hbsp", bytes);
            INFO("field ", field, ", exponent ", e);
            if (e > 0 || field == 3) {  // an infinite centre or scale, or a scale of 0
                check_error(render(path, {"--algo", "bsp"}), {path + ": ", "world transform"});
            } else {  // the coordinate reads as 0: a usable centre (the torus's is within rounding of it), drawn
                const Run r = render(path, {"--algo", "bsp"});
                INFO("stderr: ", r.err);
                CHECK(r.code == 0);
            }
        }
}

TEST_CASE("A BSP tree refuses a camera outside its fixed world and says how far the world reaches") {
    // hider-bsp fits the model alone into the world, so unlike the other algorithms (whose world fits
    // model, eye and target) a tree holds cameras only within 16 half extents of the model's centre.
    for (const std::string& model : {torus_blob(), kTorus}) {
        INFO("model ", model);
        const Run far = render(model, {"--algo", "bsp", "--eye", "0,0,1000", "--target", "0,0,0"});
        check_error(far, {"eye (0, 0, 1000) lies outside the tree's world", "model units of"});
        const std::string line = first_line(far.err);
        const size_t at = line.find("within ");
        REQUIRE(at != std::string::npos);
        const double reach = std::stod(line.substr(at + 7));
        CHECK(reach > 1.0);
        CHECK(reach < 1000.0);
        const std::string inside = "0,0," + std::to_string(0.9 * reach), outside = "0,0," + std::to_string(1.1 * reach);
        CHECK(render(model, {"--algo", "bsp", "--eye", inside, "--target", "0,0,0"}).code == 0);
        check_error(render(model, {"--algo", "bsp-front", "--eye", outside, "--target", "0,0,0"}), {"outside the tree's world"});
        check_error(render(model, {"--algo", "bsp", "--eye", "0,0,3", "--target", "0,0," + std::to_string(-2 * reach)}),
                    {"target (", "outside the tree's world"});
    }
    CHECK(render(kTorus, {"--algo", "zbuffer", "--eye", "0,0,1000", "--target", "0,0,0"}).code == 0);  // any camera
}

TEST_CASE("hider-bsp builds a model whose coordinates are near the largest double, and the tree draws it") {
    // The tree's world is the model's alone; the default eye of a camera nobody asked for (a blob holds
    // none) overflowed to inf and the build failed with "give --eye", an option a blob refuses.
    const std::string model =
        write_model("far_away.obj", "v 1.7e308 1.7e308 1.79e308\nv 1.6e308 1.7e308 1.79e308\nv 1.7e308 1.6e308 1.79e308\nf 1 2 3\n");
    const std::string tree = scratch_path("far_away.hbsp");
    const Run built = bsp_tool(model, tree);
    INFO("stderr: ", built.err);
    REQUIRE(built.code == 0);
    const Run drawn = render(tree, {"--algo", "bsp", "--size", "64x48", "--eye", "1.67e308,1.67e308,1.795e308", "--target",
                                    "1.67e308,1.67e308,1.79e308"});
    INFO("render stderr: ", drawn.err);
    REQUIRE(drawn.code == 0);
    const Image img = read_image(out_ppm(), 64, 48);
    REQUIRE(img.ok);
    CHECK(count_pixels(img, 0x000000u) < 64 * 48);  // the triangle is in view
}

TEST_CASE("A .hbsp tree with a non-BSP algorithm is rejected with the algorithms that draw it") {
    check_error(render(torus_blob(), {"--algo", "zbuffer"}), {torus_blob() + ": ", "--algo bsp or bsp-front"});
}

TEST_CASE("generated scene names: a known kind with a bad number names the field and its range") {
    hider::tool::gen::GenScene g;
    std::string why;
    CHECK(hider::tool::gen::by_name("dense-1-300", g, why));
    CHECK_FALSE(hider::tool::gen::by_name("dense-1-0", g, why));
    CHECK(why == "scene 'dense-1-0': '0' (field 2) is not a whole number in 1..100000");
    CHECK_FALSE(hider::tool::gen::by_name("grid-1-2-2000", g, why));
    CHECK(why == "scene 'grid-1-2-2000': '2000' (field 3) is not a whole number in 0..1000");
    CHECK_FALSE(hider::tool::gen::by_name("soup-99999999999999999999-3", g, why));  // past long: ERANGE
    CHECK(why.find("'99999999999999999999' (field 1) is not a whole number") != std::string::npos);
    CHECK_FALSE(hider::tool::gen::by_name("dense-1", g, why));  // a field missing: the patterns
    CHECK(why.find("unknown scene 'dense-1' (known: soup-SEED-N, dense-SEED-N") == 0);
}

namespace {
/// A fan of 16 triangles of 0.04 units around (0, 1, 0), as scene `triangle` lines, or as OBJ text.
std::string grid_fan(bool obj) {
    std::string out;
    for (int i = 0; i < 16; ++i) {
        const double a0 = i * 0.3926990817, a1 = (i + 1) * 0.3926990817;
        const std::string p1 = std::to_string(0.04 * std::cos(a0)) + " 0.999 " + std::to_string(0.04 * std::sin(a0));
        const std::string p2 = std::to_string(0.04 * std::cos(a1)) + " 0.999 " + std::to_string(0.04 * std::sin(a1));
        out += obj ? "v 0 1 0\nv " + p1 + "\nv " + p2 + "\nf " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " +
                         std::to_string(3 * i + 3) + "\n"
                   : "triangle 0 1 0 " + p1 + " " + p2 + "\n";
    }
    return out;
}
const char* const kFarTriangle = "triangle 8000 -8000 8000 8001 -8000 8000 8000 -7999 8000\n";
}  // namespace

TEST_CASE("--scene warns when a mesh's far geometry coarsens its vertex grid under its small triangles") {
    // The fan alone, and with one triangle 8,000 units away in the same OBJ mesh: the triangle test then
    // sees every vertex on a 0.0078-unit grid, under which those triangles turn over where rays graze
    // them (a red team's holes and self-shadowing).
    const std::string head = "size 32 24\ncamera eye 0.3 1.2 4 target 0 0 0 fov 45\nlight point 4 6 3\n";
    write_model("grid_fan.obj", grid_fan(true));
    write_model("grid_fan_far.obj", grid_fan(true) + "v 8000 -8000 8000\nv 8001 -8000 8000\nv 8000 -7999 8000\nf 49 50 51\n");
    const std::string near_only = write_model("grid_near.txt", head + "mesh grid_fan.obj\n");
    const std::string with_far = write_model("grid_far.txt", head + "mesh grid_fan_far.obj\n");
    const Run ok = run({"--scene", near_only, "-o", out_ppm()});
    CHECK_MESSAGE(ok.code == 0, ok.err);
    CHECK(ok.err.empty());
    const Run far = run({"--scene", with_far, "-o", out_ppm()});
    CHECK_MESSAGE(far.code == 0, far.err);
    CHECK(far.output_created);
    CHECK(far.err.find("warning: " + with_far + ": mesh 1 reaches 8001 units from the eye") != std::string::npos);
    CHECK(far.err.find("16 of its 17 triangles have an edge under 8 steps") != std::string::npos);
}

TEST_CASE("--scene: a far loose triangle does not coarsen the grid of near ones (one mesh per grid)") {
    // Loose `triangle` lines are grouped by the vertex grid each would get alone, so the fan seen closely
    // draws the same bytes with the far triangle before it, after it, or absent. As one mesh (before),
    // 259 of these 96x72 frames' 20,736 bytes moved.
    const std::string head = "size 96 72\ncamera eye 0.3 1.2 4 target 0 1 0 fov 2\nlight point 4 6 3\n";
    std::string frames[3];
    const std::string texts[3] = {head + grid_fan(false), head + grid_fan(false) + kFarTriangle, head + kFarTriangle + grid_fan(false)};
    for (int i = 0; i < 3; ++i) {
        const std::string scene = write_model("grid_loose" + std::to_string(i) + ".txt", texts[i]);
        const Run r = run({"--scene", scene, "-o", out_ppm()});
        CHECK_MESSAGE(r.code == 0, r.err);
        CHECK_MESSAGE(r.err.empty(), r.err);
        frames[i] = read_file(out_ppm());
    }
    CHECK(frames[0].size() == 96 * 72 * 3 + 13);
    CHECK(frames[0].find_first_not_of('\0', 13) != std::string::npos);  // the fan is in view
    CHECK(frames[1] == frames[0]);
    CHECK(frames[2] == frames[0]);
}

TEST_CASE("-o /dev/stdout writes the image through standard output: --stats goes to stderr, an append stays one") {
    // The image was written by reopening /dev/stdout: a redirection's file was truncated (an append lost
    // what it held) and the statistics, printed on descriptor 1 at its own offset, overwrote the image.
    const std::string model = write_model("stdout_tri.obj", kTriangle);
    const Run r = run({model, "-o", "/dev/stdout", "--size", "4x2", "--stats"}, scratch_path("none"));
    CHECK_MESSAGE(r.code == 0, r.err);
    CHECK(r.out.size() == 4 * 2 * 3 + 11);
    CHECK(r.out.rfind("P6\n4 2\n255\n", 0) == 0);
    CHECK(r.err.find("triangles 1 drawn") != std::string::npos);
    const std::string log = scratch_path("appended.txt");
    std::ofstream(log, std::ios::binary) << "log\n";
    const std::string cmd = shell_quoted(kExe) + " " + shell_quoted(model) + " -o /dev/stdout --size 4x2 >>" + shell_quoted(log);
    REQUIRE(std::system(cmd.c_str()) == 0);
    const std::string both = read_file(log);
    CHECK(both.size() == 4 + 4 * 2 * 3 + 11);
    CHECK(both.rfind("log\nP6\n4 2\n255\n", 0) == 0);
}

TEST_CASE("A directory given as the .hbsp model or as the scene is refused with exit 2 and the reason") {
    // The .hbsp reader let libstdc++'s read error escape (abort, exit 134); the scene reader said "read error".
    const std::string dir = scratch_path("dir.hbsp");
    fs::create_directories(dir);
    const Run bsp = run({dir, "-o", out_ppm(), "--algo", "bsp"});
    CHECK(bsp.code == 2);
    CHECK_MESSAGE(bsp.err.find(dir + ": cannot open file: Is a directory") != std::string::npos, bsp.err);
    CHECK_FALSE(bsp.output_created);
    const Run scene = run({"--scene", dir, "-o", out_ppm()});
    CHECK(scene.code == 2);
    CHECK_MESSAGE(scene.err.find(dir + ": cannot open file: Is a directory") != std::string::npos, scene.err);
    const Run missing = run({scratch_path("missing.hbsp"), "-o", out_ppm(), "--algo", "bsp"});  // with the reason
    CHECK(missing.code == 2);
    CHECK(missing.err.find("missing.hbsp: cannot open file: No such file or directory") != std::string::npos);
    const std::string fifo = scratch_path("fifo.hbsp");  // a device or pipe could grow the buffer without end
    fs::remove(fifo);
    if (::mkfifo(fifo.c_str(), 0600) == 0) {
        const Run pipe = run({fifo, "-o", out_ppm(), "--algo", "bsp"});
        CHECK(pipe.code == 2);
        CHECK(pipe.err.find("fifo.hbsp: cannot open file: not a regular file") != std::string::npos);
    }
}

TEST_CASE("--scene refuses --algo other than raycast, even the default's name, and --strict") {
    // An explicit --algo zbuffer was taken for the default and the scene silently ray traced.
    const std::string scene = write_model("algo_scene.txt", "camera eye 0 2 8 target 0 0 0\nsphere 0 0 0 1\n");
    const Run z = run({"--scene", scene, "-o", out_ppm(), "--algo", "zbuffer"});
    CHECK(z.code == 2);
    CHECK(z.err.find("--algo must be raycast (or left out)") != std::string::npos);
    CHECK_FALSE(z.output_created);
    const Run strict = run({"--scene", scene, "-o", out_ppm(), "--strict"});
    CHECK(strict.code == 2);
    CHECK(strict.err.find("--strict does not apply to --scene") != std::string::npos);
    const Run ray = run({"--scene", scene, "-o", out_ppm(), "--algo", "raycast"});
    CHECK_MESSAGE(ray.code == 0, ray.err);
    CHECK(ray.output_created);
}

TEST_CASE("Standard output that cannot be written (/dev/full) is an error, exit 2") {
    if (!exists("/dev/full")) return;  // Linux
    const std::string model = write_model("full_tri.obj", kTriangle);
    for (const Args& args : {Args{model, "-o", out_ppm(), "--stats"}, Args{"--help"}}) {
        std::string cmd = shell_quoted(kExe);
        for (const std::string& a : args) cmd += " " + shell_quoted(a);
        const std::string err_file = scratch_path("full_err.txt");
        const int status = std::system((cmd + " >/dev/full 2>" + shell_quoted(err_file)).c_str());
        CHECK(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 2);
        CHECK(read_file(err_file).find("hider-render: cannot write standard output") != std::string::npos);
    }
    // The image itself through standard output: its write fails, named with the path.
    const std::string err_file = scratch_path("full_err.txt");
    const std::string cmd = shell_quoted(kExe) + " " + shell_quoted(model) + " -o /dev/stdout >/dev/full 2>" + shell_quoted(err_file);
    const int status = std::system(cmd.c_str());
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(read_file(err_file).find("/dev/stdout: write failed: No space left on device") != std::string::npos);
}

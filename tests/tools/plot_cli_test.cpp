// Tests for the hider-plot command line: runs the real binary (HIDER_PLOT_EXE) through /bin/sh. Errors:
// exit 2, one stderr line "hider-plot: <file: what | reason>" (usage errors add the usage text), nothing
// on stdout, no output file. Success: exit 0 and a P6 (or PNG) file. Height maps are written at test time.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <system_error>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

const std::string kExe = HIDER_PLOT_EXE;

const std::string& scratch() {
    static const std::string dir = [] {
        const std::string d = std::string(HIDER_TEST_OUT) + "/plot_cli";
        std::error_code ec;
        fs::create_directories(d, ec);
        return d;
    }();
    return dir;
}
std::string path(const std::string& name) { return scratch() + "/" + name; }
std::string out_ppm() { return path("out.ppm"); }

std::string read_file(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
std::string write(const std::string& name, const std::string& bytes) {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
}
std::string quoted(const std::string& s) {
    std::string q = "'";
    for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

struct Run {
    std::string command;
    int code = -1;
    std::string out, err;
    bool output_created = false;
};

Run run(const Args& args, const std::string& output = out_ppm()) {
    std::error_code ec;
    fs::remove(output, ec);
    std::string cmd = quoted(kExe);
    for (const std::string& a : args) cmd += " " + quoted(a);
    Run r;
    r.command = cmd;
    const int status = std::system((cmd + " >" + quoted(path("stdout.txt")) + " 2>" + quoted(path("stderr.txt"))).c_str());
    r.code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(path("stdout.txt"));
    r.err = read_file(path("stderr.txt"));
    r.output_created = fs::exists(output, ec);
    return r;
}

Run plot(Args extra) {
    extra.insert(extra.end(), {"-o", out_ppm()});
    return run(extra);
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

enum class Usage { no, yes };

void check_error(const Run& r, const std::vector<std::string>& parts, Usage usage = Usage::no) {
    INFO("command: ", r.command);
    INFO("stderr: ", r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.output_created);
    const std::string line = r.err.substr(0, r.err.find('\n'));
    CHECK(line.rfind("hider-plot: ", 0) == 0);
    for (const std::string& part : parts) {
        INFO("expected in the first line: ", part);
        CHECK(contains(line, part));
    }
    const std::string rest = r.err.size() > line.size() ? r.err.substr(line.size() + 1) : std::string();
    if (usage == Usage::yes) CHECK(rest.rfind("usage: hider-plot", 0) == 0);
    else CHECK(r.err == line + "\n");
}

/// A P6 image as hider-plot writes it.
struct Image {
    bool ok = false;
    int w = 0, h = 0;
    std::string rgb;
    uint32_t at(int x, int y) const {
        const size_t i = (static_cast<size_t>(y) * w + x) * 3;
        auto b = [&](size_t k) { return static_cast<uint32_t>(static_cast<unsigned char>(rgb[i + k])); };
        return b(0) << 16 | b(1) << 8 | b(2);
    }
};
Image read_image(int w, int h) {
    const std::string bytes = read_file(out_ppm());
    const std::string header = "P6\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    Image img;
    img.ok = bytes.rfind(header, 0) == 0 && bytes.size() == header.size() + static_cast<size_t>(w) * h * 3;
    if (img.ok) {
        img.w = w;
        img.h = h;
        img.rgb = bytes.substr(header.size());
    }
    return img;
}

/// A P2 / P5 height map of rows x cols from v(row, col), 8- or 16-bit.
template <class F>
std::string pgm(bool binary, int cols, int rows, int maxval, F v) {
    std::string s = std::string(binary ? "P5" : "P2") + "\n# a comment\n" + std::to_string(cols) + " " +
                    std::to_string(rows) + "\n" + std::to_string(maxval) + "\n";
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const int x = v(r, c);
            if (!binary) s += std::to_string(x) + (c + 1 == cols ? "\n" : " ");
            else if (maxval < 256) s += static_cast<char>(x);
            else s += std::string{static_cast<char>(x >> 8), static_cast<char>(x & 255)};
        }
    return s;
}

int bump(int r, int c, int maxval) { return (maxval * ((r * 7 + c * 5) % 16)) / 15; }

}  // namespace

TEST_CASE("hider-plot: each built-in function plots, and the default camera frames the whole surface") {
    for (const char* f : {"sinc", "saddle", "hills", "waves"}) {
        CAPTURE(f);
        const Run r = plot({"--function", f, "--size", "160x120"});
        REQUIRE(r.code == 0);
        CHECK(r.err.empty());
        const Image img = read_image(160, 120);
        REQUIRE(img.ok);
        int lit = 0, border = 0;
        for (int y = 0; y < 120; ++y)
            for (int x = 0; x < 160; ++x) {
                const bool on = img.at(x, y) != 0;
                lit += on;
                border += on && (x < 2 || y < 2 || x > 157 || y > 117);
            }
        CHECK(lit > 1500);
        CHECK(border == 0);  // nothing cut off by the frame
    }
}

TEST_CASE("hider-plot: P2 and P5, 8 and 16 bits: the same heights give the same picture") {
    auto v8 = [](int r, int c) { return bump(r, c, 255); };
    auto v16 = [](int r, int c) { return bump(r, c, 255) * 257; };  // 65535 / 255 = 257: the same fractions
    const std::string p2 = write("h8.pgm", pgm(false, 20, 12, 255, v8));
    const std::string p5 = write("h8b.pgm", pgm(true, 20, 12, 255, v8));
    const std::string p2w = write("h16.pgm", pgm(false, 20, 12, 65535, v16));
    const std::string p5w = write("h16b.pgm", pgm(true, 20, 12, 65535, v16));
    std::string first;
    for (const std::string& file : {p2, p5, p2w, p5w}) {
        CAPTURE(file);
        const Run r = plot({"--heightmap", file, "--size", "120x90", "--shade", "id"});
        REQUIRE(r.code == 0);
        const std::string bytes = read_file(out_ppm());
        if (first.empty()) first = bytes;
        CHECK(bytes == first);
    }
    // Each row is a curve: ids 1..12 (in order of increasing z), the side edges 13 and 14.
    REQUIRE(plot({"--heightmap", p5, "--size", "240x180", "--shade", "id"}).code == 0);
    const Image img = read_image(240, 180);
    REQUIRE(img.ok);
    std::set<uint32_t> ids;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 240; ++x) ids.insert(img.at(x, y));
    for (uint32_t k = 1; k <= 12; ++k) CHECK(ids.count(k) == 1);
    CHECK(ids.count(13) == 1);
    CHECK(ids.count(14) == 1);
    CHECK(*ids.rbegin() == 14);
    // --curves resamples the rows: 30 curves.
    REQUIRE(plot({"--heightmap", p5, "--size", "240x180", "--shade", "id", "--curves", "30"}).code == 0);
    const Image resampled = read_image(240, 180);
    std::set<uint32_t> ids30;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 240; ++x) ids30.insert(resampled.at(x, y));
    CHECK(ids30.count(30) == 1);
    CHECK(ids30.count(31) == 1);
}

TEST_CASE("hider-plot: --shade id puts curve k (in order of increasing z) where its heights are") {
    // Two rows: a flat far one (z = -1) and a flat near one (z = +1) at different heights; seen from the
    // front above, the near curve (id 2) is lower on the screen than the far one (id 1).
    const std::string map = write("two.pgm", pgm(false, 8, 2, 10, [](int r, int) { return r == 0 ? 10 : 0; }));
    REQUIRE(plot({"--heightmap", map, "--size", "100x80", "--shade", "id", "--eye", "0,2,3"}).code == 0);
    const Image img = read_image(100, 80);
    REQUIRE(img.ok);
    int row1 = -1, row2 = -1;
    for (int y = 0; y < 80; ++y) {
        if (img.at(50, y) == 1 && row1 < 0) row1 = y;
        if (img.at(50, y) == 2 && row2 < 0) row2 = y;
    }
    CHECK(row1 >= 0);
    CHECK(row2 > row1);
}

TEST_CASE("hider-plot: --mesh adds constant-x lines; PNG output; a clamped view warns") {
    REQUIRE(plot({"--function", "sinc", "--size", "120x90", "--shade", "id", "--mesh", "--curves", "10", "--samples", "28"}).code == 0);
    const Image img = read_image(120, 90);
    std::set<uint32_t> ids;
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 120; ++x) ids.insert(img.at(x, y));
    CHECK(ids.count(11) == 1);               // first constant-x line
    CHECK(ids.count(11 + 9) == 1);           // mesh step 3: lines at 0, 3, .., 27
    const std::string png = path("out.png");
    const Run r = run({"--function", "hills", "-o", png}, png);
    CHECK(r.code == 0);
    CHECK(read_file(png).rfind("\x89PNG\r\n\x1a\n", 0) == 0);
}

TEST_CASE("hider-plot: a grid whose Q16 steps shrink the surface by over 1% warns") {
    // 2 / 52429 is 2.49999 raw, rounded to 2: x spans [-0.8, 0.8].
    const Run fine = plot({"--function", "saddle", "--curves", "20", "--samples", "52430", "--size", "64x48"});
    CHECK(fine.code == 0);
    CHECK(contains(fine.err, "hider-plot: warning: the grid's steps round to 1/65536: the surface spans x in [-0.8, 0.8]"));
    const Run usual = plot({"--function", "saddle", "--curves", "20", "--samples", "2000", "--size", "64x48"});  // 0.6%
    CHECK(usual.code == 0);
    CHECK(usual.err.empty());
}

TEST_CASE("hider-plot: a view whose projection may be a pixel off warns, with the bound") {
    // One peak of 500 units among zeros, the eye 6 units from the surface: the surface's box reaches far
    // beyond the frame, and the far curve (all heights 0) was drawn 2.7 pixels off without a word.
    const std::string f = write("pin.pgm", pgm(false, 3, 2, 255, [](int r, int c) { return r == 1 && c == 1 ? 255 : 0; }));
    const Run pin = plot({"--heightmap", f, "--height", "-500", "--eye", "0,2,6", "--target", "0,0,0", "--shade", "id"});
    CHECK(pin.code == 0);
    CHECK(contains(pin.err, "hider-plot: warning: projected points may lie up to "));
    CHECK(contains(pin.err, "frame more of it, or narrow the height range"));
    const Run flat = plot({"--heightmap", f, "--height", "-0.5", "--eye", "0,2,6", "--target", "0,0,0", "--shade", "id"});
    CHECK(flat.code == 0);
    CHECK(flat.err.empty());
}

TEST_CASE("hider-plot: a view off by more than a pixel warns even where error_bound_subpixels() is below one") {
    // A red team's view: hills 0.01 high seen from 0.17 units; the box reaches far beyond the frame and
    // U and V's floor to 2^14 units (which the bound leaves out) put points 1.44 pixels off, bound 0.375.
    const Run close = plot({"--function", "hills", "--height", "0.01", "--eye", "0,0.17,0.01", "--target", "0,0,0", "--fov", "26",
                            "--size", "960x1000"});
    CHECK(close.code == 0);
    CHECK(contains(close.err, "hider-plot: warning: projected points may lie up to 1.4375 pixels from their exact place"));
    const Run framed = plot({"--function", "hills", "--height", "0.01", "--eye", "0,2,3", "--target", "0,0,0", "--size", "320x240"});
    CHECK(framed.code == 0);
    CHECK(framed.err.empty());
}

TEST_CASE("hider-plot: an eye inside the surface's box warns") {
    // A red team's view: hills 100x300 from inside the box drew a fan of curves the exact view hides.
    const Run inside = plot({"--function", "hills", "--curves", "100", "--samples", "300", "--eye", "0.031,-0.068,0.409",
                             "--target", "-0.566,-0.298,1.178"});
    CHECK(inside.code == 0);
    CHECK(contains(inside.err, "hider-plot: warning: the eye is inside the surface's box"));
    const Run above = plot({"--function", "hills", "--curves", "100", "--samples", "300", "--eye", "0.031,0.8,0.409",
                            "--target", "-0.566,-0.298,1.178"});
    CHECK(above.code == 0);
    CHECK(!contains(above.err, "inside the surface's box"));
}

TEST_CASE("hider-plot: a P5 comment right after maxval ends at its newline, and the raster follows") {
    // netpbm allows a comment before the whitespace that delimits the raster. It was read as pixels: 'z'
    // (122) exceeded maxval 10, and with maxval 255 the map was silently different (a red team's file).
    std::string raster;
    for (int i = 0; i < 16; ++i) raster += static_cast<char>(i * 9);
    const std::string plain = write("plain.pgm", "P5 4 4 200\n" + raster);
    const std::string commented = write("commented.pgm", "P5 4 4 200#zz\n" + raster);
    const Run a = plot({"--heightmap", plain});
    REQUIRE(a.code == 0);
    const std::string image = read_file(out_ppm());
    const Run b = plot({"--heightmap", commented});
    CHECK_MESSAGE(b.code == 0, b.err);
    CHECK(read_file(out_ppm()) == image);
}

TEST_CASE("hider-plot: a malformed, truncated or unsupported height map is rejected with the file and the reason") {
    auto v = [](int r, int c) { return bump(r, c, 255); };
    SUBCASE("wrong magic") {
        const std::string f = write("magic.pgm", "P6\n2 2\n255\n" + std::string(12, 'x'));
        check_error(plot({"--heightmap", f}), {f + ": ", "not a PGM height map", "'P6'", "P2 or P5"});
    }
    SUBCASE("not even a header") {
        const std::string f = write("empty.pgm", "");
        check_error(plot({"--heightmap", f}), {f + ": ", "not a PGM height map"});
    }
    SUBCASE("maxval 0") {
        const std::string f = write("max0.pgm", "P2\n2 2\n0\n0 0 0 0\n");
        check_error(plot({"--heightmap", f}), {f + ": ", "maxval 0"});
    }
    SUBCASE("maxval too large") {
        const std::string f = write("max70000.pgm", "P2\n2 2\n70000\n0 0 0 0\n");
        check_error(plot({"--heightmap", f}), {f + ": ", "maxval 70000 out of range"});
    }
    SUBCASE("a bad header number") {
        const std::string f = write("badw.pgm", "P2\nabc 3\n255\n");
        check_error(plot({"--heightmap", f}), {f + ": ", "bad width 'abc'"});
    }
    SUBCASE("a header cut short") {
        const std::string f = write("short.pgm", "P5\n4 4\n");
        check_error(plot({"--heightmap", f}), {f + ": ", "truncated header", "maxval"});
    }
    SUBCASE("fewer than 2 rows or columns") {
        check_error(plot({"--heightmap", write("row.pgm", "P2\n5 1\n9\n1 2 3 4 5\n")}), {"5x1", "at least 2 rows and 2 columns"});
        check_error(plot({"--heightmap", write("col.pgm", "P2\n1 5\n9\n1 2 3 4 5\n")}), {"1x5", "at least 2 rows and 2 columns"});
    }
    SUBCASE("binary data cut short, 8 and 16 bit") {
        std::string p8 = pgm(true, 6, 4, 255, v);
        const std::string f8 = write("trunc8.pgm", p8.substr(0, p8.size() - 5));
        check_error(plot({"--heightmap", f8}), {f8 + ": ", "truncated: 19 of 24 pixel values"});
        std::string p16 = pgm(true, 6, 4, 1000, [](int r, int c) { return r * 100 + c; });
        const std::string f16 = write("trunc16.pgm", p16.substr(0, p16.size() - 3));
        check_error(plot({"--heightmap", f16}), {f16 + ": ", "truncated: 22 of 24 pixel values"});
    }
    SUBCASE("text data cut short or not a number") {
        const std::string f = write("trunc2.pgm", "P2\n3 2\n9\n1 2 3 4\n");
        check_error(plot({"--heightmap", f}), {f + ": ", "truncated: 4 of 6 pixel values"});
        const std::string g = write("nan.pgm", "P2\n2 2\n9\n1 x 3 4\n");
        check_error(plot({"--heightmap", g}), {g + ": ", "bad pixel value 'x'", "pixel 1"});
    }
    SUBCASE("a value above maxval") {
        const std::string f = write("over.pgm", "P2\n2 2\n9\n1 2 30 4\n");
        check_error(plot({"--heightmap", f}), {f + ": ", "value 30 exceeds maxval 9", "row 1, column 0"});
    }
    SUBCASE("a file that does not exist") {
        check_error(plot({"--heightmap", path("missing.pgm")}), {path("missing.pgm") + ": ", "cannot open"});
    }
}

TEST_CASE("hider-plot: bad options are rejected with a plain reason") {
    check_error(plot({"--function", "bessel"}), {"unknown function 'bessel'", "sinc, saddle, hills, waves"});
    check_error(plot({"--function", "sinc", "--curves", "1"}), {"--curves 1 out of range (2..65535)"});
    check_error(plot({"--function", "sinc", "--curves", "x"}), {"--curves: bad number 'x'"});
    check_error(plot({"--function", "sinc", "--samples", "0"}), {"--samples 0 out of range"});
    check_error(plot({"--function", "sinc", "--size", "0x10"}), {"--size 0x10 out of range"});
    check_error(plot({"--function", "sinc", "--size", "big"}), {"--size needs WxH"});
    check_error(plot({"--function", "sinc", "--fov", "200"}), {"--fov 200 out of range"});
    check_error(plot({"--function", "sinc", "--eye", "1,2"}), {"--eye needs x,y,z"});
    check_error(plot({"--function", "sinc", "--eye", "0,0,0", "--target", "0,0,0"}), {"eye and target coincide"});
    check_error(plot({"--function", "sinc", "--eye", "0,5,0", "--target", "0,0,0", "--up", "0,1,0"}), {"up vector is parallel"});
    check_error(plot({"--function", "sinc", "--eye", "9000,0,0"}), {"eye", "out of range"});
    check_error(plot({"--function", "sinc", "--height", "1e9"}), {"--height 1e9 out of range"});
    check_error(plot({"--function", "sinc", "--height", "1000"}), {"--height 1000 out of range (-1000 < S < 1000)"});
    check_error(plot({"--function", "sinc", "--shade", "rainbow"}), {"unknown shade 'rainbow'"});
    check_error(plot({"--function", "sinc", "--frobnicate"}), {"unknown argument '--frobnicate'"}, Usage::yes);
    check_error(run({"--function", "sinc"}), {"no output given"}, Usage::yes);
    check_error(plot({}), {"give exactly one of --function and --heightmap"}, Usage::yes);
    check_error(plot({"--function", "sinc", "--heightmap", "x.pgm"}), {"give exactly one of --function and --heightmap"}, Usage::yes);
    check_error(run({"--function", "sinc", "-o", out_ppm(), "--curves"}), {"--curves needs a value"}, Usage::yes);
    const std::string bad_out = path("no_such_dir/out.ppm");
    check_error(run({"--function", "sinc", "-o", bad_out}, bad_out), {bad_out});
    // Found by a red-team pass: a zero up vector was blamed on the view direction; a directory given as
    // the height map aborted (uncaught std::ios_failure); any extension but ".png" wrote PPM bytes.
    check_error(plot({"--function", "sinc", "--up", "0,0,0"}), {"up vector is zero"});
    check_error(plot({"--heightmap", path("")}), {"cannot open for reading", "Is a directory"});
    const std::string jpg = path("out.jpg");
    check_error(run({"--function", "sinc", "-o", jpg}, jpg), {"unknown image format '.jpg'", "use .ppm or .png"});
    const std::string upper = path("out.PNG");
    const Run png = run({"--function", "sinc", "--size", "40x30", "-o", upper}, upper);
    CHECK(png.code == 0);
    CHECK(read_file(upper).rfind("\x89PNG", 0) == 0);
    // A device takes PPM whatever its name (the extension check refused /dev/stdout).
    const Run out = run({"--function", "sinc", "--size", "40x30", "-o", "/dev/stdout"}, path("none"));
    CHECK(out.code == 0);
    CHECK(out.out.rfind("P6\n40 30\n255\n", 0) == 0);
    // An up vector of denormals is a direction like any other (it gave an eye of inf and nan).
    const Run tiny = run({"--function", "sinc", "--size", "40x30", "--up", "1e-310,1e-310,0", "-o", out_ppm()});
    CHECK(tiny.code == 0);
}

TEST_CASE("hider-plot: a view that cannot see the surface is an error") {
    check_error(plot({"--function", "sinc", "--eye", "0,1,3", "--target", "0,1,6"}), {"the view does not see the surface"});
    check_error(plot({"--function", "hills", "--eye", "0,3,0", "--target", "0,6,0", "--up", "0,0,1"}), {"the view does not see the surface"});
    check_error(plot({"--function", "waves", "--eye", "0,0.2,20", "--target", "9,0.2,19", "--fov", "5"}), {"the view does not see the surface"});
    // Looking at the surface's middle so closely that the frame falls between two lines (a red team's
    // view, which was told the view did not see the surface).
    check_error(plot({"--function", "saddle", "--eye", "0,1,1", "--target", "0,0,0", "--fov", "0.5"}),
                {"no line of the surface crosses the 320x240 frame, though its box reaches into it"});
}

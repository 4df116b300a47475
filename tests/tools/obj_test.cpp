// Tests for tools/common/obj.hpp: accepted OBJ syntax, every error message with its line number,
// the file loader on tests/data/obj/, and a fixed-seed mutation fuzz that must never crash.
#include <doctest/doctest.h>

#include "common/obj.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using hider::tool::ObjError;
using hider::tool::ObjFace;
using hider::tool::ObjLimits;
using hider::tool::ObjModel;

struct Parsed {
    bool ok = false;
    ObjModel model;
    ObjError err;
};

Parsed parse(const std::string& text, const ObjLimits& limits = ObjLimits{}) {
    std::istringstream in(text);
    Parsed p;
    p.ok = hider::tool::parse_obj(in, "test.obj", p.model, p.err, limits);
    return p;
}

/// The formatted error for `text`, or "ok" when it parses; compared whole so failures show both strings.
std::string error_of(const std::string& text, const ObjLimits& limits = ObjLimits{}) {
    const Parsed p = parse(text, limits);
    return p.ok ? std::string("ok") : hider::tool::format(p.err);
}

// Bounds-checked accessors: the runner builds with -fno-exceptions, so tests use CHECK, never REQUIRE,
// and a missing element reads as a default value that fails the comparison instead of crashing.
ObjFace face_at(const ObjModel& m, std::size_t i) { return i < m.faces.size() ? m.faces[i] : ObjFace{}; }

std::array<double, 3> vertex_at(const ObjModel& m, std::size_t i) {
    const double nan = std::nan("");
    return i < m.vertices.size() ? m.vertices[i] : std::array<double, 3>{nan, nan, nan};
}

std::vector<int32_t> face(const Parsed& p, std::size_t i) { return face_at(p.model, i).v; }

using Ints = std::vector<int32_t>;
const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("A triangle with plain indices loads three vertices and one face") {
    const Parsed p = parse(kTriangle + "f 1 2 3\n");
    CHECK(p.ok);
    CHECK(p.model.vertices.size() == 3);
    CHECK(vertex_at(p.model, 1)[0] == 1.0);
    CHECK(vertex_at(p.model, 2)[1] == 1.0);
    CHECK(p.model.faces.size() == 1);
    CHECK(face(p, 0) == Ints{0, 1, 2});
    CHECK(face_at(p.model, 0).id == 1);
    CHECK(face_at(p.model, 0).line == 4);
}

TEST_CASE("Face vertices accept the i, i/t, i//n and i/t/n forms") {
    const std::string head = kTriangle + "vt 0 0\nvn 0 0 1\n";
    SUBCASE("i") { CHECK(face(parse(head + "f 1 2 3\n"), 0) == Ints{0, 1, 2}); }
    SUBCASE("i/t") { CHECK(face(parse(head + "f 1/1 2/1 3/1\n"), 0) == Ints{0, 1, 2}); }
    SUBCASE("i//n") { CHECK(face(parse(head + "f 1//1 2//1 3//1\n"), 0) == Ints{0, 1, 2}); }
    SUBCASE("i/t/n") { CHECK(face(parse(head + "f 1/1/1 2/1/1 3/1/1\n"), 0) == Ints{0, 1, 2}); }
    SUBCASE("forms mixed on one line, signed texture and normal indices") {
        CHECK(face(parse(head + "f 3 +2/-1 1//+1\n"), 0) == Ints{2, 1, 0});
    }
    SUBCASE("a leading plus sign") { CHECK(face(parse(head + "f +1 +2 +3\n"), 0) == Ints{0, 1, 2}); }
}

TEST_CASE("Negative indices count back from the last vertex defined so far") {
    const Parsed p = parse(kTriangle + "f -3 -2 -1\nv 5 5 5\nf -1 -2 -4\nf -1/1 -2//1 -3/1/1\n");
    CHECK(p.ok);
    CHECK(face(p, 0) == Ints{0, 1, 2});
    CHECK(face(p, 1) == Ints{3, 2, 0});
    CHECK(face(p, 2) == Ints{3, 2, 1});
}

TEST_CASE("A w coordinate other than 1 divides x, y and z") {
    const Parsed p = parse("v 2 4 6 2\nv 1 2 3 1\nv 1 2 3 -0.5\nf 1 2 3\n");
    CHECK(p.ok);
    CHECK(vertex_at(p.model, 0) == std::array<double, 3>{1.0, 2.0, 3.0});
    CHECK(vertex_at(p.model, 1) == std::array<double, 3>{1.0, 2.0, 3.0});
    CHECK(vertex_at(p.model, 2) == std::array<double, 3>{-2.0, -4.0, -6.0});
}

TEST_CASE("Coordinates use strtod syntax: signs, exponents, bare dots and hex floats") {
    const Parsed p = parse("v 1e-3 +2.5E+2 -.5\nv 5. -0 1e0\nv 0x1.8p1 -0X10 +3\nf 1 2 3\n");
    CHECK(p.ok);
    CHECK(vertex_at(p.model, 0) == std::array<double, 3>{0.001, 250.0, -0.5});
    CHECK(vertex_at(p.model, 1) == std::array<double, 3>{5.0, 0.0, 1.0});
    CHECK(std::signbit(vertex_at(p.model, 1)[1]));
    CHECK(vertex_at(p.model, 2) == std::array<double, 3>{3.0, -16.0, 3.0});
}

TEST_CASE("Comments, blank lines, leading blanks, tabs and CRLF line endings are ignored") {
    const std::string text =
        "# header comment\r\n"
        "\r\n"
        "   \t\n"
        "\tv\t0 0 0 # trailing comment\r\n"
        "  v 1\t0   0#no space before the hash\r\n"
        "v 0 1 0\r\n"
        "f 1 2 3 # the face\r\n"
        "#";
    const Parsed p = parse(text);
    CHECK(p.ok);
    CHECK(p.model.vertices.size() == 3);
    CHECK(vertex_at(p.model, 1) == std::array<double, 3>{1.0, 0.0, 0.0});
    CHECK(face(p, 0) == Ints{0, 1, 2});
    CHECK(face_at(p.model, 0).line == 7);
}

TEST_CASE("Non-geometry and unknown keywords are ignored, even with odd arguments") {
    const std::string text =
        "mtllib a.mtl b.mtl\no thing\ng group one\ns 1\ns off\nusemtl red\n"
        "vt 0.5 0.5\nvn 0 0 1\nvp 0.1\nl 1 2\np 1\ncstype bspline\nfoo bar/baz 1e999 nan\n"
        "V 1 2\nF 0\nvx not a vertex\nfo not a face\n" +
        kTriangle + "f 1 2 3\n";
    const Parsed p = parse(text);
    CHECK(p.ok);
    CHECK(p.model.vertices.size() == 3);
    CHECK(p.model.faces.size() == 1);
}

TEST_CASE("A polygon with five vertices stays one face with five indices") {
    const Parsed p = parse(kTriangle + "v 1 1 0\nv 2 2 0\nf 1 2 4 5 3\n");
    CHECK(p.ok);
    CHECK(p.model.faces.size() == 1);
    CHECK(face(p, 0) == Ints{0, 1, 3, 4, 2});
}

TEST_CASE("Face ids count every f line, degenerate faces included") {
    const Parsed p = parse(kTriangle + "f 1 2 3\nf 1 1 1\n# gap\nv 1 1 0\nf 2 4 3\n");
    CHECK(p.ok);
    CHECK(p.model.faces.size() == 3);
    CHECK(face_at(p.model, 0).id == 1);
    CHECK(face_at(p.model, 1).id == 2);
    CHECK(face(p, 1) == Ints{0, 0, 0});
    CHECK(face_at(p.model, 2).id == 3);
    CHECK(face_at(p.model, 1).line == 5);
    CHECK(face_at(p.model, 2).line == 8);
}

TEST_CASE("A last line without a line break is still parsed") {
    const Parsed p = parse(kTriangle + "f 1 2 3");
    CHECK(p.ok);
    CHECK(face(p, 0) == Ints{0, 1, 2});
}

TEST_CASE("A bad number names the token and the coordinate") {
    CHECK(error_of("v 1 2 abc\n") == "test.obj:1: bad number 'abc' for vertex z coordinate");
    CHECK(error_of("v 1.0abc 2 3\n") == "test.obj:1: bad number '1.0abc' for vertex x coordinate");
    CHECK(error_of("v 1 1e 3\n") == "test.obj:1: bad number '1e' for vertex y coordinate");
    CHECK(error_of("v 1 --2 3\n") == "test.obj:1: bad number '--2' for vertex y coordinate");
    CHECK(error_of("v 1 +-2 3\n") == "test.obj:1: bad number '+-2' for vertex y coordinate");
    CHECK(error_of("v 1,5 2 3\n") == "test.obj:1: bad number '1,5' for vertex x coordinate");
    CHECK(error_of("v 1 2 0x\n") == "test.obj:1: bad number '0x' for vertex z coordinate");
    CHECK(error_of("v 1 2 0x-1\n") == "test.obj:1: bad number '0x-1' for vertex z coordinate");
    CHECK(error_of("v 1 2 3 w\n") == "test.obj:1: bad number 'w' for vertex w coordinate");
    CHECK(error_of("\n\nv 1 2 3\nv 1 2 .\n") == "test.obj:4: bad number '.' for vertex z coordinate");
}

TEST_CASE("Binary bytes and embedded NULs in a token are escaped in the message") {
    CHECK(error_of(std::string("v 1 2 3\0\n", 9)) == "test.obj:1: bad number '3\\x00' for vertex z coordinate");
    CHECK(error_of("v 1 2 \x01\xff\\\n") == "test.obj:1: bad number '\\x01\\xff\\x5c' for vertex z coordinate");
    const std::string long_token(100, '7');
    CHECK(error_of("v 1 2 " + long_token + "x\n") ==
          "test.obj:1: bad number '" + std::string(40, '7') + "...' for vertex z coordinate");
}

TEST_CASE("nan, inf and numbers beyond double range are rejected") {
    CHECK(error_of("v nan 0 0\n") ==
          "test.obj:1: vertex x coordinate 'nan' is not finite (nan and inf are not allowed)");
    CHECK(error_of("v 0 -inf 0\n") ==
          "test.obj:1: vertex y coordinate '-inf' is not finite (nan and inf are not allowed)");
    CHECK(error_of("v 0 0 Infinity\n") ==
          "test.obj:1: vertex z coordinate 'Infinity' is not finite (nan and inf are not allowed)");
    CHECK(error_of("v 0 0 0 nan(1)\n") ==
          "test.obj:1: vertex w coordinate 'nan(1)' is not finite (nan and inf are not allowed)");
    CHECK(error_of("v 1e999 0 0\n") == "test.obj:1: vertex x coordinate '1e999' is out of range for double");
    CHECK(error_of("v 0 -1e-400 0\n") == "test.obj:1: vertex y coordinate '-1e-400' is out of range for double");
}

TEST_CASE("A vertex needs three to four coordinates") {
    CHECK(error_of("v\n") == "test.obj:1: vertex has 0 coordinates, needs at least 3 (x y z [w])");
    CHECK(error_of("v 1\n") == "test.obj:1: vertex has 1 coordinate, needs at least 3 (x y z [w])");
    CHECK(error_of("v 1 2 # 3\n") == "test.obj:1: vertex has 2 coordinates, needs at least 3 (x y z [w])");
    CHECK(error_of("v 1 2 3 4 5\n") == "test.obj:1: vertex has 5 coordinates, at most 4 allowed (x y z [w])");
    CHECK(error_of("v 1 2 3 1 0.5 0.5\n") ==
          "test.obj:1: vertex has 6 coordinates, at most 4 allowed (x y z [w])");
}

TEST_CASE("A w of zero or a divide that overflows is an error") {
    CHECK(error_of("v 1 2 3 0\n") == "test.obj:1: vertex w coordinate is 0");
    CHECK(error_of("v 1 2 3 -0.0\n") == "test.obj:1: vertex w coordinate is 0");
    CHECK(error_of("v 1e300 0 0 1e-300\n") == "test.obj:1: vertex coordinates are not finite after dividing by w");
}

TEST_CASE("Index 0 is rejected for vertices, texture coordinates and normals") {
    CHECK(error_of(kTriangle + "f 0 1 2\n") == "test.obj:4: vertex index 0 is invalid (OBJ indices start at 1)");
    CHECK(error_of(kTriangle + "f 1 -0 2\n") == "test.obj:4: vertex index 0 is invalid (OBJ indices start at 1)");
    CHECK(error_of(kTriangle + "f 1/0 2/1 3/1\n") ==
          "test.obj:4: texture index 0 is invalid (OBJ indices start at 1)");
    CHECK(error_of(kTriangle + "f 1//1 2//0 3//1\n") ==
          "test.obj:4: normal index 0 is invalid (OBJ indices start at 1)");
}

TEST_CASE("An index out of range names the index and the vertices defined so far") {
    std::string cube;
    for (int i = 0; i < 8; ++i) cube += "v 0 0 0\n";
    CHECK(error_of(cube + "f 1 2 12\n") == "test.obj:9: vertex index 12 out of range (8 vertices defined so far)");
    CHECK(error_of(cube + "f -9 1 2\n") == "test.obj:9: vertex index -9 out of range (8 vertices defined so far)");
    CHECK(error_of("v 0 0 0\nf 1 1 2\nv 0 0 0\n") ==
          "test.obj:2: vertex index 2 out of range (1 vertex defined so far)");
    CHECK(error_of("f 1 2 3\n") == "test.obj:1: vertex index 1 out of range (0 vertices defined so far)");
    SUBCASE("huge indices are range errors, not overflow") {
        CHECK(error_of(cube + "f 1 2 99999999999999999999999\n") ==
              "test.obj:9: vertex index 99999999999999999999999 out of range (8 vertices defined so far)");
        CHECK(error_of(cube + "f 1 2 -9223372036854775808/1\n") ==
              "test.obj:9: vertex index -9223372036854775808 out of range (8 vertices defined so far)");
        CHECK(error_of(cube + "f 1 2 4294967297\n") ==
              "test.obj:9: vertex index 4294967297 out of range (8 vertices defined so far)");
        CHECK(error_of(cube + "f 1 2 3/99999999999999999999999/1\n") == "ok");  // t and n are not range-checked
    }
}

TEST_CASE("A malformed face vertex token is an error") {
    for (const char* token : {"1/2/3/4", "a", "1//", "1/", "/1", "//1", "1/a", "1.5", "+-1", "-", "1-", "1//2/",
                              "1e2", "0x1"}) {
        CAPTURE(token);
        CHECK(error_of(kTriangle + "f 1 2 " + token + "\n") == "test.obj:4: malformed face vertex '" +
                                                                    std::string(token) +
                                                                    "' (expected i, i/t, i//n or i/t/n)");
    }
}

TEST_CASE("A UTF-8 byte order mark before the first statement is skipped, and only there") {
    // It hid the first `v` line ("vertex index 3 out of range (2 vertices defined so far)").
    const Parsed p = parse("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK(p.ok);
    CHECK(p.model.vertices.size() == 3);
    CHECK(error_of("v 0 0 0\n\xEF\xBB\xBFv 1 0 0\nv 0 1 0\nf 1 2 3\n") != "ok");  // inside the file it is garbage
}

TEST_CASE("A face needs at least three vertices") {
    CHECK(error_of(kTriangle + "f\n") == "test.obj:4: face has 0 vertices, needs at least 3");
    CHECK(error_of(kTriangle + "f 1\n") == "test.obj:4: face has 1 vertex, needs at least 3");
    CHECK(error_of(kTriangle + "f 1 2 # 3\n") == "test.obj:4: face has 2 vertices, needs at least 3");
}

TEST_CASE("A model without vertices or without faces is an error not tied to a line") {
    CHECK(error_of("") == "test.obj: no vertices");
    CHECK(error_of("# only a comment\n\no empty\n") == "test.obj: no vertices");
    CHECK(error_of(kTriangle) == "test.obj: no faces");
    const Parsed p = parse(kTriangle);
    CHECK(p.err.line == 0);
    CHECK(p.err.file == "test.obj");
    CHECK(p.err.what == "no faces");
}

TEST_CASE("A line longer than 1 MiB is an error, a line of exactly 1 MiB is not") {
    CHECK(hider::tool::kObjMaxLineBytes == 1048576);
    const std::string max_comment = "#" + std::string(hider::tool::kObjMaxLineBytes - 1, 'x');
    CHECK(error_of(kTriangle + max_comment + "\nf 1 2 3\n") == "ok");
    CHECK(error_of(kTriangle + max_comment + "\r\nf 1 2 3\n") == "ok");
    CHECK(error_of(kTriangle + max_comment + "x\nf 1 2 3\n") == "test.obj:4: line longer than 1048576 bytes");
    CHECK(error_of(kTriangle + "f 1 2 3\n" + max_comment + "xx") == "test.obj:5: line longer than 1048576 bytes");
    SUBCASE("a smaller limit is honoured") {
        ObjLimits limits;
        limits.max_line_bytes = 8;
        CHECK(error_of("v 0 0 0\nv 1 0 0\r\nv 0 1 0\nf 1 2 3\n", limits) == "ok");
        CHECK(error_of("v 0 0 0\nv 100 0 0\nf 1 2 3\n", limits) == "test.obj:2: line longer than 8 bytes");
    }
}

TEST_CASE("Vertex and face counts are limited: 2^24 vertices, 2^24 - 1 faces (the largest 24-bit face id)") {
    CHECK(hider::tool::kObjMaxVertices == 16777216u);
    CHECK(hider::tool::kObjMaxFaces == 16777215u);
    // The last face's id must still encode to a colour that is not the background.
    const uint32_t id = hider::tool::kObjMaxFaces;
    CHECK(((id >> 16) & 255u) == 255u);
    CHECK(((id >> 16 & 255u) | (id >> 8 & 255u) | (id & 255u)) != 0u);
    ObjLimits limits;
    limits.max_vertices = 3;
    limits.max_faces = 2;
    CHECK(error_of(kTriangle + "f 1 2 3\nf 3 2 1\n", limits) == "ok");
    CHECK(error_of(kTriangle + "v 1 1 1\n", limits) == "test.obj:4: too many vertices (limit 3)");
    CHECK(error_of(kTriangle + "f 1 2 3\nf 3 2 1\nf 1 2 3\n", limits) == "test.obj:6: too many faces (limit 2)");
    CHECK(error_of(kTriangle + "f 1 2 3\nf 1\nf 1\n", limits) == "test.obj:5: face has 1 vertex, needs at least 3");
}

TEST_CASE("A failed parse empties the output model and a stream read error is reported") {
    Parsed p = parse(kTriangle + "f 1 2 3\n");
    CHECK(p.ok);
    std::istringstream bad(kTriangle + "f 1 2 4\n");
    CHECK_FALSE(hider::tool::parse_obj(bad, "x.obj", p.model, p.err));
    CHECK(p.model.vertices.empty());
    CHECK(p.model.faces.empty());
    std::istringstream broken(kTriangle + "f 1 2 3\n");
    broken.setstate(std::ios::badbit);
    CHECK_FALSE(hider::tool::parse_obj(broken, "x.obj", p.model, p.err));
    CHECK(hider::tool::format(p.err) == "x.obj: read error");
}

TEST_CASE("format writes file:line: what, or file: what when the line is 0") {
    CHECK(hider::tool::format(ObjError{"a.obj", 12, "oops"}) == "a.obj:12: oops");
    CHECK(hider::tool::format(ObjError{"a.obj", 0, "oops"}) == "a.obj: oops");
}

TEST_CASE("load_obj reads the hand-written cube from tests/data/obj") {
    ObjModel model;
    ObjError err;
    CHECK(hider::tool::load_obj(std::string(HIDER_TEST_DATA) + "/obj/cube.obj", model, err));
    CHECK(model.vertices.size() == 8);
    CHECK(vertex_at(model, 6) == std::array<double, 3>{1.0, 1.0, 1.0});
    CHECK(model.faces.size() == 6);
    CHECK(face_at(model, 0).v == Ints{0, 3, 2, 1});
    CHECK(face_at(model, 5).v == Ints{1, 2, 6, 5});
    for (std::size_t i = 0; i < model.faces.size(); ++i) {
        CHECK(model.faces[i].id == i + 1);
        CHECK(model.faces[i].line == static_cast<int>(21 + i));
    }
}

TEST_CASE("load_obj reports the path and line of an error in a file") {
    const std::string path = std::string(HIDER_TEST_DATA) + "/obj/bad_face.obj";
    ObjModel model;
    ObjError err;
    CHECK_FALSE(hider::tool::load_obj(path, model, err));
    CHECK(hider::tool::format(err) == path + ":5: vertex index 4 out of range (3 vertices defined so far)");
}

TEST_CASE("load_obj on a missing file or a directory fails with the system's reason") {
    ObjModel model;
    ObjError err;
    const std::string missing = std::string(HIDER_TEST_DATA) + "/obj/does_not_exist.obj";
    CHECK_FALSE(hider::tool::load_obj(missing, model, err));
    CHECK(err.line == 0);
    CHECK(hider::tool::format(err) == missing + ": cannot open file: No such file or directory");
    const std::string folder = std::string(HIDER_TEST_DATA) + "/obj";
    CHECK_FALSE(hider::tool::load_obj(folder, model, err));
    CHECK(hider::tool::format(err) == folder + ": cannot open file: Is a directory");
}

TEST_CASE("A bunny-sized grid of 36k vertices and 72k triangles loads completely") {
    constexpr int kSide = 190;
    std::string text;
    text.reserve(4u << 20);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            text += "v " + std::to_string(x * 0.001) + " " + std::to_string(y * 0.001) + " 0.0125\n";
        }
    }
    for (int y = 0; y + 1 < kSide; ++y) {
        for (int x = 0; x + 1 < kSide; ++x) {
            const int i = y * kSide + x + 1;
            text += "f " + std::to_string(i) + " " + std::to_string(i + 1) + " " + std::to_string(i + kSide) + "\n";
            text += "f " + std::to_string(i + 1) + "/1 " + std::to_string(i + kSide + 1) + "//1 " +
                    std::to_string(i + kSide) + "/1/1\n";
        }
    }
    const Parsed p = parse(text);
    CHECK(p.ok);
    CHECK(p.model.vertices.size() == 36100);
    CHECK(p.model.faces.size() == 2u * 189u * 189u);
    const ObjFace last = face_at(p.model, p.model.faces.size() - 1);
    CHECK(last.v == Ints{kSide * kSide - 1 - kSide, kSide * kSide - 1, kSide * kSide - 2});
    CHECK(last.id == 2u * 189u * 189u);
}

TEST_CASE("Mutated OBJ text either parses with every index in range or fails with a message") {
    const std::string base =
        "# fuzz seed\r\nmtllib m.mtl\nv 0 0 0\nv 1.5 0 0 1\nv 0 1e0 -0.25\nv 1 1 1 2\n"
        "vt 0 0\nvn 0 0 1\ng a b\nf 1 2 3\nf 1/1 2/1 3/1\nf 2//1 4//1 3//1\nf -4/1/1 -3/1/1 -1/1/1 -2/1/1\n"
        "usemtl x\ns 1\n\tf 1 2 3 4 # quad\n";
    static const char kBytes[] = {'0', '1', '9', ' ', '/', '-', '+', '.', 'e', '#', 'v', 'f', '\n', '\r', '\t', '\0',
                                  'x', 'n', 'i', '\xff'};
    static const char* const kTokens[] = {"-99", "1e999", "nan", "99999999999999999999", "//", " f 1 2 3\n",
                                          "\nv 1 2 3 0\n", "0x1p3", "-0", "inf"};
    std::mt19937 rng(0x0b1e5eedu);
    int parsed = 0;
    int rejected = 0;
    int broken = 0;
    std::string first_broken;
    for (int iteration = 0; iteration < 4000; ++iteration) {
        std::string text = base;
        const unsigned edits = 1 + rng() % 4;
        for (unsigned e = 0; e < edits; ++e) {
            const std::size_t pos = text.empty() ? 0 : rng() % (text.size() + 1);
            switch (rng() % 5) {
            case 0: if (pos < text.size()) text[pos] = static_cast<char>(rng() & 0xff); break;
            case 1: text.insert(pos, 1, kBytes[rng() % sizeof(kBytes)]); break;
            case 2: if (pos < text.size()) text.erase(pos, 1); break;
            case 3: text.resize(pos); break;
            default: text.insert(pos, kTokens[rng() % (sizeof(kTokens) / sizeof(kTokens[0]))]); break;
            }
        }
        std::istringstream in(text);
        ObjModel model;
        ObjError err;
        bool sound = true;
        if (hider::tool::parse_obj(in, "fuzz.obj", model, err)) {
            ++parsed;
            sound = !model.vertices.empty() && !model.faces.empty();
            for (const auto& vertex : model.vertices) {
                for (const double c : vertex) sound = sound && std::isfinite(c);
            }
            for (std::size_t i = 0; i < model.faces.size(); ++i) {
                const auto& f = model.faces[i];
                sound = sound && f.v.size() >= 3 && f.line >= 1 && (i == 0 || f.id > model.faces[i - 1].id);
                for (const int32_t index : f.v) {
                    sound = sound && index >= 0 && static_cast<std::size_t>(index) < model.vertices.size();
                }
            }
        } else {
            ++rejected;
            sound = !err.what.empty() && err.file == "fuzz.obj" && err.line >= 0 && model.vertices.empty() &&
                    model.faces.empty();
        }
        if (!sound && broken++ == 0) first_broken = text;
    }
    INFO("first unsound input: ", first_broken);
    CHECK(broken == 0);
    CHECK(parsed > 100);
    CHECK(rejected > 100);
}

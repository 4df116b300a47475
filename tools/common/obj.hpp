// Strict Wavefront OBJ reader for host tools: vertex positions (`v`) and polygon faces (`f`) only,
// with face indices resolved to 0-based vertex indices. Coordinates are double, in file units.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

// Accepted input (anything else on a `v` or `f` line is an error, never a guess):
//   v x y z [w]    numbers in strtod syntax (sign, exponent, hex floats), parsed locale-independently;
//                  nan, inf and values outside double range (overflow, or underflow such as 1e-400) are
//                  rejected; w != 1 divides x, y, z by w, and w == 0 is rejected.
//   f a b c ...    three or more of i, i/t, i//n, i/t/n; negative i counts back from the last `v` so far.
//                  Texture (t) and normal (n) indices are syntax-checked and must be non-zero, then dropped.
// Ignored: comments (`#` to end of line, also after data), blank lines, leading blanks and tabs, CRLF,
// and every other keyword (vt, vn, vp, o, g, s, l, p, usemtl, mtllib, ...). Unknown keywords are ignored
// too, so files from newer exporters still load; only `v` and `f` are parsed, and parsed strictly.
namespace hider::tool {

inline constexpr std::size_t kObjMaxLineBytes = std::size_t{1} << 20;  ///< longest line, '\n' and '\r' excluded
inline constexpr uint32_t kObjMaxVertices = uint32_t{1} << 24;         ///< most `v` lines in one file
/// Most `f` lines in one file: face ids are 24-bit colours in id images (--shade id) and 0 is the background.
inline constexpr uint32_t kObjMaxFaces = (uint32_t{1} << 24) - 1;

/// Input limits: the defaults are the project's and also the maximum (larger values are cut to them);
/// smaller ones let tests reach each limit cheaply.
struct ObjLimits {
    std::size_t max_line_bytes = kObjMaxLineBytes;
    uint32_t max_vertices = kObjMaxVertices;
    uint32_t max_faces = kObjMaxFaces;
};

struct ObjFace {
    std::vector<int32_t> v;  // 0-based indices into ObjModel::vertices, in file order (>= 3 of them)
    uint32_t id = 0;         // 1-based index of this `f` line among all `f` lines of the file
    int line = 0;            // 1-based line number of the `f` line
};

struct ObjModel {
    std::vector<std::array<double, 3>> vertices;  // x, y, z after the optional divide by w
    std::vector<ObjFace> faces;                   // one per `f` line, polygons kept whole (not triangulated)
};

struct ObjError {
    std::string file;  // path or stream name given by the caller
    int line = 0;      // 1-based line number; 0 = not tied to a line
    std::string what;  // one-line reason, no trailing newline
};

/// Reads the OBJ file at `path` into `out`; on failure fills `err`, leaves `out` empty and returns false.
bool load_obj(const std::string& path, ObjModel& out, ObjError& err);

/// Face f's vertices relative to its first, scaled by their largest offset (no overflow or underflow at any
/// model size; rounding relative to the face), into p, and their Newell normal (twice the polygon's vector
/// area) into n. False, p and n unspecified, when the vertices coincide or the offsets do not fit a double.
bool scaled_face(const ObjModel& model, const ObjFace& f, std::vector<std::array<double, 3>>& p, std::array<double, 3>& n);

/// Faces of more than 3 vertices whose fan from the first vertex (how every tool triangulates) does not
/// cover the polygon: a fan triangle turns against the polygon's (Newell) normal, so the fan paints outside
/// a concave face. Their `f` line numbers, in file order, for a warning.
std::vector<int> badly_fanned_faces(const ObjModel& model);

/// One warning line per face line (at most 5, then a count): "path:line: what".
std::vector<std::string> face_warnings(const std::string& path, const std::vector<int>& lines, const std::string& what);

/// face_warnings() for badly_fanned_faces(): "path:line: face ... (triangulate it)".
std::vector<std::string> fan_warnings(const std::string& path, const std::vector<int>& lines);

/// Reads OBJ text from `in` (named `name` in errors) into `out`; on failure fills `err`, leaves `out`
/// empty and returns false. Cost O(bytes read); memory O(model) plus one line of at most limits.max_line_bytes.
bool parse_obj(std::istream& in, const std::string& name, ObjModel& out, ObjError& err,
               const ObjLimits& limits = ObjLimits{});

/// Formats `e` as "file:line: what", or "file: what" when e.line == 0.
std::string format(const ObjError& e);

/// `token` as a message shows it: non-printable bytes as \xNN, more than 40 bytes cut with "...".
std::string printable_token(std::string_view token);

}  // namespace hider::tool

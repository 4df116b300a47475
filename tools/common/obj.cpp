// Strict Wavefront OBJ reader (see obj.hpp for the accepted syntax). Reads the stream in fixed-size
// chunks so a line is bounded before it is stored, and parses numbers with std::from_chars ("C" syntax).
#include "common/obj.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <string_view>
#include <system_error>
#include <utility>

namespace hider::tool {

constexpr std::size_t kPrintableTokenBytes = 40;  // longer tokens are cut in messages

std::string printable_token(std::string_view token) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string s;
    const std::size_t length = token.size() < kPrintableTokenBytes ? token.size() : kPrintableTokenBytes;
    for (std::size_t i = 0; i < length; ++i) {
        const auto byte = static_cast<unsigned char>(token[i]);
        if (byte >= 0x20 && byte < 0x7f && byte != '\\') {
            s += static_cast<char>(byte);
        } else {
            s += "\\x";
            s += kHex[byte >> 4];
            s += kHex[byte & 0xf];
        }
    }
    if (length < token.size()) s += "...";
    return s;
}

namespace {

constexpr std::size_t kChunkBytes = std::size_t{1} << 16;  // stream read size
constexpr int64_t kIndexSaturation = (INT64_MAX - 9) / 10;  // past this, one more digit could overflow

bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// Pops the next blank-separated token from the front of `rest`; empty when none is left.
std::string_view next_token(std::string_view& rest) {
    std::size_t begin = 0;
    while (begin < rest.size() && is_blank(rest[begin])) ++begin;
    std::size_t end = begin;
    while (end < rest.size() && !is_blank(rest[end])) ++end;
    const std::string_view token = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return token;
}

std::string quoted(std::string_view token) { return "'" + printable_token(token) + "'"; }

std::string count_of(uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

enum class NumberStatus { ok, malformed, out_of_range, not_finite };

/// Parses a whole token as a double in strtod syntax, minus locale: [+-] then decimal, inf/nan or 0x hex.
NumberStatus parse_double(std::string_view token, double& value) {
    bool negative = false;
    if (!token.empty() && (token[0] == '+' || token[0] == '-')) {
        negative = token[0] == '-';
        token.remove_prefix(1);
    }
    auto format = std::chars_format::general;
    if (token.size() > 2 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X')) {
        format = std::chars_format::hex;
        token.remove_prefix(2);
    }
    // from_chars takes a '-' of its own, so a second sign ("--1", "0x-1") must be refused here.
    if (token.empty() || token[0] == '+' || token[0] == '-') return NumberStatus::malformed;
    const char* end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value, format);
    if (result.ec == std::errc::result_out_of_range && result.ptr == end) return NumberStatus::out_of_range;
    if (result.ec != std::errc{} || result.ptr != end) return NumberStatus::malformed;
    if (!std::isfinite(value)) return NumberStatus::not_finite;
    if (negative) value = -value;
    return NumberStatus::ok;
}

/// Parses [+-]digits into `value`; huge magnitudes saturate near INT64_MAX, so they stay defined and out of range.
bool parse_index(std::string_view text, int64_t& value) {
    bool negative = false;
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
        negative = text[0] == '-';
        text.remove_prefix(1);
    }
    if (text.empty()) return false;
    int64_t magnitude = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return false;
        if (magnitude <= kIndexSaturation) magnitude = magnitude * 10 + (c - '0');
    }
    value = negative ? -magnitude : magnitude;
    return true;
}

enum class ReadStatus { line, end, too_long, failed };

/// Splits a stream into lines without '\n' or a trailing '\r', refusing lines over a byte limit.
class LineReader {
public:
    LineReader(std::istream& in, std::size_t max_bytes) : in_(in), max_bytes_(max_bytes), chunk_(kChunkBytes) {}

    /// Reads the next line into `line`; the view stays valid until the next call.
    ReadStatus next(std::string_view& line) {
        pending_.clear();
        for (;;) {
            if (pos_ == size_) {
                if (!refill()) return ReadStatus::failed;
                if (size_ == 0) {  // end of input: an unterminated last line still counts
                    if (pending_.empty()) return ReadStatus::end;
                    return finish(pending_, line);
                }
            }
            const char* begin = chunk_.data() + pos_;
            const std::size_t available = size_ - pos_;
            const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', available));
            const std::size_t take = newline ? static_cast<std::size_t>(newline - begin) : available;
            // One byte of slack lets a maximal line keep its '\r' until finish() strips it.
            if (pending_.size() + take > max_bytes_ + 1) return ReadStatus::too_long;
            pos_ += newline ? take + 1 : take;
            if (!newline) {
                pending_.append(begin, take);
            } else if (pending_.empty()) {
                return finish(std::string_view(begin, take), line);  // whole line inside the chunk: no copy
            } else {
                pending_.append(begin, take);
                return finish(pending_, line);
            }
        }
    }

private:
    ReadStatus finish(std::string_view text, std::string_view& line) const {
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        if (text.size() > max_bytes_) return ReadStatus::too_long;
        line = text;
        return ReadStatus::line;
    }

    bool refill() {
        pos_ = 0;
        size_ = 0;
        if (at_end_) return true;
        in_.read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
        size_ = static_cast<std::size_t>(in_.gcount());
        if (in_.bad()) return false;
        if (size_ < chunk_.size()) at_end_ = true;
        return true;
    }

    std::istream& in_;
    std::size_t max_bytes_;
    std::vector<char> chunk_;
    std::size_t pos_ = 0;
    std::size_t size_ = 0;
    bool at_end_ = false;
    std::string pending_;  // a line that spans chunks
};

/// Line-by-line parser state; every fail() sets the error and returns false so callers can return it.
class Parser {
public:
    Parser(const std::string& name, const ObjLimits& limits, ObjError& err)
        : name_(name), limits_(clamped(limits)), err_(err) {}

    bool run(std::istream& in) {
        LineReader reader(in, limits_.max_line_bytes);
        std::string_view text;
        for (;;) {
            const ReadStatus status = reader.next(text);
            if (status == ReadStatus::end) break;
            if (status == ReadStatus::failed) return fail(0, "read error");
            if (line_ == INT_MAX) return fail(0, "too many lines (limit " + std::to_string(INT_MAX) + ")");
            ++line_;
            if (status == ReadStatus::too_long) {
                return fail(line_, "line longer than " + std::to_string(limits_.max_line_bytes) + " bytes");
            }
            // A UTF-8 byte order mark (some Windows editors write one) hid the first statement.
            if (line_ == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
            if (!parse_line(text)) return false;
        }
        if (model_.vertices.empty()) return fail(0, "no vertices");
        if (model_.faces.empty()) return fail(0, "no faces");
        return true;
    }

    ObjModel& model() { return model_; }

private:
    /// Limits above the defaults are cut to them, so indices always fit int32_t and sizes never wrap.
    static ObjLimits clamped(ObjLimits limits) {
        if (limits.max_line_bytes > kObjMaxLineBytes) limits.max_line_bytes = kObjMaxLineBytes;
        if (limits.max_vertices > kObjMaxVertices) limits.max_vertices = kObjMaxVertices;
        if (limits.max_faces > kObjMaxFaces) limits.max_faces = kObjMaxFaces;
        return limits;
    }

    bool fail(int line, std::string what) {
        err_.file = name_;
        err_.line = line;
        err_.what = std::move(what);
        return false;
    }

    bool parse_line(std::string_view text) {
        const std::size_t hash = text.find('#');
        if (hash != std::string_view::npos) text = text.substr(0, hash);
        const std::string_view keyword = next_token(text);
        if (keyword == "v") return parse_vertex(text);
        if (keyword == "f") return parse_face(text);
        return true;  // blank, comment, or a keyword this reader ignores
    }

    bool parse_vertex(std::string_view rest) {
        static constexpr const char* kAxis[] = {"x", "y", "z", "w"};
        std::array<double, 4> c{0.0, 0.0, 0.0, 1.0};
        std::size_t count = 0;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
            if (count == c.size()) {
                while (!next_token(rest).empty()) ++count;  // count the rest for the message
                return fail(line_, "vertex has " + std::to_string(count + 1) +
                                       " coordinates, at most 4 allowed (x y z [w])");
            }
            if (!parse_coordinate(token, kAxis[count], c[count])) return false;
            ++count;
        }
        if (count < 3) {
            return fail(line_, "vertex has " + count_of(count, "coordinate", "coordinates") +
                                   ", needs at least 3 (x y z [w])");
        }
        if (c[3] == 0.0) return fail(line_, "vertex w coordinate is 0");
        if (c[3] != 1.0) {
            for (std::size_t i = 0; i < 3; ++i) c[i] /= c[3];
            if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
                return fail(line_, "vertex coordinates are not finite after dividing by w");
            }
        }
        if (model_.vertices.size() >= limits_.max_vertices) {
            return fail(line_, "too many vertices (limit " + std::to_string(limits_.max_vertices) + ")");
        }
        model_.vertices.push_back({c[0], c[1], c[2]});
        return true;
    }

    bool parse_coordinate(std::string_view token, const char* axis, double& value) {
        const std::string what = std::string("vertex ") + axis + " coordinate";
        switch (parse_double(token, value)) {
        case NumberStatus::ok: return true;
        case NumberStatus::malformed: return fail(line_, "bad number " + quoted(token) + " for " + what);
        case NumberStatus::out_of_range:
            return fail(line_, what + " " + quoted(token) + " is out of range for double");
        case NumberStatus::not_finite:
            return fail(line_, what + " " + quoted(token) + " is not finite (nan and inf are not allowed)");
        }
        return fail(line_, "bad number " + quoted(token) + " for " + what);
    }

    bool parse_face(std::string_view rest) {
        if (face_count_ >= limits_.max_faces) {
            return fail(line_, "too many faces (limit " + std::to_string(limits_.max_faces) + ")");
        }
        ObjFace face;
        face.id = ++face_count_;
        face.line = line_;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
            int32_t index = 0;
            if (!parse_face_vertex(token, index)) return false;
            face.v.push_back(index);
        }
        if (face.v.size() < 3) {
            return fail(line_, "face has " + count_of(face.v.size(), "vertex", "vertices") + ", needs at least 3");
        }
        model_.faces.push_back(std::move(face));
        return true;
    }

    /// Checks one i, i/t, i//n or i/t/n token and resolves i against the vertices defined so far.
    bool parse_face_vertex(std::string_view token, int32_t& index) {
        std::string_view part[3];
        std::size_t parts = 0;
        std::string_view rest = token;
        for (;;) {
            if (parts == 3) return fail_malformed(token);
            const std::size_t slash = rest.find('/');
            part[parts++] = rest.substr(0, slash);
            if (slash == std::string_view::npos) break;
            rest.remove_prefix(slash + 1);
        }
        // Only t may be empty, and only in i//n.
        int64_t value[3] = {0, 0, 0};
        for (std::size_t i = 0; i < parts; ++i) {
            if (i == 1 && parts == 3 && part[i].empty()) continue;
            if (!parse_index(part[i], value[i])) return fail_malformed(token);
        }
        if (value[0] == 0) return fail(line_, "vertex index 0 is invalid (OBJ indices start at 1)");
        if (parts >= 2 && !part[1].empty() && value[1] == 0) {
            return fail(line_, "texture index 0 is invalid (OBJ indices start at 1)");
        }
        if (parts == 3 && value[2] == 0) return fail(line_, "normal index 0 is invalid (OBJ indices start at 1)");
        return resolve(part[0], value[0], index);
    }

    bool resolve(std::string_view text, int64_t value, int32_t& index) {
        const auto defined = static_cast<int64_t>(model_.vertices.size());
        const int64_t resolved = value > 0 ? value - 1 : defined + value;
        if (resolved < 0 || resolved >= defined) {
            return fail(line_, "vertex index " + printable_token(text) + " out of range (" +
                                   count_of(static_cast<uint64_t>(defined), "vertex", "vertices") +
                                   " defined so far)");
        }
        index = static_cast<int32_t>(resolved);  // < vertices.size() <= kObjMaxVertices, so it fits
        return true;
    }

    bool fail_malformed(std::string_view token) {
        return fail(line_, "malformed face vertex " + quoted(token) + " (expected i, i/t, i//n or i/t/n)");
    }

    const std::string& name_;
    const ObjLimits limits_;
    ObjError& err_;
    ObjModel model_;
    int line_ = 0;
    uint32_t face_count_ = 0;
};

}  // namespace

bool parse_obj(std::istream& in, const std::string& name, ObjModel& out, ObjError& err, const ObjLimits& limits) {
    Parser parser(name, limits, err);
    if (!parser.run(in)) {
        out = ObjModel{};
        return false;
    }
    out = std::move(parser.model());
    return true;
}

bool load_obj(const std::string& path, ObjModel& out, ObjError& err) {
    struct stat st {};  // POSIX stat: the WebAssembly build's libc++ has no <filesystem>
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {  // a directory opens on Linux, then fails to read
        out = ObjModel{};
        err = ObjError{path, 0, "cannot open file: " + std::string(std::strerror(EISDIR))};
        return false;
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int code = errno;
        out = ObjModel{};
        err = ObjError{path, 0, code != 0 ? "cannot open file: " + std::string(std::strerror(code))
                                          : std::string("cannot open file")};
        return false;
    }
    return parse_obj(in, path, out, err);
}

std::string format(const ObjError& e) {
    if (e.line == 0) return e.file + ": " + e.what;
    return e.file + ":" + std::to_string(e.line) + ": " + e.what;
}

bool scaled_face(const ObjModel& model, const ObjFace& f, std::vector<std::array<double, 3>>& p, std::array<double, 3>& n) {
    const auto& o = model.vertices[static_cast<size_t>(f.v[0])];
    double scale = 0;
    p.clear();
    for (const int32_t i : f.v) {
        const auto& v = model.vertices[static_cast<size_t>(i)];
        p.push_back({v[0] - o[0], v[1] - o[1], v[2] - o[2]});
        for (const double c : p.back()) scale = std::max(scale, std::fabs(c));
    }
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    for (auto& q : p)
        for (double& c : q) c /= scale;
    n = {0, 0, 0};
    for (size_t i = 0; i < p.size(); ++i) {
        const auto& a = p[i];
        const auto& b = p[(i + 1) % p.size()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    return true;
}

std::vector<int> badly_fanned_faces(const ObjModel& model) {
    std::vector<int> lines;
    std::vector<std::array<double, 3>> p;
    std::array<double, 3> n{};
    for (const ObjFace& f : model.faces) {
        if (f.v.size() <= 3 || !scaled_face(model, f, p, n)) continue;
        const double n_len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        bool against = false;
        for (size_t i = 1; i + 1 < p.size() && !against; ++i) {
            const auto& u = p[i];
            const auto& w = p[i + 1];
            const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
            const double d = c[0] * n[0] + c[1] * n[1] + c[2] * n[2];
            const double u_len = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            const double w_len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            // Clearly turned back, not the rounding of a fan triangle whose vertices are collinear.
            against = d < -1e-9 * u_len * w_len * n_len;
        }
        if (against) lines.push_back(f.line);
    }
    return lines;
}

std::vector<std::string> face_warnings(const std::string& path, const std::vector<int>& lines, const std::string& what) {
    std::vector<std::string> out;
    for (size_t i = 0; i < lines.size() && i < 5; ++i) out.push_back(path + ":" + std::to_string(lines[i]) + ": " + what);
    if (lines.size() > 5) out.push_back(path + ": " + std::to_string(lines.size() - 5) + " more such faces");
    return out;
}

std::vector<std::string> fan_warnings(const std::string& path, const std::vector<int>& lines) {
    return face_warnings(path, lines, "face is not convex from its first vertex: its fan covers area outside it (triangulate it)");
}

}  // namespace hider::tool

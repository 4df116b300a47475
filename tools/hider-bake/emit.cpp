// Writes a baked scene header: camera and frame size, then positions (raw Q16), triangles (uint16
// indices), unit normals (Q14) and, only if they are not the default, face ids. Fixed line layout,
// so the same Scene always gives the same bytes.
#include "hider-bake/emit.hpp"

#include <cstdio>
#include <set>
#include <sstream>

namespace hider::tool::bake {
namespace {

// What the baked headers (hider-bake, hider-bake-ray, hider-bsp) name without qualification, the
// namespaces they open, the <stdint.h>/<stddef.h> types, and macros GNU C++ predefines in lower case.
// A namespace hider::scenes::NAME or hider::bsp_data::NAME of one of these breaks its own header or
// one included beside it (--name ray: every ray-baked header's ray::Surface).
const std::set<std::string> kReserved = {
    "hider", "scenes", "bsp_data", "ray", "std", "Angle", "Camera", "Light", "LightKind", "Mesh", "MeshObject",
    "Normal14", "Plane", "Q14", "Q16", "Q30", "Scene", "ScreenVertex", "Sphere", "Surface", "Tri", "Vec3q16",
    "BvhHeader", "BvhNode", "BvhTriangles", "Span", "int8_t", "int16_t", "int32_t", "int64_t", "uint8_t",
    "uint16_t", "uint32_t", "uint64_t", "size_t", "ptrdiff_t", "intptr_t", "uintptr_t", "linux", "unix",
    "i386", "errno", "assert", "offsetof"};

// C++17 keywords and alternative tokens: none of them can name a namespace.
const std::set<std::string> kKeywords = {
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
    "char", "char16_t", "char32_t", "class", "compl", "const", "constexpr", "const_cast", "continue", "decltype",
    "default", "delete", "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false",
    "float", "for", "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept",
    "not", "not_eq", "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register",
    "reinterpret_cast", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
    "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union",
    "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq"};

std::string q16(Q16 v) { return "Q16::from_raw(" + std::to_string(v.raw()) + ")"; }

std::string vec(const Vec3q16& v) { return "{" + q16(v.x) + ", " + q16(v.y) + ", " + q16(v.z) + "}"; }

std::string hex32(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08Xu", static_cast<unsigned>(v));
    return buf;
}

bool default_ids(const Scene& s) {
    for (size_t i = 0; i < s.ids.size(); ++i)
        if (s.ids[i] != i + 1) return false;
    return true;
}

/// Writes `count` items, `per_line` to a line, each followed by a comma.
template <class Fn>
void rows(std::ostringstream& o, size_t count, size_t per_line, Fn&& item) {
    for (size_t i = 0; i < count; ++i) {
        o << (i % per_line == 0 ? "    " : " ") << item(i) << ",";
        if (i % per_line == per_line - 1 || i + 1 == count) o << "\n";
    }
}

void emit_camera(std::ostringstream& o, const Camera& c) {
    o << "/// gluLookAt + gluPerspective camera for a kWidth x kHeight frame (make_view()).\n"
      << "inline constexpr Camera kCamera{\n"
      << "    " << vec(c.eye) << ",  // eye\n"
      << "    " << vec(c.target) << ",  // target\n"
      << "    " << vec(c.up) << ",  // up\n"
      << "    Angle::from_bam(" << hex32(c.fovy.bam()) << "),  // vertical field of view\n"
      << "    " << q16(c.near) << ",  // near\n"
      << "    " << q16(c.far) << ",  // far\n"
      << "};\n\n";
}

void count_check(std::ostringstream& o, const char* array, const char* count) {
    o << "static_assert(sizeof(" << array << ") / sizeof(" << array << "[0]) == " << count << ", \"" << array
      << " has the wrong length\");\n\n";
}

}  // namespace

std::string comment_text(const std::string& text) {
    std::string out = text;
    for (char& c : out) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) c = '?';
    }
    return out;
}

std::string camera_source(const Camera& camera, int width, int height) {
    std::ostringstream o;
    o << "inline constexpr int32_t kWidth = " << width << ";\n"
      << "inline constexpr int32_t kHeight = " << height << ";\n\n";
    emit_camera(o, camera);
    return o.str();
}

bool valid_name(const std::string& name, std::string& why) {
    auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (name.empty() || !alpha(name[0])) {
        why = "must start with a letter or '_'";
        return false;
    }
    for (char c : name)
        if (!alpha(c) && !digit(c)) {
            why = "may hold only letters, digits and '_'";
            return false;
        }
    if (name.find("__") != std::string::npos || (name[0] == '_' && name.size() > 1 && name[1] >= 'A' && name[1] <= 'Z')) {
        why = "is reserved in C++ ('__' anywhere, or '_' then a capital letter)";
        return false;
    }
    if (kKeywords.count(name) != 0) {
        why = "is a C++ keyword";
        return false;
    }
    if (kReserved.count(name) != 0) {
        why = "is a name the generated headers use unqualified (inside namespace ...::" + name +
              " it would mean that namespace, there or in another baked header); choose another";
        return false;
    }
    bool capitals = true;  // the macro convention: NULL, INT32_MAX, a project's own macros
    for (char c : name) capitals = capitals && !(c >= 'a' && c <= 'z');
    if (capitals) {
        why = "is all capitals, as macros are named (NULL, INT32_MAX); choose a name with a lower-case letter";
        return false;
    }
    return true;
}

std::string emit_header(const Scene& s, const BakeInfo& info) {
    const bool with_ids = !default_ids(s);
    const size_t nv = s.positions.size(), nt = s.tris.size();
    std::ostringstream o;
    o << "// " << info.name << ": baked by hider-bake from " << info.model << "; do not edit, re-bake instead.\n"
      << "// Options: " << (info.options.empty() ? "(defaults)" : info.options) << "\n"
      << "// " << nv << " vertices, " << nt << " triangles; flash: positions " << nv * sizeof(Vec3q16)
      << " B, triangles " << nt * sizeof(Tri) << " B, normals " << nt * sizeof(Normal14) << " B, ids "
      << (with_ids ? nt * sizeof(uint32_t) : 0) << " B.\n"
      << "// World units as hider-render uses them (scene fitted into +-512 units); values are raw Q16/Q14.\n"
      << "#pragma once\n#include <hider/mesh.hpp>\n\n"
      << "namespace hider::scenes::" << info.name << " {\n\n"
      << "inline constexpr int32_t kWidth = " << s.width << ";\n"
      << "inline constexpr int32_t kHeight = " << s.height << ";\n"
      << "inline constexpr size_t kVertexCount = " << nv << ";\n"
      << "inline constexpr size_t kTriangleCount = " << nt << ";\n\n";

    emit_camera(o, s.camera);
    o << "inline constexpr Vec3q16 kPositions[] = {\n";
    rows(o, nv, 1, [&](size_t i) { return vec(s.positions[i]); });
    o << "};\n";
    count_check(o, "kPositions", "kVertexCount");

    o << "inline constexpr Tri kTris[] = {\n";
    rows(o, nt, 6, [&](size_t i) {
        const Tri& t = s.tris[i];
        return "{{" + std::to_string(t.v[0]) + ", " + std::to_string(t.v[1]) + ", " + std::to_string(t.v[2]) + "}}";
    });
    o << "};\n";
    count_check(o, "kTris", "kTriangleCount");

    o << "/// Unit face normals, Q14 (one per triangle).\n"
      << "inline constexpr Normal14 kNormals[] = {\n";
    rows(o, nt, 6, [&](size_t i) {
        const Normal14& n = s.normals[i];
        return "{" + std::to_string(n.x) + ", " + std::to_string(n.y) + ", " + std::to_string(n.z) + "}";
    });
    o << "};\n";
    count_check(o, "kNormals", "kTriangleCount");

    if (with_ids) {
        o << "/// Face ids (the 1-based OBJ face each triangle came from).\n"
          << "inline constexpr uint32_t kIds[] = {\n";
        rows(o, nt, 10, [&](size_t i) { return std::to_string(s.ids[i]); });
        o << "};\n";
        count_check(o, "kIds", "kTriangleCount");
        o << "/// The mesh over the arrays above (borrowed, in flash).\n"
          << "constexpr Mesh mesh() { return {kPositions, kTris, kNormals, kIds}; }\n\n";
    } else {
        o << "/// The mesh over the arrays above (borrowed, in flash); face ids are the default, index + 1.\n"
          << "constexpr Mesh mesh() { return {kPositions, kTris, kNormals, {}}; }\n\n";
    }
    o << "}  // namespace hider::scenes::" << info.name << "\n";
    return o.str();
}

}  // namespace hider::tool::bake

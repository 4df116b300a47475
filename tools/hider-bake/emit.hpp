// hider-bake's output: a Scene (as build_scene fitted it) written as a C++17 header of constexpr arrays
// that firmware keeps in flash. Includes only <hider/mesh.hpp>; deterministic (no dates, no paths).
#pragma once

#include <string>

#include "common/scene.hpp"

namespace hider::tool::bake {

/// What the header records about how it was made (shown in its opening comment only).
struct BakeInfo {
    std::string name;       ///< C++ identifier: the header's namespace is hider::scenes::<name>
    std::string model;      ///< model file name without directories
    std::string options;    ///< the camera options as given, space-separated
};

/// Whether `name` is usable as the namespace of a baked scene: an identifier, no "__", not a keyword, not
/// a name the baked headers use unqualified (kReserved: Camera, ray, uint8_t, ...), not all capitals (macros).
bool valid_name(const std::string& name, std::string& why);

/// `text` (a file name) made safe for a `//` comment line of a generated header: every control
/// character (a newline or carriage return in a file name would end the comment and leave the rest of
/// the name as code) and DEL becomes '?'.
std::string comment_text(const std::string& text);


/// `kWidth`, `kHeight` and `kCamera` (a constexpr hider::Camera) as declarations for a baked header.
std::string camera_source(const Camera& camera, int width, int height);

/// The header text for `scene`. Ids are written only when some id differs from triangle index + 1
/// (lib/'s default), so a typical OBJ of triangles costs no flash for them.
std::string emit_header(const Scene& scene, const BakeInfo& info);

}  // namespace hider::tool::bake

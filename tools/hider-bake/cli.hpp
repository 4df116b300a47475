// Command-line camera options shared by hider-bake and its round-trip check, with hider-render's
// syntax and limits: --size WxH, --eye/--target/--up x,y,z, --fov DEG, --near N, --far F.
#pragma once

#include <string>

#include "common/scene.hpp"

namespace hider::tool::bake {

/// Prints "<program>: <msg>" on stderr and exits with status 2.
[[noreturn]] void fail(const std::string& program, const std::string& msg);

/// If argv[i] is a camera option, parses it and its value into `cam`, appends "option value" to
/// `recorded` (space-separated), advances i past the value and returns true. Bad values fail().
bool parse_camera_option(const std::string& program, int argc, char** argv, int& i, CameraArgs& cam,
                         std::string& recorded);

}  // namespace hider::tool::bake

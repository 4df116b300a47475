// Command-line number parsing shared by hider-render, hider-bake and hider-bench: strict (the whole
// token must be a number), locale-independent for what the tools accept, no exceptions.
#pragma once
#include <string>

#include "common/scene.hpp"

namespace hider::tool {

/// strtod syntax, the whole string, finite (an underflow to a denormal or 0 included). False on anything else.
bool parse_double(const std::string& s, double& out);

/// Makes an allocation that fails print "<tool>: out of memory" and exit with status 2 (the tools are
/// built without exceptions: std::bad_alloc would abort), and an exit whose standard output could not be
/// written (a full disk, /dev/full) print "<tool>: cannot write standard output" and exit 2. Call first
/// in main().
void exit_2_when_out_of_memory(const char* tool);

/// Decimal integer (optional '-'), the whole string, in range of long. False on anything else.
bool parse_int(const std::string& s, long& out);

/// The image format of an output path by its extension, case-insensitively: .ppm (png = false) or .png
/// (png = true); PPM for a path under /dev/ (/dev/stdout) or a pipe. False with the user message for any other.
bool output_format(const std::string& path, bool& png, std::string& why);

/// True when `a` and `b` name the same existing file (device and inode): an output that would overwrite
/// the tool's input.
bool same_file(const std::string& a, const std::string& b);

/// True when `path` ends with `ext` (given in lower case, dot included) in any case: "T.HBSP" has ".hbsp".
bool has_extension(const std::string& path, const std::string& ext);

/// "x,y,z" for option `opt`; on failure returns false and sets `why` to the user message.
bool parse_vec3(const std::string& opt, const std::string& s, Vec3d& out, std::string& why);

}  // namespace hider::tool

// Command-line number parsing shared by the host tools.
#include "common/cli.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cfloat>
#include <cstdio>
#include <new>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace hider::tool {

bool parse_double(const std::string& s, double& out) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(s.c_str(), &end);
    // An underflow (1e-310, a denormal or 0) is still a number strtod read; an overflow is not.
    const bool in_range = errno == 0 || (errno == ERANGE && std::fabs(out) <= DBL_MIN);
    return end == s.c_str() + s.size() && in_range && std::isfinite(out);
}

namespace {
const char* g_tool_name = "hider";
void out_of_memory() {
    std::fprintf(stderr, "%s: out of memory\n", g_tool_name);
    std::_Exit(2);  // outputs are written whole or not at all (port::write_file), so nothing partial is left
}
/// At exit: what the tool printed must have reached standard output (a full disk, /dev/full).
void check_standard_output() {
    errno = 0;
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return;
    std::fprintf(stderr, "%s: cannot write standard output%s%s\n", g_tool_name, errno != 0 ? ": " : "",
                 errno != 0 ? std::strerror(errno) : "");
    std::_Exit(2);
}
}  // namespace

void exit_2_when_out_of_memory(const char* tool) {
    g_tool_name = tool;
    std::set_new_handler(out_of_memory);
    std::atexit(check_standard_output);
}

bool parse_int(const std::string& s, long& out) {
    if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-')) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtol(s.c_str(), &end, 10);
    return end == s.c_str() + s.size() && errno == 0;
}

bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

bool has_extension(const std::string& path, const std::string& ext) {
    if (path.size() < ext.size()) return false;
    for (size_t i = 0; i < ext.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i]) return false;
    return true;
}

bool output_format(const std::string& path, bool& png, std::string& why) {
    struct stat st {};  // a device or a pipe (/dev/stdout, a fifo) takes PPM, whatever its name
    if (path.rfind("/dev/", 0) == 0 || (::stat(path.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)))) {
        png = false;
        return true;
    }
    const size_t slash = path.find_last_of('/'), dot = path.find_last_of('.');
    std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "ppm" || ext == "png") {
        png = ext == "png";
        return true;
    }
    why = "output '" + path + "': unknown image format '" + (ext.empty() ? std::string("(no extension)") : "." + ext) +
          "' (use .ppm or .png)";
    return false;
}

bool parse_vec3(const std::string& opt, const std::string& s, Vec3d& out, std::string& why) {
    size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const size_t comma = s.find(',', start);
        const bool last = i == 2;
        if (last != (comma == std::string::npos)) {
            why = opt + " needs x,y,z (got '" + s + "')";
            return false;
        }
        const std::string part = s.substr(start, last ? std::string::npos : comma - start);
        if (!parse_double(part, out[i])) {
            why = opt + ": bad number '" + part + "'";
            return false;
        }
        start = comma + 1;
    }
    return true;
}

}  // namespace hider::tool

// Camera option parsing for hider-bake (same syntax, checks and messages as hider-render's).
#include "hider-bake/cli.hpp"

#include "common/cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace hider::tool::bake {
namespace {

Vec3d parse_vec(const std::string& program, const std::string& opt, const std::string& s) {
    Vec3d v{};
    std::string why;
    if (!parse_vec3(opt, s, v, why)) fail(program, why);
    return v;
}

}  // namespace

void fail(const std::string& program, const std::string& msg) {
    std::cerr << program << ": " << msg << "\n";
    std::exit(2);
}

bool parse_camera_option(const std::string& program, int argc, char** argv, int& i, CameraArgs& cam,
                         std::string& recorded) {
    const std::string a = argv[i];
    if (a != "--size" && a != "--eye" && a != "--target" && a != "--up" && a != "--fov" && a != "--near" &&
        a != "--far")
        return false;
    if (i + 1 >= argc) fail(program, a + " needs a value");
    const std::string v = argv[++i];
    if (a == "--size") {
        const size_t x = v.find('x');
        long w = 0, h = 0;
        if (x == std::string::npos || !parse_int(v.substr(0, x), w) || !parse_int(v.substr(x + 1), h))
            fail(program, "--size needs WxH (got '" + v + "')");
        if (w < 1 || h < 1 || w > kMaxFrameSide || h > kMaxFrameSide)
            fail(program, "--size " + v + " out of range (1.." + std::to_string(kMaxFrameSide) + " per side)");
        cam.width = static_cast<int>(w);
        cam.height = static_cast<int>(h);
    } else if (a == "--eye" || a == "--target" || a == "--up") {
        (a == "--eye" ? cam.eye : a == "--target" ? cam.target : cam.up) = parse_vec(program, a, v);
    } else if (a == "--fov") {
        if (!parse_double(v, cam.fov_deg)) fail(program, "--fov: bad number '" + v + "'");
    } else {
        double d = 0;
        if (!parse_double(v, d)) fail(program, a + ": bad number '" + v + "'");
        (a == "--near" ? cam.near : cam.far) = d;
    }
    recorded += (recorded.empty() ? "" : " ") + a + " " + v;
    return true;
}

}  // namespace hider::tool::bake

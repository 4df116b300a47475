// hider-plot: hidden-line plots of surfaces y = S f(x, z) with lib/'s floating horizon (the same code
// that runs on the chip). Usage: kUsage below and README.md. Errors print "file: what" or a plain
// reason and exit 2; success exits 0 (a warning on stderr when lib/ had to clamp points).
#include <iostream>
#include <string>

#include "common/cli.hpp"
#include "hider-plot/plot.hpp"
#include "hider-plot/surface.hpp"
#include "host/png.hpp"
#include "host/ppm.hpp"

namespace {

using namespace hider;
using namespace hider::plot;

const char* kUsage =
    "usage: hider-plot (--function NAME | --heightmap FILE.pgm) -o OUT.ppm|OUT.png [--size WxH]\n"
    "                  [--eye x,y,z] [--target x,y,z] [--up x,y,z] [--fov DEG] [--curves N] [--samples M]\n"
    "                  [--height S] [--mesh] [--mesh-step K] [--shade plain|height|id] [--band ROWS]\n";

[[noreturn]] void fail(const std::string& msg) {
    std::cerr << "hider-plot: " << msg;
    if (msg.empty() || msg.back() != '\n') std::cerr << '\n';
    std::exit(2);
}

Vec3d parse_vec(const std::string& opt, const std::string& s) {
    tool::Vec3d v{};
    std::string why;
    if (!tool::parse_vec3(opt, s, v, why)) fail(why);
    return {v[0], v[1], v[2]};
}

long parse_count(const std::string& opt, const std::string& s, long lo, long hi) {
    long v = 0;
    if (!tool::parse_int(s, v)) fail(opt + ": bad number '" + s + "'");
    if (v < lo || v > hi) fail(opt + " " + s + " out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-plot");
    std::string function, heightmap, out_path;
    ViewArgs view;
    Options opt;
    long curves = 0, samples = 0;
    double scale = 0.5;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value\n" + kUsage);
            return argv[++i];
        };
        if (a == "-o") out_path = value();
        else if (a == "--function") function = value();
        else if (a == "--heightmap") heightmap = value();
        else if (a == "--size") {
            const std::string v = value();
            const size_t x = v.find('x');
            long w = 0, h = 0;
            if (x == std::string::npos || !tool::parse_int(v.substr(0, x), w) || !tool::parse_int(v.substr(x + 1), h))
                fail("--size needs WxH (got '" + v + "')");
            if (w < 1 || h < 1 || w > kMaxFrameSide || h > kMaxFrameSide)
                fail("--size " + v + " out of range (1.." + std::to_string(kMaxFrameSide) + " per side)");
            view.width = static_cast<int>(w);
            view.height = static_cast<int>(h);
        } else if (a == "--eye") view.eye = parse_vec(a, value());
        else if (a == "--target") view.target = parse_vec(a, value());
        else if (a == "--up") view.up = parse_vec(a, value());
        else if (a == "--fov") {
            const std::string v = value();
            if (!tool::parse_double(v, view.fov_deg)) fail("--fov: bad number '" + v + "'");
        } else if (a == "--curves") curves = parse_count(a, value(), 2, horizon::SurfaceProjection::kMaxCount);
        else if (a == "--samples") samples = parse_count(a, value(), 2, horizon::SurfaceProjection::kMaxCount);
        else if (a == "--height") {
            const std::string v = value();
            if (!tool::parse_double(v, scale)) fail("--height: bad number '" + v + "'");
            if (!(scale > -1000 && scale < 1000)) fail("--height " + v + " out of range (-1000 < S < 1000)");
        } else if (a == "--mesh") opt.mesh = true;
        else if (a == "--mesh-step") opt.mesh_step = static_cast<int>(parse_count(a, value(), 1, horizon::SurfaceProjection::kMaxCount));
        else if (a == "--shade") {
            const std::string v = value();
            if (v == "plain") opt.shade = Shade::plain;
            else if (v == "height") opt.shade = Shade::height;
            else if (v == "id") opt.shade = Shade::id;
            else fail("unknown shade '" + v + "' (available: plain, height, id)");
        } else if (a == "--band") opt.band_rows = static_cast<int>(parse_count(a, value(), 1, kMaxFrameSide));
        else if (a == "-h" || a == "--help") {
            std::cout << kUsage;
            return 0;
        } else fail("unknown argument '" + a + "'\n" + kUsage);
    }
    if (function.empty() == heightmap.empty()) fail(std::string("give exactly one of --function and --heightmap\n") + kUsage);
    if (out_path.empty()) fail(std::string("no output given (-o OUT.ppm)\n") + kUsage);
    if (curves * samples > (1L << 24)) fail("--curves x --samples above 2^24 samples");
    bool png = false;
    std::string why_format;
    if (!tool::output_format(out_path, png, why_format)) fail(why_format);  // .ppm or .png, any case; before the work

    HeightGrid grid;
    if (!function.empty()) {
        if (!sample_function(function, scale, curves > 0 ? static_cast<int>(curves) : 48,
                             samples > 0 ? static_cast<int>(samples) : 160, grid))
            fail("unknown function '" + function + "' (available: " + function_names() + ")");
    } else {
        Pgm pgm;
        std::string why;
        if (!read_pgm(heightmap, pgm, why)) fail(why);
        if (static_cast<long>(pgm.width) * (curves > 0 ? curves : pgm.height) > (1L << 24) ||
            static_cast<long>(samples > 0 ? samples : pgm.width) * (curves > 0 ? curves : pgm.height) > (1L << 24))
            fail(heightmap + ": too many samples (at most 2^24 curves x samples)");
        grid = heightmap_grid(pgm, scale, static_cast<int>(curves), static_cast<int>(samples));
    }
    CameraD cam;
    std::string why;
    if (!resolve_camera(grid, view, cam, why)) fail(why);
    Result result;
    if (!render(grid, cam, opt, result, why)) fail(why);
    if (!(png ? port::write_png(out_path, result.width, result.height, result.rgb, why)
              : port::write_ppm(out_path, result.width, result.height, result.rgb, why)))
        fail(why);
    if (!result.warning.empty()) std::cerr << "hider-plot: warning: " << result.warning << "\n";
    return 0;
}

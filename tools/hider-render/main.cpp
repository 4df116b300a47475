// hider-render: renders an OBJ model to a binary PPM with lib/ (the same code that runs on the chip).
// Usage: see usage() below and README.md. Errors print "file:line: what" or a plain reason and exit 2.
#include <sys/stat.h>

#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>
#include <iostream>
#include <string>

#include "common/bsp_build.hpp"
#include "common/cli.hpp"
#include "common/render_bsp.hpp"
#include "common/obj.hpp"
#include "common/ray_scene.hpp"
#include "common/render.hpp"
#include "common/render_ray.hpp"
#include "common/scene.hpp"
#include "host/png.hpp"
#include "host/ppm.hpp"

namespace {

using namespace hider;
using namespace hider::tool;

const char* kUsage =
    "usage: hider-render MODEL.obj|TREE.hbsp -o OUT.ppm|OUT.png [--size WxH] [--eye x,y,z] [--target x,y,z] [--up x,y,z]\n"
    "                    [--fov DEG] [--near N] [--far F] [--shade headlight|id|depth] [--no-cull]\n"
    "                    [--algo NAME] [--depth-bits 16|32] [--band ROWS] [--format rgb565|rgb888|grey8]\n"
    "                    [--painter-key farthest|barycenter] [--pool N] [--reorders N] [--stats] [--strict]\n"
    "       hider-render --scene FILE.txt -o OUT.ppm|OUT.png [--size WxH] [--band ROWS] [--format ...] [--stats]\n";

[[noreturn]] void fail(const std::string& msg) {
    std::cerr << "hider-render: " << msg;
    if (msg.empty() || msg.back() != '\n') std::cerr << '\n';
    std::exit(2);
}

/// A model of faces on lines or points (in the model, or too small for its extent): warned, then drawn.
void no_area_warning(const std::string& model_path) {
    std::cerr << "hider-render: warning: " << model_path << ": no face has an area: the image shows only the background\n";
}

Vec3d parse_vec(const std::string& opt, const std::string& s) {
    Vec3d v{};
    std::string why;
    if (!parse_vec3(opt, s, v, why)) fail(why);
    return v;
}

/// The whole file at `path`; false with "path: what" when it cannot be read.
bool read_bytes(const std::string& path, std::vector<uint8_t>& out, std::string& why) {
    // Only a regular file (a directory "opens" on Linux and its read throws from libstdc++; a device
    // could grow the buffer until memory ends), no larger than a blob's 32-bit total_size.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        why = path + ": cannot open file: " + std::strerror(errno);
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        why = path + ": cannot open file: " + (S_ISDIR(st.st_mode) ? std::string(std::strerror(EISDIR)) : "not a regular file");
        return false;
    }
    if (static_cast<unsigned long long>(st.st_size) > 0xFFFFFFFFull) {
        why = path + ": " + std::to_string(static_cast<unsigned long long>(st.st_size)) +
              " bytes, more than a BSP blob can hold (4 GiB - 1)";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        why = path + ": cannot open";
        return false;
    }
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) {
        why = path + ": cannot read";
        return false;
    }
    return true;
}

/// Writes the frame as PPM or PNG by the extension of `path` (checked before rendering); exits 2 on failure.
void write_image(const std::string& path, const RenderResult& r) {
    bool png = false;
    std::string why;
    if (!output_format(path, png, why) ||
        !(png ? port::write_png(path, r.width, r.height, r.rgb, why) : port::write_ppm(path, r.width, r.height, r.rgb, why)))
        fail(why);
}

/// Says on stderr what a render could not do (a full pool, a spent budget, a piece with too many cuts)
/// and returns the exit status: 0, or 2 with --strict.
int warn_incomplete(const RenderOptions& opt, const RenderResult& r, bool strict) {
    if (r.stats.status == Status::ok) return 0;
    const NewellStats& n = r.newell;
    const char* kind = strict ? "hider-render: error: " : "hider-render: warning: ";
    if (n.dropped != 0) {
        std::cerr << kind << "Newell's cut pool of " << r.pool << " polygons is full: " << n.dropped << " cuts dropped, ";
        if (r.pool_needed != 0)
            std::cerr << "this view needs a pool of " << r.pool_needed << " (--pool " << r.pool_needed << ")\n";
        else
            std::cerr << "and a pool of " << kMaxSplitPool << " was not enough either\n";
    }
    if (n.too_deep != 0)
        std::cerr << kind << n.too_deep << " pairs left uncut: their pieces already carry " << kMaxPieceCuts << " cuts\n";
    if (n.budget_exhausted)
        std::cerr << kind << "Newell's budget of pair tests ran out after " << n.pair_tests
                  << "; the rest is drawn in depth order\n";
    if (n.unresolved != 0) {
        std::cerr << kind << n.unresolved << " pairs left uncut in an order some of their shared pixels disagree with";
        if (r.reorders_needed != 0)
            std::cerr << ": the " << opt.reorders << " words of pixel-ordered pairs are too few, this view needs --reorders "
                      << r.reorders_needed << "\n";
        else if (n.dropped != 0 || n.too_deep != 0 || n.budget_exhausted)
            std::cerr << " (see the other warnings)\n";
        else
            std::cerr << " (a pair no line cuts, or more than " << r.reorders_tried << " words of pixel-ordered pairs)\n";
    }
    if (n.inexact_cuts != 0)
        std::cerr << kind << n.inexact_cuts << " cuts along a line that leaves a pixel centre on the wrong side of the plane\n";
    if (n.dropped == 0 && n.too_deep == 0 && !n.budget_exhausted && n.unresolved == 0 && n.inexact_cuts == 0)
        std::cerr << kind << "the frame is incomplete: " << status_name(r.stats.status) << "\n";
    return strict ? 2 : 0;
}

/// Options that only make sense with an OBJ model (the scene file sets its own camera and shading).
bool model_only_option(const std::string& a) {
    return a == "--eye" || a == "--target" || a == "--up" || a == "--fov" || a == "--near" || a == "--far" ||
           a == "--shade" || a == "--no-cull" || a == "--depth-bits" || a == "--painter-key" || a == "--pool" ||
           a == "--reorders";
}

/// Where --stats goes: stdout, or stderr when the image itself goes to standard output.
std::FILE* stats_stream(const std::string& out_path) { return hider::port::is_standard_output(out_path) ? stderr : stdout; }

/// --scene FILE.txt: ray traces a scene file (README.md, "Scene files (`hider-render --scene`)").
int render_scene_file(const std::string& scene_path, const std::string& model_path, const std::string& out_path,
                      bool size_given, const CameraArgs& cam, const RenderOptions& opt, bool algo_given, bool strict,
                      bool stats, int argc, char** argv) {
    if (!model_path.empty()) fail("give either a model or --scene, not both ('" + model_path + "', '" + scene_path + "')");
    for (int i = 1; i < argc; ++i)
        if (model_only_option(argv[i])) fail(std::string(argv[i]) + " does not apply to --scene (the scene file sets camera and shading)");
    if (algo_given && opt.algo != Algo::raycast) fail("--scene is ray traced: --algo must be raycast (or left out)");
    if (strict) fail("--strict does not apply to --scene (a scene's frame is complete or the run fails)");
    if (out_path.empty()) fail(std::string("no output given (-o OUT.ppm)\n") + kUsage);
    bool png = false;
    std::string why_format;
    if (!output_format(out_path, png, why_format)) fail(why_format);
    RayScene scene;
    std::string why;
    if (!load_ray_scene(scene_path, scene, why)) fail(why);
    for (const std::string& w : grid_warnings(scene)) std::cerr << "hider-render: warning: " << scene_path << ": " << w << "\n";
    const int width = size_given ? cam.width : scene.width, height = size_given ? cam.height : scene.height;
    RenderResult result;
    if (!render_ray_scene(scene, width, height, opt, result, why)) fail(scene_path + ": " + why);
    write_image(out_path, result);
    if (stats) {
        const RayCounts& r = result.ray;
        std::fprintf(stats_stream(out_path), "rays %llu hits %llu shadow-rays %llu box-tests %llu triangle-tests %llu\n",
                    static_cast<unsigned long long>(r.rays), static_cast<unsigned long long>(r.hits),
                    static_cast<unsigned long long>(r.shadow_rays), static_cast<unsigned long long>(r.boxes),
                    static_cast<unsigned long long>(r.triangles));
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    hider::tool::exit_2_when_out_of_memory("hider-render");
    std::string model_path, out_path, scene_path;
    bool size_given = false;
    CameraArgs cam;
    RenderOptions opt;
    bool stats = false, strict = false, algo_given = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value\n" + kUsage);
            return argv[++i];
        };
        if (a == "-o") out_path = value();
        else if (a == "--size") {
            const std::string v = value();
            const size_t x = v.find('x');
            long w = 0, h = 0;
            if (x == std::string::npos || !parse_int(v.substr(0, x), w) || !parse_int(v.substr(x + 1), h))
                fail("--size needs WxH (got '" + v + "')");
            if (w < 1 || h < 1 || w > kMaxFrameSide || h > kMaxFrameSide)
                fail("--size " + v + " out of range (1.." + std::to_string(kMaxFrameSide) + " per side)");
            cam.width = static_cast<int>(w);
            cam.height = static_cast<int>(h);
            size_given = true;
        } else if (a == "--scene") scene_path = value();
        else if (a == "--eye") cam.eye = parse_vec(a, value());
        else if (a == "--target") cam.target = parse_vec(a, value());
        else if (a == "--up") cam.up = parse_vec(a, value());
        else if (a == "--fov") {
            const std::string v = value();
            if (!parse_double(v, cam.fov_deg)) fail("--fov: bad number '" + v + "'");
            if (!(cam.fov_deg >= 0.5 && cam.fov_deg <= 179.5)) fail("--fov " + v + " out of range (0.5..179.5 degrees)");
        } else if (a == "--near" || a == "--far") {
            const std::string v = value();
            double d = 0;
            if (!parse_double(v, d)) fail(a + ": bad number '" + v + "'");
            (a == "--near" ? cam.near : cam.far) = d;
        } else if (a == "--shade") {
            const std::string v = value();
            if (v == "headlight") opt.shade = Shade::headlight;
            else if (v == "id") opt.shade = Shade::id;
            else if (v == "depth") opt.shade = Shade::depth;
            else fail("unknown shade '" + v + "' (available: headlight, id, depth)");
        } else if (a == "--no-cull") opt.cull = false;
        else if (a == "--algo") {
            const std::string v = value();
            algo_given = true;
            if (!parse_algo(v, opt.algo)) fail("unknown algo '" + v + "' (available: " + algo_names() + ")");
        } else if (a == "--depth-bits") {
            const std::string v = value();
            if (v != "16" && v != "32") fail("--depth-bits must be 16 or 32 (got '" + v + "')");
            opt.depth_bits = v == "16" ? 16 : 32;
        } else if (a == "--band") {
            const std::string v = value();
            long rows = 0;
            if (!parse_int(v, rows) || rows < 1 || rows > kMaxFrameSide) fail("--band needs a row count 1.." + std::to_string(kMaxFrameSide) + " (got '" + v + "')");
            opt.band_rows = static_cast<int>(rows);
        } else if (a == "--format") {
            const std::string v = value();
            if (v == "rgb565") opt.format = PixelFormat::rgb565;
            else if (v == "rgb888") opt.format = PixelFormat::rgb888;
            else if (v == "grey8") opt.format = PixelFormat::grey8;
            else fail("unknown format '" + v + "' (available: rgb565, rgb888, grey8)");
        } else if (a == "--painter-key") {
            const std::string v = value();
            if (v == "farthest") opt.painter_key = DepthKey::farthest;
            else if (v == "barycenter") opt.painter_key = DepthKey::barycenter;
            else fail("unknown painter key '" + v + "' (available: farthest, barycenter)");
        } else if (a == "--pool") {
            const std::string v = value();
            long n = 0;
            if (!parse_int(v, n) || n < 1 || n > (1L << 24)) fail("--pool needs a polygon count 1..16777216 (got '" + v + "')");
            opt.split_pool = static_cast<size_t>(n);
        } else if (a == "--reorders") {
            const std::string v = value();
            long n = 0;
            if (!parse_int(v, n) || n < 0 || n > static_cast<long>(kMaxReorders) || n % 2 != 0)
                fail("--reorders needs an even word count 0.." + std::to_string(kMaxReorders) + " (got '" + v + "')");
            opt.reorders = static_cast<size_t>(n);
        } else if (a == "--stats") stats = true;
        else if (a == "--strict") strict = true;
        else if (a == "-h" || a == "--help") {
            const RenderOptions d;
            const CameraArgs c;
            std::cout << kUsage << "algorithms: " << algo_names() << "\n"
                      << "defaults: --size " << c.width << 'x' << c.height << " --fov " << c.fov_deg
                      << " --algo zbuffer --shade headlight --depth-bits " << d.depth_bits
                      << " --format rgb565 --painter-key farthest --reorders " << d.reorders << ", the whole frame at once, the camera framing the model\n";
            return 0;
        }
        else if (!a.empty() && a[0] == '-') fail("unknown option '" + a + "'\n" + kUsage);
        else if (model_path.empty()) model_path = a;
        else fail("more than one model given ('" + model_path + "', '" + a + "')");
    }
    std::string why_format;
    if (!scene_path.empty()) return render_scene_file(scene_path, model_path, out_path, size_given, cam, opt, algo_given, strict, stats, argc, argv);
    if (model_path.empty()) fail(std::string("no model given\n") + kUsage);
    if (out_path.empty()) fail(std::string("no output given (-o OUT.ppm)\n") + kUsage);
    bool png = false;
    if (!output_format(out_path, png, why_format)) fail(why_format);
    if (opt.shade == Shade::id) opt.format = PixelFormat::rgb888;  // ids need all 24 bits

    Scene scene;
    std::string why;
    RenderResult result;
    const bool bsp = opt.algo == Algo::bsp || opt.algo == Algo::bsp_front;
    if (has_extension(model_path, ".hbsp") && !bsp) fail(model_path + ": a BSP tree draws with --algo bsp or bsp-front");
    if (bsp) {
        // A tree from a .hbsp file, or built from the OBJ with the default heuristic: the same bytes, the
        // same world (the model's own fit), so both give the same image.
        std::vector<uint8_t> blob;
        if (has_extension(model_path, ".hbsp")) {
            if (!read_bytes(model_path, blob, why)) fail(why);
        } else {
            BspStats bs;
            if (!bsp_from_obj(model_path, BspOptions{}, blob, bs, why)) fail(why);
            for (const std::string& w : fan_warnings(model_path, bs.badly_fanned)) std::cerr << "hider-render: warning: " << w << "\n";
            for (const std::string& w : collapse_warnings(model_path, bs.collapsed)) std::cerr << "hider-render: warning: " << w << "\n";
            if (bs.triangles == 0) no_area_warning(model_path);
        }
        const AlignedBlob aligned(blob);
        std::vector<uint32_t> probe(bsp_stack_entries(kToolMaxBspDepth));
        BspTree tree;
        BspLoadInfo info;
        const Status ls = bsp_load(aligned.span(), {probe.data(), probe.size()}, tree, &info);
        if (ls == Status::capacity_exceeded)
            fail(model_path + ": the tree is deeper than the " + std::to_string(kToolMaxBspDepth) +
                 " levels hider-render walks (build it with hider-bsp --max-chain, e.g. 256)");
        if (ls != Status::ok) fail(model_path + ": not a valid BSP tree: " + bsp_load_message(ls, info));
        if (!bsp_scene(tree, cam, scene, why)) fail(model_path + ": " + why);
        if (!render_bsp(scene, blob, opt, result, why)) fail(model_path + ": " + why);
    } else {
        ObjModel model;
        ObjError err;
        if (!load_obj(model_path, model, err)) fail(format(err));
        for (const std::string& w : fan_warnings(model_path, badly_fanned_faces(model))) std::cerr << "hider-render: warning: " << w << "\n";
        if (!build_scene(model, cam, scene, why)) fail(model_path + ": " + why);
        for (const std::string& w : collapse_warnings(model_path, collapsed_faces(model, scene)))
            std::cerr << "hider-render: warning: " << w << "\n";
        if (!any_triangle_with_area(scene)) no_area_warning(model_path);
        if (!render(scene, opt, result, why)) fail(why);
    }
    // --strict: an incomplete frame is an error, and an error leaves no image behind.
    if (!(strict && result.stats.status != Status::ok)) write_image(out_path, result);
    if (stats) {
        const FrameStats& s = result.stats;
        std::FILE* const out = stats_stream(out_path);
        if (opt.algo == Algo::raycast)  // rays meet triangles through the BVH: none is set up, culled or clipped
            std::fprintf(out, "triangles %u (ray cast: no drawn, culled or clipped counts; rays below)\n", s.triangles_in);
        else
            std::fprintf(out, "triangles %u drawn %u culled %u degenerate %u outside %u clipped %u\n", s.triangles_in,
                        s.triangles_drawn, s.triangles_culled, s.triangles_degenerate, s.triangles_outside, s.triangles_clipped);
        std::fprintf(out, "fragments %llu written %llu covered %u overdraw %.2f\n", static_cast<unsigned long long>(s.fragments),
                    static_cast<unsigned long long>(s.pixels_written), result.pixels_covered,
                    result.pixels_covered == 0 ? 0.0 : static_cast<double>(s.pixels_written) / result.pixels_covered);
        if (opt.algo == Algo::raycast)
            std::fprintf(out, "rays %llu hits %llu box-tests %llu triangle-tests %llu\n", static_cast<unsigned long long>(result.ray.rays),
                        static_cast<unsigned long long>(result.ray.hits), static_cast<unsigned long long>(result.ray.boxes),
                        static_cast<unsigned long long>(result.ray.triangles));
        if (bsp)
            std::fprintf(out, "bsp nodes-visited %u subtrees-skipped %u triangles %zu\n", s.nodes_visited, s.subtrees_skipped,
                        static_cast<size_t>(s.triangles_in));
        if (opt.algo == Algo::newell || opt.algo == Algo::reverse) {
            const NewellStats& n = result.newell;
            std::fprintf(out, "newell polygons %zu pair-tests %llu moves %u splits %u cycles %u unresolved %u dropped %u too-deep %u pixel-ordered %u inexact-cuts %u reorders-peak %u\n",
                        result.polygons, static_cast<unsigned long long>(n.pair_tests), n.moves, n.splits, n.cycles,
                        n.unresolved, n.dropped, n.too_deep, n.pixel_ordered, n.inexact_cuts, n.reorders_peak);
        }
        if (s.status != Status::ok) std::fprintf(out, "status %s\n", status_name(s.status));
    }
    return warn_incomplete(opt, result, strict);
}

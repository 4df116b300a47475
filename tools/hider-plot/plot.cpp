// hider-plot driver: camera defaults and checks in double, one conversion to lib/ types, the plot.
#include "hider-plot/plot.hpp"
#include "common/hypot3.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "host/ppm.hpp"

namespace hider::plot {
namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec3d& v) { return tool::hypot3(v[0], v[1], v[2]); }
Vec3d scaled(const Vec3d& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }

std::string fmt(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

/// Largest |coordinate| of eye and target hider-plot accepts (lib/'s world range is 8192).
constexpr double kWorldLimit = 4096.0;

Q16 q16(double v) { return Q16::from_raw(static_cast<int32_t>(std::lround(v * 65536.0))); }

/// Heights' range, at least a tiny span so the box has a height.
void y_range(const HeightGrid& g, double& lo, double& hi) {
    lo = *std::min_element(g.y.begin(), g.y.end());
    hi = *std::max_element(g.y.begin(), g.y.end());
}

/// A colour ramp for --shade height: dark blue, cyan, green, yellow, red, white (64 steps).
std::vector<Rgb> height_ramp() {
    const double stops[][3] = {{20, 30, 140}, {0, 200, 230}, {40, 220, 60}, {250, 230, 40}, {240, 50, 30}, {255, 255, 255}};
    std::vector<Rgb> ramp;
    for (int i = 0; i < 64; ++i) {
        const double t = i / 63.0 * 5.0;
        const int s = std::min(static_cast<int>(t), 4);
        const double f = t - s;
        auto mix = [&](int c) { return static_cast<uint8_t>(std::lround(stops[s][c] + (stops[s + 1][c] - stops[s][c]) * f)); };
        ramp.push_back({mix(0), mix(1), mix(2)});
    }
    return ramp;
}

}  // namespace

bool resolve_camera(const HeightGrid& g, const ViewArgs& args, CameraD& out, std::string& error) {
    if (args.width < 1 || args.height < 1 || args.width > kMaxFrameSide || args.height > kMaxFrameSide) {
        error = "frame size " + std::to_string(args.width) + "x" + std::to_string(args.height) + " out of range (1.." +
                std::to_string(kMaxFrameSide) + " per side)";
        return false;
    }
    if (!(args.fov_deg >= 0.5 && args.fov_deg <= 179.5)) {
        error = "--fov " + fmt(args.fov_deg) + " out of range (0.5..179.5 degrees)";
        return false;
    }
    double ylo = 0, yhi = 0;
    y_range(g, ylo, yhi);
    const Vec3d lo{-1.0, ylo, -1.0}, hi{1.0, yhi, 1.0};
    auto corner = [&](int c) { return Vec3d{(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]}; };
    CameraD cam;
    cam.width = args.width;
    cam.height = args.height;
    cam.fov_deg = args.fov_deg;
    cam.target = args.target.value_or(Vec3d{0.0, (ylo + yhi) / 2, 0.0});
    cam.up = args.up.value_or(Vec3d{0.0, 1.0, 0.0});
    const double up_max = std::max({std::fabs(cam.up[0]), std::fabs(cam.up[1]), std::fabs(cam.up[2])});
    if (up_max == 0) {
        error = "up vector is zero";
        return false;
    }
    for (double& c : cam.up) c /= up_max;  // a denormal up (1e-310) made the side vector's norm 0 or inf
    if (args.eye) {
        cam.eye = *args.eye;
    } else {  // from above the front edge (z = +1), just far enough to frame the box
        const double n = std::hypot(0.75, 1.0);
        const Vec3d back{0.0, 0.75 / n, 1.0 / n};
        const Vec3d side = cross(scaled(back, -1.0), cam.up);
        const double side_len = length(side);
        if (side_len == 0) {
            error = "up vector is parallel to the default view direction; give --eye";
            return false;
        }
        const Vec3d s = scaled(side, 1.0 / side_len), u = cross(s, scaled(back, -1.0));
        const double ty = 0.95 * std::tan(args.fov_deg * M_PI / 360.0);
        const double tx = ty * args.width / args.height;
        double d = 0;
        for (int c = 0; c < 8; ++c) {
            const Vec3d p = sub(corner(c), cam.target);
            d = std::max({d, dot(p, back) + std::fabs(dot(p, s)) / tx, dot(p, back) + std::fabs(dot(p, u)) / ty});
        }
        cam.eye = {cam.target[0] + back[0] * d, cam.target[1] + back[1] * d, cam.target[2] + back[2] * d};
    }
    for (const Vec3d* v : {&cam.eye, &cam.target})
        for (double c : *v)
            if (!(std::fabs(c) < kWorldLimit)) {
                error = std::string(v == &cam.eye ? "eye" : "target") + " (" + fmt((*v)[0]) + "," + fmt((*v)[1]) + "," +
                        fmt((*v)[2]) + ") out of range (|coordinate| < " + fmt(kWorldLimit) + ")";
                return false;
            }
    const Vec3d view = sub(cam.target, cam.eye);
    const double dist = length(view);
    if (dist < 1e-3) {
        error = "eye and target coincide";
        return false;
    }
    if (length(cross(view, cam.up)) < 2e-4 * dist * length(cam.up)) {
        error = "up vector is parallel to the view direction";
        return false;
    }
    // Near: half the distance to the nearest corner in front (a hundredth of the eye-target distance
    // when the eye is inside the box); far: past the farthest corner. Only near clips the plot.
    const Vec3d f = scaled(view, 1.0 / dist);
    double nearest = 1e30, farthest = 0;
    for (int c = 0; c < 8; ++c) {
        const double depth = dot(sub(corner(c), cam.eye), f);
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    cam.near = std::max({nearest * 0.5, dist * 0.01, 1.0 / 128});
    cam.far = std::min(std::max(farthest * 1.01, cam.near * 2), 30000.0);
    out = cam;
    return true;
}

FixedGrid to_fixed(const HeightGrid& g) {
    FixedGrid f;
    horizon::Surface& s = f.surface;
    s.samples = g.cols;
    s.curves = g.rows;
    // Steps rounded to Q16, the grid centred on 0: x and z span [-1, 1] to within 1/65536 per step.
    s.dx = Q16::from_raw(static_cast<int32_t>(std::lround(2.0 * 65536.0 / (g.cols - 1))));
    s.dz = Q16::from_raw(static_cast<int32_t>(std::lround(2.0 * 65536.0 / (g.rows - 1))));
    s.x0 = Q16::from_raw(-static_cast<int32_t>((static_cast<int64_t>(g.cols - 1) * s.dx.raw()) / 2));
    s.z0 = Q16::from_raw(-static_cast<int32_t>((static_cast<int64_t>(g.rows - 1) * s.dz.raw()) / 2));
    f.values.resize(g.y.size());
    for (size_t i = 0; i < g.y.size(); ++i) f.values[i] = q16(g.y[i]).raw();
    s.value_min = *std::min_element(f.values.begin(), f.values.end());
    s.value_max = *std::max_element(f.values.begin(), f.values.end());
    s.y_unit_raw = 1;
    return f;
}

Camera to_camera(const CameraD& cam) {
    Camera c;
    c.eye = {q16(cam.eye[0]), q16(cam.eye[1]), q16(cam.eye[2])};
    c.target = {q16(cam.target[0]), q16(cam.target[1]), q16(cam.target[2])};
    const double ul = length(cam.up);
    c.up = {q16(cam.up[0] / ul), q16(cam.up[1] / ul), q16(cam.up[2] / ul)};
    c.fovy = Angle::from_degrees(q16(cam.fov_deg));
    c.near = q16(cam.near);
    c.far = q16(cam.far);
    return c;
}

int mesh_step(const Options& opt, int curves, int samples) {
    if (!opt.mesh) return samples - 1;  // the side edges alone: constant-x lines 0 and 1
    if (opt.mesh_step > 0) return opt.mesh_step;
    return std::max(1, static_cast<int>(std::lround(static_cast<double>(samples - 1) / (curves - 1))));
}

/// The largest distance, in 1/16 pixel, between a grid point's projection by `proj` and its exact
/// projection through the same fixed-point view (make_view(), evaluated in double), over the points in
/// front of the near plane that land in the frame: what error_bound_subpixels() bounds, measured, with
/// the floor of U and V to 2^14 units that the bound leaves out.
int32_t measured_error_subpixels(const horizon::SurfaceProjection& proj, const FixedGrid& fixed, const Camera& camera) {
    View view;
    if (make_view(camera, proj.width(), proj.height(), view) != Status::ok) return 0;
    const horizon::Surface& s = fixed.surface;
    const Transform& t = view.to_view;
    const double k = view.k_q8 / 256.0, cx = 8.0 * proj.width(), cy = 8.0 * proj.height();
    std::vector<horizon::PlotPoint> pts(static_cast<size_t>(s.samples));
    double worst = 0;
    for (int32_t c = 0; c < s.curves; ++c) {
        const int32_t* values = fixed.values.data() + static_cast<size_t>(c) * static_cast<size_t>(s.samples);
        (void)proj.project_row(values, c, pts.data());
        for (int32_t i = 0; i < s.samples; ++i) {
            if (pts[static_cast<size_t>(i)].x == horizon::kNoPoint) continue;
            const double p[3] = {static_cast<double>(s.x0.raw()) + static_cast<double>(i) * s.dx.raw(),
                                 static_cast<double>(values[i]) * s.y_unit_raw,
                                 static_cast<double>(s.z0.raw()) + static_cast<double>(c) * s.dz.raw()};
            double v[3];
            for (int r = 0; r < 3; ++r)
                v[r] = (t.rot.m[r][0].raw() * p[0] + t.rot.m[r][1].raw() * p[1] + t.rot.m[r][2].raw() * p[2]) / 1073741824.0 +
                       (r == 0 ? t.trans.x.raw() : r == 1 ? t.trans.y.raw() : t.trans.z.raw());
            const double w = -v[2];
            if (w < view.near_raw) continue;
            const double x = k * v[0] / w + cx, y = -k * v[1] / w + cy;
            if (x < 0 || y < 0 || x >= 16.0 * proj.width() || y >= 16.0 * proj.height()) continue;
            worst = std::max({worst, std::fabs(pts[static_cast<size_t>(i)].x - x), std::fabs(pts[static_cast<size_t>(i)].y - y)});
        }
    }
    return static_cast<int32_t>(std::ceil(worst));
}

/// Whether the surface's bounding box (x, z over the grid, y over the heights) may reach into the frame:
/// it straddles the near plane, or its corners' screen rectangle overlaps the frame (through the same view).
bool box_reaches_frame(const FixedGrid& fixed, const Camera& camera, int width, int height) {
    View view;
    if (make_view(camera, width, height, view) != Status::ok) return false;
    const horizon::Surface& s = fixed.surface;
    const Transform& t = view.to_view;
    const double k = view.k_q8 / 256.0;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    int behind = 0;
    for (int c = 0; c < 8; ++c) {
        const double p[3] = {static_cast<double>(s.x0.raw()) + ((c & 1) ? static_cast<double>(s.samples - 1) * s.dx.raw() : 0.0),
                             static_cast<double>((c & 2) ? s.value_max : s.value_min) * s.y_unit_raw,
                             static_cast<double>(s.z0.raw()) + ((c & 4) ? static_cast<double>(s.curves - 1) * s.dz.raw() : 0.0)};
        double v[3];
        for (int r = 0; r < 3; ++r)
            v[r] = (t.rot.m[r][0].raw() * p[0] + t.rot.m[r][1].raw() * p[1] + t.rot.m[r][2].raw() * p[2]) / 1073741824.0 +
                   (r == 0 ? t.trans.x.raw() : r == 1 ? t.trans.y.raw() : t.trans.z.raw());
        const double w = -v[2];
        if (w <= view.near_raw) {  // this corner behind the near plane: no screen point
            ++behind;
            continue;
        }
        const double xy[2] = {k * v[0] / w + 8.0 * width, -k * v[1] / w + 8.0 * height};
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], xy[a]);
            hi[a] = std::max(hi[a], xy[a]);
        }
    }
    if (behind == 8) return false;
    if (behind > 0) return true;  // the box straddles the near plane: assume it reaches the frame
    return hi[0] >= 0 && hi[1] >= 0 && lo[0] < 16.0 * width && lo[1] < 16.0 * height;
}

bool render(const HeightGrid& g, const CameraD& cam, const Options& opt, Result& out, std::string& error) {
    const FixedGrid fixed = to_fixed(g);
    horizon::SurfaceProjection proj;
    const Status st = proj.prepare(to_camera(cam), cam.width, cam.height, fixed.surface);
    if (st != Status::ok) {
        error = std::string("lib/ rejected the camera or surface (") + status_name(st) + ")";
        return false;
    }
    const int w = cam.width, h = cam.height, band = opt.band_rows > 0 ? std::min(opt.band_rows, h) : h;
    std::vector<int16_t> upper(static_cast<size_t>(w)), lower(upper.size());
    horizon::Horizon hz;
    if (horizon::make_horizon({upper.data(), upper.size()}, {lower.data(), lower.size()}, w, h, hz) != Status::ok) {
        error = "frame size rejected by lib/";
        return false;
    }
    const size_t n = static_cast<size_t>(std::max(fixed.surface.samples, fixed.surface.curves));  // any sweep
    std::vector<horizon::PlotPoint> cur(n), prev(n);
    std::vector<int32_t> values_cur(n), values_prev(n);
    std::vector<int16_t> pending_upper(static_cast<size_t>(w)), pending_lower(pending_upper.size());
    const horizon::PlotBuffers buffers{{cur.data(), n},
                                       {prev.data(), n},
                                       {values_cur.data(), n},
                                       {values_prev.data(), n},
                                       {pending_upper.data(), pending_upper.size()},
                                       {pending_lower.data(), pending_lower.size()}};
    const horizon::GridSource<int32_t> src{fixed.values.data(), fixed.surface.samples, fixed.surface.curves, 0};
    const std::vector<Rgb> white{{255, 255, 255}}, ramp = height_ramp();
    horizon::PlotStyle style;
    style.shading = opt.shade == Shade::id ? horizon::Shading::id
                    : opt.shade == Shade::height ? horizon::Shading::height : horizon::Shading::palette;
    style.colours = opt.shade == Shade::height ? Span<const Rgb>(ramp.data(), ramp.size()) : Span<const Rgb>(white.data(), 1);
    style.mesh = opt.mesh;
    style.mesh_step = mesh_step(opt, fixed.surface.curves, fixed.surface.samples);
    std::vector<Rgb888> pixels(static_cast<size_t>(w) * band);
    out = Result{};
    out.width = w;
    out.height = h;
    uint32_t drawn = 0;
    for (int y0 = 0; y0 < h; y0 += band) {
        const int y1 = std::min(h, y0 + band);
        const auto frame = band_view<Rgb888Format, uint16_t>(pixels.data(), nullptr, w, h, y0, y1);
        clear(frame, Rgb{0, 0, 0});
        const horizon::PlotStats s = horizon::plot(proj, src, hz, buffers, horizon::FrameTarget<Rgb888Format>(frame), style);
        if (s.status == Status::invalid_argument) {
            error = "lib/ rejected the plot arguments";
            return false;
        }
        drawn += s.pixels;
        out.stats = s;
        port::append_rgb888(frame, out.rgb);
    }
    out.stats.pixels = drawn;
    if (drawn == 0) {
        const std::string frame = std::to_string(w) + "x" + std::to_string(h) + " frame";
        error = box_reaches_frame(fixed, to_camera(cam), w, h)
                    ? "no line of the surface crosses the " + frame +
                          ", though its box reaches into it (the view falls between the lines: more --curves or --samples, or a "
                          "wider --fov)"
                    : "the view does not see the surface (nothing of it lands in the " + frame + ")";
        return false;
    }
    if (out.stats.points_clamped != 0)
        out.warning = std::to_string(out.stats.points_clamped) +
                      " projected points lay too far outside the frame and were clamped (segments near them may shift)";
    // The steps are Q16: with thousands of samples their rounding adds up to a visibly narrower or
    // wider surface than [-1, 1].
    const double span_x = (g.cols - 1) * (fixed.surface.dx.raw() / 65536.0), span_z = (g.rows - 1) * (fixed.surface.dz.raw() / 65536.0);
    if (std::fabs(span_x - 2) > 0.02 || std::fabs(span_z - 2) > 0.02) {
        std::ostringstream o;
        o << std::setprecision(3) << (out.warning.empty() ? "" : "; ") << "the grid's steps round to 1/65536: the surface spans x in [-"
          << span_x / 2 << ", " << span_x / 2 << "] and z in [-" << span_z / 2 << ", " << span_z / 2
          << "] instead of [-1, 1] (use fewer samples or curves)";
        out.warning += o.str();
    }
    // The eye inside the surface's box: the strips next to it, which the method does not draw, cover much
    // of the frame (README, "Limit of rough surfaces"; a red team's views: 12 of 106 below 97% agreement).
    {
        const horizon::Surface& fs = fixed.surface;
        const Camera c = to_camera(cam);
        const int64_t x1 = int64_t{fs.x0.raw()} + int64_t{fs.dx.raw()} * (fs.samples - 1),
                      z1 = int64_t{fs.z0.raw()} + int64_t{fs.dz.raw()} * (fs.curves - 1);
        if (c.eye.x.raw() > fs.x0.raw() && c.eye.x.raw() < x1 && c.eye.z.raw() > fs.z0.raw() && c.eye.z.raw() < z1 &&
            int64_t{c.eye.y.raw()} > int64_t{fs.value_min} * fs.y_unit_raw &&
            int64_t{c.eye.y.raw()} < int64_t{fs.value_max} * fs.y_unit_raw) {
            out.warning += std::string(out.warning.empty() ? "" : "; ") +
                           "the eye is inside the surface's box: next to it the strips between lines, which the floating "
                           "horizon does not draw, can hide much of what it shows (move the eye above or outside the surface)";
        }
    }
    out.error_subpixels = std::max(proj.error_bound_subpixels(), measured_error_subpixels(proj, fixed, to_camera(cam)));
    if (out.error_subpixels > 16) {
        std::ostringstream o;
        o << (out.warning.empty() ? "" : "; ") << "projected points may lie up to " << out.error_subpixels / 16.0
          << " pixels from their exact place (the surface reaches far beyond the frame for the distance of its "
             "nearest point: frame more of it, or narrow the height range)";
        out.warning += o.str();
    }
    return true;
}

}  // namespace hider::plot

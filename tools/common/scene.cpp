// Scene fitting: bounding box of model + eye + target into +-kFitHalfExtent world units, camera defaults
// that frame the model, and conversion of every value to fixed point exactly once.
#include "common/scene.hpp"
#include "common/hypot3.hpp"

#include <hider/view.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace hider::tool {
namespace {

std::string fmt(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

double length(const Vec3d& v) { return hypot3(v[0], v[1], v[2]); }
Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// Nearest Q16 to v; false if it does not fit int32.
bool to_q16(double v, Q16& out) {
    const double r = std::nearbyint(v * 65536.0);
    if (!std::isfinite(r) || std::fabs(r) >= 2147483647.0) return false;
    out = Q16::from_raw(static_cast<int32_t>(r));
    return true;
}

}  // namespace

bool build_scene(const ObjModel& model, const CameraArgs& args, Scene& out, std::string& error, size_t max_vertices) {
    if (model.vertices.empty() || model.faces.empty()) {
        error = "empty model";
        return false;
    }
    if (model.vertices.size() > max_vertices) {
        error = "model has " + std::to_string(model.vertices.size()) + " vertices; hider meshes hold at most " +
                std::to_string(max_vertices);
        return false;
    }
    if (args.width < 1 || args.height < 1 || args.width > kMaxFrameSide || args.height > kMaxFrameSide) {
        error = "frame size " + std::to_string(args.width) + "x" + std::to_string(args.height) +
                " out of range (1.." + std::to_string(kMaxFrameSide) + " per side)";
        return false;
    }
    if (!(args.fov_deg >= 0.5 && args.fov_deg <= 179.5)) {
        error = "field of view " + fmt(args.fov_deg) + " degrees out of range (0.5..179.5)";
        return false;
    }
    // Model bounding box and sphere.
    Vec3d lo = model.vertices[0], hi = model.vertices[0];
    for (const auto& v : model.vertices)
        for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], v[i]); hi[i] = std::max(hi[i], v[i]); }
    const Vec3d mid{lo[0] / 2 + hi[0] / 2, lo[1] / 2 + hi[1] / 2, lo[2] / 2 + hi[2] / 2};  // no overflow near 1.8e308
    const double radius = length(sub(hi, lo)) / 2;
    if (!std::isfinite(radius)) {
        error = "model coordinates are too large to represent (bounding box is not finite)";
        return false;
    }
    // Camera defaults frame the bounding sphere.
    const double aspect = static_cast<double>(args.width) / args.height;
    const double half_fov = args.fov_deg * M_PI / 360.0;
    const double half_fov_x = std::atan(std::tan(half_fov) * aspect);
    const Vec3d target = args.target.value_or(mid);
    const double r = radius > 0 ? radius : 1.0;
    // Default eye on +z from the target, as close as keeps every bounding-box corner inside 95% of the view.
    Vec3d eye{};
    if (args.eye) {
        eye = *args.eye;
    } else {
        const double tx = 0.95 * std::tan(half_fov_x), ty = 0.95 * std::tan(half_fov);
        double d = 0;
        for (int c = 0; c < 8; ++c) {
            const Vec3d k{(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]};
            const double dz = k[2] - target[2];
            d = std::max({d, dz + std::fabs(k[0] - target[0]) / tx, dz + std::fabs(k[1] - target[1]) / ty, dz + r * 0.01});
        }
        eye = Vec3d{target[0], target[1], target[2] + d};
    }
    const Vec3d up = args.up.value_or(Vec3d{0, 1, 0});
    const double dist = length(sub(eye, mid));
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(eye[i])) {
            error = "the default eye for target (" + fmt(target[0]) + ", " + fmt(target[1]) + ", " + fmt(target[2]) +
                    ") lies beyond the range of double; give --eye";
            return false;
        }
    if (!std::isfinite(dist) || !std::isfinite((dist + r) * 1.01)) {
        error = "scene is too large to represent: eye and model lie more than " + fmt(1.79e308) + " apart";
        return false;
    }
    if (length(up) == 0) {
        error = "up vector is zero";
        return false;
    }
    if (length(sub(target, eye)) == 0) {
        error = "eye and target coincide";
        return false;
    }
    // Fit model + eye + target into the world cube.
    Vec3d blo = lo, bhi = hi;
    for (const Vec3d& p : {eye, target})
        for (int i = 0; i < 3; ++i) { blo[i] = std::min(blo[i], p[i]); bhi[i] = std::max(bhi[i], p[i]); }
    Vec3d centre{(blo[0] + bhi[0]) / 2, (blo[1] + bhi[1]) / 2, (blo[2] + bhi[2]) / 2};
    double half = 0;
    for (int i = 0; i < 3; ++i) half = std::max(half, (bhi[i] - blo[i]) / 2);
    if (!std::isfinite(half) || half <= 0 || !std::isfinite(kFitHalfExtent / half)) {
        error = "scene cannot be represented in fixed point (extent " + fmt(half * 2) + ")";
        return false;
    }
    double scale = kFitHalfExtent / half;
    if (args.fit_centre && args.fit_scale) {
        centre = *args.fit_centre;
        scale = *args.fit_scale;
    }
    // A far plane beyond the scene changes no visibility: far is clamped to just past the farthest box
    // corner, and the default near follows the clamped far, never a far given far beyond the scene.
    double farthest = 0;
    for (int c = 0; c < 8; ++c) {
        const Vec3d corner{(c & 1) ? bhi[0] : blo[0], (c & 2) ? bhi[1] : blo[1], (c & 4) ? bhi[2] : blo[2]};
        farthest = std::max(farthest, length(sub(corner, eye)));
    }
    if (args.near && !(*args.near > 0)) {
        error = "near plane must be > 0 (got " + fmt(*args.near) + ")";
        return false;
    }
    if (args.far && !(*args.far > 0)) {
        error = "far plane must be > 0 (got " + fmt(*args.far) + ")";
        return false;
    }
    if (args.near && args.far && !(*args.far > *args.near)) {
        error = "far plane (" + fmt(*args.far) + ") must be greater than near (" + fmt(*args.near) + ")";
        return false;
    }
    double far = std::min(args.far.value_or((dist + r) * 1.01), farthest * 1.01);
    if (args.near && !args.far) far = std::max(far, std::min(*args.near * 2, farthest * 1.01));
    double near = args.near.value_or(std::max((dist - r) * 0.99, far / 1000.0));
    if (!args.near && near >= far) near = far / 1000.0;
    if (!(far > near)) {
        error = "near plane (" + fmt(near) + ") lies beyond the whole scene (farthest point " + fmt(farthest) + ")";
        return false;
    }
    const double near_world = near * scale, far_world = far * scale;
    const double min_near = kMinNearRaw / 65536.0;
    if (near_world < min_near) {
        // A near plane the user did not give was derived (at least far / 1000): say so, and from what.
        const std::string from = args.near ? "" : " (not given: derived from the far plane " + fmt(far) + "; give --near)";
        error = "near plane " + fmt(near) + from + " is too small for a scene of extent " + fmt(half * 2) +
                " (hider needs near >= " + fmt(min_near / scale) + ")";
        return false;
    }
    if (args.fit_centre && args.fit_scale) {  // a world fixed before the camera (a BSP tree's): the camera must fit it
        const double limit = kWorldLimitRaw / 65536.0 / scale;  // model units from the world's centre, per axis
        const std::pair<const char*, const Vec3d*> points[] = {{"eye", &eye}, {"target", &target}};
        for (const auto& [what, p] : points)
            for (int i = 0; i < 3; ++i)
                if (!(std::fabs((*p)[i] - centre[i]) < limit)) {
                    error = std::string(what) + " (" + fmt((*p)[0]) + ", " + fmt((*p)[1]) + ", " + fmt((*p)[2]) +
                            ") lies outside the tree's world: eye and target must lie within " + fmt(limit) +
                            " model units of (" + fmt(centre[0]) + ", " + fmt(centre[1]) + ", " + fmt(centre[2]) +
                            ") on each axis";
                    return false;
                }
    }
    Scene s;
    s.width = args.width;
    s.height = args.height;
    s.centre = centre;
    s.scale = scale;
    auto fit = [&](const Vec3d& p, Vec3q16& q) {
        return to_q16((p[0] - centre[0]) * scale, q.x) && to_q16((p[1] - centre[1]) * scale, q.y) &&
               to_q16((p[2] - centre[2]) * scale, q.z);
    };
    s.positions.resize(model.vertices.size());
    for (size_t i = 0; i < model.vertices.size(); ++i)
        if (!fit(model.vertices[i], s.positions[i])) {
            error = "vertex " + std::to_string(i + 1) + " cannot be represented in fixed point";
            return false;
        }
    Camera& cam = s.camera;
    const double up_len = length(up);
    if (!fit(eye, cam.eye) || !fit(target, cam.target) || !to_q16(up[0] / up_len, cam.up.x) ||
        !to_q16(up[1] / up_len, cam.up.y) || !to_q16(up[2] / up_len, cam.up.z) || !to_q16(near_world, cam.near) ||
        !to_q16(far_world, cam.far)) {
        error = "camera cannot be represented in fixed point";
        return false;
    }
    cam.fovy = Angle::from_bam(static_cast<uint32_t>(std::llround(args.fov_deg / 360.0 * 4294967296.0)));
    // Faces become fans (v0, vi, vi+1); every triangle keeps its face's id.
    for (const ObjFace& f : model.faces) {
        for (size_t i = 1; i + 1 < f.v.size(); ++i) {
            const Tri t{{static_cast<uint16_t>(f.v[0]), static_cast<uint16_t>(f.v[i]), static_cast<uint16_t>(f.v[i + 1])}};
            s.tris.push_back(t);
            s.normals.push_back(face_normal(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]));
            s.ids.push_back(f.id);
        }
    }
    // make_view() answers invalid_argument for several reasons: name the one that applies, in user units.
    if (cam.far.raw() <= cam.near.raw()) {
        error = "near plane (" + fmt(near) + ") and far plane (" + fmt(far) +
                ") are too close together to tell apart in fixed point";
        return false;
    }
    if (cam.eye == cam.target) {
        error = "eye and target are too close together for a scene of extent " + fmt(half * 2);
        return false;
    }
    View probe;
    const Status st = make_view(cam, s.width, s.height, probe);
    if (st != Status::ok) {
        Transform unused;
        error = look_at(cam.eye, cam.target, cam.up, unused) == Status::invalid_argument
                    ? std::string("up vector is parallel to the view direction")
                    : std::string("camera rejected: ") + status_name(st);
        return false;
    }
    out = std::move(s);
    return true;
}

bool area_on_grid(const Vec3q16& a, const Vec3q16& b, const Vec3q16& c) {
    const Vec3i64 n = cross_raw(b - a, c - a);
    return n.x != 0 || n.y != 0 || n.z != 0;
}

std::vector<int> collapsed_faces(const ObjModel& model, const Scene& scene) {
    std::vector<int> lines;
    std::vector<std::array<double, 3>> p;
    std::array<double, 3> n{};
    for (const ObjFace& f : model.faces) {
        bool some_area = false;  // some fan triangle keeps an area
        for (size_t i = 1; i + 1 < f.v.size() && !some_area; ++i)
            some_area = area_on_grid(scene.positions[static_cast<size_t>(f.v[0])], scene.positions[static_cast<size_t>(f.v[i])],
                                     scene.positions[static_cast<size_t>(f.v[i + 1])]);
        if (some_area) continue;
        // An area in the model: a Newell normal clearly above the rounding of a face on a line.
        if (scaled_face(model, f, p, n) && std::fabs(n[0]) + std::fabs(n[1]) + std::fabs(n[2]) > 1e-9) lines.push_back(f.line);
    }
    return lines;
}

bool any_triangle_with_area(const Scene& scene) {
    for (const Tri& t : scene.tris)
        if (area_on_grid(scene.positions[t.v[0]], scene.positions[t.v[1]], scene.positions[t.v[2]])) return true;
    return false;
}

std::vector<std::string> collapse_warnings(const std::string& path, const std::vector<int>& lines) {
    return face_warnings(path, lines,
                         "face has an area in the model but none on the fixed-point grid: it is too small for the "
                         "model's extent and draws nothing");
}

}  // namespace hider::tool

// Ray-tracing scene reader (format: README.md, "Scene files (`hider-render --scene`)"). Every number is checked against the
// range lib/ can hold before it is converted to fixed point, once; meshes get their BVH here.
#include "common/ray_scene.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/cli.hpp"
#include "common/obj.hpp"

namespace hider::tool {

ray::Scene RayScene::view() const {
    objects_.clear();
    for (const MeshData& m : meshes) {
        ray::MeshObject o;
        o.mesh = {{m.positions.data(), m.positions.size()}, {m.tris.data(), m.tris.size()},
                  {m.normals.data(), m.normals.size()}, {}};
        o.bvh = m.bvh.view();
        o.surface = m.surface;
        o.triangle_surfaces = {m.surfaces.data(), m.surfaces.size()};
        objects_.push_back(o);
    }
    ray::Scene s;
    s.spheres = {spheres.data(), spheres.size()};
    s.planes = {planes.data(), planes.size()};
    s.meshes = {objects_.data(), objects_.size()};
    s.lights = {lights.data(), lights.size()};
    s.surfaces = {surfaces.data(), surfaces.size()};
    s.ambient = ambient;
    s.background = background;
    s.max_bounces = bounces;
    s.max_distance = max_distance;
    s.sphere_bound = sphere_bound;
    return s;
}

size_t RayScene::stack_depth() const {
    size_t d = 1;
    for (const MeshData& m : meshes) d = std::max<size_t>(d, m.bvh.header.max_depth);
    return d;
}

namespace {

constexpr size_t kMaxLineBytes = 4096;
constexpr double kWorld = 8192.0;  // the world cube: |coordinate| < 2^13 units

std::string fmt(double v) {
    std::ostringstream s;
    s.precision(8);
    s << v;
    return s.str();
}

/// One statement's tokens, read left to right; errors name the statement.
class Statement {
public:
    Statement(std::vector<std::string> tokens) : t_(std::move(tokens)) {}
    const std::string& keyword() const { return t_[0]; }
    bool done() const { return pos_ >= t_.size(); }
    const std::string& peek() const { return t_[pos_]; }
    std::string next() { return t_[pos_++]; }

    /// The next token as a number named `field`; false with `error` set when missing or malformed.
    bool number(const std::string& field, double& v, std::string& error) {
        if (done()) {
            error = keyword() + ": missing " + field;
            return false;
        }
        const std::string s = next();
        if (!parse_double(s, v)) {
            error = keyword() + ": bad number '" + printable_token(s) + "' for " + field;
            return false;
        }
        return true;
    }
    bool vec(const std::string& field, double (&v)[3], std::string& error) {
        static const char* kAxis[3] = {" x", " y", " z"};
        for (int i = 0; i < 3; ++i)
            if (!number(field + kAxis[i], v[i], error)) return false;
        return true;
    }
    /// False with `error` set when `field` was already given in this statement (else records it): a
    /// repeated attribute is a mistake, not an override.
    bool first_time(const std::string& field, std::string& error) {
        for (const std::string& f : seen_)
            if (f == field) {
                error = keyword() + ": " + field + " given twice";
                return false;
            }
        seen_.push_back(field);
        return true;
    }
    bool end(std::string& error) const {
        if (done()) return true;
        error = keyword() + ": unexpected '" + printable_token(t_[pos_]) + "'";
        return false;
    }

private:
    std::vector<std::string> t_;
    size_t pos_ = 1;
    std::vector<std::string> seen_;  // fields given so far (first_time())
};

bool world_point(const std::string& what, const double (&v)[3], Vec3q16& out, std::string& error) {
    Q16* c[3] = {&out.x, &out.y, &out.z};
    static const char* kAxis[3] = {" x ", " y ", " z "};
    for (int i = 0; i < 3; ++i) {
        const double raw = std::nearbyint(v[i] * 65536.0);
        if (!(std::fabs(raw) < ray::kRayWorldLimitRaw)) {  // also NaN
            error = what + kAxis[i] + fmt(v[i]) + " is outside the world cube (|coordinate| < 8192)";
            return false;
        }
        *c[i] = Q16::from_raw(static_cast<int32_t>(raw));
    }
    return true;
}

/// A direction as a unit Q30 vector; false for the zero vector.
bool unit_direction(const std::string& what, const double (&v)[3], Vec3q30& out, std::string& error) {
    // Scaled to 2^29 for the largest component, then made unit in lib/'s own arithmetic.
    const double m = std::fmax(std::fabs(v[0]), std::fmax(std::fabs(v[1]), std::fabs(v[2])));
    if (!(m > 0) || !std::isfinite(m)) {
        error = what + " is the zero vector";
        return false;
    }
    const int32_t c[3] = {static_cast<int32_t>(std::lround(v[0] / m * 536870912.0)),
                          static_cast<int32_t>(std::lround(v[1] / m * 536870912.0)),
                          static_cast<int32_t>(std::lround(v[2] / m * 536870912.0))};
    return ray::unit_q30(c[0], c[1], c[2], out) || (error = what + " is the zero vector", false);
}

bool colour(Statement& st, const std::string& field, Rgb& out, std::string& error) {
    double c[3];
    static const char* kChannel[3] = {" red", " green", " blue"};
    for (int i = 0; i < 3; ++i) {
        if (!st.number(field + kChannel[i], c[i], error)) return false;
        if (!(c[i] >= 0 && c[i] <= 1)) {
            error = st.keyword() + ": " + field + kChannel[i] + " " + fmt(c[i]) + " outside [0, 1]";
            return false;
        }
    }
    out = {static_cast<uint8_t>(std::lround(c[0] * 255)), static_cast<uint8_t>(std::lround(c[1] * 255)),
           static_cast<uint8_t>(std::lround(c[2] * 255))};
    return true;
}

/// Surface attributes up to the end of the statement: color, checker, reflect.
bool surface(Statement& st, RayScene& scene, uint16_t& index, std::string& error) {
    ray::Surface f;
    while (!st.done()) {
        const std::string a = st.next();
        if ((a == "color" || a == "checker" || a == "reflect") && !st.first_time(a, error)) return false;
        if (a == "color") {
            if (!colour(st, "color", f.color, error)) return false;
        } else if (a == "checker") {
            double size = 0;
            if (!st.number("checker size", size, error)) return false;
            if (!(size > 0 && size < kWorld) || std::lround(size * 65536) < 1) {
                error = st.keyword() + ": checker size " + fmt(size) + " outside (0, 8192)";
                return false;
            }
            f.checker_size = Q16::from_raw(static_cast<int32_t>(std::lround(size * 65536)));
            if (!colour(st, "checker", f.checker_color, error)) return false;
        } else if (a == "reflect") {
            double k = 0;
            if (!st.number("reflectivity", k, error)) return false;
            if (!(k >= 0 && k <= 1)) {
                error = st.keyword() + ": reflectivity " + fmt(k) + " outside [0, 1]";
                return false;
            }
            f.reflect_q15 = static_cast<uint16_t>(std::lround(k * ray::kReflectOne));
        } else {
            error = st.keyword() + ": unknown attribute '" + printable_token(a) + "' (expected color, checker or reflect)";
            return false;
        }
    }
    if (scene.surfaces.size() >= ray::kMaxSceneObjects) {
        error = "too many objects (at most 65535 surfaces)";
        return false;
    }
    index = static_cast<uint16_t>(scene.surfaces.size());
    scene.surfaces.push_back(f);
    return true;
}

}  // namespace

// Statement readers, one per keyword (each returns false with `error` set).
namespace {

struct CameraLine {
    bool seen = false;
    double eye[3]{}, target[3]{}, up[3]{0, 1, 0}, fov = 60;
    int line = 0;
};

bool read_camera(Statement& st, CameraLine& cam, std::string& error) {
    if (cam.seen) {
        error = "camera: given twice (first on line " + std::to_string(cam.line) + ")";
        return false;
    }
    bool eye = false, target = false;
    while (!st.done()) {
        const std::string k = st.next();
        if ((k == "eye" || k == "target" || k == "up" || k == "fov") && !st.first_time(k, error)) return false;
        if (k == "eye") { if (!st.vec("eye", cam.eye, error)) return false; eye = true; }
        else if (k == "target") { if (!st.vec("target", cam.target, error)) return false; target = true; }
        else if (k == "up") { if (!st.vec("up", cam.up, error)) return false; }
        else if (k == "fov") {
            if (!st.number("fov", cam.fov, error)) return false;
            if (!(cam.fov >= 0.5 && cam.fov <= 179.5)) {
                error = "camera: fov " + fmt(cam.fov) + " outside [0.5, 179.5] degrees";
                return false;
            }
        } else {
            error = "camera: unknown field '" + printable_token(k) + "' (expected eye, target, up or fov)";
            return false;
        }
    }
    if (!eye || !target) {
        error = std::string("camera: missing ") + (eye ? "target" : "eye");
        return false;
    }
    cam.seen = true;
    return true;
}

bool read_sphere(Statement& st, RayScene& s, std::string& error) {
    double c[3], r = 0;
    if (!st.vec("centre", c, error) || !st.number("radius", r, error)) return false;
    if (!(r > 0)) {
        error = "sphere: radius must be > 0 (got " + fmt(r) + ")";
        return false;
    }
    // The test lib/'s validate_scene() applies, on the values rounded to Q16 (so that a value that only
    // fails once rounded is reported here, with its line).
    auto fits = [r](double v) {
        return std::fabs(std::nearbyint(v * 65536.0)) + static_cast<double>(std::llround(r * 65536.0)) < ray::kRayWorldLimitRaw;
    };
    for (double v : c)
        if (!(std::fabs(v) + r < kWorld) || !fits(v)) {
            error = "sphere: centre " + fmt(v) + " with radius " + fmt(r) + " does not fit the world cube (|coordinate| + radius < 8192)";
            return false;
        }
    ray::Sphere sp{};
    if (!world_point("sphere: centre", c, sp.centre, error)) return false;
    sp.radius = Q16::from_raw(static_cast<int32_t>(std::lround(r * 65536)));
    if (sp.radius.raw() == 0) {
        error = "sphere: radius " + fmt(r) + " is below the fixed-point resolution (2^-16)";
        return false;
    }
    if (!surface(st, s, sp.surface, error)) return false;
    s.spheres.push_back(sp);
    return true;
}

bool read_plane(Statement& st, RayScene& s, std::string& error) {
    double n[3], d = 0;
    if (!st.vec("normal", n, error) || !st.number("offset", d, error)) return false;
    // |n|, from the normal scaled by its largest component when its squares overflow (1e300) or vanish.
    const double m = std::fmax(std::fabs(n[0]), std::fmax(std::fabs(n[1]), std::fabs(n[2])));
    if (!(m > 0)) {
        error = "plane: normal is the zero vector";
        return false;
    }
    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!std::isfinite(len) || !(len > 0))
        len = m * std::sqrt((n[0] / m) * (n[0] / m) + (n[1] / m) * (n[1] / m) + (n[2] / m) * (n[2] / m));
    ray::Plane pl{};
    if (!unit_direction("plane: normal", n, pl.normal, error)) return false;
    const double offset = d / len;  // n.p = d with n scaled to unit length
    if (!(std::fabs(offset) < 2 * kWorld) || std::llabs(std::llround(offset * 65536)) >= ray::kMaxPlaneOffsetRaw) {  // validate_scene()'s test
        error = "plane: offset " + fmt(offset) + " (along the unit normal) outside the world (|offset| < 16384)";
        return false;
    }
    pl.offset = Q16::from_raw(static_cast<int32_t>(std::lround(offset * 65536)));
    if (!surface(st, s, pl.surface, error)) return false;
    s.planes.push_back(pl);
    return true;
}

/// Appends triangle (a, b, c) to mesh m with its face normal.
void add_triangle(RayScene::MeshData& m, const Vec3q16& a, const Vec3q16& b, const Vec3q16& c) {
    const uint16_t base = static_cast<uint16_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c});
    m.tris.push_back({{base, static_cast<uint16_t>(base + 1), static_cast<uint16_t>(base + 2)}});
    m.normals.push_back(face_normal(a, b, c));
}

/// How far p lies from `eye` on any axis (raw), as bvh_reach() measures a mesh's box.
uint32_t reach_from(const Vec3q16& p, const Vec3q16& eye) {
    uint32_t reach = 0;
    for (const int64_t d : {int64_t{p.x.raw()} - eye.x.raw(), int64_t{p.y.raw()} - eye.y.raw(), int64_t{p.z.raw()} - eye.z.raw()})
        reach = std::max(reach, static_cast<uint32_t>(d < 0 ? -d : d));
    return reach;
}

/// How far a triangle reaches from `eye` on any axis (raw).
uint32_t triangle_reach(const RayScene::MeshData& m, const Tri& t, const Vec3q16& eye) {
    uint32_t reach = 0;
    for (const uint16_t v : t.v) reach = std::max(reach, reach_from(m.positions[v], eye));
    return reach;
}

/// The loose triangles as one mesh per vertex grid the eye's rays would give each of them alone
/// (ray::triangle_grid_shift() of its reach), nearest first, file order within each: one triangle far
/// away then no longer coarsens the grid of near ones (README "Ray tracing").
std::vector<RayScene::MeshData> split_by_grid(const RayScene::MeshData& loose, const Vec3q16& eye) {
    std::vector<RayScene::MeshData> groups;
    std::vector<int> keys(loose.tris.size());
    for (size_t i = 0; i < loose.tris.size(); ++i) keys[i] = ray::triangle_grid_shift(triangle_reach(loose, loose.tris[i], eye));
    std::vector<int> order(keys);
    std::sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    groups.resize(order.size());
    for (size_t i = 0; i < loose.tris.size(); ++i) {
        RayScene::MeshData& g = groups[static_cast<size_t>(std::lower_bound(order.begin(), order.end(), keys[i]) - order.begin())];
        const Tri& t = loose.tris[i];
        add_triangle(g, loose.positions[t.v[0]], loose.positions[t.v[1]], loose.positions[t.v[2]]);
        g.surfaces.push_back(loose.surfaces[i]);
    }
    return groups;
}

bool read_triangle(Statement& st, RayScene::MeshData& loose, RayScene& s, std::string& error) {
    Vec3q16 p[3];
    static const char* kNames[3] = {"vertex 1", "vertex 2", "vertex 3"};
    for (int i = 0; i < 3; ++i) {
        double v[3];
        if (!st.vec(kNames[i], v, error) || !world_point(std::string("triangle: ") + kNames[i], v, p[i], error)) return false;
    }
    if (!area_on_grid(p[0], p[1], p[2])) {  // refused as read_mesh() refuses a mesh of only such triangles
        error = "triangle: no area at the fixed-point resolution (2^-16): nothing of it could be hit";
        return false;
    }
    if (loose.positions.size() + 3 > kMaxMeshVertices) {
        error = "triangle: too many triangles (at most 21845)";
        return false;
    }
    uint16_t f = 0;
    if (!surface(st, s, f, error)) return false;
    add_triangle(loose, p[0], p[1], p[2]);
    loose.surfaces.push_back(f);
    return true;
}

/// rot = Rz(az) Ry(ay) Rx(ax) applied to v.
void rotate(const double (&deg)[3], double (&v)[3]) {
    for (int axis = 0; axis < 3; ++axis) {
        const double a = deg[axis] * M_PI / 180, c = std::cos(a), s = std::sin(a);
        const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // x: (y, z), y: (z, x), z: (x, y)
        const double vi = v[i], vj = v[j];
        v[i] = c * vi - s * vj;
        v[j] = s * vi + c * vj;
    }
}

bool read_mesh(Statement& st, const std::string& base_dir, RayScene& s, std::string& error) {
    if (st.done()) {
        error = "mesh: missing file name";
        return false;
    }
    const std::string file = st.next();
    double scale = 1, rot[3] = {0, 0, 0}, move[3] = {0, 0, 0};
    while (!st.done() && (st.peek() == "scale" || st.peek() == "rotate" || st.peek() == "translate")) {
        const std::string k = st.next();
        if (!st.first_time(k, error)) return false;
        if (k == "scale") {
            if (!st.number("scale", scale, error)) return false;
            if (!(scale > 0)) {
                error = "mesh: scale must be > 0 (got " + fmt(scale) + ")";
                return false;
            }
        } else if (k == "rotate") {
            if (!st.vec("rotate", rot, error)) return false;
        } else if (!st.vec("translate", move, error)) {
            return false;
        }
    }
    RayScene::MeshData m;
    if (!surface(st, s, m.surface, error)) return false;
    const std::string path = file.empty() || file[0] == '/' || base_dir.empty() ? file : base_dir + "/" + file;
    ObjModel model;
    ObjError oerr;
    if (!load_obj(path, model, oerr)) {
        error = "mesh: " + format(oerr);
        return false;
    }
    if (model.vertices.size() > kMaxMeshVertices || model.faces.empty()) {
        error = "mesh: " + path + " has " + std::to_string(model.vertices.size()) + " vertices and " +
                std::to_string(model.faces.size()) + " faces (1..65536 vertices and at least one face)";
        return false;
    }
    for (const auto& v : model.vertices) {
        double p[3] = {v[0] * scale, v[1] * scale, v[2] * scale};
        rotate(rot, p);
        for (int i = 0; i < 3; ++i) p[i] += move[i];
        Vec3q16 q{};
        if (!world_point("mesh: " + path + ": transformed vertex", p, q, error)) return false;
        m.positions.push_back(q);
    }
    for (const ObjFace& f : model.faces)
        for (size_t i = 1; i + 1 < f.v.size(); ++i) {
            const Tri t{{static_cast<uint16_t>(f.v[0]), static_cast<uint16_t>(f.v[i]), static_cast<uint16_t>(f.v[i + 1])}};
            m.tris.push_back(t);
            m.normals.push_back(face_normal(m.positions[t.v[0]], m.positions[t.v[1]], m.positions[t.v[2]]));
        }
    // Scaled below the fixed-point resolution, every triangle can round to a line or a point: nothing of the
    // mesh could be hit (as a sphere's radius below 2^-16 is refused).
    size_t flat = 0;
    for (const Tri& t : m.tris) flat += !area_on_grid(m.positions[t.v[0]], m.positions[t.v[1]], m.positions[t.v[2]]);
    if (flat == m.tris.size()) {
        error = "mesh: " + path + ": all " + std::to_string(flat) + " triangles have no area at the fixed-point resolution (2^-16) after scale " +
                fmt(scale) + ": nothing of it could be hit";
        return false;
    }
    if (!build_bvh({{m.positions.data(), m.positions.size()}, {m.tris.data(), m.tris.size()}, {}, {}}, m.bvh, error)) {
        error = "mesh: " + error;
        return false;
    }
    s.meshes.push_back(std::move(m));
    return true;
}

bool read_light(Statement& st, RayScene& s, std::string& error) {
    if (st.done() || (st.peek() != "point" && st.peek() != "directional")) {
        error = "light: expected 'point' or 'directional'" + (st.done() ? std::string() : " (got '" + printable_token(st.peek()) + "')");
        return false;
    }
    ray::Light l;
    l.kind = st.next() == "point" ? ray::LightKind::point : ray::LightKind::directional;
    double v[3];
    if (!st.vec(l.kind == ray::LightKind::point ? "position" : "direction", v, error)) return false;
    if (l.kind == ray::LightKind::point ? !world_point("light: position", v, l.position, error)
                                        : !unit_direction("light: direction", v, l.direction, error))
        return false;
    while (!st.done()) {
        const std::string k = st.next();
        if (k != "color") {
            error = "light: unknown attribute '" + printable_token(k) + "' (expected color)";
            return false;
        }
        if (!st.first_time(k, error)) return false;
        if (!colour(st, "color", l.color, error)) return false;
    }
    s.lights.push_back(l);
    return true;
}

bool read_setting(Statement& st, RayScene& s, std::string& error) {
    const std::string& k = st.keyword();
    if (k == "background" || k == "ambient") return colour(st, k, k == "background" ? s.background : s.ambient, error) && st.end(error);
    double v = 0;
    if (k == "size") {
        double h = 0;
        if (!st.number("width", v, error) || !st.number("height", h, error)) return false;
        if (v != std::floor(v) || h != std::floor(h) || v < 1 || h < 1 || v > kMaxFrameSide || h > kMaxFrameSide) {
            error = "size: " + fmt(v) + "x" + fmt(h) + " out of range (whole numbers 1..1024)";
            return false;
        }
        s.width = static_cast<int>(v);
        s.height = static_cast<int>(h);
        return st.end(error);
    }
    if (k == "bounces") {
        if (!st.number("count", v, error)) return false;
        if (v != std::floor(v) || v < 0 || v > kMaxSceneBounces) {
            error = "bounces: " + fmt(v) + " out of range (whole number 0.." + std::to_string(kMaxSceneBounces) + ")";
            return false;
        }
        s.bounces = static_cast<uint8_t>(v);
        return st.end(error);
    }
    if (!st.number("distance", v, error)) return false;  // max-distance
    if (!(v > 0 && v < 32768) || std::llround(v * 65536) > INT32_MAX) {  // also what rounds to 32768
        error = "max-distance: " + fmt(v) + " out of range (0 < distance < 32768)";
        return false;
    }
    s.max_distance = Q16::from_raw(static_cast<int32_t>(std::lround(v * 65536)));
    if (s.max_distance.raw() == 0) {
        error = "max-distance: " + fmt(v) + " is below the fixed-point resolution (2^-16)";
        return false;
    }
    return st.end(error);
}

bool finish_camera(const CameraLine& c, RayScene& s, std::string& error) {
    Camera& cam = s.camera;
    if (!world_point("camera: eye", c.eye, cam.eye, error) || !world_point("camera: target", c.target, cam.target, error))
        return false;
    Vec3q30 up{};
    if (!unit_direction("camera: up", c.up, up, error)) return false;
    cam.up = {Q16::from_raw(up.x.raw() >> 14), Q16::from_raw(up.y.raw() >> 14), Q16::from_raw(up.z.raw() >> 14)};
    cam.fovy = Angle::from_bam(static_cast<uint32_t>(std::llround(c.fov / 360.0 * 4294967296.0)));
    cam.near = Q16::from_raw(kMinNearRaw);  // the ray tracer has no near or far plane
    cam.far = Q16::from_int(16383);
    if (cam.eye == cam.target) {
        error = "camera: eye and target coincide";
        return false;
    }
    View probe;
    if (make_view(cam, s.width, s.height, probe) != Status::ok) {
        error = "camera: up is parallel to the view direction";
        return false;
    }
    return true;
}

}  // namespace

bool parse_ray_scene(std::istream& in, const std::string& name, const std::string& base_dir, RayScene& out,
                     std::string& error) {
    RayScene s;
    RayScene::MeshData loose;
    CameraLine cam;
    std::string text;
    int line = 0;
    auto fail = [&](const std::string& what) {
        error = name + ":" + std::to_string(line) + ": " + what;
        return false;
    };
    // One line, at most kMaxLineBytes: a longer one (or /dev/zero) fails when it passes the limit, not
    // after the whole line is in memory. 1: a line, 0: the end, -1: too long.
    auto next_line = [&in](std::string& into) -> int {
        into.clear();
        for (int c = in.get(); c != std::char_traits<char>::eof(); c = in.get()) {
            if (c == '\n') return 1;
            if (into.size() == kMaxLineBytes) return -1;
            into.push_back(static_cast<char>(c));
        }
        return into.empty() ? 0 : 1;
    };
    for (int got = next_line(text); got != 0; got = next_line(text)) {
        ++line;
        if (got < 0) return fail("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
        if (line == 1 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // a UTF-8 byte order mark
        const size_t hash = text.find('#');
        if (hash != std::string::npos) text.resize(hash);
        std::istringstream words(text);
        std::vector<std::string> tokens;
        for (std::string w; words >> w;) tokens.push_back(w);
        if (tokens.empty()) continue;
        Statement st(std::move(tokens));
        const std::string& k = st.keyword();
        std::string why;
        bool ok = false;
        if (k == "camera") { ok = read_camera(st, cam, why); cam.line = line; }
        else if (k == "sphere") ok = read_sphere(st, s, why);
        else if (k == "plane") ok = read_plane(st, s, why);
        else if (k == "triangle") ok = read_triangle(st, loose, s, why);
        else if (k == "mesh") ok = read_mesh(st, base_dir, s, why);
        else if (k == "light") ok = read_light(st, s, why);
        else if (k == "size" || k == "background" || k == "ambient" || k == "bounces" || k == "max-distance") ok = read_setting(st, s, why);
        else why = "unknown keyword '" + printable_token(k) + "'";
        if (!ok) return fail(why);
        if (s.spheres.size() > ray::kMaxSceneObjects || s.planes.size() > ray::kMaxSceneObjects ||
            s.lights.size() > ray::kMaxSceneObjects || s.meshes.size() >= ray::kMaxSceneObjects)
            return fail("too many objects of one kind (at most 65535)");
    }
    if (in.bad()) return fail("read error");
    line = cam.line;
    if (!cam.seen) {
        error = name + ": no camera line (camera eye X Y Z target X Y Z [up X Y Z] [fov DEG])";
        return false;
    }
    std::string why;
    if (!finish_camera(cam, s, why)) return fail(why);
    for (RayScene::MeshData& group : split_by_grid(loose, s.camera.eye)) {
        if (!build_bvh({{group.positions.data(), group.positions.size()}, {group.tris.data(), group.tris.size()}, {}, {}},
                       group.bvh, why))
            return fail(why);
        s.meshes.push_back(std::move(group));
    }
    if (s.meshes.size() > ray::kMaxSceneObjects) return fail("too many objects of one kind (at most 65535)");
    s.sphere_bound = ray::enclosing_sphere({s.spheres.data(), s.spheres.size()});
    std::vector<ray::BvhStackEntry> stack(s.stack_depth());
    const Status st = ray::validate_scene(s.view(), {stack.data(), stack.size()});
    if (st != Status::ok) {
        error = name + ": scene rejected by lib/: " + status_name(st);
        return false;
    }
    out = std::move(s);
    return true;
}

bool load_ray_scene(const std::string& path, RayScene& out, std::string& error) {
    struct stat st {};  // POSIX stat, as load_obj(): a directory opens on Linux, then fails to read
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        error = path + ": cannot open file: " + std::strerror(EISDIR);
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot open file: " + std::strerror(errno);
        return false;
    }
    const size_t slash = path.find_last_of('/');
    return parse_ray_scene(in, path, slash == std::string::npos ? std::string() : path.substr(0, slash), out, error);
}

std::vector<std::string> grid_warnings(const RayScene& s) {
    std::vector<std::string> out;
    const Vec3q16 eye = s.camera.eye;
    for (size_t m = 0; m < s.meshes.size(); ++m) {
        const RayScene::MeshData& md = s.meshes[m];
        uint32_t reach = 0;
        for (const Vec3q16& p : md.positions) reach = std::max(reach, reach_from(p, eye));
        const int shift = ray::triangle_grid_shift(reach);
        if (shift == 0) continue;
        size_t bad = 0;
        for (const Tri& t : md.tris) {
            int64_t snapped[3][3], exact[3][3];
            for (int k = 0; k < 3; ++k) {
                const Vec3q16& p = md.positions[t.v[k]];
                const int64_t d[3] = {int64_t{p.x.raw()} - eye.x.raw(), int64_t{p.y.raw()} - eye.y.raw(), int64_t{p.z.raw()} - eye.z.raw()};
                for (int i = 0; i < 3; ++i) {
                    exact[k][i] = d[i];
                    snapped[k][i] = d[i] >> shift;  // the triangle test's floor
                }
            }
            auto normal = [](const int64_t (&v)[3][3], __int128 (&n)[3]) {
                const int64_t e1[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
                const int64_t e2[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
                n[0] = static_cast<__int128>(e1[1]) * e2[2] - static_cast<__int128>(e1[2]) * e2[1];
                n[1] = static_cast<__int128>(e1[2]) * e2[0] - static_cast<__int128>(e1[0]) * e2[2];
                n[2] = static_cast<__int128>(e1[0]) * e2[1] - static_cast<__int128>(e1[1]) * e2[0];
            };
            __int128 ns[3], ne[3];
            normal(snapped, ns);
            normal(exact, ne);
            // the snapped normal against the exact one's direction (doubles: only the sign matters)
            const double agree = static_cast<double>(ns[0]) * static_cast<double>(ne[0]) +
                                 static_cast<double>(ns[1]) * static_cast<double>(ne[1]) +
                                 static_cast<double>(ns[2]) * static_cast<double>(ne[2]);
            // an edge under 8 steps: its facet turns by a large angle on the grid (over |cos| at grazing rays)
            int64_t shortest = INT64_MAX;
            for (int k = 0; k < 3; ++k) {
                const int64_t(&a)[3] = snapped[k];
                const int64_t(&b)[3] = snapped[(k + 1) % 3];
                auto span = [](int64_t v) { return v < 0 ? -v : v; };
                shortest = std::min(shortest, std::max({span(b[0] - a[0]), span(b[1] - a[1]), span(b[2] - a[2])}));
            }
            if (agree <= 0 || shortest < 8) ++bad;
        }
        if (bad == 0) continue;
        char line[400];
        std::snprintf(line, sizeof line,
                      "mesh %zu%s reaches %.0f units from the eye, so ray tests see its vertices on a grid of %g units: "
                      "%zu of its %zu triangles have an edge under 8 steps of it or collapse, and may turn over or leave holes "
                      "where rays graze them (put distant geometry in a mesh of its own, or use a plane)",
                      m + 1, md.surfaces.empty() ? "" : " (loose `triangle` lines)", reach / 65536.0,
                      static_cast<double>(int64_t{1} << shift) / 65536.0, bad, md.tris.size());
        out.emplace_back(line);
    }
    return out;
}

}  // namespace hider::tool

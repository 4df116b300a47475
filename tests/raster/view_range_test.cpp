// check_view_range() and its callers: a model transform (with_model()) can carry a valid mesh so far
// from the eye that apply()'s view coordinates wrap modulo 2^32. project_vertices(), draw_bsp() and
// order_bsp() refuse such a view and draw nothing; placements that do not wrap, even far outside the
// world range, draw as the double reference does. The O(1) bound is checked at its edge and against
// exact view coordinates on random placements; three cases a red team found in the first version: a
// translation that wraps inside compose(), a view z of INT32_MIN, and a composed entry just past -1.
#include <hider/bsp/order.hpp>
#include <hider/bsp/walk.hpp>
#include <hider/raster/zbuffer.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <doctest/doctest.h>

#include "bsp/bsp_blobs.hpp"
#include "bsp/bsp_exercise.hpp"
#include "support/reference.hpp"

using namespace hider;

namespace {

Vec3q16 units(int32_t x, int32_t y, int32_t z) { return {Q16::from_int(x), Q16::from_int(y), Q16::from_int(z)}; }

/// The exact view coordinate of p, as the test computes it: floor(R p / 2^30) + t in 64 bits.
int64_t exact_coordinate(const Transform& t, int row, const Vec3q16& p) {
    const Q30(&r)[3] = t.rot.m[row];
    const int64_t sum = int64_t{r[0].raw()} * p.x.raw() + int64_t{r[1].raw()} * p.y.raw() + int64_t{r[2].raw()} * p.z.raw();
    const int64_t floor = sum >= 0 ? sum / (int64_t{1} << 30) : -((-sum + (int64_t{1} << 30) - 1) / (int64_t{1} << 30));
    const int32_t tr[3] = {t.trans.x.raw(), t.trans.y.raw(), t.trans.z.raw()};
    return floor + tr[row];
}

bool wraps(const Transform& t, const Vec3q16& p) {
    for (int row = 0; row < 3; ++row) {
        const int64_t c = exact_coordinate(t, row, p);
        if (c <= INT32_MIN || c > INT32_MAX) return true;  // INT32_MIN: w = -z would overflow
    }
    return false;
}

Transform turned(uint32_t a, uint32_t b, uint32_t c, Vec3q16 trans) {
    Transform t;
    t.rot = mul(rotation_y(Angle::from_bam(a)), mul(rotation_x(Angle::from_bam(b)), rotation_z(Angle::from_bam(c))));
    t.trans = trans;
    return t;
}

ref::Vec3d to_d(const Vec3q16& p) { return {p.x.raw() / 65536.0, p.y.raw() / 65536.0, p.z.raw() / 65536.0}; }

ref::Vec3d placed_d(const Transform& t, const Vec3q16& p) {
    const ref::Vec3d q = to_d(p), tr = to_d(t.trans);
    const double v[3] = {q.x, q.y, q.z}, o[3] = {tr.x, tr.y, tr.z};
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = o[i] + (t.rot.m[i][0].raw() * v[0] + t.rot.m[i][1].raw() * v[1] + t.rot.m[i][2].raw() * v[2]) / 1073741824.0;
    return {r[0], r[1], r[2]};
}

std::vector<uint32_t> ids_of(const std::vector<Rgb888>& px) {
    std::vector<uint32_t> ids(px.size());
    for (size_t i = 0; i < px.size(); ++i) ids[i] = (uint32_t{px[i].r} << 16) | (uint32_t{px[i].g} << 8) | px[i].b;
    return ids;
}

/// A camera looking from eye to target, y up, near 1 unit.
Camera camera(Vec3q16 eye, Vec3q16 target, int fov_degrees, int far_units) {
    Camera cam;
    cam.eye = eye;
    cam.target = target;
    cam.up = units(0, 1, 0);
    cam.fovy = Angle::from_degrees(Q16::from_int(fov_degrees));
    cam.near = Q16::from_int(1);
    cam.far = Q16::from_int(far_units);
    return cam;
}

/// The z-buffer's face ids (Shade::id, no culling, 32-bit depth) of a W x H frame; the status in `st`.
std::vector<Rgb888> zbuffer_frame(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, int w, int h, FrameStats& st) {
    std::vector<Rgb888> px(static_cast<size_t>(w) * h);
    std::vector<uint32_t> depth(px.size());
    const auto f = frame_view<Rgb888Format, uint32_t>(px.data(), depth.data(), w, h);
    clear(f, Rgb{0, 0, 0});
    DrawOptions opt;
    opt.shade = Shade::id;
    opt.cull = false;
    st = draw_zbuffer(view, mesh, verts, f, opt);
    return px;
}

/// A cube of side 2 half units about the origin, twelve triangles.
struct Cube {
    std::vector<Vec3q16> pos;
    std::vector<Tri> tris;
    explicit Cube(int32_t half) {
        for (int k = 0; k < 8; ++k) pos.push_back(units(k & 1 ? half : -half, k & 2 ? half : -half, k & 4 ? half : -half));
        const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& q : quads) {
            tris.push_back({{uint16_t(q[0]), uint16_t(q[1]), uint16_t(q[2])}});
            tris.push_back({{uint16_t(q[0]), uint16_t(q[2]), uint16_t(q[3])}});
        }
    }
    Mesh mesh() const { return Mesh{{pos.data(), pos.size()}, {tris.data(), tris.size()}, {}, {}}; }
};

long painted(const std::vector<Rgb888>& px) {
    long n = 0;
    for (const Rgb888& c : px) n += (c.r | c.g | c.b) != 0;
    return n;
}

/// The z-buffer's face ids of `mesh` under `model` (48 x 36, near 1) and the double reference's.
struct Drawn {
    Status projected = Status::ok;
    FrameStats st;
    std::vector<uint32_t> ids, want;
};
Drawn draw_placed(const Camera& cam, const Mesh& mesh, const Transform& model, double fovy_deg, double far) {
    constexpr int W = 48, H = 36;
    Drawn d;
    View view;
    REQUIRE(make_view(cam, W, H, view) == Status::ok);
    const View placed = with_model(view, model);
    std::vector<ScreenVertex> verts(mesh.positions.size());
    d.projected = project_vertices(placed, mesh.positions, {verts.data(), verts.size()});
    d.ids = ids_of(zbuffer_frame(placed, mesh, {verts.data(), verts.size()}, W, H, d.st));
    std::vector<ref::RefTriangle> rt;
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        ref::RefTriangle r{};
        for (int k = 0; k < 3; ++k) r.v[k] = placed_d(model, mesh.positions[mesh.tris[t].v[k]]);
        r.id = static_cast<uint32_t>(t + 1);
        rt.push_back(r);
    }
    d.want = ref::render_ids(rt, ref::RefCamera{to_d(cam.eye), to_d(cam.target), to_d(cam.up), fovy_deg, 1.0, far, W, H}, false);
    return d;
}

long nonzero(const std::vector<uint32_t>& ids) {
    long n = 0;
    for (const uint32_t v : ids) n += v != 0;
    return n;
}

}  // namespace

TEST_CASE("check_view_range: the O(1) bound's edge, matrix entries, and the exact test behind it") {
    // Identity rows: the cube of 2^29 reaches |t| + 2^29 + 1 (the floor), which must stay <= INT32_MAX.
    const int32_t edge = INT32_MAX - (int32_t{1} << 29) - 1;
    for (int axis = 0; axis < 3; ++axis)
        for (const int32_t sign : {1, -1}) {
            Transform t;
            Q16* c = axis == 0 ? &t.trans.x : axis == 1 ? &t.trans.y : &t.trans.z;
            *c = Q16::from_raw(sign * edge);
            CHECK(check_view_range(t, kWorldLimitBits) == Status::ok);
            *c = Q16::from_raw(sign * (edge + 1));
            CHECK(check_view_range(t, kWorldLimitBits) == Status::out_of_range);
            CHECK(check_view_range(t, kWorldLimitBits - 2) == Status::ok);  // the BSP's smaller cube
            // Past the bound, the positions decide exactly: the origin is fine; a position at the cube's
            // side reaches INT32_MAX (or -INT32_MAX) with the translation below and is refused one raw unit further.
            const Vec3q16 origin[1] = {units(0, 0, 0)};
            CHECK(check_view_range(t, Span<const Vec3q16>{origin, 1}) == Status::ok);
            Vec3q16 p[1] = {};
            Q16* pc = axis == 0 ? &p[0].x : axis == 1 ? &p[0].y : &p[0].z;
            *pc = Q16::from_raw(sign * (kWorldLimitRaw - 1));
            // (-INT32_MAX, not INT32_MIN, on the negative side: to_view_point() negates z.)
            const int32_t last = sign * (INT32_MAX - (kWorldLimitRaw - 1));
            *c = Q16::from_raw(last);
            CHECK(check_view_range(t, kWorldLimitBits) == Status::out_of_range);
            CHECK(check_view_range(t, Span<const Vec3q16>{p, 1}) == Status::ok);
            *c = Q16::from_raw(last + sign);
            CHECK(check_view_range(t, Span<const Vec3q16>{p, 1}) == Status::out_of_range);
            *pc = Q16::from_raw(-sign * (kWorldLimitRaw - 1));  // the far side of the cube comes back
            CHECK(check_view_range(t, Span<const Vec3q16>{p, 1}) == Status::ok);
        }
    // Entries of +-1 are a rotation's; beyond, the 32-bit transforms do not hold (ARMv6-M's split).
    Transform t;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            for (const int32_t e : {Q30::kOne, -Q30::kOne}) {
                t.rot.m[i][j] = Q30::from_raw(e);
                CHECK(check_view_range(t, kWorldLimitBits) == Status::ok);
            }
            for (const int32_t e : {Q30::kOne + 1, -Q30::kOne - 1}) {
                t.rot.m[i][j] = Q30::from_raw(e);
                CHECK(check_view_range(t, kWorldLimitBits) == Status::invalid_argument);
                CHECK(check_view_range(t, Span<const Vec3q16>{}) == Status::invalid_argument);
            }
            t.rot.m[i][j] = Q30::from_raw(i == j ? Q30::kOne : 0);
        }
}

TEST_CASE("check_view_range agrees with exact view coordinates on random placements; the O(1) bound never accepts a wrap") {
    // Mesh positions at the world cube's corners and random points; rotations from three turns;
    // translations spread over all of int32, so both sides of the bound and of the wrap are met.
    std::mt19937 rng(20261205);
    const int32_t m = kWorldLimitRaw - 1;
    std::vector<Vec3q16> pos;
    for (int k = 0; k < 8; ++k)
        pos.push_back({Q16::from_raw(k & 1 ? m : -m), Q16::from_raw(k & 2 ? m : -m), Q16::from_raw(k & 4 ? m : -m)});
    long accepted_fast = 0, accepted_exact = 0, refused = 0;
    for (int n = 0; n < 20000; ++n) {
        std::vector<Vec3q16> p;
        const int count = 1 + static_cast<int>(rng() % 6);
        for (int i = 0; i < count; ++i) {
            if (rng() % 2 != 0) {
                p.push_back(pos[rng() % 8]);
            } else {
                auto c = [&] { return Q16::from_raw(static_cast<int32_t>(rng() % (2u * uint32_t(m) + 1)) - m); };
                p.push_back({c(), c(), c()});
            }
        }
        auto tr = [&] { return Q16::from_raw(static_cast<int32_t>(rng())); };
        const Transform t = turned(rng(), rng(), rng(), {tr(), tr(), tr()});
        bool any_wrap = false;
        for (const Vec3q16& q : p) any_wrap = any_wrap || wraps(t, q);
        const Status s = check_view_range(t, Span<const Vec3q16>{p.data(), p.size()});
        CHECK(s == (any_wrap ? Status::out_of_range : Status::ok));
        if (check_view_range(t, kWorldLimitBits) == Status::ok) {
            CHECK_FALSE(any_wrap);
            ++accepted_fast;
        } else if (!any_wrap) {
            ++accepted_exact;
        } else {
            ++refused;
        }
    }
    MESSAGE("accepted by the bound " << accepted_fast << ", exactly " << accepted_exact << ", refused " << refused);
    CHECK(accepted_fast > 1000);
    CHECK(accepted_exact > 1000);
    CHECK(refused > 1000);
}

TEST_CASE("project_vertices refuses a placement whose view coordinates wrap and marks every vertex outside") {
    // The red team's floor: half a turn about the y axis through (-8000, 0, -8000) puts a corner at
    // (-24000, -100, -24000), about 43,800 units from this eye: view coordinates past 2^15 units.
    const Vec3q16 pos[4] = {units(8000, -100, 8000), units(-8000, -100, 8000), units(-8000, -100, -8000), units(8000, -100, -8000)};
    const Tri tris[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    const Mesh mesh{{pos, 4}, {tris, 2}, {}, {}};
    REQUIRE(validate(mesh) == Status::ok);
    const Camera cam = camera(units(7000, 300, 7000), units(-8000, 0, -8000), 60, 30000);
    constexpr int W = 64, H = 48;
    View view;
    REQUIRE(make_view(cam, W, H, view) == Status::ok);
    const Vec3q16 axis = units(-8000, 0, -8000);
    auto turn = [&](uint32_t bam) {
        Transform t, r;
        t.rot = rotation_y(Angle::from_bam(bam));
        r.rot = t.rot;
        t.trans = axis - apply(r, axis);
        return t;
    };
    const View half = with_model(view, turn(0x80000000u));
    bool wrapped = false;
    for (const Vec3q16& p : pos) wrapped = wrapped || wraps(half.to_view, p);
    REQUIRE(wrapped);
    ScreenVertex verts[4];
    for (ScreenVertex& v : verts) v = ScreenVertex{1, 2, 3};
    DepthRange range;
    range.min = 7;
    CHECK(project_vertices(half, mesh.positions, {verts, 4}, &range) == Status::out_of_range);
    for (const ScreenVertex& v : verts) CHECK(v.outside() == kClipNear);
    CHECK(range.min == kDepthFar);  // empty
    CHECK(range.max == kDepthNear);
    // A caller that ignores the status draws nothing rather than the wrapped floor.
    FrameStats st;
    CHECK(painted(zbuffer_frame(half, mesh, {verts, 4}, W, H, st)) == 0);
    CHECK(st.ok());
    // Unturned, the same floor is drawn (and the bound takes the O(1) path).
    const View still = with_model(view, turn(0));
    CHECK(check_view_range(still.to_view, kWorldLimitBits) == Status::ok);
    CHECK(project_vertices(still, mesh.positions, {verts, 4}) == Status::ok);
    CHECK(painted(zbuffer_frame(still, mesh, {verts, 4}, W, H, st)) > W * H / 4);
    CHECK(st.ok());
}

TEST_CASE("placements far outside the world range draw as the double reference does, unless they wrap") {
    // A cube 2,000 units wide placed 9,000 to 40,000 units from a random eye, in a random direction the
    // camera looks along: those that stay inside int32 in view space must give the reference's picture
    // (exact drawing past the world range), those that leave it must be refused and draw nothing.
    const Cube cube(1000);
    const std::vector<Vec3q16>& pos = cube.pos;
    const Mesh mesh = cube.mesh();
    REQUIRE(validate(mesh) == Status::ok);
    constexpr int W = 48, H = 36;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    long drawn = 0, refused = 0, wrong = 0, skipped = 0, empty = 0;
    for (int n = 0; n < 240; ++n) {
        const Vec3q16 eye = units(static_cast<int32_t>(unit(rng) * 6000), static_cast<int32_t>(unit(rng) * 6000),
                                  static_cast<int32_t>(unit(rng) * 6000));
        double d[3] = {unit(rng), unit(rng), unit(rng)};
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (len < 0.2) continue;
        const double dist = 9000 + (n % 8) * 4000 + 1000 * unit(rng);
        int32_t c[3];
        bool fits = true;
        const int32_t e[3] = {eye.x.floor_int(), eye.y.floor_int(), eye.z.floor_int()};
        for (int i = 0; i < 3; ++i) {
            const double v = e[i] + d[i] / len * dist;
            fits = fits && std::fabs(v) < 32000;
            c[i] = static_cast<int32_t>(v);
        }
        if (!fits) { ++skipped; continue; }  // the translation itself must be a Q16 value
        const Camera cam = camera(eye,
                                  units(e[0] + static_cast<int32_t>(d[0] / len * 100), e[1] + static_cast<int32_t>(d[1] / len * 100),
                                        e[2] + static_cast<int32_t>(d[2] / len * 100)),
                                  10, 32000);
        View view;
        if (make_view(cam, W, H, view) != Status::ok) continue;  // up along the view
        const Transform model = turned(rng(), rng(), rng(), units(c[0], c[1], c[2]));
        const View placed = with_model(view, model);
        bool any_wrap = false;
        for (const Vec3q16& p : pos) any_wrap = any_wrap || wraps(placed.to_view, p);
        CAPTURE(n);
        const Drawn dr = draw_placed(cam, mesh, model, 10.0, 32000.0);
        CHECK(dr.projected == (any_wrap ? Status::out_of_range : Status::ok));
        REQUIRE(dr.st.ok());
        if (any_wrap) {
            ++refused;
            CHECK(nonzero(dr.ids) == 0);
            continue;
        }
        wrong += ref::compare_ids(dr.ids, dr.want, W, H).off_edge_mismatch;
        if (nonzero(dr.ids) > 0) ++drawn; else ++empty;
    }
    MESSAGE("drawn " << drawn << ", refused " << refused << ", skipped " << skipped << ", empty " << empty << ", off-edge pixels unlike the reference " << wrong);
    CHECK(wrong == 0);
    CHECK(drawn > 40);
    CHECK(refused > 20);
}

TEST_CASE("draw_bsp and order_bsp refuse a model transform that carries the tree's cube where view coordinates wrap") {
    const std::vector<uint8_t> bytes = test::blob_of_obj("models/suzanne.obj");
    std::vector<uint64_t> store;
    const Span<const uint8_t> blob = test::aligned_copy(bytes.data(), bytes.size(), store);
    std::vector<uint32_t> stack(4096);
    BspTree tree;
    REQUIRE(bsp_load(blob, {stack.data(), stack.size()}, tree) == Status::ok);
    const Camera cam = camera(units(-8000, 0, 0), units(0, 0, 0), 20, 32000);
    constexpr int W = 32, H = 24;
    View view;
    REQUIRE(make_view(cam, W, H, view) == Status::ok);
    std::vector<Rgb888> px(W * H);
    const auto f = frame_view<Rgb888Format, uint16_t>(px.data(), nullptr, W, H);
    DrawOptions opt;
    std::vector<ScreenVertex> verts(tree.vertices.size());
    std::vector<BspDrawEntry> entries(4096);
    BoundedList<BspDrawEntry> list(entries.data(), entries.size());
    std::vector<uint32_t> coverage(H * coverage_words(W));
    // At the world range's edge, 16,000 units away: the cube of 2^27 raw (2,048 units) fits.
    Transform model;
    model.trans = units(8000, 0, 0);
    const View edge = with_model(view, model);
    mark_unprojected({verts.data(), verts.size()});
    FrameStats st = draw_bsp(edge, apply_inverse(model, cam.eye), tree, {verts.data(), verts.size()}, f, opt, {stack.data(), stack.size()});
    CHECK(st.ok());
    CHECK(painted(px) > 0);
    CHECK(order_bsp(edge, apply_inverse(model, cam.eye), tree, {verts.data(), verts.size()}, opt, {stack.data(), stack.size()}, list).ok());
    CHECK(list.size() > 0);
    // The world eye is not the view's: refused by every walk (check_bsp_view()).
    CHECK(draw_bsp(edge, cam.eye, tree, {verts.data(), verts.size()}, f, opt, {stack.data(), stack.size()}).status ==
          Status::invalid_argument);
    CHECK(draw_bsp_front(edge, cam.eye, tree, {verts.data(), verts.size()}, f, opt, {stack.data(), stack.size()},
                         {coverage.data(), coverage.size()})
              .status == Status::invalid_argument);
    CHECK(order_bsp(edge, cam.eye, tree, {verts.data(), verts.size()}, opt, {stack.data(), stack.size()}, list).status ==
          Status::invalid_argument);
    // 31,000 units along the view: the cube's far side passes 2^15 units.
    model.trans = units(23000, 0, 0);
    const View beyond = with_model(view, model);
    mark_unprojected({verts.data(), verts.size()});
    clear(f, Rgb{0, 0, 0});
    st = draw_bsp(beyond, apply_inverse(model, cam.eye), tree, {verts.data(), verts.size()}, f, opt, {stack.data(), stack.size()});
    CHECK(st.status == Status::out_of_range);
    CHECK(painted(px) == 0);
    CHECK(st.nodes_visited == 0);
    st = draw_bsp_front(beyond, apply_inverse(model, cam.eye), tree, {verts.data(), verts.size()}, f, opt, {stack.data(), stack.size()},
                        {coverage.data(), coverage.size()});
    CHECK(st.status == Status::out_of_range);
    CHECK(order_bsp(beyond, apply_inverse(model, cam.eye), tree, {verts.data(), verts.size()}, opt, {stack.data(), stack.size()}, list).status ==
          Status::out_of_range);
    CHECK(list.size() == 0);
    // A matrix that is no rotation is refused before anything is drawn.
    View scaled = view;
    scaled.to_view.rot.m[1][1] = Q30::from_raw(Q30::kOne + 1);
    st = draw_bsp(scaled, cam.eye, tree, {verts.data(), verts.size()}, f, opt, {stack.data(), stack.size()});
    CHECK(st.status == Status::invalid_argument);
}

TEST_CASE("with_model(): a translation that wraps in compose() is not taken for a placement in front of the eye") {
    // A 2,000-unit square 4,000 units along +z in the model; the eye at z = -8,000 looks down -z and the
    // model moves the square 32,000 units along +z: 44,000 units behind the eye. compose() wraps that
    // translation (40,000 units, past 2^15) to 25,536 units in front, where every vertex is an int32.
    const Vec3q16 pos[4] = {units(-1000, -1000, 4000), units(1000, -1000, 4000), units(1000, 1000, 4000), units(-1000, 1000, 4000)};
    const Tri tris[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    const Mesh mesh{{pos, 4}, {tris, 2}, {}, {}};
    REQUIRE(validate(mesh) == Status::ok);
    Transform model;
    model.trans = units(0, 0, 32000);
    const Drawn d = draw_placed(camera(units(0, 0, -8000), units(0, 0, -8100), 10, 32000), mesh, model, 10.0, 32000.0);
    REQUIRE(nonzero(d.want) == 0);  // behind the eye
    CHECK(d.st.ok());
    CHECK(d.projected == Status::out_of_range);  // was ok
    CHECK(nonzero(d.ids) == 0);                  // was 400 pixels of the square
}

TEST_CASE("check_view_range(): a view z of INT32_MIN, which to_view_point() cannot negate, is refused or drawn right") {
    // One vertex exactly 2^15 units ahead (view z = INT32_MIN raw, beyond the far plane), two 24,768 units
    // ahead: the far plane should cut the tip off; the negated INT32_MIN put it behind the near plane.
    const Vec3q16 pos[3] = {units(0, 0, 0), units(-1000, -1000, 8000), units(1000, -1000, 8000)};
    const Tri tris[1] = {{{0, 1, 2}}};
    const Mesh mesh{{pos, 3}, {tris, 1}, {}, {}};
    REQUIRE(validate(mesh) == Status::ok);
    Transform model;
    model.trans = {Q16::from_int(0), Q16::from_int(0), Q16::from_raw(INT32_MIN)};
    const Drawn d = draw_placed(camera(units(0, 0, 0), units(0, 0, -100), 10, 32000), mesh, model, 10.0, 32000.0);
    CHECK(d.st.ok());
    if (d.projected == Status::ok) {
        const ref::Agreement ag = ref::compare_ids(d.ids, d.want, 48, 36);
        CHECK(ag.off_edge_mismatch == 0);  // was 232 (a wedge below the triangle)
    } else {
        CHECK(d.projected == Status::out_of_range);
        CHECK(nonzero(d.ids) == 0);
    }
}

TEST_CASE("with_model(): a rotation composed with the view's is not refused for an entry one raw unit past +-1") {
    // A cube at the origin seen from (100, 0, -100), the model turned 45 degrees about y: compose()
    // floors an entry to -2^30 - 1, and check_view_range() called that no rotation (invalid_argument).
    const Cube cube(20);
    const Mesh mesh = cube.mesh();
    Transform model;
    model.rot = rotation_y(Angle::from_bam(0x20000000u));  // 45 degrees
    REQUIRE(validate(mesh, model) == Status::ok);
    const Camera cam = camera(units(100, 0, -100), units(0, 0, 0), 60, 1000);
    View view;
    REQUIRE(make_view(cam, 48, 36, view) == Status::ok);
    CHECK(check_view_range(with_model(view, model).to_view, kWorldLimitBits) == Status::ok);  // was invalid_argument
    const Drawn d = draw_placed(cam, mesh, model, 60.0, 1000.0);
    CHECK(d.projected == Status::ok);
    CHECK(d.st.ok());
    CHECK(nonzero(d.ids) > 50);  // was 0 (100 before the range check)
    CHECK(ref::compare_ids(d.ids, d.want, 48, 36).off_edge_mismatch == 0);
}

// Camera and projection: world -> view (gluLookAt) and projection of a view-space point to a ScreenVertex.
// The clip tests against near, far and the guard band live with the clipper (raster/clip.hpp).
// Units: positions Q16; w = -z_view (distance along the view axis); screen in 1/16 pixel from the centre.
// Depth z = kDepthNear + (kDepthFar - kDepthNear) (1 - n/w) / (1 - n/f): affine in screen space (1/w).
#pragma once
#include <hider/frame.hpp>
#include <hider/mat.hpp>
#include <hider/screen.hpp>

namespace hider {

/// |coordinate| of a world position, eye or target must stay below this (2^13 units).
constexpr int kWorldLimitBits = 29;
constexpr int32_t kWorldLimitRaw = int32_t{1} << kWorldLimitBits;
/// The near plane may not be closer than 1/256 unit.
constexpr int32_t kMinNearRaw = 256;

/// gluLookAt + gluPerspective inputs (aspect = width / height of the frame).
struct Camera {
    Vec3q16 eye{}, target{}, up{};
    Angle fovy{};  ///< vertical field of view, in [0.5, 179.5] degrees
    Q16 near{}, far{};
};

/// Everything per frame that vertex projection and triangle setup need. Build with make_view().
struct View {
    Transform to_view{};        ///< model/world -> view space
    int32_t width = 0, height = 0;
    int32_t k_q8 = 0;           ///< subpixels per unit of x_view / w, Q8: X = x k / w
    int32_t near_raw = 0, far_raw = 0;
    uint32_t near_over_far_q31 = 0;
    uint64_t depth_scale_q31 = 0;  ///< (kDepthFar - kDepthNear) / (1 - n/f), Q31
};

/// A point in view space, raw Q16: x right, y up, w = -z_view (positive in front of the eye).
struct ViewPoint {
    int32_t x, y, w;
};

/// Checks the camera and frame size and builds the view. Errors: invalid_argument (size, fov,
/// near/far order, eye == target, up parallel to the view), out_of_range (eye/target outside the world range).
inline Status make_view(const Camera& cam, int32_t width, int32_t height, View& out) {
    if (width < 1 || height < 1 || width > kMaxFrameSide || height > kMaxFrameSide) return Status::invalid_argument;
    const uint32_t half_degree = 0x005B05B0u;  // 2^32 / 720, rounded down
    if (cam.fovy.bam() < half_degree || cam.fovy.bam() > 0x80000000u - half_degree) return Status::invalid_argument;
    if (cam.near.raw() < kMinNearRaw || cam.far.raw() <= cam.near.raw()) return Status::invalid_argument;
    const Vec3q16 pts[2] = {cam.eye, cam.target};
    for (const Vec3q16& p : pts) {
        const int32_t c[3] = {p.x.raw(), p.y.raw(), p.z.raw()};
        for (int32_t e : c)
            if (e <= -kWorldLimitRaw || e >= kWorldLimitRaw) return Status::out_of_range;
    }
    View v;
    const Status s = look_at(cam.eye, cam.target, cam.up, v.to_view);
    if (s != Status::ok) return s;
    v.width = width;
    v.height = height;
    const Angle half_fov = Angle::from_bam(cam.fovy.bam() / 2);
    // k = (H / 2) * cot(fovy / 2) * 16 subpixels, in Q8.
    v.k_q8 = saturate32(div_round(int64_t{height} * (kSubpixel / 2) * 256 * cos(half_fov).raw(), sin(half_fov).raw()));
    v.near_raw = cam.near.raw();
    v.far_raw = cam.far.raw();
    v.near_over_far_q31 = static_cast<uint32_t>((uint64_t{static_cast<uint32_t>(v.near_raw)} << 31) /
                                                static_cast<uint32_t>(v.far_raw));
    const uint64_t range = kDepthFar - kDepthNear;
    v.depth_scale_q31 = (range << 31) / ((uint64_t{1} << 31) - v.near_over_far_q31);
    out = v;
    return Status::ok;
}

/// The same view with a model transform applied first (model -> world -> view). Preconditions: the
/// transform is a rotation and a translation, and the placed mesh lies in the world range, which
/// validate(mesh, model) checks (mesh.hpp; with_model() cannot see the mesh). Where a placement would
/// wrap view coordinates, project_vertices() and the BSP walks refuse it (check_view_range()).
/// compose() takes the model's translation through apply(), which wraps modulo 2^32 like the points: a
/// model whose origin lies 2^15 units or more from the eye along a view axis would compose to a
/// translation the check below cannot tell from a near one (44,000 units behind the eye became 25,536 in
/// front, drawn with status ok). Such a model gives a view that every draw call refuses as out_of_range
/// (no rotation, translation (INT32_MIN, 0, 0): every position's view x is INT32_MIN), even where some of
/// its positions would come back within int32.
inline View with_model(const View& v, const Transform& model) {
    View r = v;
    r.to_view = compose(v.to_view, model);
    const Vec3i64 t = apply_wide(v.to_view, model.trans);
    const int64_t c[3] = {t.x, t.y, t.z};
    for (const int64_t e : c)
        if (e < INT32_MIN || e > INT32_MAX) {
            r.to_view.rot = Mat3{};
            r.to_view.trans = {Q16::from_raw(INT32_MIN), Q16::from_raw(0), Q16::from_raw(0)};
        }
    return r;
}

/// Whether `to_view` (a View's, with or without a model) keeps every view coordinate of every point with
/// |coordinates| <= 2^bits raw within int32, in O(1): |t_i| + sum_j |R_ij| 2^bits / 2^30 + 1 (the floor)
/// at most INT32_MAX for each row i (the largest |coordinate| over that cube; INT32_MIN is excluded, since
/// w = -z must not overflow). Precondition: 0 <= bits <= 29. Returns invalid_argument for a matrix entry
/// beyond +-1 (no rotation; the 32-bit transforms rely on it), else ok or out_of_range. Out of line: a
/// walk that calls it once keeps its registers for its loop.
__attribute__((noinline)) inline Status check_view_range(const Transform& to_view, int bits) {
    const int32_t t[3] = {to_view.trans.x.raw(), to_view.trans.y.raw(), to_view.trans.z.raw()};
    Status s = Status::ok;
    for (int i = 0; i < 3; ++i) {
        uint32_t sum = 0;  // sum_j |R_ij|, at most 3 2^30
        for (const Q30& e : to_view.rot.m[i]) {
            const int32_t r = e.raw();
            if (r < -Q30::kOne || r > Q30::kOne) return Status::invalid_argument;
            sum += static_cast<uint32_t>(r < 0 ? -r : r);
        }
        const uint32_t at = t[i] < 0 ? 0u - static_cast<uint32_t>(t[i]) : static_cast<uint32_t>(t[i]);  // <= 2^31
        if (at + (sum >> (30 - bits)) + 1 > static_cast<uint32_t>(INT32_MAX)) s = Status::out_of_range;  // < 2^32
    }
    return s;
}

/// Whether `to_view` keeps every view coordinate of `positions` (each inside the world range:
/// validate(mesh)) within int32. apply() wraps modulo 2^32, so a model (with_model()) that carries a mesh
/// 2^15 units from the eye would draw it elsewhere with status ok; the drawing that follows the transform
/// is exact for any int32 view coordinate but INT32_MIN. O(1) without a model (eye and mesh in the world
/// range: at most 2 sqrt(3) 2^13 units apart) and while a model's origin stays within about 14,000 units
/// of the eye along each view axis; otherwise each position is transformed exactly in 64 bits. Returns
/// invalid_argument for a matrix entry beyond +-1, out_of_range where a coordinate wraps.
inline Status check_view_range(const Transform& to_view, Span<const Vec3q16> positions) {
    const Status s = check_view_range(to_view, kWorldLimitBits);
    if (s != Status::out_of_range) return s;
    for (const Vec3q16& p : positions) {
        const Vec3i64 w = apply_wide(to_view, p);
        const int64_t c[3] = {w.x, w.y, w.z};
        for (const int64_t e : c)  // INT32_MIN too: to_view_point() negates z (w = -z), and x, y alike
            if (e <= INT32_MIN || e > INT32_MAX) return Status::out_of_range;
    }
    return Status::ok;
}

/// -z modulo 2^32: a view z of INT32_MIN (refused by check_view_range(), which project_vertices() runs
/// after its loop on RV32 and the host) gives INT32_MIN without signed overflow.
__attribute__((always_inline)) constexpr int32_t negate_wrapping(int32_t z) {
    return static_cast<int32_t>(0u - static_cast<uint32_t>(z));
}

/// View-space position of p. Precondition: |p| components below kWorldLimitRaw.
__attribute__((always_inline)) inline ViewPoint to_view_point(const View& v, Vec3q16 p) {
    const Vec3q16 q = apply(v.to_view, p);
    return {q.x.raw(), q.y.raw(), negate_wrapping(q.z.raw())};
}

/// to_view_point() through a PreparedTransform of v.to_view (many points, one view).
__attribute__((always_inline)) inline ViewPoint to_view_point(const PreparedTransform& t, const Vec3q16& p) {
    const Vec3q16 q = t.apply(p);
    return {q.x.raw(), q.y.raw(), negate_wrapping(q.z.raw())};
}

/// The products x k and y k of a view point, which the clip tests and the projection both need.
struct ScaledXY {
    int64_t xk, yk;
};
inline ScaledXY scaled_xy(const View& v, const ViewPoint& p) { return {mul_wide(p.x, v.k_q8), mul_wide(p.y, v.k_q8)}; }

namespace detail {
/// div_round(n, 256 w) for w > 0: |n| / (256 w) rounded half away from zero is
/// floor(floor((|n| + 128 w) / 256) / w) (nested floors), so one 64/32 division by the prepared w does
/// it on 32-bit targets, no library 64-bit division (the quotient is a screen coordinate, far below 2^32).
/// Returns false (nothing computed) when the quotient would not fit 32 bits.
template <class D>
inline bool div_round_w256_by_parts(int64_t n, const D& w, int64_t& out) {
    const uint64_t un = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
    const uint32_t uw = w.value();
    const uint64_t m = (un + (uint64_t{uw} << 7)) >> 8;
    if ((m >> 32) >= uw) return false;
    uint32_t r = 0;
    const int64_t q = w.divide(m, r);
    out = n < 0 ? -q : q;
    return true;
}

/// X = div_round(n, 256 w) for the prepared divisor w (SharedDivisor32: a reciprocal on ARMv6-M,
/// udiv64_32 elsewhere), clamped to the coordinate limit; div_round when the quotient needs 64 bits.
/// With a hardware 32-bit divide, screen coordinates (quotients below 2^15: every point inside the
/// guard band) take div_small_quotient() instead.
template <class D>
inline int16_t project_coord(int64_t n, const D& w) {
    uint32_t small = 0;
    const uint64_t un = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
    if (kHardwareDivide32 && div_small_quotient((un + (uint64_t{w.value()} << 7)) >> 8, w.value(), small)) {
        const int32_t c = static_cast<int32_t>(min<uint32_t>(small, kCoordLimit));  // 32-bit clamp
        return static_cast<int16_t>(n < 0 ? -c : c);
    }
    int64_t q = 0;
    if (!div_round_w256_by_parts(n, w, q)) q = div_round(n, int64_t{w.value()} * 256);
    return static_cast<int16_t>(clamp<int64_t>(q, -kCoordLimit, kCoordLimit));
}
}  // namespace detail

/// Projects a point inside (or, after clipping, on) the view volume; coordinates are clamped to the
/// guard band and depth to [kDepthNear, kDepthFar], so rounding at clip planes never overflows.
__attribute__((always_inline)) inline ScreenVertex project(const View& v, const ViewPoint& p, const ScaledXY& xy) {
    const int32_t w = max(p.w, int32_t{1});
    const uint64_t n31 = uint64_t{static_cast<uint32_t>(v.near_raw)} << 31;
    ScreenVertex s;
    uint32_t u = uint32_t{1} << 31;  // u = n / w in Q31, 1 when w <= n
    if (kSlow64BitDivide) {  // three quotients by one prepared w; exact, so equal to the host's
        const SharedDivisor32 dw(static_cast<uint32_t>(w));
        s.x = detail::project_coord(xy.xk, dw);
        s.y = detail::project_coord(-xy.yk, dw);
        uint32_t r = 0;
        if (w > v.near_raw) u = dw.divide(n31, r);  // n < w: below 2^31
    } else {
        s.x = static_cast<int16_t>(clamp<int64_t>(div_round(xy.xk, int64_t{w} * 256), -kCoordLimit, kCoordLimit));
        s.y = static_cast<int16_t>(clamp<int64_t>(div_round(-xy.yk, int64_t{w} * 256), -kCoordLimit, kCoordLimit));
        if (w > v.near_raw) u = static_cast<uint32_t>(n31 / static_cast<uint32_t>(w));
    }
    // z = near + scale (1 - u) / (1 - n/f).
    u = clamp<uint32_t>(u, v.near_over_far_q31, uint32_t{1} << 31);
    const uint64_t z = kDepthNear + ((mul_u32_u64((uint32_t{1} << 31) - u, v.depth_scale_q31) + (uint64_t{1} << 30)) >> 31);
    s.z = static_cast<uint32_t>(min<uint64_t>(z, kDepthFar));
    return s;
}

/// project() for a point whose products are not at hand.
inline ScreenVertex project(const View& v, const ViewPoint& p) { return project(v, p, scaled_xy(v, p)); }

/// Columns [x0, x0 + width) of a frame, centred in it: x0 columns left out on either side.
struct ColumnWindow {
    int32_t x0 = 0;
    int32_t width = 0;
};

/// The narrowest centred window of a `frame_width`-wide frame whose first and last column centres lie
/// at or beyond every vertex of `verts` (projected vertices), with the largest |x| rounded up by at most
/// one subpixel. A triangle covers only pixels whose centres lie inside it, so a frame drawn from these
/// vertices is background outside the window, and each triangle meets the same set-up path as in the
/// whole frame. The whole width when a vertex is outside a clip plane (clipping makes new vertices
/// anywhere), when one reaches past a side, for no vertices, or for a width outside [1, kMaxFrameSide].
/// Centred because screen coordinates count from the frame's centre: window_view() draws the window
/// with every set-up and the vertex cache unchanged (an object off centre gets a wider window than its
/// extent). Out of line: one tight loop a frame.
__attribute__((noinline)) inline ColumnWindow centred_window(Span<const ScreenVertex> verts, int32_t frame_width) {
    const ColumnWindow whole{0, frame_width};
    if (verts.empty() || frame_width < 1 || frame_width > kMaxFrameSide) return whole;
    uint32_t far = 0;  // the largest |x|, less 1 where that x is negative
    auto reach_of = [&far](const ScreenVertex& v) __attribute__((always_inline)) {
        const int32_t x = v.x;
        const uint32_t a = static_cast<uint32_t>(x ^ (x >> 31));
        if (a > far) far = a;
    };
    // Four a turn; the z tests written as the loop's condition, each a forward branch out (as all_projected()).
    const ScreenVertex* v = verts.begin();
    const ScreenVertex* const block_end = v + (verts.size() & ~size_t{3});
    while (v != block_end && v[0].z != 0 && v[1].z != 0 && v[2].z != 0 && v[3].z != 0) {
        reach_of(v[0]);
        reach_of(v[1]);
        reach_of(v[2]);
        reach_of(v[3]);
        v += 4;
    }
    if (v != block_end) return whole;
    for (const ScreenVertex* const end = verts.end(); v != end; ++v) {
        if (v->z == 0) return whole;
        reach_of(*v);
    }
    const int32_t reach = static_cast<int32_t>(far) + 1;  // >= |x| of every vertex (at most 2^15)
    // The last column centre at or right of +reach is the mirror of the first at or left of -reach (the
    // centres sit symmetrically about 0), so one margin serves both sides.
    const int32_t margin = (-reach - pixel_centre_origin(frame_width)) >> kSubpixelBits;
    return margin > 0 ? ColumnWindow{margin, frame_width - 2 * margin} : whole;
}

/// `view` narrowed to the centred window `w` of its frame: draw_zbuffer() and draw_zbuffer_binned() given
/// `out` and a frame of w.width columns draw the frame's columns [w.x0, w.x0 + w.width), the same bytes
/// and counts as the whole frame there (the other draw calls are not checked for it). The projection
/// does not depend on the width: vertices projected with either view serve.
/// Errors: invalid_argument for a window that is not centred in view's frame (2 x0 + width != width).
inline Status window_view(const View& view, const ColumnWindow& w, View& out) {
    if (w.x0 < 0 || w.width < 1 || int64_t{w.x0} * 2 + w.width != view.width) return Status::invalid_argument;
    out = view;
    out.width = w.width;
    return Status::ok;
}

}  // namespace hider

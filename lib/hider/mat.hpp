// Rigid transforms: a Q30 rotation matrix plus a Q16 translation (no scale: meshes are baked into
// world units). Rotation about the axes from Angle, composition, and gluLookAt's view transform.
#pragma once
#include <hider/angle.hpp>
#include <hider/status.hpp>
#include <hider/vec.hpp>

namespace hider {

/// 3x3 matrix of Q30 entries, row-major; used for rotations.
struct Mat3 {
    Q30 m[3][3];
    static constexpr Mat3 identity() {
        const Q30 o = Q30::from_raw(Q30::kOne), z = Q30::from_raw(0);
        return {{{o, z, z}, {z, o, z}, {z, z, o}}};
    }
};

/// p' = rot * p + trans. Precondition for apply(): |p| components < 2^13 units, result < 2^15.
struct Transform {
    Mat3 rot = Mat3::identity();
    Vec3q16 trans{};
};

namespace detail {
/// floor((r0 p0 + r1 p1 + r2 p2) / 2^30) for |r| <= 2^30 and |p| < 2^29 in 32-bit arithmetic only: with
/// r = rh 2^16 + rl and p = ph 2^16 + pl (rl, pl in [0, 2^16)) the sum is
/// HH 2^32 + MID 2^16 + LL, and the floor is taken in stages (nested floors are exact): LL's top bits
/// from its parts, then MID plus those over 2^14, each term split into its floor and remainder so no
/// sum overflows. Twelve 32-bit multiplies where the 64-bit sum takes three 32x32->64 products, which
/// ARMv6-M (no long multiply) builds from four each.
constexpr int32_t dot3_split_floor(const int32_t (&rh)[3], const int32_t (&rl)[3], const int32_t (&ph)[3],
                                   const int32_t (&pl)[3]) {
    // LL = sum of rl pl (each < 2^32, unsigned): floor(LL / 2^16) from the halves of each product.
    const uint32_t ll0 = uint32_t(rl[0]) * uint32_t(pl[0]), ll1 = uint32_t(rl[1]) * uint32_t(pl[1]),
                   ll2 = uint32_t(rl[2]) * uint32_t(pl[2]);
    const int32_t l16 = int32_t((ll0 >> 16) + (ll1 >> 16) + (ll2 >> 16) +
                                (((ll0 & 0xFFFFu) + (ll1 & 0xFFFFu) + (ll2 & 0xFFFFu)) >> 16));
    // MID + l16 in three int32 partial sums (|rh pl| < 2^30, |rl ph| < 2^29, l16 < 2^18), then
    // floor(sum / 2^14) = sum of the floors + floor(sum of the remainders).
    const int32_t s1 = rh[0] * pl[0] + rh[1] * pl[1];
    const int32_t s2 = rh[2] * pl[2] + rl[0] * ph[0];
    const int32_t s3 = rl[1] * ph[1] + rl[2] * ph[2] + l16;
    return 4 * (rh[0] * ph[0] + rh[1] * ph[1] + rh[2] * ph[2]) + (s1 >> 14) + (s2 >> 14) + (s3 >> 14) +
           (((s1 & 0x3FFF) + (s2 & 0x3FFF) + (s3 & 0x3FFF)) >> 14);
}

/// dot3_split_floor of r and p split here.
constexpr int32_t dot3_q30_floor_by_parts(int32_t r0, int32_t r1, int32_t r2, int32_t p0, int32_t p1, int32_t p2) {
    const int32_t rh[3] = {r0 >> 16, r1 >> 16, r2 >> 16}, rl[3] = {r0 & 0xFFFF, r1 & 0xFFFF, r2 & 0xFFFF};
    const int32_t ph[3] = {p0 >> 16, p1 >> 16, p2 >> 16}, pl[3] = {p0 & 0xFFFF, p1 & 0xFFFF, p2 & 0xFFFF};
    return dot3_split_floor(rh, rl, ph, pl);
}

/// Row r of a Q30 matrix times a Q16 vector, plus a Q16 offset; one floor at the end.
__attribute__((always_inline)) constexpr Q16 row_dot(const Q30 (&row)[3], const Vec3q16& p, Q16 offset) {
    if constexpr (kNarrowMultiply) {
        return Q16::from_raw(dot3_q30_floor_by_parts(row[0].raw(), row[1].raw(), row[2].raw(), p.x.raw(), p.y.raw(),
                                                     p.z.raw()) + offset.raw());
    }
    // floor((sum + t 2^30) / 2^30) = floor(sum / 2^30) + t: the translation after the shift (one 32-bit
    // add instead of building t 2^30 in 64 bits per point), modulo 2^32 like the 64-bit form.
    const int64_t acc = mul_wide(row[0].raw(), p.x.raw()) + mul_wide(row[1].raw(), p.y.raw()) +
                        mul_wide(row[2].raw(), p.z.raw());
    return Q16::from_raw(static_cast<int32_t>(static_cast<uint32_t>(acc >> 30) + static_cast<uint32_t>(offset.raw())));
}
}  // namespace detail

/// Applies t to point p (rotation then translation), floored once per component.
constexpr Vec3q16 apply(const Transform& t, const Vec3q16& p) {
    return {detail::row_dot(t.rot.m[0], p, t.trans.x), detail::row_dot(t.rot.m[1], p, t.trans.y),
            detail::row_dot(t.rot.m[2], p, t.trans.z)};
}

/// apply() without its wrap: floor(R p / 2^30) + t exactly in 64 bits, the value apply() gives modulo
/// 2^32 per component (to check where a transform puts a point before trusting apply()).
constexpr Vec3i64 apply_wide(const Transform& t, const Vec3q16& p) {
    const Q16 tr[3] = {t.trans.x, t.trans.y, t.trans.z};
    int64_t c[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        const Q30(&r)[3] = t.rot.m[i];
        c[i] = ((mul_wide(r[0].raw(), p.x.raw()) + mul_wide(r[1].raw(), p.y.raw()) + mul_wide(r[2].raw(), p.z.raw())) >> 30) +
               tr[i].raw();
    }
    return {c[0], c[1], c[2]};
}

/// apply() forced inline, for a loop over many points that keeps its other work in registers.
__attribute__((always_inline)) constexpr Vec3q16 apply_inline(const Transform& t, const Vec3q16& p) {
    return {detail::row_dot(t.rot.m[0], p, t.trans.x), detail::row_dot(t.rot.m[1], p, t.trans.y),
            detail::row_dot(t.rot.m[2], p, t.trans.z)};
}

/// A transform prepared for many points (the vertices of a frame). On ARMv6-M its rotation is split into
/// 16-bit halves once, so each point costs its own split and the twelve 32-bit products per row of
/// detail::dot3_split_floor; elsewhere it is apply(). Same results as apply() everywhere.
class PreparedTransform {
public:
    explicit constexpr PreparedTransform(const Transform& t) : t_(t), h_(), l_() {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                h_[i][j] = t.rot.m[i][j].raw() >> 16;
                l_[i][j] = t.rot.m[i][j].raw() & 0xFFFF;
            }
    }
    constexpr const Transform& transform() const { return t_; }

    constexpr Vec3q16 apply(const Vec3q16& p) const {
        if constexpr (kNarrowMultiply) return apply_by_parts(p);
        return hider::apply(t_, p);
    }

    /// The ARMv6-M form of apply() (32-bit multiplies only), available everywhere for tests.
    constexpr Vec3q16 apply_by_parts(const Vec3q16& p) const {
        const int32_t ph[3] = {p.x.raw() >> 16, p.y.raw() >> 16, p.z.raw() >> 16};
        const int32_t pl[3] = {p.x.raw() & 0xFFFF, p.y.raw() & 0xFFFF, p.z.raw() & 0xFFFF};
        return {Q16::from_raw(row(0, ph, pl) + t_.trans.x.raw()), Q16::from_raw(row(1, ph, pl) + t_.trans.y.raw()),
                Q16::from_raw(row(2, ph, pl) + t_.trans.z.raw())};
    }

private:
    constexpr int32_t row(int i, const int32_t (&ph)[3], const int32_t (&pl)[3]) const {
        return detail::dot3_split_floor(h_[i], l_[i], ph, pl);
    }
    Transform t_;
    int32_t h_[3][3], l_[3][3];
};

/// The point p' with apply(t, p') = p for a rigid t: R^T (p - trans), floored once per component (the
/// difference in 64 bits). For a BSP walk under with_model(view, model): the camera's eye in the tree's
/// coordinates. Precondition: t rigid, p - trans below 2^31 raw and the result below 2^31 raw.
constexpr Vec3q16 apply_inverse(const Transform& t, const Vec3q16& p) {
    const int64_t d[3] = {int64_t{p.x.raw()} - t.trans.x.raw(), int64_t{p.y.raw()} - t.trans.y.raw(),
                          int64_t{p.z.raw()} - t.trans.z.raw()};
    int32_t out[3] = {0, 0, 0};
    for (int j = 0; j < 3; ++j) {
        int64_t acc = 0;  // |entries| <= 2^30, |d| < 2^31: each product below 2^61, the sum below 2^63
        for (int i = 0; i < 3; ++i) acc += t.rot.m[i][j].raw() * d[i];
        out[j] = static_cast<int32_t>(acc >> 30);
    }
    return {Q16::from_raw(out[0]), Q16::from_raw(out[1]), Q16::from_raw(out[2])};
}

/// Matrix product a * b (Q30, floored per entry, then clamped to +-1: the floored sum of two rotations'
/// products can pass -1 by a raw unit, e.g. look_at((100, 0, -100) -> origin) after rotation_y(45
/// degrees), and check_view_range() refuses an entry beyond +-1 as no rotation).
constexpr Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int64_t acc = 0;
            for (int k = 0; k < 3; ++k) acc += mul_wide(a.m[i][k].raw(), b.m[k][j].raw());
            const int64_t e = acc >> 30;
            r.m[i][j] = Q30::from_raw(static_cast<int32_t>(e < -Q30::kOne ? -Q30::kOne : (e > Q30::kOne ? Q30::kOne : e)));
        }
    return r;
}

/// a after b: (a * b)(p) = a(b(p)).
constexpr Transform compose(const Transform& a, const Transform& b) {
    return {mul(a.rot, b.rot), apply(a, b.trans)};
}

/// Rotation by `angle` about the x, y or z axis (right-handed, counter-clockwise looking down the axis).
constexpr Mat3 rotation_x(Angle a) {
    const Q30 c = cos(a), s = sin(a), o = Q30::from_raw(Q30::kOne), z = Q30::from_raw(0);
    return {{{o, z, z}, {z, c, -s}, {z, s, c}}};
}
constexpr Mat3 rotation_y(Angle a) {
    const Q30 c = cos(a), s = sin(a), o = Q30::from_raw(Q30::kOne), z = Q30::from_raw(0);
    return {{{c, z, s}, {z, o, z}, {-s, z, c}}};
}
constexpr Mat3 rotation_z(Angle a) {
    const Q30 c = cos(a), s = sin(a), o = Q30::from_raw(Q30::kOne), z = Q30::from_raw(0);
    return {{{c, -s, z}, {s, c, z}, {z, z, o}}};
}

/// Smallest sin(angle between view direction and up) look_at accepts: 2^-12 (about 0.014 degrees).
constexpr int32_t kMinUpSinQ30 = int32_t{1} << 18;

/// gluLookAt: the world-to-view transform with the eye at the origin looking down -Z, up
/// re-orthogonalised as GLU does (f = norm(target - eye), s = norm(f x up), u = s x f).
/// Returns invalid_argument if target == eye, up is zero, or up is (nearly) parallel to the view;
/// out_of_range if |eye.x| + |eye.y| + |eye.z| reaches 2^31 raw (32,768 units), where the translation
/// -R eye could pass the Q16 range (make_view()'s world range keeps it below 1.5 2^30).
inline Status look_at(Vec3q16 eye, Vec3q16 target, Vec3q16 up, Transform& out) {
    Vec3q30 f{}, upn{}, s{};
    const int64_t eye_l1 = abs_value(int64_t{eye.x.raw()}) + abs_value(int64_t{eye.y.raw()}) + abs_value(int64_t{eye.z.raw()});
    if (eye_l1 >= (int64_t{1} << 31)) return Status::out_of_range;
    // target - eye in 64 bits: exact for any two points (a Q16 difference could wrap).
    if (!normalize({int64_t{target.x.raw()} - eye.x.raw(), int64_t{target.y.raw()} - eye.y.raw(),
                    int64_t{target.z.raw()} - eye.z.raw()},
                   f))
        return Status::invalid_argument;
    if (!normalize({up.x.raw(), up.y.raw(), up.z.raw()}, upn)) return Status::invalid_argument;
    const Vec3i64 side{mul_wide(f.y.raw(), upn.z.raw()) - mul_wide(f.z.raw(), upn.y.raw()),
                       mul_wide(f.z.raw(), upn.x.raw()) - mul_wide(f.x.raw(), upn.z.raw()),
                       mul_wide(f.x.raw(), upn.y.raw()) - mul_wide(f.y.raw(), upn.x.raw())};
    const int64_t sin_q60 = max(abs_value(side.x), max(abs_value(side.y), abs_value(side.z)));
    if (sin_q60 < (int64_t{kMinUpSinQ30} << 30)) return Status::invalid_argument;
    if (!normalize(side, s)) return Status::invalid_argument;
    const Vec3i64 upo{mul_wide(s.y.raw(), f.z.raw()) - mul_wide(s.z.raw(), f.y.raw()),
                      mul_wide(s.z.raw(), f.x.raw()) - mul_wide(s.x.raw(), f.z.raw()),
                      mul_wide(s.x.raw(), f.y.raw()) - mul_wide(s.y.raw(), f.x.raw())};
    Vec3q30 u{};
    if (!normalize(upo, u)) return Status::invalid_argument;
    out.rot = {{{s.x, s.y, s.z}, {u.x, u.y, u.z}, {-f.x, -f.y, -f.z}}};
    const Q16 zero = Q16::from_raw(0);
    const Vec3q16 neg_eye{-eye.x, -eye.y, -eye.z};
    out.trans = {detail::row_dot(out.rot.m[0], neg_eye, zero), detail::row_dot(out.rot.m[1], neg_eye, zero),
                 detail::row_dot(out.rot.m[2], neg_eye, zero)};
    return Status::ok;
}

}  // namespace hider

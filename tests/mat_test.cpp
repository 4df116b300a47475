// Vectors, rotations and look_at against double references (gluLookAt), in LSBs of Q30 / Q16.
#include <hider/mat.hpp>

#include <cmath>
#include <random>

#include "support/fixed_print.hpp"

using namespace hider;

namespace {
Vec3q16 q16(double x, double y, double z) {
    return {Q16::from_raw(static_cast<int32_t>(std::lround(x * 65536))),
            Q16::from_raw(static_cast<int32_t>(std::lround(y * 65536))),
            Q16::from_raw(static_cast<int32_t>(std::lround(z * 65536)))};
}
double d(Q16 v) { return v.raw() / 65536.0; }
double d(Q30 v) { return v.raw() / 1073741824.0; }
}  // namespace

TEST_CASE("normalize gives unit vectors within 3 LSB of Q30 for tiny and huge inputs") {
    std::mt19937_64 rng(5);
    for (int i = 0; i < 20000; ++i) {
        const int shift = static_cast<int>(rng() % 62);
        const Vec3i64 v{static_cast<int64_t>(rng()) >> shift, static_cast<int64_t>(rng()) >> shift,
                        static_cast<int64_t>(rng()) >> shift};
        Vec3q30 n{};
        const bool ok = normalize(v, n);
        if (v.x == 0 && v.y == 0 && v.z == 0) { CHECK_FALSE(ok); continue; }
        REQUIRE(ok);
        const long double len = std::sqrt(static_cast<long double>(v.x) * v.x + static_cast<long double>(v.y) * v.y +
                                          static_cast<long double>(v.z) * v.z);
        if (len < 1e6L) continue;  // tiny integer vectors: direction itself is coarse
        CHECK(std::fabs(n.x.raw() - static_cast<double>(v.x / len * 1073741824.0L)) <= 3.0);
        CHECK(std::fabs(n.y.raw() - static_cast<double>(v.y / len * 1073741824.0L)) <= 3.0);
        CHECK(std::fabs(n.z.raw() - static_cast<double>(v.z / len * 1073741824.0L)) <= 3.0);
    }
    Vec3q30 n{};
    CHECK_FALSE(normalize({0, 0, 0}, n));
    REQUIRE(normalize({0, 0, -3}, n));
    CHECK(n.z.raw() == -(1 << 30));
    REQUIRE(normalize({INT64_MAX, 0, 0}, n));
    CHECK(n.x.raw() == 1 << 30);
}

TEST_CASE("face_normal follows the right-hand rule and marks degenerate faces") {
    const Normal14 n = face_normal(q16(0, 0, 0), q16(1, 0, 0), q16(0, 1, 0));
    CHECK(n.x == 0);
    CHECK(n.y == 0);
    CHECK(n.z == 16384);
    const Normal14 z = face_normal(q16(1, 1, 1), q16(2, 2, 2), q16(3, 3, 3));
    CHECK((z.x == 0 && z.y == 0 && z.z == 0));
    const Normal14 t = face_normal(q16(0, 0, 0), q16(0, 0, 1e-4), q16(0, 1e-4, 0));  // tiny but valid
    CHECK(t.x == -16384);
}

TEST_CASE("rotations match cos/sin and compose like matrices") {
    const Angle a = Angle::from_bam(0x15555555u);  // 30 degrees
    const Mat3 r = rotation_z(a);
    const Vec3q16 p = apply({r, {}}, q16(1, 0, 0));
    CHECK(std::fabs(d(p.x) - std::cos(M_PI / 6)) < 3e-5);
    CHECK(std::fabs(d(p.y) - std::sin(M_PI / 6)) < 3e-5);
    const Mat3 twice = mul(r, r);
    const Mat3 sixty = rotation_z(a + a);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CHECK(std::abs(twice.m[i][j].raw() - sixty.m[i][j].raw()) <= 8);
    const Transform t1{rotation_x(a), q16(1, 2, 3)}, t2{rotation_y(a), q16(-4, 0, 0.5)};
    const Vec3q16 v = q16(0.25, -7, 100);
    const Vec3q16 direct = apply(t1, apply(t2, v)), composed = apply(compose(t1, t2), v);
    CHECK(std::abs(direct.x.raw() - composed.x.raw()) <= 16);
    CHECK(std::abs(direct.y.raw() - composed.y.raw()) <= 16);
    CHECK(std::abs(direct.z.raw() - composed.z.raw()) <= 16);
}

TEST_CASE("look_at matches gluLookAt in double to within 32 LSB of Q30 per entry (more as up nears the view axis)") {
    std::mt19937 rng(11);
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    for (int i = 0; i < 2000; ++i) {
        const double e[3] = {u(-4000, 4000), u(-4000, 4000), u(-4000, 4000)};
        const double t[3] = {u(-4000, 4000), u(-4000, 4000), u(-4000, 4000)};
        const double up[3] = {u(-1, 1), u(-1, 1), u(-1, 1)};
        Transform view;
        const Vec3q16 eq = q16(e[0], e[1], e[2]), tq = q16(t[0], t[1], t[2]), uq = q16(up[0], up[1], up[2]);
        if (look_at(eq, tq, uq, view) != Status::ok) continue;
        // Reference from the exact fixed inputs.
        const double E[3] = {d(eq.x), d(eq.y), d(eq.z)}, T[3] = {d(tq.x), d(tq.y), d(tq.z)}, U[3] = {d(uq.x), d(uq.y), d(uq.z)};
        double f[3] = {T[0] - E[0], T[1] - E[1], T[2] - E[2]};
        double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        for (double& c : f) c /= fl;
        double s[3] = {f[1] * U[2] - f[2] * U[1], f[2] * U[0] - f[0] * U[2], f[0] * U[1] - f[1] * U[0]};
        double sl = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        if (sl < 1e-3 * std::sqrt(U[0] * U[0] + U[1] * U[1] + U[2] * U[2])) continue;
        for (double& c : s) c /= sl;
        // Rounding of f and up (a few LSB) is amplified by 1 / sin(angle between them) in s = f x up.
        const double tol = 32.0 / 1073741824.0 + 8.0 / 1073741824.0 * std::sqrt(U[0] * U[0] + U[1] * U[1] + U[2] * U[2]) / sl;
        const double uu[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
        const double rows[3][3] = {{s[0], s[1], s[2]}, {uu[0], uu[1], uu[2]}, {-f[0], -f[1], -f[2]}};
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) CHECK(std::fabs(d(view.rot.m[r][c]) - rows[r][c]) < tol);
            const double tr = -(rows[r][0] * E[0] + rows[r][1] * E[1] + rows[r][2] * E[2]);
            CHECK(std::fabs(d(r == 0 ? view.trans.x : r == 1 ? view.trans.y : view.trans.z) - tr) < 2e-4);
        }
    }
}

TEST_CASE("look_at rejects a zero direction, a zero up and an up parallel to the view") {
    Transform v;
    CHECK(look_at(q16(1, 2, 3), q16(1, 2, 3), q16(0, 1, 0), v) == Status::invalid_argument);
    CHECK(look_at(q16(0, 0, 0), q16(0, 0, -1), q16(0, 0, 0), v) == Status::invalid_argument);
    CHECK(look_at(q16(0, 0, 0), q16(0, 5, 0), q16(0, 1, 0), v) == Status::invalid_argument);
    CHECK(look_at(q16(0, 0, 0), q16(0, 5, 0), q16(0, -2, 0), v) == Status::invalid_argument);
    CHECK(look_at(q16(0, 0, 0), q16(0, 5, 0), q16(0.01, 1, 0), v) == Status::ok);  // 0.57 degrees off: fine
}

TEST_CASE("look_at is exact for eye and target far apart, and refuses an eye whose translation could wrap") {
    // A red-team case: target - eye as a Q16 difference wrapped to INT32_MIN here, and look_at said ok
    // with the camera turned around.
    const auto raw = [](int32_t x, int32_t y, int32_t z) {
        return Vec3q16{Q16::from_raw(x), Q16::from_raw(y), Q16::from_raw(z)};
    };
    const int32_t big = int32_t{1} << 30;
    const Vec3q16 up = q16(0, 1, 0);
    Transform far{}, near{};
    REQUIRE(look_at(raw(-big, 0, 0), raw(big, 0, 0), up, far) == Status::ok);
    REQUIRE(look_at(q16(0, 0, 0), q16(1, 0, 0), up, near) == Status::ok);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) CHECK(far.rot.m[r][c].raw() == near.rot.m[r][c].raw());  // looking down +x
    CHECK(apply(far, raw(0, 0, 0)).z.raw() == -big);  // the origin 2^30 raw ahead of the eye
    // The two ends of every axis (2^32 - 2 raw apart), against the same direction from the origin.
    for (int axis = 0; axis < 3; ++axis) {
        int32_t e[3] = {0, 0, 0}, t[3] = {0, 0, 0};
        e[axis] = INT32_MIN + 1;
        t[axis] = INT32_MAX;
        const Vec3q16 u = axis == 1 ? q16(0, 0, 1) : up;
        Transform a{};
        CHECK(look_at(raw(e[0], e[1], e[2]), raw(t[0], t[1], t[2]), u, a) == Status::ok);
        int32_t dir[3] = {0, 0, 0};
        dir[axis] = 1 << 16;
        Transform b{};
        REQUIRE(look_at(q16(0, 0, 0), raw(dir[0], dir[1], dir[2]), u, b) == Status::ok);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) CHECK(a.rot.m[r][c].raw() == b.rot.m[r][c].raw());
    }
    // The eye's L1 norm: below 2^31 raw accepted (the translation fits), at 2^31 refused, INT32_MIN too.
    Transform v{};
    CHECK(look_at(raw(big - 1, big, 0), q16(0, 0, 0), q16(0, 0, 1), v) == Status::ok);
    CHECK(look_at(raw(big, big, 0), q16(0, 0, 0), q16(0, 0, 1), v) == Status::out_of_range);
    CHECK(look_at(raw(INT32_MIN, 0, 0), q16(0, 0, 0), up, v) == Status::out_of_range);
    CHECK(look_at(raw(0, 0, INT32_MIN), q16(0, 0, 0), up, v) == Status::out_of_range);
}

TEST_CASE("the ARMv6-M row product from 16-bit halves equals the floored exact 64-bit sum") {
    std::mt19937_64 rng(73);
    auto check = [](const int32_t (&r)[3], const int32_t (&p)[3]) {
        const int64_t exact = int64_t{r[0]} * p[0] + int64_t{r[1]} * p[1] + int64_t{r[2]} * p[2];
        const int64_t floored = exact >> 30;
        if (floored < INT32_MIN || floored > INT32_MAX) return;  // outside apply()'s precondition
        CHECK(hider::detail::dot3_q30_floor_by_parts(r[0], r[1], r[2], p[0], p[1], p[2]) == floored);
    };
    for (int i = 0; i < 300000; ++i) {
        int32_t r[3], p[3];
        for (int j = 0; j < 3; ++j) {
            r[j] = static_cast<int32_t>(static_cast<int64_t>(rng()) >> (33 + rng() % 31));  // |r| <= 2^30
            p[j] = static_cast<int32_t>(static_cast<int64_t>(rng()) >> (35 + rng() % 29));  // |p| <= 2^28
        }
        check(r, p);
    }
    const int32_t one = int32_t{1} << 30, lim = (int32_t{1} << 29) - 1;
    const int32_t rows[][3] = {{one, one, one}, {-one, -one, -one}, {one, -one, one}, {0, 0, 0}, {-1, -1, -1},
                               {one - 1, 65535, -65536}, {-one, 65535, 1}};
    const int32_t points[][3] = {{lim, lim, lim}, {-lim, -lim, -lim}, {lim, -lim, 65535}, {-1, 0, 1},
                                 {65536, -65536, 0}, {-lim, 65535, -65535}};
    for (const auto& r : rows)
        for (const auto& p : points) check(r, p);
}

TEST_CASE("PreparedTransform (and its ARMv6-M 32-bit form) applies exactly like apply()") {
    std::mt19937_64 rng(89);
    for (int i = 0; i < 2000; ++i) {
        Transform t;
        t.rot = mul(rotation_x(Angle::from_bam(static_cast<uint32_t>(rng()))),
                    mul(rotation_y(Angle::from_bam(static_cast<uint32_t>(rng()))), rotation_z(Angle::from_bam(static_cast<uint32_t>(rng())))));
        t.trans = {Q16::from_raw(static_cast<int32_t>(rng() >> 40)), Q16::from_raw(-static_cast<int32_t>(rng() >> 40)),
                   Q16::from_raw(static_cast<int32_t>(rng() >> 41))};
        const PreparedTransform pt(t);
        for (int k = 0; k < 20; ++k) {
            const Vec3q16 p{Q16::from_raw(static_cast<int32_t>(static_cast<int64_t>(rng()) >> 38)),
                            Q16::from_raw(static_cast<int32_t>(static_cast<int64_t>(rng()) >> 38)),
                            Q16::from_raw(static_cast<int32_t>(static_cast<int64_t>(rng()) >> 38))};
            const Vec3q16 a = apply(t, p), b = pt.apply(p), c = pt.apply_by_parts(p);
            CHECK(a.x == b.x);
            CHECK(a.y == b.y);
            CHECK(a.z == b.z);
            CHECK(a.x == c.x);  // the ARMv6-M path, run here on the host
            CHECK(a.y == c.y);
            CHECK(a.z == c.z);
        }
    }
}

TEST_CASE("apply_inverse undoes a rotation and translation: exactly on a quarter turn, within 4 raw units otherwise") {
    for (uint32_t k = 0; k < 64; ++k) {
        Transform t;
        t.rot = mul(rotation_y(Angle::from_bam(k * 0x04000000u)), rotation_x(Angle::from_bam(k * 0x0300000u)));
        t.trans = {Q16::from_int(100), Q16::from_int(-7), Q16::from_ratio(1, 3)};
        const Vec3q16 p{Q16::from_int(250), Q16::from_int(-40), Q16::from_int(900)};
        const Vec3q16 back = apply(t, apply_inverse(t, p));
        CHECK(std::abs(back.x.raw() - p.x.raw()) <= 4);
        CHECK(std::abs(back.y.raw() - p.y.raw()) <= 4);
        CHECK(std::abs(back.z.raw() - p.z.raw()) <= 4);
    }
    // A quarter turn about y has exact entries: R^T (p - t) = (-(p - t).z, (p - t).y, (p - t).x), raw for raw.
    Transform quarter;
    quarter.rot = rotation_y(Angle::from_bam(0x40000000u));
    REQUIRE((quarter.rot.m[0][0].raw() == 0 && quarter.rot.m[0][2].raw() == Q30::kOne && quarter.rot.m[2][0].raw() == -Q30::kOne));
    quarter.trans = {Q16::from_raw(70000), Q16::from_raw(-3), Q16::from_raw(123457)};
    const Vec3q16 pq{Q16::from_raw(-200001), Q16::from_raw(99999), Q16::from_raw(31)};
    const Vec3q16 iq = apply_inverse(quarter, pq);
    CHECK(iq.x.raw() == -(31 - 123457));
    CHECK(iq.y.raw() == 99999 + 3);
    CHECK(iq.z.raw() == -200001 - 70000);
    const Vec3q16 round_trip = apply(quarter, iq);
    CHECK((round_trip.x.raw() == pq.x.raw() && round_trip.y.raw() == pq.y.raw() && round_trip.z.raw() == pq.z.raw()));
    Transform id;
    const Vec3q16 p{Q16::from_raw(-123456789), Q16::from_raw(5), Q16::from_raw(536870911)};
    const Vec3q16 q = apply_inverse(id, p);
    CHECK((q.x.raw() == p.x.raw() && q.y.raw() == p.y.raw() && q.z.raw() == p.z.raw()));
}

TEST_CASE("apply_wide is apply() without the wrap") {
    Transform t;
    t.rot = mul(rotation_y(Angle::from_bam(0x15000000u)), rotation_x(Angle::from_bam(0x0A000000u)));
    t.trans = {Q16::from_int(100), Q16::from_int(-7), Q16::from_ratio(1, 3)};
    const Vec3q16 p{Q16::from_int(250), Q16::from_int(-40), Q16::from_int(900)};
    const Vec3q16 a = apply(t, p);
    const Vec3i64 w = apply_wide(t, p);
    CHECK((w.x == a.x.raw() && w.y == a.y.raw() && w.z == a.z.raw()));
    // Past 2^15 units apply() wraps modulo 2^32; apply_wide keeps the value.
    t.trans.x = Q16::from_raw(INT32_MAX);
    const Vec3i64 far = apply_wide(t, p);
    CHECK(far.x > INT32_MAX);
    CHECK(static_cast<int32_t>(static_cast<uint32_t>(far.x)) == apply(t, p).x.raw());
}

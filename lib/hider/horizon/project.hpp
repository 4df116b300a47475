// Projection of a surface y = f(x, z) sampled on a grid (curve k at z = z0 + k dz, sample i at
// x = x0 + i dx, height y = value * y_unit) with the hider-render camera (view.hpp: gluLookAt +
// gluPerspective, CONVENTIONS.md). For a grid the homogeneous screen coordinates U, V, W (X = U / W,
// Y = V / W in 1/16 pixel from the top-left corner) are affine in (i, k, value), so prepare() turns
// the camera into int32 steps once (exact 128-bit setup, each of U, V, W scaled to 29 bits over the
// surface's bounding box) and a sample costs three multiplies, a table reciprocal of W and two
// 32x16-bit products: no division, the same integer operations on every target.
#pragma once
#include <hider/horizon/level_pass.hpp>
#include <hider/horizon/row_pass.hpp>
#include <hider/horizon/surface.hpp>
#include <hider/view.hpp>

namespace hider::horizon {

/// A surface and camera prepared for projection. prepare() once per camera/surface (about a hundred
/// 64-bit products); the projection functions are const and may run for any number of frames.
class SurfaceProjection {
public:
    /// Most samples per curve and curves per surface (keeps the summed rounding of the steps below 2^17).
    static constexpr int32_t kMaxCount = 65535;
    /// Bound on the rounding of U, V, W: at most 1/2 unit per step, times i + k + value + 1 < 2^17.
    static constexpr int64_t kStepError = int64_t{1} << 17;

    /// Checks the surface and the camera and builds the per-frame steps. Errors: those of make_view(),
    /// invalid_argument (fewer than 2 samples or curves, dx or dz <= 0, value_min > value_max, y_unit < 1),
    /// out_of_range (a corner of the surface's bounding box outside the world range).
    Status prepare(const Camera& cam, int32_t width, int32_t height, const Surface& s) {
        error_subpixels_ = INT32_MAX;
        if (s.samples < 2 || s.curves < 2 || s.samples > kMaxCount || s.curves > kMaxCount || s.dx.raw() <= 0 ||
            s.dz.raw() <= 0 || s.value_min > s.value_max || s.y_unit_raw < 1)
            return Status::invalid_argument;
        const int64_t xs[2] = {s.x0.raw(), s.x0.raw() + int64_t{s.dx.raw()} * (s.samples - 1)};
        const int64_t zs[2] = {s.z0.raw(), s.z0.raw() + int64_t{s.dz.raw()} * (s.curves - 1)};
        const int64_t ys[2] = {int64_t{s.value_min} * s.y_unit_raw, int64_t{s.value_max} * s.y_unit_raw};
        for (int e = 0; e < 2; ++e)
            if (!in_world(xs[e]) || !in_world(ys[e]) || !in_world(zs[e])) return Status::out_of_range;
        View view;
        const Status st = make_view(cam, width, height, view);
        if (st != Status::ok) return st;
        surface_ = s;
        width_ = width;
        height_ = height;
        eye_x_raw_ = cam.eye.x.raw();
        eye_z_raw_ = cam.eye.z.raw();
        // Heights enter as (value - value_min) >> shift, below 2^15.
        value_shift_ = 0;
        while (((int64_t{s.value_max} - s.value_min) >> value_shift_) >= (int64_t{1} << 15)) ++value_shift_;

        // U, V, W as linear forms of the world point (raw Q16) in units of 2^-38: U = X W, V = Y W with X, Y
        // in subpixels from the top-left, W = w (distance along the view axis, Q16 raw).
        const Transform& t = view.to_view;
        const int64_t k = view.k_q8, cx = int64_t{2048} * width, cy = int64_t{2048} * height;
        detail::Form f[3];
        for (int a = 0; a < 3; ++a) {
            const int64_t r0 = t.rot.m[0][a].raw(), r1 = t.rot.m[1][a].raw(), r2 = t.rot.m[2][a].raw();
            f[0].c[a] = k * r0 - cx * r2;
            f[1].c[a] = -k * r1 - cy * r2;
            f[2].c[a] = -256 * r2;
        }
        f[0].c0 = k * t.trans.x.raw() - cx * t.trans.z.raw();
        f[1].c0 = -k * t.trans.y.raw() - cy * t.trans.z.raw();
        f[2].c0 = -256 * int64_t{t.trans.z.raw()};
        const int64_t unit = int64_t{s.y_unit_raw} * (int64_t{1} << value_shift_);
        int64_t w_top = 0, w_bottom = INT64_MAX;
        for (int q = 0; q < 3; ++q) {
            // Scale so |F| < 2^28 at every corner of the bounding box (F is affine: the corners bound it).
            int bits = 0;
            for (int c = 0; c < 8; ++c) bits = max(bits, detail::bit_length(f[q].at(xs[c & 1], ys[(c >> 1) & 1], zs[c >> 2])));
            const int shift = max(bits - 28, 0);
            Axis& ax = axis_[q];
            ax.shift = shift;
            ax.base = static_cast<int32_t>(detail::round_shift(f[q].at(xs[0], ys[0], zs[0]), shift));
            ax.di = static_cast<int32_t>(detail::round_shift(mul128(f[q].c[0], s.dx.raw()), shift));
            ax.dk = static_cast<int32_t>(detail::round_shift(mul128(f[q].c[2], s.dz.raw()), shift));
            ax.dv = static_cast<int32_t>(detail::round_shift(mul128(f[q].c[1], unit), shift));
            if (q == 2) {
                for (int c = 0; c < 8; ++c) {
                    const int64_t w = detail::round_shift(f[2].at(xs[c & 1], ys[(c >> 1) & 1], zs[c >> 2]), shift);
                    w_top = max(w_top, w);
                    w_bottom = min(w_bottom, w - kStepError);
                }
                // The near plane in W's units, saturated: below shift 7 (and above int32 after it) it lies
                // beyond every sample, which are all behind it then. (It wrapped: points behind the near
                // plane were drawn, through a table index far out of range.)
                const int64_t near = shift >= 7 ? detail::round_shift(mul128(int64_t{view.near_raw}, int64_t{1} << 38), shift)
                                                : int64_t{INT32_MAX};
                near_w_ = static_cast<int32_t>(min<int64_t>(max<int64_t>(near, 1), INT32_MAX));
            }
        }
        error_subpixels_ = error_bound(w_bottom + kStepError);
        w_top = min<int64_t>(w_top + kStepError, (int64_t{1} << 29) - 1);
        n0_ = 0;
        while ((w_top << n0_) < (int64_t{1} << 29)) ++n0_;
        du_ = axis_[0].shift - axis_[2].shift;
        dv_ = axis_[1].shift - axis_[2].shift;
        fast_n_ = 24 - max(du_, dv_);
        // Every sample in front of the near plane and on the fast path: project_row() needs no checks.
        int n_max = n0_;
        if (w_bottom >= near_w_)
            while (n_max < 40 && (w_bottom << n_max) < (int64_t{1} << 29)) ++n_max;
        // Every shift 31 - n - du (or dv) in [7, 31]: no check per point (the passes shift by s, s + dvu).
        checked_ = !(w_bottom >= near_w_ && n_max <= fast_n_ && n0_ + min(du_, dv_) >= 0);
        level_ = !checked_ && axis_[2].di == 0 && axis_[1].di == 0;  // no yaw: W, V constant along a curve
        sweep_ = choose_sweep();
        compact_ = false;
        if (w_bottom >= near_w_) {  // every point in front: the corners' hull bounds the screen points
            compact_ = true;
            RowCounts c;
            for (int q = 0; q < 8; ++q) {
                const PlotPoint pt = project(at(q & 1 ? s.samples - 1 : 0, q & 4 ? s.curves - 1 : 0,
                                                q & 2 ? s.value_max : s.value_min), c);
                compact_ = compact_ && abs_value(pt.x) < kCompactLimit && abs_value(pt.y) < kCompactLimit;
            }
        }
        return Status::ok;
    }

    /// A bound on how far (in 1/16 pixel) a point in the frame and in front of the near plane may lie
    /// from its exact projection: the int32 steps round U, V and W by up to half a unit each, and a point
    /// adds up samples + curves + heights of them; plus a quarter pixel for the reciprocal table, the
    /// camera's rotation and the output's rounding. Below a pixel for a surface framed whole; it grows
    /// with the ratio of the farthest corner's screen reach to the nearest point's distance (a tall
    /// height range seen from close by). It leaves out one rounding: X and Y take U and V floored to
    /// 2^14 units (detail::scale16()), up to 2^(14 + d) / W subpixels at a point of scaled distance W (d:
    /// the axis's shift over W's). Counted against the nearest corner that term would swamp the bound on
    /// every view, so it is not; it shows where points in the frame lie much nearer than the box's extent
    /// (README, "Floating horizon"). hider-plot therefore also measures every point against its exact
    /// projection.
    int32_t error_bound_subpixels() const { return error_subpixels_; }

    const Surface& surface() const { return surface_; }
    int32_t width() const { return width_; }
    int32_t height() const { return height_; }
    /// The eye's world x and z (Q16 raw): which lines lie on which side of it.
    int32_t eye_x_raw() const { return eye_x_raw_; }
    int32_t eye_z_raw() const { return eye_z_raw_; }
    /// The sweep this view needs (chosen by prepare()).
    Sweep sweep() const { return sweep_; }
    /// Every point of the surface projects in front of the near plane within |x|, |y| < 2^15 (what the
    /// walk kernel needs).
    bool compact() const { return compact_; }

    /// Homogeneous coordinates of sample i of curve k with height `value` (clamped to the surface's range).
    HomPoint at(int32_t i, int32_t k, int32_t value) const {
        const int32_t h = reduce(clamp(value, surface_.value_min, surface_.value_max));
        return {axis_[0].at(i, k, h), axis_[1].at(i, k, h), axis_[2].at(i, k, h)};
    }

    /// The point where the segment from a (in front of the near plane) to b (behind it) crosses it.
    PlotPoint near_crossing(const HomPoint& a, const HomPoint& b, RowCounts& counts) const {
        const int64_t num = int64_t{a.w} - near_w_, den = int64_t{a.w} - b.w;  // den > num >= 0
        HomPoint p = detail::lerp(a, b, static_cast<int32_t>(den == 0 ? 0 : (num << 16) / den));
        p.w = max(p.w, near_w_);
        return project(p, counts);
    }

    /// Screen point of h (1/16 pixel from the top-left), or x == kNoPoint behind the near plane.
    /// Coordinates beyond kPointLimit are clamped to it (counted in counts.points_clamped).
    __attribute__((always_inline)) PlotPoint project(const HomPoint& h, RowCounts& counts) const {
        if (h.w < near_w_) {
            ++counts.behind;
            return {kNoPoint, 0};
        }
        uint32_t wn = static_cast<uint32_t>(h.w) << n0_;
        int n = n0_;
        while (wn < (uint32_t{1} << 29)) {
            wn <<= 1;
            ++n;
        }
        const uint32_t r = detail::recip45(wn);  // 2^45 / wn
        if (n <= fast_n_ && n + min(du_, dv_) >= 0)  // shifts in [7, 31]: |X|, |Y| < 2^24
            return {detail::scale16(h.u, r, 31 - n - du_), detail::scale16(h.v, r, 31 - n - dv_)};
        return {detail::scale_slow(h.u, r, 31 - n - du_, counts), detail::scale_slow(h.v, r, 31 - n - dv_, counts)};
    }

    /// Projects the constant-x line at sample i from the heights values[0..curves) of each curve there
    /// into out[0..curves).
    RowCounts project_column(const int32_t* values, int32_t i, PlotPoint* out) const {
        RowCounts counts;
        for (int32_t k = 0, n = surface_.curves; k < n; ++k) {
            if (values[k] < surface_.value_min || values[k] > surface_.value_max) ++counts.values_clamped;
            out[k] = project(at(i, k, values[k]), counts);
        }
        return counts;
    }

    /// Projects curve k from its heights values[0..samples) into out[0..samples).
    template <class T>
    RowCounts project_row(const T* values, int32_t k, PlotPoint* out) const {
        if (!checked_ && value_shift_ == 0 && detail::in_type_range<T>(surface_.value_min, surface_.value_max)) {
            if constexpr (detail::is_same_type<T, uint8_t>::value) {
                if (level_ && project_row_level(values, k, out)) return {};
            }
            project_row_fast(values, k, out);
            return {};
        }
        RowCounts counts;
        const int32_t vmin = surface_.value_min, vmax = surface_.value_max;
        int32_t u = axis_[0].base + k * axis_[0].dk, v = axis_[1].base + k * axis_[1].dk,
                w = axis_[2].base + k * axis_[2].dk;
        const int32_t du = axis_[0].di, dv = axis_[1].di, dw = axis_[2].di;
        const int32_t hu = axis_[0].dv, hv = axis_[1].dv, hw = axis_[2].dv;
        const int shift = value_shift_;
        for (int32_t i = 0, n = surface_.samples; i < n; ++i) {
            int32_t value = detail::height_value(values[i]);
            if (value < vmin || value > vmax) {
                value = clamp(value, vmin, vmax);
                ++counts.values_clamped;
            }
            const int32_t h = static_cast<int32_t>((static_cast<uint32_t>(value) - static_cast<uint32_t>(vmin)) >> shift);
            out[i] = project({u + h * hu, v + h * hv, w + h * hw}, counts);
            u += du;
            v += dv;
            w += dw;
        }
        return counts;
    }

private:
    /// One of U, V, W: value = (base + k dk + i di + h dv), then times 2^shift in units of 2^-38.
    struct Axis {
        int32_t base = 0, di = 0, dk = 0, dv = 0;
        int shift = 0;
        int32_t at(int32_t i, int32_t k, int32_t h) const { return base + k * dk + i * di + h * dv; }
    };
    /// The curves when a step along x moves across the screen at least as much (relative to its
    /// length there) as a step along z; measured on chords through the middle of the surface at mid height.
    Sweep choose_sweep() const {
        const int32_t mid = surface_.value_min + static_cast<int32_t>((int64_t{surface_.value_max} - surface_.value_min) / 2);
        const int32_t m = surface_.samples, n = surface_.curves;
        RowCounts c;
        const PlotPoint x0 = project(at(m / 4, n / 2, mid), c), x1 = project(at(m - 1 - m / 4, n / 2, mid), c);
        const PlotPoint z0 = project(at(m / 2, n / 4, mid), c), z1 = project(at(m / 2, n - 1 - n / 4, mid), c);
        if (x0.x == kNoPoint || x1.x == kNoPoint || z0.x == kNoPoint || z1.x == kNoPoint) return Sweep::curves;
        const int64_t ax = abs_value(int64_t{x1.x} - x0.x), ay = abs_value(int64_t{x1.y} - x0.y);
        const int64_t bx = abs_value(int64_t{z1.x} - z0.x), by = abs_value(int64_t{z1.y} - z0.y);
        // ax / (ax + ay) >= bx / (bx + by), products below 2^52.
        return ax * (bx + by) >= bx * (ax + ay) ? Sweep::curves : Sweep::x_lines;
    }

    /// project_row() when every sample is in front of the near plane, needs the fast product and no
    /// clamping (prepare() and in_type_range() decide): the same points from the two passes of
    /// row_pass.hpp (Thumb-1 loops on ARMv6-M for 8-bit heights).
    template <class T>
    void project_row_fast(const T* values, int32_t k, PlotPoint* out) const {
        const int32_t n = surface_.samples, vmin = surface_.value_min;
        RowPass p;
        p.out = out;
        p.out_end = out + n;
        // W << n0 fits 30 bits for every sample (prepare()), so the steps shift with it.
        p.hw = static_cast<int32_t>(static_cast<uint32_t>(axis_[2].dv) << n0_);
        p.dw = static_cast<int32_t>(static_cast<uint32_t>(axis_[2].di) << n0_);
        p.w = static_cast<int32_t>(static_cast<uint32_t>(axis_[2].base + k * axis_[2].dk - vmin * axis_[2].dv) << n0_);
        p.s0 = 31 - du_ - n0_;
        p.unused = 0;
        p.table = reinterpret_cast<uintptr_t>(detail::kRecip.v) - 1024;
        p.hu = axis_[0].dv;
        p.du = axis_[0].di;
        p.u = axis_[0].base + k * axis_[0].dk - vmin * p.hu;
        p.hv = axis_[1].dv;
        p.dv = axis_[1].di;
        p.v = axis_[1].base + k * axis_[1].dk - vmin * p.hv;
        p.dvu = du_ - dv_;
        if constexpr (detail::is_same_type<T, uint8_t>::value) {
            p.values = values;
            run_row_passes(p);
        } else {
            row_passes_any(values, p);
        }
    }

    /// project_row() for 8-bit heights when level_: the knots of curve k, then the level pass. False
    /// (nothing written) when W varies by more than a quarter over the heights or a knot leaves the fast
    /// path's range: project_row_fast() then.
    bool project_row_level(const uint8_t* values, int32_t k, PlotPoint* out) const {
        // W and V at value 0 and 256 lie within one step of the box (|.| < 2^29): int32 throughout.
        constexpr int32_t kStep = 1 << kLevelKnotBits;
        const int32_t vmin = surface_.value_min, dw = axis_[2].dv * kStep, dv = axis_[1].dv * kStep;
        const int32_t w0 = axis_[2].base + k * axis_[2].dk - vmin * axis_[2].dv;
        const int32_t v0 = axis_[1].base + k * axis_[1].dk - vmin * axis_[1].dv;
        const int32_t w_end = w0 + (kLevelKnots - 1) * dw, w_lo = min(w0, w_end);
        if (w_lo < near_w_ || 8 * abs_value(w_end - w0) > w_lo || max(w0, w_end) >= (int32_t{1} << (30 - n0_)))
            return false;
        LevelKnot knots[kLevelKnots];
        int e_max = 0;
        if (!make_level_knots(w0, v0, dw, dv, n0_, du_, dv_, knots, e_max)) return false;
        LevelPass p;
        p.values = values;
        p.out = out;
        p.out_end = out + surface_.samples;
        p.knots = knots;
        p.hu = axis_[0].dv;
        p.du = axis_[0].di;
        p.u = axis_[0].base + k * axis_[0].dk - vmin * p.hu;
        p.s = 31 - e_max - du_;
        run_level_pass(p);
        return true;
    }

    /// error_bound_subpixels() for the axes just set, the nearest corner's scaled W being w_near.
    int32_t error_bound(int64_t w_near) const {
        const int64_t h_max = (int64_t{surface_.value_max} - surface_.value_min) >> value_shift_;
        const int64_t e = (int64_t{surface_.samples} + surface_.curves + h_max + 2) / 2 + 1;  // units of each axis
        const int64_t w_min = max<int64_t>(w_near, near_w_);  // near_w_ >= 1
        auto in_w_units = [&](int q) {  // e units of axis q in units of W's scale, rounded up
            const int d = axis_[q].shift - axis_[2].shift;
            return d >= 0 ? (d > 30 ? INT64_MAX / 4 : e << d) : ((e >> -d) + 1);
        };
        const int64_t reach = 16 * int64_t{max(width_, height_)};  // |X|, |Y| of a point in the frame
        const int64_t worst = max(in_w_units(0), in_w_units(1));
        if (worst >= INT64_MAX / 4) return INT32_MAX;
        // plus a quarter pixel: the reciprocal table, the camera's fixed-point rotation, the output's rounding
        return static_cast<int32_t>(min<int64_t>((worst + reach * e + w_min - 1) / w_min + 4, INT32_MAX));
    }

    static constexpr bool in_world(int64_t c) { return c > -kWorldLimitRaw && c < kWorldLimitRaw; }
    /// (value - value_min) >> value_shift, below 2^15, for value in [value_min, value_max].
    int32_t reduce(int32_t value) const {
        return static_cast<int32_t>((static_cast<uint32_t>(value) - static_cast<uint32_t>(surface_.value_min)) >> value_shift_);
    }

    Surface surface_{};
    Axis axis_[3];
    int32_t width_ = 0, height_ = 0, eye_x_raw_ = 0, eye_z_raw_ = 0;
    Sweep sweep_ = Sweep::curves;
    int32_t near_w_ = 1;
    int value_shift_ = 0, n0_ = 0, du_ = 0, dv_ = 0, fast_n_ = 0;
    int32_t error_subpixels_ = INT32_MAX;  ///< unknown until prepare() succeeds
    bool checked_ = true;  ///< project_row() must check near plane and slow path per sample
    bool level_ = false;   ///< W and V do not change along a curve (level_pass.hpp)
    bool compact_ = false;
    /// Corners within this bound: every point within 2^15 (a margin for the steps' rounding).
    static constexpr int32_t kCompactLimit = (int32_t{1} << 15) - (int32_t{1} << 11);
};

}  // namespace hider::horizon

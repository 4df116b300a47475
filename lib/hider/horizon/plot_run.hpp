// One floating-horizon plot's sweep (plot.hpp): the lines of one family in order of distance, each
// projected into the caller's buffer, the pieces of the other family since the previous line, then the
// line itself, in two passes when the eye's plane cuts the surface. Private to plot.hpp.
#pragma once
#include <hider/horizon/drawer.hpp>
#include <hider/horizon/source.hpp>
#include <hider/horizon/style.hpp>

namespace hider::horizon {

namespace detail {

template <bool B, class T, class F> struct conditional_type { using type = T; };
template <class T, class F> struct conditional_type<false, T, F> { using type = F; };

/// One plot: the lines of the sweep (kCurves: curve a = k, its point b = sample i; else constant-x
/// line a = i, its point b = curve k), the line drawn last, the drawer.
template <class Target, class Source, bool kByValue, bool kCurves>
class PlotRun {
public:
    /// Heights of the current line: a grid row in place (curve sweep), else gathered into scratch.
    using Value = typename conditional_type<kCurves, typename Source::Value, int32_t>::type;

    PlotRun(const SurfaceProjection& p, const Source& src, const Horizon& h, const PlotBuffers& b, const Target& t,
            const PlotStyle& st)
        : proj_(p), s_(p.surface()), src_(src), buf_(b), style_(st), drawer_(h, t) {
        if constexpr (kByValue) drawer_.set_ramp(make_ramp(st.colours, s_.value_min, s_.value_max));
        drawer_.set_compact(p.compact());
        // A step past the last sample draws what samples - 1 draws (the first and last lines) and keeps
        // the sums below from overflowing.
        step_ = min(st.mesh_step, max(s_.samples - 1, int32_t{1}));
        last_x_line_ = (s_.samples - 1 + step_ - 1) / step_;
        points_ = kCurves ? s_.samples : s_.curves;
        whole_previous_ = !kCurves || st.mesh;
        batches_ = whole_previous_;  // plain curves: the side edges alone need no batch
        if (batches_) {
            for (int32_t c = 0; c < h.width; ++c) {
                b.pending_upper[static_cast<size_t>(c)] = INT16_MAX;
                b.pending_lower[static_cast<size_t>(c)] = INT16_MIN;
            }
        }
    }

    /// Sweeps lines first, first + step, ... (count of them). `other` >= 0: the line across the eye's
    /// plane next to `first`; the halves of the pieces between them on this side are drawn first.
    void pass(int32_t first, int32_t step, int32_t count, int32_t other) {
        have_prev_ = false;
        bool deferred = false;  // the previous line is undrawn and its horizons not yet widened
        if (other >= 0) {
            load(other);
            keep_as_previous(other);
        }
        for (int32_t n = 0, a = first; n < count; ++n, a += step) {
            load(a);
            if (batches_) drawer_.begin_batch(buf_.pending_upper.data(), buf_.pending_lower.data());
            // An undrawn constant-x line widens the horizons only after the pieces beyond it are tested:
            // they start on its points, and in those pixel columns its extent (no pixels of its own to
            // show) would hide them; the pieces before it already cover its points.
            if (deferred) draw_line(prev_a_, buf_.previous.data(), prev_row_);
            if (have_prev_) pieces(a, other >= 0 && n == 0);
            deferred = !kCurves && !x_line_drawn(a);
            if (!deferred) draw_line(a, buf_.current.data(), row_);
            if (batches_) drawer_.end_batch();
            keep_as_previous(a);
        }
    }

    PlotStats stats() {
        stats_.pixels = drawer_.pixels();
        if (stats_.values_clamped != 0 || stats_.points_clamped != 0) stats_.status = Status::out_of_range;
        return stats_;
    }

private:
    static constexpr int32_t sample_i(int32_t a, int32_t b) { return kCurves ? b : a; }
    static constexpr int32_t curve_k(int32_t a, int32_t b) { return kCurves ? a : b; }

    /// Projects line a into the current buffer.
    void load(int32_t a) {
        RowCounts c;
        if constexpr (kCurves) {
            row_ = src_.row(a, buf_.values_current.data(), proj_);
            c = proj_.project_row(row_, a, buf_.current.data());
        } else {
            src_.column(a, buf_.values_current.data(), proj_);
            row_ = buf_.values_current.data();
            c = proj_.project_column(row_, a, buf_.current.data());
        }
        stats_.samples += static_cast<uint32_t>(points_);
        all_in_front_ = c.behind == 0;
        add(c);
    }

    void add(const RowCounts& c) {
        stats_.behind += c.behind;
        stats_.values_clamped += c.values_clamped;
        stats_.points_clamped += c.points_clamped;
    }

    /// Remembers the current line as the previous one: its ends, or all of it.
    void keep_as_previous(int32_t a) {
        prev_a_ = a;
        have_prev_ = true;
        ends_[0] = buf_.current[0];
        ends_[1] = buf_.current[static_cast<size_t>(points_ - 1)];
        end_values_[0] = detail::height_value(row_[0]);
        end_values_[1] = detail::height_value(row_[points_ - 1]);
        if (whole_previous_) {  // the buffers trade places; row_ keeps pointing at the same heights
            swap_values(buf_.current, buf_.previous);
            if (!kCurves || Source::kNeedsValues) swap_values(buf_.values_current, buf_.values_previous);
            prev_row_ = row_;
        }
    }

    static Rgb id_colour(uint32_t id) { return {uint8_t(id >> 16 & 255), uint8_t(id >> 8 & 255), uint8_t(id & 255)}; }

    /// Sets the drawer up for curve k.
    void curve_style(int32_t k) {
        drawer_.set_visible(true);
        if constexpr (!kByValue) {
            const Rgb c = style_.shading == Shading::id ? id_colour(static_cast<uint32_t>(k) + 1)
                                                        : style_.colours[static_cast<size_t>(k) % style_.colours.size()];
            drawer_.set_pixel(Target::pack(c));
        }
    }

    /// Whether the constant-x line at sample i is part of the picture.
    bool x_line_drawn(int32_t i) const {
        const int32_t last = s_.samples - 1;
        if (i == 0 || i == last) return style_.mesh || style_.side_edges;
        return style_.mesh && i % step_ == 0;
    }

    /// Sets the drawer up for constant-x line j (at sample i); `drawn`: part of the picture (else it
    /// only widens the horizons).
    void x_line_style(int32_t j, bool drawn) {
        drawer_.set_visible(drawn);
        if constexpr (!kByValue) {
            drawer_.set_pixel(Target::pack(style_.shading == Shading::id
                                               ? id_colour(static_cast<uint32_t>(s_.curves + 1 + j))
                                               : style_.mesh_colour));
        }
    }

    /// Index j of the constant-x line at sample i (i a multiple of mesh_step, or the last sample).
    int32_t x_line_index(int32_t i) const { return i == s_.samples - 1 ? last_x_line_ : i / step_; }

    /// Draws line a (points pts, heights row), clipped at the near plane.
    void draw_line(int32_t a, const PlotPoint* pts, const Value* row) {
        if constexpr (kCurves) {
            curve_style(a);
        } else {
            const bool drawn = x_line_drawn(a);
            x_line_style(drawn ? x_line_index(a) : 0, drawn);
        }
        if constexpr (!kByValue) {
            if (all_in_front_ && pts == buf_.current.data()) {  // one piece, no near-plane checks
                drawer_.move_to(pts[0]);
                drawer_.walk(pts + 1, pts + points_);
                drawer_.finish();
                ++stats_.curves;
                return;
            }
        }
        bool pen = false;
        for (int32_t b = 0, n = points_; b < n; ++b) {
            const PlotPoint p = pts[b];
            const int32_t value = kByValue ? detail::height_value(row[b]) : 0;
            if (p.x != kNoPoint) {
                if (pen) {
                    if constexpr (!kByValue) {  // the rest of a run of projected points in one go
                        int32_t e = b + 1;
                        while (e < n && pts[e].x != kNoPoint) ++e;
                        drawer_.walk(pts + b, pts + e);
                        b = e - 1;
                    } else {
                        drawer_.line_to(p, value);
                    }
                } else {
                    if (b > 0) {  // came back in front of the near plane: start on it
                        drawer_.move_to(crossing(a, b, detail::height_value(row[b]), a, b - 1, detail::height_value(row[b - 1])), value);
                        drawer_.line_to(p, value);
                    } else {
                        drawer_.move_to(p, value);
                    }
                    pen = true;
                }
            } else if (pen) {  // goes behind the near plane: end on it
                drawer_.line_to(crossing(a, b - 1, detail::height_value(row[b - 1]), a, b, detail::height_value(row[b])), value);
                drawer_.finish();
                pen = false;
            }
        }
        drawer_.finish();
        ++stats_.curves;
    }

    /// Near-plane crossing of the segment from point (aa, ba) (in front) to (ab, bb) (behind).
    PlotPoint crossing(int32_t aa, int32_t ba, int32_t va, int32_t ab, int32_t bb, int32_t vb) {
        RowCounts c;
        const PlotPoint p = proj_.near_crossing(proj_.at(sample_i(aa, ba), curve_k(aa, ba), va),
                                                proj_.at(sample_i(ab, bb), curve_k(ab, bb), vb), c);
        add(c);
        return p;
    }

    /// The pieces between the previous line and line a. `split`: they cross the eye's plane; only the
    /// part from that plane to line a is drawn.
    void pieces(int32_t a, bool split) {
        if constexpr (kCurves) {
            const int32_t last = s_.samples - 1;
            if (!style_.mesh) {  // the side edges at most
                if (!style_.side_edges) return;
                for (int32_t e = 0; e < 2; ++e) {
                    x_line_style(e == 0 ? 0 : last_x_line_, true);
                    piece(a, e == 0 ? 0 : last, split, ends_[e], end_values_[e]);
                }
                return;
            }
            for (int32_t j = 0, i = 0; j <= last_x_line_; ++j, i = min(i + step_, last)) {
                x_line_style(j, true);
                piece(a, i, split, buf_.previous[static_cast<size_t>(i)], detail::height_value(prev_row_[i]));
            }
        } else {
            for (int32_t k = 0; k < s_.curves; ++k) {
                curve_style(k);
                piece(a, k, split, buf_.previous[static_cast<size_t>(k)], detail::height_value(prev_row_[k]));
            }
        }
    }

    /// The piece at point b from the previous line (projected pa, height va) to line a, as a curve of
    /// its own, clipped at the near plane (and at the eye's plane when split).
    void piece(int32_t a, int32_t b, bool split, PlotPoint pa, int32_t va) {
        const int32_t vb = detail::height_value(row_[b]);
        PlotPoint pb = buf_.current[static_cast<size_t>(b)];
        if (!split && pa.x != kNoPoint && pb.x != kNoPoint) {  // the common case: both ends projected
            drawer_.move_to(pa, va);
            drawer_.line_to(pb, vb);
            drawer_.finish();
            return;
        }
        HomPoint ha = proj_.at(sample_i(prev_a_, b), curve_k(prev_a_, b), va);
        RowCounts c;
        if (split) {  // start where the piece crosses the plane through the eye
            const Surface& s = s_;
            const int64_t origin = kCurves ? s.z0.raw() : s.x0.raw(), delta = kCurves ? s.dz.raw() : s.dx.raw();
            const int64_t eye = kCurves ? proj_.eye_z_raw() : proj_.eye_x_raw();
            const int64_t t = (eye - origin - prev_a_ * delta) * 65536 / (int64_t{a - prev_a_} * delta);
            ha = detail::lerp(ha, proj_.at(sample_i(a, b), curve_k(a, b), vb),
                              static_cast<int32_t>(clamp<int64_t>(t, 0, 65536)));
            pa = proj_.project(ha, c);
        }
        const bool a_in = pa.x != kNoPoint, b_in = pb.x != kNoPoint;
        if (a_in || b_in) {
            if (!a_in) pa = proj_.near_crossing(proj_.at(sample_i(a, b), curve_k(a, b), vb), ha, c);
            if (!b_in) pb = proj_.near_crossing(ha, proj_.at(sample_i(a, b), curve_k(a, b), vb), c);
            drawer_.move_to(pa, va);
            drawer_.line_to(pb, vb);
            drawer_.finish();
        }
        add(c);
    }

    const SurfaceProjection& proj_;
    const Surface& s_;
    const Source& src_;
    PlotBuffers buf_;
    const PlotStyle& style_;
    CurveDrawer<Target, kByValue> drawer_;
    PlotStats stats_{};
    const Value* row_ = nullptr;
    const Value* prev_row_ = nullptr;
    PlotPoint ends_[2] = {{0, 0}, {0, 0}};
    int32_t end_values_[2] = {0, 0};
    int32_t prev_a_ = 0, step_ = 1, last_x_line_ = 0, points_ = 0;  // step_: mesh_step, at most samples - 1
    bool have_prev_ = false, whole_previous_ = false, batches_ = false;
    bool all_in_front_ = false;  ///< the current buffer has no point behind the near plane
};

template <class Target, class Source, bool kByValue, bool kCurves>
PlotStats plot_passes(const SurfaceProjection& p, const Source& src, const Horizon& h, const PlotBuffers& b,
                      const Target& t, const PlotStyle& st) {
    const Surface& s = p.surface();
    const int32_t lines = kCurves ? s.curves : s.samples;
    const int64_t origin = kCurves ? s.z0.raw() : s.x0.raw(), delta = kCurves ? s.dz.raw() : s.dx.raw();
    // ke = lines at or below the eye's coordinate: one side of the plane through the eye, the rest the other.
    const int64_t rel = int64_t{kCurves ? p.eye_z_raw() : p.eye_x_raw()} - origin;
    const int32_t ke = rel < 0 ? 0 : static_cast<int32_t>(min<int64_t>(rel / delta + 1, lines));
    PlotRun<Target, Source, kByValue, kCurves> run(p, src, h, b, t, st);
    reset(h);
    if (ke < lines) run.pass(ke, 1, lines - ke, ke > 0 ? ke - 1 : -1);  // beyond the eye: increasing
    if (ke > 0) {
        if (ke < lines) reset(h);
        run.pass(ke - 1, -1, ke, ke < lines ? ke : -1);  // up to the eye: decreasing
    }
    return run.stats();
}

template <class Target, class Source, bool kByValue>
PlotStats plot_sweep(const SurfaceProjection& p, const Source& src, const Horizon& h, const PlotBuffers& b,
                     const Target& t, const PlotStyle& st) {
    return p.sweep() == Sweep::curves ? plot_passes<Target, Source, kByValue, true>(p, src, h, b, t, st)
                                      : plot_passes<Target, Source, kByValue, false>(p, src, h, b, t, st);
}

}  // namespace detail

}  // namespace hider::horizon

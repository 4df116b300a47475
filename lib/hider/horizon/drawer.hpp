// The curve drawer: tests a curve (a polyline in screen space, points in 1/16 pixel) against the
// horizons (horizon.hpp) and draws what shows. It walks the curve column by column, takes the rows it
// covers in each pixel column (rows whose centre line it crosses there, else the row of its middle),
// draws the visible part of that run, then widens the column's horizons. Crossings between columns are
// interpolated, so a curve passing behind a horizon is drawn exactly up to where it crosses it. Columns
// outside the frame are skipped, so no access leaves the horizon arrays. The hot loop is walk_kernel.hpp.
#pragma once
#include <hider/horizon/horizon.hpp>
#include <hider/horizon/walk_kernel.hpp>

namespace hider::horizon {

namespace detail {
/// a + b modulo 2^32 (what the instruction does, without signed overflow's undefined behaviour).
constexpr int32_t add_wrapping(int32_t a, int32_t b) {
    return static_cast<int32_t>(static_cast<uint32_t>(a) + static_cast<uint32_t>(b));
}
}  // namespace detail

/// Draws curves against a Horizon into a Target (target.hpp). Use: set_pixel() (or set_ramp() when
/// kByValue), then per curve move_to(), line_to() for each further point, finish(). Points within one
/// curve must run monotonically in x for the result to be exact (a curve that folds back over its own
/// columns is hidden there by itself). Borrows the horizon's arrays and the target for its lifetime.
template <class Target, bool kByValue = false>
class CurveDrawer {
public:
    using Pixel = typename Target::Pixel;

    /// Precondition: h.width == t.width(), h.height == t.height().
    CurveDrawer(const Horizon& h, const Target& t)
        : upper_(h.upper), lower_(h.lower), width_(h.width), height_(h.height), band0_(t.band_begin()),
          band1_(t.band_end()), target_(t) {}

    /// Batches: until end_batch(), curves are tested against the horizons as they were at
    /// begin_batch() and widen `pending_upper/lower` (>= width entries, all empty: INT16_MAX / INT16_MIN)
    /// instead; end_batch() merges them. For lines that cannot hide each other (a line and the mesh
    /// pieces ending on it), so none hides another where they share a pixel column.
    void begin_batch(int16_t* pending_upper, int16_t* pending_lower) {
        pending_upper_ = pending_upper;
        pending_lower_ = pending_lower;
        batch_first_ = INT32_MAX;
        batch_last_ = INT32_MIN;
    }
    void end_batch() {
        for (int32_t c = batch_first_; c <= batch_last_; ++c) {
            upper_[c] = min(upper_[c], pending_upper_[c]);
            lower_[c] = max(lower_[c], pending_lower_[c]);
            pending_upper_[c] = INT16_MAX;
            pending_lower_[c] = INT16_MIN;
        }
        pending_upper_ = pending_lower_ = nullptr;
    }

    void set_pixel(Pixel p) { pixel_ = p; }
    /// false: curves still update the horizons but draw nothing (lines that only bound the surface).
    void set_visible(bool v) { visible_ = v; }
    /// kByValue only: a column's colour is ramp(value of its topmost point).
    void set_ramp(const ValueRamp& r) { ramp_ = r; }

    /// Starts another piece at p (the pending column of the previous piece is finished first).
    void move_to(PlotPoint p, int32_t value = 0) {
        finish();
        col_ = p.x >> kPointFracBits;
        ymin_ = ymax_ = p.y;
        vtop_ = value;
        last_ = p;
        vlast_ = value;
    }

    /// Continues the piece with a straight segment to p.
    void line_to(PlotPoint p, int32_t value = 0) {
        const int32_t c = p.x >> kPointFracBits;
        if (c == col_) {
            include(p.y, value);
        } else {
            cross(p, value, c);
        }
        last_ = p;
        vlast_ = value;
    }

    /// Points of this drawer's curves all have |y| < 2^15 (SurfaceProjection::compact()): walk() may
    /// use the walk kernel.
    void set_compact(bool c) { compact_ = c; }

    /// line_to() for each point of [p, end) (none kNoPoint), with the same results: walk_kernel.hpp's
    /// loop, which hands back the columns to draw and the steps it does not take. Not for kByValue.
    void walk(const PlotPoint* p, const PlotPoint* end) {
        static_assert(!kByValue, "walk() carries no heights");
        if (!compact_) {
            for (; p != end; ++p) line_to(*p);
            return;
        }
        int32_t runs[3 * kQueuedRuns];
        WalkKernel k{p, end, col_, ymin_, ymax_, upper_, lower_, static_cast<uint32_t>(width_), detail::kSlope.v, runs,
                     runs + 3 * kQueuedRuns};
        for (;;) {
            const int r = run_walk_kernel(k);
            show_queue(runs, k.runs);
            k.runs = runs;
            if (r == kWalkDone) break;
            if (r == kWalkCross) {
                col_ = k.col;
                ymin_ = k.ymin;
                ymax_ = k.ymax;
                last_ = k.p[-1];
                line_to(*k.p);
                k.col = col_;
                k.ymin = ymin_;
                k.ymax = ymax_;
                ++k.p;
            }
        }
        col_ = k.col;
        ymin_ = k.ymin;
        ymax_ = k.ymax;
        if (end != p) last_ = end[-1];
    }

    /// Draws the pending column and ends the piece.
    void finish() {
        flush();
        col_ = kNoColumn;
    }

    /// Pixels written so far.
    uint32_t pixels() const { return pixels_; }

private:
    static constexpr int32_t kNoColumn = INT32_MIN / 2;
    static constexpr int kQueuedRuns = 32;  ///< columns the walk kernel queues before they are drawn  // never a frame column, never equal to p.x >> 4

    __attribute__((always_inline)) void include(int32_t y, int32_t v) {
        if (y < ymin_) {
            ymin_ = y;
            if constexpr (kByValue) vtop_ = v;
        }
        if (y > ymax_) ymax_ = y;
    }

    /// The segment last_ -> p leaves column col_ for column c: visits each column boundary in between
    /// that lies in 0..width (the rest are outside the frame), finishing one column per boundary.
    void cross(PlotPoint p, int32_t value, int32_t c) {
        const bool right = c > col_;
        const int32_t first = right ? col_ + 1 : col_;  // boundary b is at x = 16 b
        const int32_t last = right ? c : c + 1;
        int32_t b = right ? max(first, int32_t{0}) : min(first, width_);
        const int32_t end = right ? min(last, width_) : max(last, int32_t{0});
        if (right ? b > end : b < end) {  // both ends beyond the same side of the frame
            restart(c, p.y, value);
            return;
        }
        const PlotPoint a = last_;
        const PlotPoint& l = right ? a : p;  // left and right end, so a segment gives the same rows both ways
        const PlotPoint& r = right ? p : a;
        const int32_t dx = r.x - l.x, dy = r.y - l.y;
        // Heights outside the surface's range (counted, status out_of_range) may differ by more than int32
        // holds: the difference and the sums wrap as uint32, the same instructions without the overflow.
        const int32_t vl = right ? vlast_ : value;
        const int32_t dv = static_cast<int32_t>(right ? static_cast<uint32_t>(value) - static_cast<uint32_t>(vlast_)
                                                      : static_cast<uint32_t>(vlast_) - static_cast<uint32_t>(value));
        if (dx < 256 && dy < 65536 && dy > -65536) {  // short: a Q15 fraction from the slope table
            const uint32_t inv = detail::kSlope.v[dx];
            for (;;) {
                const int32_t t = static_cast<int32_t>((static_cast<uint32_t>(b * 16 - l.x) * inv) >> 9);
                boundary(b, right, l.y + ((dy * t) >> 15), kByValue ? detail::add_wrapping(vl, static_cast<int32_t>((int64_t{dv} * t) >> 15)) : 0);
                if (b == end) break;
                b += right ? 1 : -1;
            }
        } else {  // long: exact DDA, y = l.y + floor((x - l.x) dy / dx), one 64-bit division per segment
            const int32_t step = right ? 16 : -16;
            const int64_t n = int64_t{b * 16 - l.x} * dy;
            int32_t q = static_cast<int32_t>(div_floor(n, dx));
            int32_t rem = static_cast<int32_t>(n - int64_t{q} * dx);
            const int32_t dq = static_cast<int32_t>(div_floor(int64_t{step} * dy, dx));
            const int32_t drem = static_cast<int32_t>(int64_t{step} * dy - int64_t{dq} * dx);
            for (;;) {
                const int32_t v = kByValue ? detail::add_wrapping(vl, static_cast<int32_t>(int64_t{dv} * (b * 16 - l.x) / dx)) : 0;
                boundary(b, right, l.y + q, v);
                if (b == end) break;
                b += right ? 1 : -1;
                q += dq;
                rem += drem;
                if (rem >= dx) {
                    rem -= dx;
                    ++q;
                }
            }
        }
        if (end != last) {  // left the frame before reaching p's column
            restart(c, p.y, value);
            return;
        }
        include(p.y, value);
    }

    /// The curve crosses boundary b (x = 16 b) at height y: finish the column it leaves, open the next.
    __attribute__((always_inline)) void boundary(int32_t b, bool right, int32_t y, int32_t v) {
        include(y, v);
        flush();
        col_ = right ? b : b - 1;
        ymin_ = ymax_ = y;
        vtop_ = v;
    }

    void restart(int32_t c, int32_t y, int32_t v) {
        col_ = c;
        ymin_ = ymax_ = y;
        vtop_ = v;
    }

    /// Draws the visible rows of the pending column and widens its horizons.
    __attribute__((always_inline)) void flush() { flush_column(col_, ymin_, ymax_); }

    /// The rows a curve covers in column c, from its extent [ymin, ymax] there: those whose centre
    /// (16 r + 8) lies inside, or the row of the middle when none does. Wholly between the horizons
    /// (most columns of the far curves): hidden, nothing changes; else show() draws and widens.
    __attribute__((always_inline)) void flush_column(int32_t c, int32_t ymin, int32_t ymax) {
        if (static_cast<uint32_t>(c) >= static_cast<uint32_t>(width_)) return;
        int32_t lo = (ymin + 7) >> kPointFracBits, hi = (ymax - 8) >> kPointFracBits;
        if (lo > hi) lo = hi = (ymin + ymax) >> (kPointFracBits + 1);
        const int32_t up = upper_[c], down = lower_[c];
        if (lo >= up && hi <= down) return;
        show(c, lo, hi, up, down);
    }

    /// show() for each queued (lo, column, hi) triple, the common case (a drawn line, no batch, no
    /// height colours) in one loop.
    void show_queue(const int32_t* q, const int32_t* end) {
        if (kByValue || !visible_ || pending_upper_ != nullptr) {
            for (; q != end; q += 3) show(q[1], q[0], q[2], upper_[q[1]], lower_[q[1]]);
            return;
        }
        int16_t* const upper = upper_;
        int16_t* const lower = lower_;
        const int32_t height = height_;
        for (; q != end; q += 3) {
            const int32_t lo = q[0], c = q[1], hi = q[2];
            const int32_t up = upper[c], down = lower[c];
            int32_t a = lo, b = hi;  // rows drawn: [a, b] (and [down + 1, hi] when two parts)
            if (lo < up) {
                upper[c] = static_cast<int16_t>(clamp(lo, int32_t{-1}, height));
                if (hi > down) {
                    lower[c] = static_cast<int16_t>(clamp(hi, int32_t{-1}, height));
                    if (up <= down) {  // a horizon between the parts: the lower one first
                        draw(c, down + 1, hi);
                        b = up - 1;
                    }  // else nothing drawn here yet: one part
                } else if (hi >= up) {
                    b = up - 1;
                }
            } else if (hi > down) {
                lower[c] = static_cast<int16_t>(clamp(hi, int32_t{-1}, height));
                a = max(lo, down + 1);
            } else {
                continue;  // hidden after all (a column queued twice)
            }
            draw(c, a, b);
        }
    }

    /// Draws the rows of [lo, hi] outside the horizons (up, down) of column c and widens them.
    void show(int32_t c, int32_t lo, int32_t hi, int32_t up, int32_t down) {
        if (visible_) {
            const int32_t top_end = min(hi, up - 1), bottom_begin = max(lo, down + 1);
            if (top_end + 1 >= bottom_begin) {
                draw(c, lo, hi);
            } else {
                if (top_end >= lo) draw(c, lo, top_end);
                if (bottom_begin <= hi) draw(c, bottom_begin, hi);
            }
        } else {
            lo = hi = (lo + hi) >> 1;  // an undrawn line: its middle, so it hides nothing its own pixels
                                       // would not (they are not there to cover it)
        }
        const int16_t top = static_cast<int16_t>(clamp(lo, int32_t{-1}, height_));
        const int16_t bottom = static_cast<int16_t>(clamp(hi, int32_t{-1}, height_));
        if (pending_upper_ == nullptr) {
            if (top < up) upper_[c] = top;
            if (bottom > down) lower_[c] = bottom;
        } else {
            pending_upper_[c] = min(pending_upper_[c], top);
            pending_lower_[c] = max(pending_lower_[c], bottom);
            batch_first_ = min(batch_first_, c);
            batch_last_ = max(batch_last_, c);
        }
    }

    __attribute__((always_inline)) void draw(int32_t c, int32_t y_first, int32_t y_last) {
        y_first = max(y_first, band0_);
        y_last = min(y_last, band1_ - 1);
        if (y_first > y_last) return;
        Pixel p = pixel_;
        if constexpr (kByValue) p = Target::pack(ramp_(vtop_));
        target_.vline(c, y_first, y_last, p);
        pixels_ += static_cast<uint32_t>(y_last - y_first + 1);
    }

    int16_t* upper_;
    int16_t* lower_;
    int16_t* pending_upper_ = nullptr;  // in a batch: where the horizons widen until end_batch()
    int16_t* pending_lower_ = nullptr;
    int32_t batch_first_ = 0, batch_last_ = 0;
    int32_t width_, height_, band0_, band1_;
    const Target& target_;
    Pixel pixel_{};
    bool visible_ = true;
    bool compact_ = false;
    ValueRamp ramp_{};
    int32_t col_ = kNoColumn;
    int32_t ymin_ = 0, ymax_ = 0, vtop_ = 0, vlast_ = 0;
    PlotPoint last_{0, 0};
    uint32_t pixels_ = 0;
};

}  // namespace hider::horizon

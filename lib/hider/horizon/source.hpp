// Where a plot's heights come from: a caller grid of any integer type (row = curve, optionally a ring
// of rows for waterfalls) or a function f(x, z) sampled on the grid. plot_run.hpp reads a curve's row
// in place or gathers a constant-x line's heights through them.
#pragma once
#include <hider/horizon/project.hpp>

namespace hider::horizon {

/// Heights in a caller array of T (any integer type): curve k is row (first_row + k) mod rows, one
/// `row_stride` elements apart; the first `samples` elements of a row are its heights.
template <class T>
struct GridSource {
    const T* data = nullptr;
    int32_t row_stride = 0;
    int32_t rows = 0;       ///< rows in the array (>= curves)
    int32_t first_row = 0;  ///< row of curve 0, in [0, rows)

    using Value = T;
    static constexpr bool kNeedsValues = false;  ///< curve sweeps read rows in place

    const T* row(int32_t k, int32_t* /*scratch*/, const SurfaceProjection&) const {
        int32_t r = first_row + k;
        if (r >= rows) r -= rows;
        return data + static_cast<ptrdiff_t>(r) * row_stride;
    }
    void column(int32_t i, int32_t* out, const SurfaceProjection& p) const {
        for (int32_t k = 0; k < p.surface().curves; ++k) out[k] = detail::height_value(row(k, nullptr, p)[i]);
    }
    bool valid(const Surface& s) const {
        return data != nullptr && rows >= s.curves && row_stride >= s.samples && 0 <= first_row && first_row < rows;
    }
};

/// Heights from a function: f(Q16 x, Q16 z) returns the height as Q16 (use y_unit_raw = 1), evaluated
/// once per sample per plot into PlotBuffers::values_*.
template <class F>
struct FunctionSource {
    F f;

    using Value = int32_t;
    static constexpr bool kNeedsValues = true;

    const int32_t* row(int32_t k, int32_t* scratch, const SurfaceProjection& p) const {
        const Surface& s = p.surface();
        const Q16 z = Q16::from_raw(s.z0.raw() + k * s.dz.raw());
        for (int32_t i = 0; i < s.samples; ++i) scratch[i] = f(Q16::from_raw(s.x0.raw() + i * s.dx.raw()), z).raw();
        return scratch;
    }
    void column(int32_t i, int32_t* out, const SurfaceProjection& p) const {
        const Surface& s = p.surface();
        const Q16 x = Q16::from_raw(s.x0.raw() + i * s.dx.raw());
        for (int32_t k = 0; k < s.curves; ++k) out[k] = f(x, Q16::from_raw(s.z0.raw() + k * s.dz.raw())).raw();
    }
    bool valid(const Surface&) const { return true; }
};

}  // namespace hider::horizon

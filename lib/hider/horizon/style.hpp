// How a floating-horizon plot looks (shading, mesh, side edges), the caller's scratch it needs, and
// what it reports.
#pragma once
#include <hider/horizon/point.hpp>
#include <hider/frame.hpp>
#include <hider/status.hpp>

namespace hider::horizon {

enum class Shading : uint8_t {
    palette,  ///< curve k (0-based, by z) in colours[k % size]; constant-x lines in mesh_colour
    height,   ///< each column of a line by the height of its topmost point; colours[] is a ramp (at most
              ///< 256) from value_min to value_max
    id,       ///< curve k as id k + 1, constant-x line j (at sample min(j mesh_step, samples - 1)) as
              ///< curves + 1 + j, packed (id >> 16 & 255, id >> 8 & 255, id & 255)
};

struct PlotStyle {
    Shading shading = Shading::palette;
    Span<const Rgb> colours;         ///< palette or height ramp (not empty for those)
    Rgb mesh_colour{255, 255, 255};  ///< palette shading: constant-x lines and side edges
    bool mesh = false;               ///< constant-x lines at every mesh_step-th sample (wire-mesh look)
    int32_t mesh_step = 1;
    bool side_edges = true;          ///< constant-x lines at the first and the last sample
};

/// Caller scratch. Curve sweep: `current` >= samples; `previous` >= samples with the mesh (else may be
/// empty); values_* >= samples for function sources (previous only with the mesh); pending_* >= width
/// with the mesh. Constant-x sweep (views from the side): points and values >= curves, pending_* >=
/// width. Points and values of max(samples, curves) and pending of width serve every view.
struct PlotBuffers {
    Span<PlotPoint> current, previous;
    Span<int32_t> values_current, values_previous;
    Span<int16_t> pending_upper, pending_lower;  ///< batches (see CurveDrawer::begin_batch)
};

/// What a plot did. status: invalid_argument (nothing drawn) for unusable arguments; out_of_range
/// when heights or projections had to be clamped (the plot is complete but those points moved).
struct [[nodiscard]] PlotStats {
    Status status = Status::ok;
    uint32_t curves = 0;          ///< lines swept (curves or constant-x lines)
    uint32_t samples = 0;         ///< samples projected
    uint32_t behind = 0;          ///< of those, behind the near plane (their segments are clipped there)
    uint32_t values_clamped = 0;  ///< heights outside [value_min, value_max]
    uint32_t points_clamped = 0;  ///< projections beyond kPointLimit
    uint32_t pixels = 0;          ///< pixels written in the target's band

    constexpr bool ok() const { return status == Status::ok; }
};

}  // namespace hider::horizon

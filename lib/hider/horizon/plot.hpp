// Floating-horizon plot of a surface y = f(x, z). The planes of one family (z = const: the curves, or
// x = const when x runs into the picture; SurfaceProjection::sweep()) are swept nearest to the eye
// first, whatever the view direction; the line in each plane is drawn against the horizons of the
// lines before it, so both sides of the surface show (upper horizon: the top, lower: the underside).
// Between consecutive lines the pieces of the other family (constant-x lines between curves, or the
// curves' segments between constant-x lines) are drawn just before the line, against the same
// horizons, which keeps a mesh a hidden-line picture; constant-x lines that are not drawn still
// update the horizons when they are swept. When the eye lies between two planes of the family, the
// two sides of its own plane cannot hide each other: each is a pass with fresh horizons.
// Heights: a caller grid (row = curve; a ring of rows for waterfalls) or a function on the grid.
#pragma once
#include <hider/horizon/plot_run.hpp>
#include <hider/horizon/target.hpp>

namespace hider::horizon {

/// Whether `b` is large enough to plot `p`'s surface with `src` in style `st` (see PlotBuffers).
template <class Source>
bool buffers_fit(const SurfaceProjection& p, const Source&, const PlotBuffers& b, const PlotStyle& st) {
    const Surface& s = p.surface();
    const size_t w = static_cast<size_t>(p.width());
    const bool pending = b.pending_upper.size() >= w && b.pending_lower.size() >= w;
    if (p.sweep() == Sweep::x_lines) {
        const size_t n = static_cast<size_t>(s.curves);
        return b.current.size() >= n && b.previous.size() >= n && b.values_current.size() >= n &&
               b.values_previous.size() >= n && pending;
    }
    const size_t n = static_cast<size_t>(s.samples);
    return b.current.size() >= n && (!st.mesh || (b.previous.size() >= n && pending)) &&
           (!Source::kNeedsValues || (b.values_current.size() >= n && (!st.mesh || b.values_previous.size() >= n)));
}

/// Plots the surface of `p` with heights from `src` into `t` (its band only; the caller clears it),
/// using the horizons `h` (reset here) and the scratch `b`. Cost: per sample one projection and the
/// column walk; per line two projected ends (all of the previous line with the mesh).
template <class Target, class Source>
PlotStats plot(const SurfaceProjection& p, const Source& src, const Horizon& h, const PlotBuffers& b,
               const Target& t, const PlotStyle& st) {
    const Surface& s = p.surface();
    bool ok = s.samples >= 2 && t.valid() && h.upper != nullptr && h.width == t.width() && h.height == t.height() &&
              p.width() == t.width() && p.height() == t.height() && src.valid(s) && st.mesh_step >= 1 &&
              buffers_fit(p, src, b, st);
    if (st.shading != Shading::id) ok = ok && !st.colours.empty();
    if (st.shading == Shading::height) ok = ok && st.colours.size() <= 256;
    if (!ok) {
        PlotStats bad;
        bad.status = Status::invalid_argument;
        return bad;
    }
    return st.shading == Shading::height ? detail::plot_sweep<Target, Source, true>(p, src, h, b, t, st)
                                         : detail::plot_sweep<Target, Source, false>(p, src, h, b, t, st);
}

}  // namespace hider::horizon

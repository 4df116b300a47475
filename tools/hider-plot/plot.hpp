// hider-plot's boundary between doubles and lib/: resolves the camera (defaults frame the surface from
// above its front edge), converts heights and camera to fixed point once, runs lib/hider/horizon and
// returns the frame as RGB888. Shared by the tool and the tests.
#pragma once
#include <hider/horizon/plot.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hider-plot/surface.hpp"

namespace hider::plot {

using Vec3d = std::array<double, 3>;

/// Camera as given on the command line; unset values get defaults.
struct ViewArgs {
    std::optional<Vec3d> eye, target, up;
    double fov_deg = 40.0;  ///< vertical
    int width = 320, height = 240;
};

/// A resolved camera in world units (the surface's: x, z in [-1, 1]).
struct CameraD {
    Vec3d eye{}, target{}, up{};
    double fov_deg = 40.0, near = 0.01, far = 100.0;
    int width = 0, height = 0;
};

enum class Shade { plain, height, id };

struct Options {
    Shade shade = Shade::plain;
    bool mesh = false;
    int mesh_step = 0;  ///< 0: about the curve spacing ((samples - 1) / (curves - 1), rounded)
    int band_rows = 0;  ///< 0: the whole frame at once
};

/// The surface as lib/ sees it: exact world coordinates of the samples after the conversion.
struct FixedGrid {
    horizon::Surface surface;
    std::vector<int32_t> values;  ///< Q16 heights, row-major (row = curve)
    double x(int i) const { return (surface.x0.raw() + static_cast<double>(i) * surface.dx.raw()) / 65536.0; }
    double z(int k) const { return (surface.z0.raw() + static_cast<double>(k) * surface.dz.raw()) / 65536.0; }
    double y(int k, int i) const { return values[static_cast<size_t>(k) * surface.samples + i] / 65536.0; }
};

struct Result {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  ///< width * height * 3
    horizon::PlotStats stats;  ///< summed over bands (pixels) / of the last band (the rest)
    std::string warning;       ///< non-empty when lib/ had to clamp something or may be a pixel off
    int32_t error_subpixels = 0;  ///< the larger of error_bound_subpixels() and the error measured on every point
};

/// Fills unset camera values: target = centre of the bounding box, eye from above the front edge
/// (direction (0, 0.75, 1) from the target) as close as keeps every box corner inside 95% of the view;
/// near and far around the box. False with a plain reason for a camera lib/ cannot use.
bool resolve_camera(const HeightGrid& g, const ViewArgs& args, CameraD& out, std::string& error);

/// Converts the grid to Q16 heights over x, z in [-1, 1] (to within 1/65536 per sample).
FixedGrid to_fixed(const HeightGrid& g);

/// The lib/ camera of `cam`.
Camera to_camera(const CameraD& cam);

/// Plots `g` with lib/. False with a reason when lib/ rejects the setup or nothing of the surface lands
/// in the frame ("the view does not see the surface", or "no line of the surface crosses the ... frame"
/// when its box does reach into the frame).
bool render(const HeightGrid& g, const CameraD& cam, const Options& opt, Result& out, std::string& error);

/// Mesh step render() uses for `opt` and a grid of curves x samples (samples - 1 without the mesh: the
/// side edges are then constant-x lines 0 and 1).
int mesh_step(const Options& opt, int curves, int samples);

}  // namespace hider::plot

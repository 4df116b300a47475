// Independent double-precision reference for floating-horizon plots (does not use lib/): the surface
// as a triangle mesh (two triangles per grid cell), each line of the plot (the curves z = const, the
// constant-x lines) sampled densely in 3D, and each sample's visibility decided by casting the ray
// from the eye to it against the mesh. Conventions as hider's: gluLookAt, gluPerspective, row 0 on
// top, pixel (c, r) covers [c, c + 1) x [r, r + 1) in pixel units; samples nearer than `near` are hidden.
#pragma once

#include <stdint.h>

#include <vector>

namespace hider::ref {

struct HorizonSurface {
    int rows = 0, cols = 0;     ///< curves, samples per curve
    std::vector<double> x, z;   ///< x of each sample (cols), z of each curve (rows)
    std::vector<double> y;      ///< heights, row-major
};

struct HorizonCamera {
    double eye[3], target[3], up[3];
    double fovy_deg, near;
    int width, height;
};

/// A line of the plot: consecutive grid points (row, col) joined by straight 3D segments, and its id.
struct HorizonLine {
    uint32_t id;
    std::vector<int> rows, cols;
};

/// The plot's lines as hider draws them: curve k (id k + 1) along each row; constant-x line j at
/// column min(j step, cols - 1) (id rows + 1 + j) down the rows, every j with `mesh`, else only the
/// first and last (the side edges).
std::vector<HorizonLine> horizon_lines(const HorizonSurface& s, bool mesh, int step);

/// Visible pixels of each line: out[n] lists (sorted, unique) the pixel indices y * width + x where
/// some visible sample of lines[n] falls.
std::vector<std::vector<uint32_t>> visible_pixels(const HorizonSurface& s, const HorizonCamera& cam,
                                                  const std::vector<HorizonLine>& lines);

/// Agreement of an id image (0 = background) with the reference: a pixel of line `id` counts as
/// matched when the other side has a pixel of the same line within one pixel (8-neighbourhood). A
/// reference pixel also counts when the image shows there another line the reference sees there too
/// (lines closer than a pixel share pixels, and an id image keeps one of them).
struct LineAgreement {
    long image_pixels = 0, image_matched = 0;  ///< pixels of the lines in the image
    long ref_pixels = 0, ref_matched = 0;      ///< visible pixels in the reference
    double image_rate() const { return image_pixels == 0 ? 1.0 : static_cast<double>(image_matched) / image_pixels; }
    double ref_rate() const { return ref_pixels == 0 ? 1.0 : static_cast<double>(ref_matched) / ref_pixels; }
};

/// Compares the lines with ids in [first_id, last_id]. `ids` is width * height.
LineAgreement compare_lines(const std::vector<uint32_t>& ids, int width, int height, const std::vector<HorizonLine>& lines,
                            const std::vector<std::vector<uint32_t>>& visible, uint32_t first_id, uint32_t last_id);

}  // namespace hider::ref

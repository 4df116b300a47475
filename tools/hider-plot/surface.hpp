// hider-plot's surfaces on the host (doubles): the built-in functions and PGM height maps, both as a
// grid of heights over x, z in [-1, 1] (row j = the curve at z = -1 + 2 j / (rows - 1), row 0 at
// z = -1; column i at x = -1 + 2 i / (cols - 1)). Converted to lib/ types once, in plot.cpp.
#pragma once
#include <string>
#include <vector>

namespace hider::plot {

/// Heights y (world units) on a rows x cols grid, row-major.
struct HeightGrid {
    int rows = 0, cols = 0;
    std::vector<double> y;
    double at(int row, int col) const { return y[static_cast<size_t>(row) * cols + col]; }
};

/// Names of the built-in functions, comma-separated (for messages).
std::string function_names();

/// f(x, z) of a built-in function, unscaled (about -1..1); false for an unknown name.
bool function_value(const std::string& name, double x, double z, double& out);

/// Samples built-in function `name` times `scale` on curves x samples points. False for an unknown name.
bool sample_function(const std::string& name, double scale, int curves, int samples, HeightGrid& out);

/// A PGM image: width x height values in [0, maxval], row 0 first.
struct Pgm {
    int width = 0, height = 0;
    int maxval = 0;
    std::vector<int> values;
};

/// Reads a P2 (text) or P5 (binary, 8 or 16 bit big-endian) PGM. On failure returns false and sets
/// `error` to "path: what" (unreadable, wrong magic, bad or missing header field, maxval 0 or above 65535,
/// truncated data, a value above maxval, fewer than 2 rows or columns).
bool read_pgm(const std::string& path, Pgm& out, std::string& error);

/// The height map of a PGM: height = scale * value / maxval, resampled bilinearly to curves x samples
/// (curves <= 0 or samples <= 0: the image's own rows or columns).
HeightGrid heightmap_grid(const Pgm& pgm, double scale, int curves, int samples);

}  // namespace hider::plot

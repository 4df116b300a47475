// Built-in functions and the PGM reader of hider-plot.
#include "hider-plot/surface.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>

namespace hider::plot {
namespace {

const char* const kFunctions[] = {"sinc", "saddle", "hills", "waves"};

double gauss(double x, double z, double cx, double cz, double s2) {
    return std::exp(-((x - cx) * (x - cx) + (z - cz) * (z - cz)) / s2);
}

/// Reads one whitespace-separated header or P2 token, skipping '#' comments. False at the end of data.
bool next_token(const std::string& data, size_t& pos, std::string& token) {
    for (;;) {
        while (pos < data.size() && std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
        if (pos < data.size() && data[pos] == '#') {
            while (pos < data.size() && data[pos] != '\n') ++pos;
            continue;
        }
        break;
    }
    if (pos >= data.size()) return false;
    const size_t start = pos;
    while (pos < data.size() && !std::isspace(static_cast<unsigned char>(data[pos])) && data[pos] != '#') ++pos;
    token = data.substr(start, pos - start);
    return true;
}

/// A non-negative decimal integer below 2^31.
bool to_count(const std::string& s, long& out) {
    if (s.empty() || s.size() > 10) return false;
    long v = 0;
    for (const char c : s) {
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
        v = v * 10 + (c - '0');
    }
    if (v > 2147483647L) return false;
    out = v;
    return true;
}

/// Linear interpolation in a row-major grid at fractional (row, col).
double bilinear(const std::vector<double>& g, int rows, int cols, double r, double c) {
    const int r0 = std::min(static_cast<int>(std::floor(r)), rows - 2), c0 = std::min(static_cast<int>(std::floor(c)), cols - 2);
    const double fr = r - r0, fc = c - c0;
    auto at = [&](int i, int j) { return g[static_cast<size_t>(i) * cols + j]; };
    return (1 - fr) * ((1 - fc) * at(r0, c0) + fc * at(r0, c0 + 1)) + fr * ((1 - fc) * at(r0 + 1, c0) + fc * at(r0 + 1, c0 + 1));
}

}  // namespace

std::string function_names() {
    std::string s;
    for (const char* f : kFunctions) s += (s.empty() ? "" : ", ") + std::string(f);
    return s;
}

bool function_value(const std::string& name, double x, double z, double& out) {
    if (name == "sinc") {  // sin(r) / r ripple, 3.5 periods from the centre to the corners
        const double r = 11.0 * std::hypot(x, z);
        out = r < 1e-9 ? 1.0 : std::sin(r) / r;
    } else if (name == "saddle") {
        out = x * x - z * z;
    } else if (name == "hills") {  // a sum of Gaussians: two hills, a ridge and a hollow
        out = 0.9 * gauss(x, z, -0.35, -0.3, 0.09) + 0.6 * gauss(x, z, 0.45, 0.35, 0.05) +
              0.35 * gauss(x, z, 0.5, -0.5, 0.02) - 0.4 * gauss(x, z, -0.2, 0.55, 0.06);
    } else if (name == "waves") {
        out = 0.5 * std::sin(5.0 * x + 2.0 * z) + 0.3 * std::cos(7.0 * z - 3.0 * x);
    } else {
        return false;
    }
    return true;
}

bool sample_function(const std::string& name, double scale, int curves, int samples, HeightGrid& out) {
    double probe = 0;
    if (!function_value(name, 0, 0, probe) || curves < 2 || samples < 2) return false;
    out.rows = curves;
    out.cols = samples;
    out.y.assign(static_cast<size_t>(curves) * samples, 0.0);
    for (int j = 0; j < curves; ++j)
        for (int i = 0; i < samples; ++i) {
            double v = 0;
            function_value(name, -1.0 + 2.0 * i / (samples - 1), -1.0 + 2.0 * j / (curves - 1), v);
            out.y[static_cast<size_t>(j) * samples + i] = scale * v;
        }
    return true;
}

bool read_pgm(const std::string& path, Pgm& out, std::string& error) {
    struct stat st {};  // a directory opens on Linux, then throws from its first read
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        error = path + ": cannot open for reading: " + std::strerror(EISDIR);
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot open for reading";
        return false;
    }
    auto fail = [&](const std::string& what) {
        error = path + ": " + what;
        return false;
    };
    // Read in chunks up to the largest map the header may declare (2^26 values of up to 5 digits and a
    // separator in P2): /dev/zero or a huge file is an error, not an unbounded allocation.
    constexpr size_t kMaxBytes = size_t{6} << 26;
    std::string data;
    std::vector<char> chunk(size_t{1} << 20);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        data.append(chunk.data(), static_cast<size_t>(in.gcount()));
        if (data.size() > kMaxBytes) return fail("file larger than " + std::to_string(kMaxBytes) + " bytes, hider-plot's limit for a height map");
    }
    if (in.bad()) return fail("read error");
    if (data.size() < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '5')) {
        const std::string magic = data.substr(0, std::min<size_t>(2, data.size()));
        return fail("not a PGM height map (magic '" + magic + "', expected P2 or P5)");
    }
    const bool binary = data[1] == '5';
    size_t pos = 2;
    if (pos < data.size() && !std::isspace(static_cast<unsigned char>(data[pos])) && data[pos] != '#')
        return fail("not a PGM height map (magic '" + data.substr(0, 3) + "', expected P2 or P5)");
    const char* const fields[] = {"width", "height", "maxval"};
    long header[3] = {0, 0, 0};
    for (int f = 0; f < 3; ++f) {
        std::string token;
        if (!next_token(data, pos, token)) return fail(std::string("truncated header: no ") + fields[f]);
        if (!to_count(token, header[f])) return fail(std::string("bad ") + fields[f] + " '" + token + "'");
    }
    const long width = header[0], height = header[1], maxval = header[2];
    if (maxval == 0) return fail("maxval 0 (must be 1..65535)");
    if (maxval > 65535) return fail("maxval " + std::to_string(maxval) + " out of range (1..65535)");
    if (width < 2 || height < 2)
        return fail("image is " + std::to_string(width) + "x" + std::to_string(height) +
                    "; a height map needs at least 2 rows and 2 columns");
    if (width > 65535 || height > 65535 || width * height > (1L << 26))
        return fail("image is " + std::to_string(width) + "x" + std::to_string(height) +
                    "; at most 65535 per side and 2^26 pixels");
    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    out.width = static_cast<int>(width);
    out.height = static_cast<int>(height);
    out.maxval = static_cast<int>(maxval);
    out.values.clear();  // filled as values are read: a header that promises more than the file holds costs nothing
    if (binary) {
        // Exactly one whitespace byte ends the header, or a comment right after maxval up to its newline
        // (netpbm: comments may come before the whitespace that delimits the raster); then 1 or 2
        // (big-endian) bytes per value.
        if (pos < data.size() && data[pos] == '#')
            while (pos < data.size() && data[pos] != '\n' && data[pos] != '\r') ++pos;
        if (pos >= data.size()) return fail("truncated: no pixel data");
        ++pos;
        const size_t bytes = maxval < 256 ? 1 : 2;
        const size_t have = (data.size() - pos) / bytes;
        if (have < count)
            return fail("truncated: " + std::to_string(have) + " of " + std::to_string(count) + " pixel values");
        out.values.assign(count, 0);
        for (size_t i = 0; i < count; ++i) {
            const auto b = [&](size_t k) { return static_cast<int>(static_cast<unsigned char>(data[pos + i * bytes + k])); };
            out.values[i] = bytes == 1 ? b(0) : b(0) << 8 | b(1);
        }
    } else {
        for (size_t i = 0; i < count; ++i) {
            std::string token;
            if (!next_token(data, pos, token))
                return fail("truncated: " + std::to_string(i) + " of " + std::to_string(count) + " pixel values");
            long v = 0;
            if (!to_count(token, v)) return fail("bad pixel value '" + token + "' (pixel " + std::to_string(i) + ")");
            out.values.push_back(static_cast<int>(std::min<long>(v, 1L << 30)));
        }
    }
    for (size_t i = 0; i < count; ++i)
        if (out.values[i] > maxval)
            return fail("pixel " + std::to_string(i) + " (row " + std::to_string(i / width) + ", column " +
                        std::to_string(i % width) + ") value " + std::to_string(out.values[i]) + " exceeds maxval " +
                        std::to_string(maxval));
    return true;
}

HeightGrid heightmap_grid(const Pgm& pgm, double scale, int curves, int samples) {
    const int rows = curves > 0 ? curves : pgm.height, cols = samples > 0 ? samples : pgm.width;
    std::vector<double> src(pgm.values.size());
    for (size_t i = 0; i < src.size(); ++i) src[i] = scale * pgm.values[i] / pgm.maxval;
    HeightGrid g;
    g.rows = rows;
    g.cols = cols;
    g.y.assign(static_cast<size_t>(rows) * cols, 0.0);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            const double r = rows == pgm.height ? j : static_cast<double>(j) * (pgm.height - 1) / (rows - 1);
            const double c = cols == pgm.width ? i : static_cast<double>(i) * (pgm.width - 1) / (cols - 1);
            g.y[static_cast<size_t>(j) * cols + i] = bilinear(src, pgm.height, pgm.width, r, c);
        }
    return g;
}

}  // namespace hider::plot

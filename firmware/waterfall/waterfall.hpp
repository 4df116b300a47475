// The waterfall example, for firmware and host alike: a spectrum-style waterfall. Each frame a fresh
// spectrum (128 bins, uint8) enters at the front and the older ones move back; the last 64 are kept in
// a ring of rows (8 KB) and plotted as a floating-horizon surface with lib/hider/horizon: 128x64 1-bit
// (an OLED's page layout) whole, and 160x128 RGB565 coloured by height, 8-row bands through a BandSink.
// The spectrum is synthetic and fixed point (cos/sin from angle.hpp): drifting Hann-shaped peaks on a
// noise floor. Io: bool open(path), bool write(data, size), bool close(), print(text), print_u32(v).
#pragma once
#include <hider/horizon/plot.hpp>

#include "common/bench.hpp"
#include "spin/ppm_sink.hpp"

namespace waterfall {

constexpr int32_t kSamples = 128;  ///< bins per spectrum (points per curve)
constexpr int32_t kCurves = 64;    ///< spectra on screen
constexpr int32_t kFrames = 4;     ///< frames each program writes
constexpr int32_t kPeaks = 5;
constexpr int32_t kShapeWidth = 6;  ///< a peak reaches kShapeWidth - 1 bins either side

/// A synthetic spectrum source: kPeaks peaks whose bins and heights drift with time, on a noise floor.
class Spectrum {
public:
    Spectrum() {
        // Hann window (1 + cos(pi d / W)) / 2 in 1/255, from the Q30 cosine.
        for (int32_t d = 0; d < kShapeWidth; ++d) {
            const hider::Angle a = hider::Angle::from_bam(static_cast<uint32_t>(d) * (0x80000000u / kShapeWidth));
            shape_[d] = static_cast<uint8_t>((255 * (int64_t{hider::Q30::kOne} + hider::cos(a).raw()) + (int64_t{1} << 30)) >> 31);
        }
    }

    /// The next spectrum: kSamples values.
    void next(uint8_t* row) {
        int32_t centre[kPeaks], height[kPeaks];
        for (int32_t j = 0; j < kPeaks; ++j) {
            const uint32_t phase = static_cast<uint32_t>(j) * 0x3C000000u;
            centre[j] = kCentre[j] + ((kSwing[j] * (wave(phase + t_ * kSpeed[j]) >> 14)) >> 16);
            height[j] = 120 + ((110 * (wave(phase * 3 + t_ * (kSpeed[j] * 5 / 2)) >> 14)) >> 16);
        }
        for (int32_t i = 0; i < kSamples; ++i) {
            seed_ = seed_ * 1664525u + 1013904223u;  // noise floor 4..19
            int32_t v = 4 + static_cast<int32_t>(seed_ >> 28);
            for (int32_t j = 0; j < kPeaks; ++j) {
                const int32_t d = i > centre[j] ? i - centre[j] : centre[j] - i;
                if (d < kShapeWidth) v += (height[j] * shape_[d]) >> 8;
            }
            row[i] = static_cast<uint8_t>(v > 255 ? 255 : v);
        }
        ++t_;
    }

private:
    static int32_t wave(uint32_t bam) { return hider::sin(hider::Angle::from_bam(bam)).raw(); }
    static constexpr int32_t kCentre[kPeaks] = {18, 42, 64, 88, 110};
    static constexpr int32_t kSwing[kPeaks] = {6, 12, 3, 10, 5};
    static constexpr uint32_t kSpeed[kPeaks] = {0x01200000u, 0x00C00000u, 0x02800000u, 0x00E00000u, 0x01800000u};
    uint8_t shape_[kShapeWidth] = {};
    uint32_t t_ = 0;
    uint32_t seed_ = 0x2545F491u;
};

/// The last kCurves spectra, a ring of rows: curve 0 (the farthest, oldest) is row `first`.
struct History {
    uint8_t rows[kCurves][kSamples];
    int32_t first;

    /// Overwrites the oldest row with the next spectrum, which becomes curve kCurves - 1 (the front).
    void push(Spectrum& s) {
        s.next(rows[first]);
        first = first + 1 == kCurves ? 0 : first + 1;
    }
    hider::horizon::GridSource<uint8_t> source() const { return {&rows[0][0], kSamples, kCurves, first}; }
};

/// Where the spectra lie: bins along x in [-1, 1], time along z in [-1, 1] (front = z 1), heights up to 0.4.
inline hider::horizon::Surface surface() {
    hider::horizon::Surface s;
    s.samples = kSamples;
    s.curves = kCurves;
    s.dx = hider::Q16::from_ratio(2, kSamples - 1);
    s.x0 = hider::Q16::from_raw(-(s.dx.raw() * (kSamples - 1)) / 2);
    s.dz = hider::Q16::from_ratio(2, kCurves - 1);
    s.z0 = hider::Q16::from_raw(-(s.dz.raw() * (kCurves - 1)) / 2);
    s.value_min = 0;
    s.value_max = 255;
    s.y_unit_raw = (65536 * 2 / 5 + 127) / 255;  // 255 -> 0.4
    return s;
}

/// The camera: in front of the newest spectrum and above it, looking along the time axis (no yaw). The
/// 1-bit display looks from lower, so peaks hide the spectra behind them (64 curves on 64 rows).
inline hider::Camera camera(bool low) {
    using hider::Q16;
    hider::Camera c;
    c.eye = {Q16::from_int(0), low ? Q16::from_ratio(9, 10) : Q16::from_ratio(17, 10), Q16::from_ratio(27, 10)};
    c.target = {Q16::from_int(0), low ? Q16::from_ratio(1, 10) : Q16::from_ratio(-1, 5), Q16::from_ratio(-1, 5)};
    c.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
    c.fovy = hider::Angle::from_degrees(Q16::from_int(42));
    c.near = Q16::from_ratio(1, 4);
    c.far = Q16::from_int(10);
    return c;
}

/// What the plot of one frame needs besides the target; declared by the application.
struct Buffers {
    hider::Span<int16_t> upper, lower;             ///< width each
    hider::Span<hider::horizon::PlotPoint> points;  ///< kSamples
};

/// Height ramp of the colour plot: deep blue, cyan, green, yellow, red.
inline constexpr hider::Rgb kRamp[] = {{30, 40, 160}, {20, 110, 230}, {0, 190, 230}, {30, 220, 120},
                                        {150, 230, 40}, {250, 220, 30}, {250, 120, 20}, {240, 40, 30}};

/// A prepared plot: camera and surface for one frame size, horizons and points.
class Plotter {
public:
    hider::Status prepare(int32_t width, int32_t height, const Buffers& b, bool colour) {
        const hider::Status s = proj_.prepare(camera(!colour), width, height, surface());
        if (s != hider::Status::ok) return s;
        buffers_.current = b.points;
        style_.shading = colour ? hider::horizon::Shading::height : hider::horizon::Shading::palette;
        style_.colours = colour ? hider::Span<const hider::Rgb>(kRamp) : hider::Span<const hider::Rgb>(kWhite);
        return hider::horizon::make_horizon(b.upper, b.lower, width, height, horizon_);
    }

    /// Plots the history into `t` (its band; the caller clears it).
    template <class Target>
    hider::horizon::PlotStats plot(const History& h, const Target& t) const {
        return hider::horizon::plot(proj_, h.source(), horizon_, buffers_, t, style_);
    }

    /// Projects every curve of the history into the points buffer, as plot() does first for each
    /// curve (the projection share of a frame, for hider-bench).
    void project_only(const History& h) const {
        const hider::horizon::GridSource<uint8_t> src = h.source();
        for (int32_t k = 0; k < kCurves; ++k)
            (void)proj_.project_row(src.row(k, nullptr, proj_), k, buffers_.current.data());
    }

private:
    static constexpr hider::Rgb kWhite[] = {{255, 255, 255}};
    hider::horizon::SurfaceProjection proj_;
    hider::horizon::Horizon horizon_;
    hider::horizon::PlotBuffers buffers_;
    hider::horizon::PlotStyle style_;
};

/// What a program's bench_begin()/bench_end() pairs bracket each frame.
enum class Measure : uint8_t {
    frame,       ///< clear + plot (the incoming spectrum excluded)
    projection,  ///< the projection of every curve alone (then the frame is plotted unmeasured)
};

/// "<prefix>_NNN.<ext>" into out (room for prefix + 12 characters); n < 1000.
inline void file_name(char* out, const char* prefix, int32_t n, const char* ext) {
    while (*prefix != '\0') *out++ = *prefix++;
    *out++ = '_';
    *out++ = static_cast<char>('0' + n / 100 % 10);
    *out++ = static_cast<char>('0' + n / 10 % 10);
    *out++ = static_cast<char>('0' + n % 10);
    *out++ = '.';
    while (*ext != '\0') *out++ = *ext++;
    *out = '\0';
}

/// Writes a 1-bit frame as a binary PBM (P4: rows of bytes, leftmost pixel in the top bit, 1 = lit).
template <class Io>
bool write_pbm(Io& io, const char* path, const hider::horizon::MonoFrame& f) {
    if (!io.open(path)) return false;
    const char header[] = "P4\n128 64\n";
    bool ok = f.width == 128 && f.height == 64 && io.write(header, sizeof header - 1);
    for (int32_t y = 0; y < f.height && ok; ++y) {
        uint8_t row[128 / 8] = {};
        for (int32_t x = 0; x < f.width; ++x)
            if (f.lit(x, y)) row[x / 8] = static_cast<uint8_t>(row[x / 8] | (0x80u >> (x % 8)));
        ok = io.write(row, sizeof row);
    }
    return io.close() && ok;
}

/// Shared tail of both programs: a failed frame prints why; returns the exit status.
template <class Io>
int report(Io& io, const char* what, const char* path, hider::Status s) {
    io.print("waterfall: ");
    io.print(what);
    io.print(" ");
    io.print(path);
    io.print(": ");
    io.print(hider::status_name(s));
    io.print("\n");
    return 1;
}

/// The 128x64 1-bit program: fills the history (kCurves spectra), then kFrames times pushes one
/// spectrum, clears, plots and writes <prefix>_NNN.pbm. Returns the exit status.
template <class Io>
int run_mono(Io& io, History& history, const Buffers& b, const hider::horizon::MonoFrame& frame, const char* prefix,
             Measure measure) {
    Spectrum spectrum;
    history.first = 0;
    for (int32_t k = 0; k < kCurves; ++k) history.push(spectrum);
    Plotter plotter;
    hider::Status st = plotter.prepare(frame.width, frame.height, b, false);
    if (st != hider::Status::ok) return report(io, "prepare", prefix, st);
    const hider::horizon::MonoTarget target(frame);
    for (int32_t n = 0; n < kFrames; ++n) {
        history.push(spectrum);
        if (measure == Measure::projection) {
            bench_begin();
            plotter.project_only(history);
            bench_end();
        }
        if (measure == Measure::frame) bench_begin();
        hider::horizon::clear(frame);
        const hider::horizon::PlotStats ps = plotter.plot(history, target);
        if (measure == Measure::frame) bench_end();
        char path[48];
        file_name(path, prefix, n, "pbm");
        if (!ps.ok()) return report(io, "plot", path, ps.status);
        if (!write_pbm(io, path, frame)) return report(io, "cannot write", path, hider::Status::ok);
        io.print(path);
        io.print(": pixels ");
        io.print_u32(ps.pixels);
        io.print("\n");
    }
    return 0;
}

/// The 160x128 RGB565 program: as run_mono, but each frame is plotted band by band (`rows` rows of
/// `band`, width 160) and streamed as <prefix>_NNN.ppm through spin::PpmSink. `frame` measures the
/// whole banded frame (every band re-plots: the horizons need every curve).
template <class Io>
int run_colour(Io& io, History& history, const Buffers& b, hider::Span<uint16_t> band, int32_t rows,
               hider::Span<uint8_t> ppm_row, const char* prefix, Measure measure) {
    constexpr int32_t kWidth = 160, kHeight = 128;
    if (rows < 1 || band.size() < static_cast<size_t>(kWidth * rows)) return report(io, "band", prefix, hider::Status::invalid_argument);
    Spectrum spectrum;
    history.first = 0;
    for (int32_t k = 0; k < kCurves; ++k) history.push(spectrum);
    Plotter plotter;
    const hider::Status st = plotter.prepare(kWidth, kHeight, b, true);
    if (st != hider::Status::ok) return report(io, "prepare", prefix, st);
    for (int32_t n = 0; n < kFrames; ++n) {
        history.push(spectrum);
        char path[48];
        file_name(path, prefix, n, "ppm");
        if (!io.open(path)) return report(io, "cannot write", path, hider::Status::ok);
        spin::PpmSink<Io> ppm(io, ppm_row);
        const hider::port::BandSink sink = ppm.sink();
        bool sent = sink.begin_frame(sink.user, kWidth, kHeight);
        uint32_t pixels = 0;
        for (int32_t y0 = 0; y0 < kHeight && sent; y0 += rows) {
            const int32_t y1 = y0 + rows < kHeight ? y0 + rows : kHeight;
            const auto view = hider::band_view<hider::Rgb565Format, uint16_t>(band.data(), nullptr, kWidth, kHeight, y0, y1);
            if (measure == Measure::frame) bench_begin();
            hider::clear(view, hider::Rgb{0, 0, 0});
            const hider::horizon::PlotStats ps = plotter.plot(history, hider::horizon::FrameTarget<hider::Rgb565Format>(view));
            if (measure == Measure::frame) bench_end();
            if (!ps.ok()) return report(io, "plot", path, ps.status);
            pixels += ps.pixels;
            sent = sink.write_rows(sink.user, static_cast<uint16_t>(y0), static_cast<uint16_t>(y1 - y0), band.data(), kWidth);
        }
        const bool ended = sink.end_frame(sink.user);
        if (!io.close() || !sent || !ended) return report(io, "cannot write", path, hider::Status::ok);
        io.print(path);
        io.print(": pixels ");
        io.print_u32(pixels);
        io.print("\n");
    }
    return 0;
}

}  // namespace waterfall

// A BandSink that streams RGB565 rows as a binary PPM (P6, maxval 255) to an output, the way a display
// driver would take them: each pixel expands to RGB888 by Rgb565Format::unpack (bit replication, as
// port/host/ppm.hpp's append_rgb888), a row or a part of a row at a time through a caller-owned buffer.
// The call order is checked with BandSequenceChecker. Freestanding: firmware and host references share it.
#pragma once
#include <hider/frame.hpp>
#include <hider/status.hpp>

#include "common/decimal.hpp"
#include "display/sink.hpp"

namespace spin {

/// Output: any type with `bool write(const void* data, size_t size)` (semihosted file, stdio, memory).
template <class Output>
class PpmSink {
public:
    /// Borrows `out` and `row_rgb` (3 bytes per pixel of the widest frame accepted) for its lifetime.
    PpmSink(Output& out, hider::Span<uint8_t> row_rgb)
        : out_(out), row_(row_rgb), checker_(static_cast<uint16_t>(row_rgb.size() / 3)) {}
    /// Borrows `out` and `chunk_rgb` (3 bytes a pixel, at least one pixel: rows go out in parts of that
    /// many pixels) for its lifetime; accepts frames up to max_width pixels wide.
    PpmSink(Output& out, hider::Span<uint8_t> chunk_rgb, uint16_t max_width)
        : out_(out), row_(chunk_rgb), checker_(max_width) {}

    /// The sink to hand to a renderer; valid while this object lives. `windows` false leaves out
    /// BandSink::write_columns (a sink of full-width rows only).
    hider::port::BandSink sink(bool windows = true) {
        return {this, &begin_thunk, &write_thunk, &end_thunk, windows ? &columns_thunk : nullptr};
    }

    /// First refusal seen (ok if none): a contract breach from the checker, or not_ready when the
    /// output refused bytes.
    hider::port::BandStatus status() const { return status_; }

private:
    static PpmSink& self(void* user) { return *static_cast<PpmSink*>(user); }
    static bool begin_thunk(void* user, uint16_t width, uint16_t height) { return self(user).begin(width, height); }
    static bool write_thunk(void* user, uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px) {
        return self(user).rows(y0, rows, rgb565, stride_px);
    }
    static bool end_thunk(void* user) { return self(user).end(); }
    static bool columns_thunk(void* user, uint16_t y0, uint16_t rows, uint16_t x0, uint16_t width, uint16_t fill,
                              const uint16_t* rgb565, uint32_t stride_px) {
        return self(user).columns(y0, rows, x0, width, fill, rgb565, stride_px);
    }

    bool refuse(hider::port::BandStatus s) {
        if (status_ == hider::port::BandStatus::ok) status_ = s;
        return false;
    }

    bool begin(uint16_t width, uint16_t height) {
        const hider::port::BandStatus s = checker_.begin_frame(width, height);
        if (s != hider::port::BandStatus::ok) return refuse(s);
        char header[32] = {'P', '6', '\n'};  // "P6\n<W> <H>\n255\n", as port/host/ppm.cpp writes it
        char* p = append_decimal(header + 3, width);
        *p++ = ' ';
        p = append_decimal(p, height);
        const char tail[] = "\n255\n";
        for (int i = 0; i < 5; ++i) *p++ = tail[i];
        if (!out_.write(header, static_cast<size_t>(p - header))) return refuse(hider::port::BandStatus::not_ready);
        return true;
    }

    bool rows(uint16_t y0, uint16_t count, const uint16_t* rgb565, uint32_t stride_px) {
        const hider::port::BandStatus s = checker_.write_rows(y0, count, rgb565, stride_px);
        if (s != hider::port::BandStatus::ok) return refuse(s);
        return emit(count, 0, checker_.width(), 0, rgb565, stride_px);
    }

    bool columns(uint16_t y0, uint16_t count, uint16_t x0, uint16_t width, uint16_t fill, const uint16_t* rgb565,
                 uint32_t stride_px) {
        const hider::port::BandStatus s = checker_.write_columns(y0, count, x0, width, rgb565, stride_px);
        if (s != hider::port::BandStatus::ok) return refuse(s);
        return emit(count, x0, width, fill, rgb565, stride_px);
    }

    /// Writes `count` full rows: columns [x0, x0 + width) from rgb565 (row r at r * stride_px), `fill`
    /// elsewhere; in chunks of the caller's buffer.
    bool emit(uint16_t count, uint16_t x0, uint16_t width, uint16_t fill, const uint16_t* rgb565, uint32_t stride_px) {
        const uint16_t frame_width = checker_.width();
        const uint16_t chunk = static_cast<uint16_t>(hider::min<size_t>(row_.size() / 3, frame_width));
        if (chunk == 0) return refuse(hider::port::BandStatus::too_large);
        const uint32_t x1 = uint32_t{x0} + width;
        for (uint16_t r = 0; r < count; ++r) {
            const uint16_t* src = rgb565 + size_t{r} * stride_px;
            for (uint32_t at = 0; at < frame_width; at += chunk) {  // 32-bit: no wrap near 65,535 columns
                const uint32_t n = hider::min<uint32_t>(chunk, frame_width - at);
                uint8_t* dst = row_.data();
                for (uint32_t x = at; x < at + n; ++x, dst += 3) {
                    const hider::Rgb c = hider::Rgb565Format::unpack(x >= x0 && x < x1 ? src[x - x0] : fill);
                    dst[0] = c.r;
                    dst[1] = c.g;
                    dst[2] = c.b;
                }
                if (!out_.write(row_.data(), size_t{n} * 3)) return refuse(hider::port::BandStatus::not_ready);
            }
        }
        return true;
    }

    bool end() {
        const hider::port::BandStatus s = checker_.end_frame();
        return s == hider::port::BandStatus::ok ? true : refuse(s);
    }

    Output& out_;
    hider::Span<uint8_t> row_;
    hider::port::BandSequenceChecker checker_;
    hider::port::BandStatus status_ = hider::port::BandStatus::ok;
};

/// The exit status of a render streamed through `ppm` (the painter and BSP examples): 0 when the render's
/// status is ok, the renderer's sink calls all succeeded, the output closed and no band failed its
/// coverage check; else prints "<who>: failed: ..." on `io` and returns 1.
template <class Io, class Output>
int stream_verdict(Io& io, const char* who, hider::Status status, bool sink_ok, const PpmSink<Output>& ppm, bool closed,
                   uint32_t coverage_mismatches) {
    if (status == hider::Status::ok && sink_ok && ppm.status() == hider::port::BandStatus::ok && closed && coverage_mismatches == 0)
        return 0;
    io.print(who);
    io.print(": failed: ");
    io.print(hider::status_name(status));
    io.print(", sink status ");
    io.print_u32(static_cast<uint32_t>(ppm.status()));
    io.print(", coverage mismatches ");
    io.print_u32(coverage_mismatches);
    io.print("\n");
    return 1;
}

}  // namespace spin

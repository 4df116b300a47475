// Band sink: how a band-by-band renderer hands finished rows of RGB565 pixels (uint16_t each, native
// endianness in memory, 5:6:5 bits red:green:blue from the top bit) to a display or file, and a checker for
// the call order. Freestanding: C headers only, no heap, no virtuals.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace hider::port {

// A frame is sent as begin_frame, then write_rows (or write_columns) for bands from top to bottom that cover
// rows [0, height) exactly once, then end_frame. Each call returns false when the sink refuses it; after a
// refused begin_frame the frame never opened, after a refused band the caller still calls end_frame so the
// sink can release its device. `rgb565` is borrowed for the call only; row r of the band starts at
// rgb565 + r * stride_px. Plain function pointers plus a `user` context: a C-compatible layout.
// write_columns is optional (null, the default: the sink takes full-width rows only): a band of which only
// the columns [x0, x0 + width) are in memory, every other pixel of its rows being `fill` (a renderer's
// column window, <hider/view.hpp>'s centred_window(): the background outside it); it may stand for
// write_rows in any band.
struct BandSink {
    void* user;
    bool (*begin_frame)(void* user, uint16_t width, uint16_t height);
    bool (*write_rows)(void* user, uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px);
    bool (*end_frame)(void* user);
    bool (*write_columns)(void* user, uint16_t y0, uint16_t rows, uint16_t x0, uint16_t width, uint16_t fill,
                          const uint16_t* rgb565, uint32_t stride_px) = nullptr;
};

/// Whether all three callbacks of `sink` are set.
inline bool is_complete(const BandSink& sink) {
    return sink.begin_frame != nullptr && sink.write_rows != nullptr && sink.end_frame != nullptr;
}

// Why BandSequenceChecker refused a call (ok = accepted).
enum class [[nodiscard]] BandStatus : uint8_t {
    ok = 0,
    not_in_frame,  // a band or end_frame without an open frame
    frame_open,    // begin_frame while a frame is open
    bad_size,      // zero width or height, a band of zero rows, an empty window or one past the side
    out_of_order,  // y0 is not the row after the previous band (gap, overlap or repeat)
    past_end,      // the band runs past the frame's last row
    bad_pixels,    // null pixel pointer or stride_px below the band's width (the frame's or the window's)
    incomplete,    // end_frame before every row arrived (the frame is closed anyway)
    too_large,     // the frame is wider or taller than the checker's limits
    not_ready,     // the sink's device is not ready (set by sinks, never by the checker)
};

// Tracks one frame's band sequence so a sink can refuse calls that break the BandSink contract. A refused
// begin_frame, write_rows or write_columns leaves the state unchanged; end_frame always closes the frame.
// 12 bytes, no heap.
class BandSequenceChecker {
public:
    /// Makes a checker that refuses frames wider than `max_width` or taller than `max_height`.
    constexpr explicit BandSequenceChecker(uint16_t max_width = UINT16_MAX, uint16_t max_height = UINT16_MAX)
        : max_width_(max_width), max_height_(max_height) {}

    /// Opens a frame of width x height pixels; refused while a frame is open, for a zero size or past the limits.
    BandStatus begin_frame(uint16_t width, uint16_t height) {
        if (in_frame_) return BandStatus::frame_open;
        if (width == 0 || height == 0) return BandStatus::bad_size;
        if (width > max_width_ || height > max_height_) return BandStatus::too_large;
        width_ = width;
        height_ = height;
        next_row_ = 0;
        in_frame_ = true;
        return BandStatus::ok;
    }

    /// Accepts rows [y0, y0 + rows) only if they continue the frame exactly where the previous band ended.
    BandStatus write_rows(uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px) {
        if (!in_frame_) return BandStatus::not_in_frame;
        return accept(y0, rows, rgb565, stride_px, width_);
    }

    /// write_rows() for a band of which columns [x0, x0 + width) are in memory (BandSink::write_columns):
    /// also refuses an empty window or one past the frame's right side (bad_size), and stride_px < width.
    BandStatus write_columns(uint16_t y0, uint16_t rows, uint16_t x0, uint16_t width, const uint16_t* rgb565,
                             uint32_t stride_px) {
        if (!in_frame_) return BandStatus::not_in_frame;
        if (width == 0 || uint32_t{x0} + width > width_) return BandStatus::bad_size;
        return accept(y0, rows, rgb565, stride_px, width);
    }

    /// Closes the frame and reports whether every row arrived.
    BandStatus end_frame() {
        if (!in_frame_) return BandStatus::not_in_frame;
        in_frame_ = false;
        return next_row_ == height_ ? BandStatus::ok : BandStatus::incomplete;
    }

    /// Whether a frame is open.
    bool in_frame() const { return in_frame_; }
    /// Width of the current (or last) frame in pixels.
    uint16_t width() const { return width_; }
    /// Height of the current (or last) frame in rows.
    uint16_t height() const { return height_; }
    /// First row the next band must start at.
    uint16_t next_row() const { return next_row_; }

private:
    /// The band checks of write_rows() and write_columns(), rows `width` pixels wide in memory.
    BandStatus accept(uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px, uint16_t width) {
        if (rows == 0) return BandStatus::bad_size;
        if (y0 != next_row_) return BandStatus::out_of_order;
        if (uint32_t{y0} + rows > height_) return BandStatus::past_end;
        if (rgb565 == nullptr || stride_px < width) return BandStatus::bad_pixels;
        next_row_ = static_cast<uint16_t>(y0 + rows);
        return BandStatus::ok;
    }

    uint16_t max_width_;
    uint16_t max_height_;
    uint16_t width_ = 0;
    uint16_t height_ = 0;
    uint16_t next_row_ = 0;
    bool in_frame_ = false;
};

/// Sends a whole frame held in memory through `sink` in bands of `band_rows` rows (the last may be shorter);
/// stops at the first refused call, always calls end_frame once begin_frame succeeded, and returns true only
/// if every call succeeded. Borrows `rgb565` (height rows of stride_px pixels) for the call.
[[nodiscard]] inline bool send_frame_in_bands(const BandSink& sink, const uint16_t* rgb565, uint16_t width,
                                              uint16_t height, uint32_t stride_px, uint16_t band_rows) {
    if (!is_complete(sink) || rgb565 == nullptr || band_rows == 0) return false;
    if (!sink.begin_frame(sink.user, width, height)) return false;
    bool ok = true;
    for (uint16_t y = 0; y < height && ok;) {
        const uint16_t left = static_cast<uint16_t>(height - y);
        const uint16_t rows = left < band_rows ? left : band_rows;
        ok = sink.write_rows(sink.user, y, rows, rgb565 + size_t{y} * stride_px, stride_px);
        y = static_cast<uint16_t>(y + rows);
    }
    const bool ended = sink.end_frame(sink.user);
    return ok && ended;
}

}  // namespace hider::port

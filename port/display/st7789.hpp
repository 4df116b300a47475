// SPI driver for ST7789 and ILI9341 TFT controllers in 16-bit RGB565 mode (COLMOD 0x55), written against a
// five-function user HAL. Pixels go out big-endian (high byte first) through a 64-byte internal buffer.
// Command codes and delays: Sitronix ST7789V datasheet s.9 (commands); Ilitek ILI9341 datasheet v1.11 s.8.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <display/sink.hpp>

namespace hider::port {

// The board's pins and SPI bus. spi_write must be done with `data` before it returns (the driver reuses its
// buffer). set_dc(true) selects data, false command; set_cs(true) selects the panel (drives CS low).
// set_reset and set_cs may be null when RESET or CS is not wired (CS tied low); the rest are required.
struct SpiTftHal {
    void* user;
    void (*spi_write)(void* user, const uint8_t* data, size_t len);
    void (*set_dc)(void* user, bool data);
    void (*set_cs)(void* user, bool selected);
    void (*set_reset)(void* user, bool high);
    void (*delay_ms)(void* user, uint32_t ms);
};

enum class Controller : uint8_t { st7789, ili9341 };

// MADCTL (0x36) bits, the same on both controllers: row/column order, row-column exchange, BGR panels.
constexpr uint8_t kMadctlMy = 0x80;   // mirror rows
constexpr uint8_t kMadctlMx = 0x40;   // mirror columns
constexpr uint8_t kMadctlMv = 0x20;   // swap rows and columns (90-degree rotation with MX or MY)
constexpr uint8_t kMadctlBgr = 0x08;  // panel wired B-G-R (most ILI9341 modules)

// Panel geometry after MADCTL is applied: width x height visible pixels, whose top-left sits at
// (x_offset, y_offset) in controller RAM (for example a 240x240 ST7789 module rotated 180 degrees: y_offset 80).
struct TftConfig {
    Controller controller;
    uint16_t width;
    uint16_t height;
    uint16_t x_offset;
    uint16_t y_offset;
    uint8_t madctl;  // kMadctl* bits
    bool invert;     // send INVON (most IPS ST7789 panels need it) instead of INVOFF
};

namespace tft {
constexpr uint8_t kSwReset = 0x01;
constexpr uint8_t kSleepOut = 0x11;
constexpr uint8_t kNormalOn = 0x13;
constexpr uint8_t kInvertOff = 0x20;
constexpr uint8_t kInvertOn = 0x21;
constexpr uint8_t kDisplayOn = 0x29;
constexpr uint8_t kColumnSet = 0x2A;    // CASET: x0, x1 as 16-bit big-endian
constexpr uint8_t kRowSet = 0x2B;       // RASET: y0, y1 as 16-bit big-endian
constexpr uint8_t kMemoryWrite = 0x2C;  // RAMWR: pixel data follows with DC high
constexpr uint8_t kMadctl = 0x36;
constexpr uint8_t kColmod = 0x3A;
constexpr uint8_t kColmod16Bit = 0x55;  // 16 bits per pixel on both interfaces

// Delays with margin over the datasheet minimums (both controllers agree): RESX low >= 10 us; after reset
// 5 ms before any command and 120 ms before SLPOUT; after SLPOUT 5 ms before the next command and 120 ms
// before SLPIN. Ticks of delay_ms may return early by up to 1 ms, hence no 1 ms values.
constexpr uint32_t kResetLowMs = 10;
constexpr uint32_t kResetRecoverMs = 120;
constexpr uint32_t kSwResetMs = 150;
constexpr uint32_t kSleepOutMs = 120;

constexpr size_t kChunkBytes = 64;  // pixel buffer inside SpiTft; one spi_write per full chunk
}  // namespace tft

// One panel. Usage: init(), then set_window + write_pixels/fill_pixels + end_write, or hand sink() to a band
// renderer. Failures return false and send nothing. While a window is open CS stays selected and DC high;
// any command or end_write closes it. 120 bytes on 32-bit targets (64 of them the chunk buffer); no heap.
class SpiTft {
public:
    /// Copies the HAL and config; sends nothing until init().
    SpiTft(const SpiTftHal& hal, const TftConfig& config)
        : hal_(hal), config_(config), band_(config.width, config.height) {}

    /// Resets the panel (pulse on RESET if wired, then SWRESET) and runs the controller's init sequence; false
    /// if a required HAL function is missing, the config is empty or its offsets put the panel's last column
    /// or row past RAM address 0xFFFF. Blocks for about 400 ms in delay_ms.
    [[nodiscard]] bool init() {
        initialized_ = false;
        if (band_.in_frame()) (void)band_.end_frame();
        close_window();
        if (!hal_complete() || config_.width == 0 || config_.height == 0) return false;
        if (uint32_t{config_.x_offset} + config_.width > 0x10000u || uint32_t{config_.y_offset} + config_.height > 0x10000u)
            return false;
        if (config_.controller != Controller::st7789 && config_.controller != Controller::ili9341) return false;
        if (hal_.set_reset != nullptr) {
            hal_.set_reset(hal_.user, false);
            hal_.delay_ms(hal_.user, tft::kResetLowMs);
            hal_.set_reset(hal_.user, true);
            hal_.delay_ms(hal_.user, tft::kResetRecoverMs);
        }
        const uint8_t colmod = tft::kColmod16Bit;
        const uint8_t madctl = config_.madctl;
        const uint8_t invert = config_.invert ? tft::kInvertOn : tft::kInvertOff;
        command(tft::kSwReset, nullptr, 0);
        hal_.delay_ms(hal_.user, tft::kSwResetMs);
        if (config_.controller == Controller::st7789) {
            command(tft::kSleepOut, nullptr, 0);
            hal_.delay_ms(hal_.user, tft::kSleepOutMs);
            command(tft::kColmod, &colmod, 1);
            command(tft::kMadctl, &madctl, 1);
            command(invert, nullptr, 0);
            command(tft::kNormalOn, nullptr, 0);
            command(tft::kDisplayOn, nullptr, 0);
        } else {
            // Minimal documented set: power (PWCTR 0xC0/0xC1), VCOM (VMCTR 0xC5/0xC7) and gamma keep their
            // OTP/reset values, which suit most modules; send panel-specific ones with send_command().
            command(tft::kColmod, &colmod, 1);
            command(tft::kMadctl, &madctl, 1);
            command(invert, nullptr, 0);
            command(tft::kSleepOut, nullptr, 0);
            hal_.delay_ms(hal_.user, tft::kSleepOutMs);
            command(tft::kDisplayOn, nullptr, 0);
        }
        initialized_ = true;
        return true;
    }

    /// Whether init() succeeded.
    bool initialized() const { return initialized_; }
    /// The panel configuration.
    const TftConfig& config() const { return config_; }

    /// Sends one command (DC low) and its `len` parameter bytes (DC high) in one CS transaction; closes an open
    /// window first. Refused without a complete HAL, with null params and len > 0, or during a sink frame.
    [[nodiscard]] bool send_command(uint8_t cmd, const uint8_t* params, size_t len) {
        if (!hal_complete() || (params == nullptr && len > 0) || band_.in_frame()) return false;
        command(cmd, params, len);
        return true;
    }

    /// Opens the inclusive pixel rectangle [x0, x1] x [y0, y1] for writing (CASET, RASET, RAMWR) and leaves
    /// CS selected; refused before init, during a sink frame, or unless x0 <= x1 < width and y0 <= y1 < height.
    [[nodiscard]] bool set_window(uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1) {
        if (!initialized_ || band_.in_frame()) return false;
        if (x0 > x1 || y0 > y1 || x1 >= config_.width || y1 >= config_.height) return false;
        if (uint32_t{x1} + config_.x_offset > UINT16_MAX || uint32_t{y1} + config_.y_offset > UINT16_MAX) return false;
        open_window(x0, y0, x1, y1);
        return true;
    }

    /// Streams `count` RGB565 pixels into the open window, high byte first; refused (nothing sent) without an
    /// open window, during a sink frame, or if `count` exceeds the pixels the window has left.
    [[nodiscard]] bool write_pixels(const uint16_t* rgb565, size_t count) {
        if (!writing_ || band_.in_frame() || count > window_left_ || (rgb565 == nullptr && count > 0)) return false;
        stream(rgb565, count);
        return true;
    }

    /// Streams `count` copies of one RGB565 colour into the open window, with the same refusals as write_pixels.
    [[nodiscard]] bool fill_pixels(uint16_t rgb565, size_t count) {
        if (!writing_ || band_.in_frame() || count > window_left_) return false;
        stream_fill(rgb565, count);
        return true;
    }

    /// Closes an open window and deselects the panel; does nothing when no window is open, and nothing during
    /// a sink frame (whose window the sink's end_frame closes: closing it early would send the rest unselected).
    void end_write() {
        if (!band_.in_frame()) close_window();
    }

    /// Whether a window is open for pixel data.
    bool writing() const { return writing_; }
    /// Pixels the open window still accepts (0 when closed).
    uint32_t window_pixels_left() const { return window_left_; }

    /// A BandSink that draws frames at the panel's top-left; it borrows this object, which must stay at one
    /// address and outlive the sink. begin_frame refuses frames larger than the panel or before init.
    /// Bands of a column window (BandSink::write_columns) go out as whole rows, the columns outside it as
    /// the band's fill colour.
    BandSink sink() { return BandSink{this, &sink_begin_frame, &sink_write_rows, &sink_end_frame, &sink_write_columns}; }
    /// Why the sink last refused a call (BandStatus::ok after an accepted one).
    BandStatus last_band_status() const { return last_band_status_; }

private:
    bool hal_complete() const {
        return hal_.spi_write != nullptr && hal_.set_dc != nullptr && hal_.delay_ms != nullptr;
    }
    void select() {
        if (hal_.set_cs != nullptr) hal_.set_cs(hal_.user, true);
    }
    void deselect() {
        if (hal_.set_cs != nullptr) hal_.set_cs(hal_.user, false);
    }
    void put_pixel(size_t i, uint16_t rgb565) {
        chunk_[2 * i] = static_cast<uint8_t>(rgb565 >> 8);
        chunk_[2 * i + 1] = static_cast<uint8_t>(rgb565 & 0xFF);
    }

    void close_window() {
        if (!writing_) return;
        writing_ = false;
        window_left_ = 0;
        deselect();
    }

    // Command byte with DC low, then parameters with DC high; CS stays selected when `keep_selected`.
    void command(uint8_t cmd, const uint8_t* params, size_t len, bool keep_selected = false) {
        close_window();
        select();
        hal_.set_dc(hal_.user, false);
        hal_.spi_write(hal_.user, &cmd, 1);
        hal_.set_dc(hal_.user, true);
        if (len > 0) hal_.spi_write(hal_.user, params, len);
        if (!keep_selected) deselect();
    }

    // Caller checked the rectangle; coordinates go out with the RAM offsets added.
    void open_window(uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1) {
        const uint16_t ram_x0 = static_cast<uint16_t>(x0 + config_.x_offset);
        const uint16_t ram_x1 = static_cast<uint16_t>(x1 + config_.x_offset);
        const uint16_t ram_y0 = static_cast<uint16_t>(y0 + config_.y_offset);
        const uint16_t ram_y1 = static_cast<uint16_t>(y1 + config_.y_offset);
        const uint8_t columns[4] = {static_cast<uint8_t>(ram_x0 >> 8), static_cast<uint8_t>(ram_x0 & 0xFF),
                                    static_cast<uint8_t>(ram_x1 >> 8), static_cast<uint8_t>(ram_x1 & 0xFF)};
        const uint8_t rows[4] = {static_cast<uint8_t>(ram_y0 >> 8), static_cast<uint8_t>(ram_y0 & 0xFF),
                                 static_cast<uint8_t>(ram_y1 >> 8), static_cast<uint8_t>(ram_y1 & 0xFF)};
        command(tft::kColumnSet, columns, 4);
        command(tft::kRowSet, rows, 4);
        command(tft::kMemoryWrite, nullptr, 0, true);
        writing_ = true;
        window_left_ = (uint32_t{x1} - x0 + 1) * (uint32_t{y1} - y0 + 1);  // < 2^32: both factors <= 65535
    }

    // Caller checked the window has room for `count` pixels.
    void stream(const uint16_t* rgb565, size_t count) {
        const size_t chunk_px = tft::kChunkBytes / 2;
        window_left_ -= static_cast<uint32_t>(count);
        while (count > 0) {
            const size_t n = count < chunk_px ? count : chunk_px;
            for (size_t i = 0; i < n; ++i) put_pixel(i, rgb565[i]);
            hal_.spi_write(hal_.user, chunk_, n * 2);
            rgb565 += n;
            count -= n;
        }
    }

    // Caller checked the window has room for `count` pixels.
    void stream_fill(uint16_t rgb565, size_t count) {
        const size_t chunk_px = tft::kChunkBytes / 2;
        for (size_t i = 0; i < chunk_px && i < count; ++i) put_pixel(i, rgb565);
        window_left_ -= static_cast<uint32_t>(count);
        while (count > 0) {
            const size_t n = count < chunk_px ? count : chunk_px;
            hal_.spi_write(hal_.user, chunk_, n * 2);
            count -= n;
        }
    }

    static bool sink_begin_frame(void* user, uint16_t width, uint16_t height) {
        SpiTft& tft = *static_cast<SpiTft*>(user);
        if (!tft.initialized_) {
            tft.last_band_status_ = BandStatus::not_ready;
            return false;
        }
        tft.last_band_status_ = tft.band_.begin_frame(width, height);
        if (tft.last_band_status_ != BandStatus::ok) return false;
        tft.open_window(0, 0, static_cast<uint16_t>(width - 1), static_cast<uint16_t>(height - 1));
        return true;
    }

    // Rows of a checked band: columns [x0, x0 + width) from rgb565, the rest of each row `fill`.
    void send_rows(uint16_t rows, uint16_t x0, uint16_t width, uint16_t fill, const uint16_t* rgb565, uint32_t stride_px) {
        const size_t right = size_t{band_.width()} - x0 - width;
        if (x0 == 0 && right == 0 && stride_px == width) return stream(rgb565, size_t{rows} * width);  // fullest chunks
        for (uint16_t r = 0; r < rows; ++r) {
            if (x0 != 0) stream_fill(fill, x0);
            stream(rgb565 + size_t{r} * stride_px, width);
            if (right != 0) stream_fill(fill, right);
        }
    }

    static bool sink_write_rows(void* user, uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px) {
        SpiTft& tft = *static_cast<SpiTft*>(user);
        tft.last_band_status_ = tft.band_.write_rows(y0, rows, rgb565, stride_px);
        if (tft.last_band_status_ != BandStatus::ok) return false;
        tft.send_rows(rows, 0, tft.band_.width(), 0, rgb565, stride_px);
        return true;
    }

    static bool sink_write_columns(void* user, uint16_t y0, uint16_t rows, uint16_t x0, uint16_t width, uint16_t fill,
                                   const uint16_t* rgb565, uint32_t stride_px) {
        SpiTft& tft = *static_cast<SpiTft*>(user);
        tft.last_band_status_ = tft.band_.write_columns(y0, rows, x0, width, rgb565, stride_px);
        if (tft.last_band_status_ != BandStatus::ok) return false;
        tft.send_rows(rows, x0, width, fill, rgb565, stride_px);
        return true;
    }

    static bool sink_end_frame(void* user) {
        SpiTft& tft = *static_cast<SpiTft*>(user);
        const bool was_open = tft.band_.in_frame();
        tft.last_band_status_ = tft.band_.end_frame();
        if (was_open) tft.close_window();
        return tft.last_band_status_ == BandStatus::ok;
    }

    SpiTftHal hal_;
    TftConfig config_;
    BandSequenceChecker band_;
    BandStatus last_band_status_ = BandStatus::ok;
    bool initialized_ = false;
    bool writing_ = false;
    uint32_t window_left_ = 0;
    uint8_t chunk_[tft::kChunkBytes] = {};
};

}  // namespace hider::port

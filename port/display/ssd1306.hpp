// Driver for 1-bit OLED controllers SSD1306 and SH1106 (128x64, 128x32 and smaller modules) over a HAL
// of one write function (plus a delay and an optional reset pin), and a BandSink that turns any band renderer's RGB565 rows into lit pixels by an 8x8 ordered
// dither of their luma. A byte of controller RAM holds 8 rows of one column (a page); the sink collects
// each page in a width-byte buffer, so bands of any height work. Commands and init sequences: Solomon
// Systech SSD1306 datasheet rev 1.1 s.9-10 and its software initialisation flow; Sino Wealth SH1106
// datasheet v2.3 s.9 (page addressing only, 132-column RAM, DC-DC control 0xAD).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <display/sink.hpp>
#include <hider/frame.hpp>

namespace hider::port {

/// The bus. `write` sends `len` bytes as one transfer after the control byte `control`: 0x00 for a
/// command stream, 0x40 for display data (on I2C the control byte goes out after the address, exactly
/// these values; an SPI board drives D/C low for 0x00 and high for 0x40 and sends only the bytes). It
/// returns false when the transfer failed (no I2C acknowledge); the driver then stops and reports it. A
/// HAL whose I2C buffer is smaller than `len` may split the bytes into several transactions, each
/// starting again with the same control byte. set_reset may be null when RES is not wired (most I2C
/// modules); write and delay_ms are required.
struct OledHal {
    void* user;
    bool (*write)(void* user, uint8_t control, const uint8_t* bytes, size_t len);
    void (*set_reset)(void* user, bool high);
    void (*delay_ms)(void* user, uint32_t ms);
};

enum class OledController : uint8_t { ssd1306, sh1106 };

/// Panel geometry: width <= 128 (SSD1306) or <= 132 (SH1106) columns starting at RAM column `column_offset`
/// upright (SH1106 modules of 128 columns: 2; SSD1306 64x32 and 64x48 modules: 32; 96x16: 0), height 16, 32,
/// 48 or 64 rows. `flip` rotates the image by 180 degrees (segment and COM scan order); the glass stays on its
/// segments, so turned it starts at RAM column (128 or 132) - column_offset - width: the same column for a
/// centred glass, 32 for a 96x16 SSD1306 (u8g2's flipmode_x_offset). `external_vcc` leaves the charge pump off.
/// `com_pins` is the COM pins configuration (command 0xDA) the module is wired for; 0 takes the usual
/// one, 0x12 for 64 rows and 0x02 otherwise (128x32, 96x16), but 64x32 and 64x48 modules need 0x12.
struct OledConfig {
    OledController controller;
    uint8_t width;
    uint8_t height;
    uint8_t column_offset;
    uint8_t contrast;
    bool flip;
    bool external_vcc;
    uint8_t com_pins;
};

namespace oled {
constexpr uint8_t kCommands = 0x00;  // control byte: command stream
constexpr uint8_t kData = 0x40;      // control byte: display data stream
constexpr uint8_t kDisplayOff = 0xAE;
constexpr uint8_t kDisplayOn = 0xAF;
constexpr uint8_t kContrast = 0x81;
constexpr uint8_t kMemoryMode = 0x20;   // SSD1306: 0 horizontal, 1 vertical, 2 page addressing
constexpr uint8_t kColumnRange = 0x21;  // SSD1306, horizontal mode: first and last column
constexpr uint8_t kPageRange = 0x22;    // SSD1306, horizontal mode: first and last page
constexpr uint8_t kPageStart = 0xB0;    // page addressing: | page
constexpr uint8_t kColumnLow = 0x00;    // page addressing: | low nibble of the column
constexpr uint8_t kColumnHigh = 0x10;   // page addressing: | high nibble of the column
constexpr uint8_t kStartLine = 0x40;
constexpr uint8_t kSegmentRemap = 0xA1;  // column 0 on the right edge's segment (A0: left)
constexpr uint8_t kComScanDown = 0xC8;   // COM scan from the last row (C0: from row 0)
constexpr uint8_t kMultiplex = 0xA8;
constexpr uint8_t kDisplayOffset = 0xD3;
constexpr uint8_t kClock = 0xD5;
constexpr uint8_t kPrecharge = 0xD9;
constexpr uint8_t kComPins = 0xDA;
constexpr uint8_t kVcomDeselect = 0xDB;
constexpr uint8_t kChargePump = 0x8D;   // SSD1306: 0x14 on, 0x10 off
constexpr uint8_t kDcDc = 0xAD;         // SH1106: 0x8B on, 0x8A off
constexpr uint8_t kFollowRam = 0xA4;
constexpr uint8_t kNormal = 0xA6;
constexpr uint8_t kScrollOff = 0x2E;
constexpr uint32_t kResetLowMs = 2;     // RES# low >= 3 us
constexpr uint32_t kPowerOnMs = 100;    // charge pump / DC-DC settling before display on, as common drivers wait

/// Threshold of the 8x8 ordered dither at (x, y): the Bayer index times 4 plus 2, so luma 0 lights
/// nothing, 255 everything, and luma v lights about v/256 of a flat area.
constexpr uint8_t dither_threshold(uint32_t x, uint32_t y) {
    // Bayer index from the bit-reversed interleave of (x ^ y) and y.
    const uint32_t a = x ^ y, b = y;
    const uint32_t index = ((a & 1u) << 5) | ((b & 1u) << 4) | ((a & 2u) << 2) | ((b & 2u) << 1) |
                           ((a & 4u) >> 1) | ((b & 4u) >> 2);
    return static_cast<uint8_t>(index * 4u + 2u);
}

/// The COM pins configuration `c` sends: its own, or the usual one for its height.
constexpr uint8_t com_pins(const OledConfig& c) { return c.com_pins != 0 ? c.com_pins : (c.height == 64 ? 0x12 : 0x02); }

/// Whether an RGB565 pixel at (x, y) is lit: Grey8Format's luma of its RGB888 expansion above the threshold.
constexpr bool lit(uint16_t rgb565, uint32_t x, uint32_t y) {
    return Grey8Format::pack(Rgb565Format::unpack(rgb565)) > dither_threshold(x, y);
}

/// lit() in table form, as the sink uses it: 256 x luma is the sum of three per-field terms, and a pixel
/// is lit when that sum reaches (threshold + 1) x 256 (384 bytes of constants).
struct DitherTables {
    uint16_t red[32], green[64], blue[32];  ///< 77, 150 and 29 times each field's 8-bit expansion
    uint16_t lit_from[8][8];                ///< [y & 7][x & 7]: the smallest sum that is lit there
};
constexpr DitherTables make_dither_tables() {
    DitherTables t{};
    for (uint32_t v = 0; v < 32; ++v) {
        t.red[v] = static_cast<uint16_t>(77u * ((v << 3) | (v >> 2)));
        t.blue[v] = static_cast<uint16_t>(29u * ((v << 3) | (v >> 2)));
    }
    for (uint32_t v = 0; v < 64; ++v) t.green[v] = static_cast<uint16_t>(150u * ((v << 2) | (v >> 4)));
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x) t.lit_from[y][x] = static_cast<uint16_t>((dither_threshold(x, y) + 1u) << 8);
    return t;
}
inline constexpr DitherTables kDither = make_dither_tables();

/// Ors `bit` into pages[x] for each lit pixel x of one row of `width` RGB565 pixels at row y. Out of
/// line: inlined into Oled::write_rows(), the M0+ loop kept `pages` on the stack (4 more instructions a
/// lit pixel) once the page transfer around it changed.
__attribute__((noinline)) inline void dither_row(const uint16_t* row, uint32_t width, uint32_t y, uint8_t bit, uint8_t* pages) {
    const uint16_t* lit_from = kDither.lit_from[y & 7u];
    for (uint32_t x = 0; x < width; ++x) {
        const uint32_t p = row[x];
        if (p == 0) continue;  // black: never lit (a dark background costs a test a pixel)
        const uint32_t sum = uint32_t{kDither.red[p >> 11]} + kDither.green[(p >> 5) & 63u] + kDither.blue[p & 31u];
        if (sum >= lit_from[x & 7u]) pages[x] = static_cast<uint8_t>(pages[x] | bit);
    }
}
}  // namespace oled

/// One panel. Usage: init(), then begin_frame(), write_rows() per band and end_frame() (or hand sink() to
/// a band renderer, or write_page() yourself). Every function returns false and stops at the first
/// transfer the HAL refuses; init() must run again after that. 172 bytes on 32-bit targets, 132 of them
/// the page buffer.
class Oled {
public:
    /// Copies the HAL and config; sends nothing until init().
    Oled(const OledHal& hal, const OledConfig& config) : hal_(hal), config_(config), band_(config.width, config.height) {}

    /// Pulses RES if wired, sends the controller's init sequence, clears its whole RAM (no random pixels
    /// before the first frame) and turns the display on; false for an incomplete HAL, a geometry the
    /// controller does not have, or a refused transfer.
    [[nodiscard]] bool init() {
        initialized_ = false;
        if (band_.in_frame()) (void)band_.end_frame();
        if (hal_.write == nullptr || hal_.delay_ms == nullptr || !geometry_ok()) return false;
        if (hal_.set_reset != nullptr) {
            hal_.set_reset(hal_.user, false);
            hal_.delay_ms(hal_.user, oled::kResetLowMs);
            hal_.set_reset(hal_.user, true);
            hal_.delay_ms(hal_.user, oled::kResetLowMs);
        }
        const bool sh = config_.controller == OledController::sh1106;
        const uint8_t seg = config_.flip ? 0xA0 : oled::kSegmentRemap, com = config_.flip ? 0xC0 : oled::kComScanDown;
        const uint8_t pins = oled::com_pins(config_);
        const uint8_t pump0 = sh ? oled::kDcDc : oled::kChargePump;
        const uint8_t pump1 = sh ? (config_.external_vcc ? 0x8A : 0x8B) : (config_.external_vcc ? 0x10 : 0x14);
        const uint8_t sequence[] = {oled::kDisplayOff, oled::kClock, 0x80, oled::kMultiplex,
                                    static_cast<uint8_t>(config_.height - 1), oled::kDisplayOffset, 0x00,
                                    oled::kStartLine, pump0, pump1, seg, com, oled::kComPins, pins, oled::kContrast,
                                    config_.contrast, oled::kPrecharge, static_cast<uint8_t>(config_.external_vcc ? 0x22 : 0xF1),
                                    // VCOMH 0x40: above the table's 0.83 Vcc, as Adafruit's and u8g2's drivers send
                                    oled::kVcomDeselect, 0x40, oled::kFollowRam, oled::kNormal};
        if (!hal_.write(hal_.user, oled::kCommands, sequence, sizeof sequence)) return false;
        if (!sh) {  // SSD1306: horizontal addressing (SH1106 has only page addressing), no scrolling
            const uint8_t mode[] = {oled::kMemoryMode, 0x00, oled::kScrollOff};
            if (!hal_.write(hal_.user, oled::kCommands, mode, sizeof mode)) return false;
        }
        if (!clear_ram()) return false;
        hal_.delay_ms(hal_.user, oled::kPowerOnMs);
        const uint8_t on = oled::kDisplayOn;
        if (!hal_.write(hal_.user, oled::kCommands, &on, 1)) return false;
        initialized_ = true;
        return true;
    }

    /// Sends `len` command bytes (with their parameters) as one command transfer, for settings this driver
    /// does not make (contrast, display off, inverse, scrolling); refused before init, during a frame or for
    /// null bytes. Commands that change addressing break the next frame: the driver sets its own per page.
    [[nodiscard]] bool send_commands(const uint8_t* bytes, size_t len) {
        if (!initialized_ || band_.in_frame() || (bytes == nullptr && len > 0)) return false;
        if (!hal_.write(hal_.user, oled::kCommands, bytes, len)) {
            initialized_ = false;
            return false;
        }
        return true;
    }

    /// Whether init() succeeded and no transfer failed since.
    bool initialized() const { return initialized_; }
    /// The panel configuration.
    const OledConfig& config() const { return config_; }

    /// Writes `bits` (width bytes: bit k of byte x lights row 8 page + k of column x) to page `page` at the
    /// panel's left edge; refused before init, during a frame (as send_commands()) or past the panel's pages.
    [[nodiscard]] bool write_page(uint8_t page, const uint8_t* bits) {
        return !band_.in_frame() && send_page(page, bits);
    }

    /// Opens a frame of exactly the panel's size, whose rows write_rows() dithers as oled::lit() says and
    /// sends page by page; refused (last_band_status() says why) while a frame is open (frame_open, whatever
    /// the size; the open frame keeps its rows), before init or for another size.
    [[nodiscard]] bool begin_frame(uint16_t width, uint16_t height) {
        if (band_.in_frame()) return refuse(BandStatus::frame_open);
        if (!initialized_) return refuse(BandStatus::not_ready);
        if (width != config_.width || height != config_.height) return refuse(BandStatus::bad_size);
        last_band_status_ = band_.begin_frame(width, height);
        if (last_band_status_ != BandStatus::ok) return false;
        frame_failed_ = false;
        for (uint8_t& b : page_) b = 0;
        return true;
    }

    /// Takes rows [y0, y0 + rows) of RGB565 pixels (row r at rgb565 + r * stride_px), which must follow the
    /// previous call's rows; sends each page as its last row arrives. Refused out of order, and for a
    /// failed transfer (then init() again; end_frame() fails too).
    [[nodiscard]] bool write_rows(uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px) {
        last_band_status_ = band_.write_rows(y0, rows, rgb565, stride_px);
        if (last_band_status_ != BandStatus::ok) return false;
        const uint32_t width = config_.width;
        for (uint32_t r = 0; r < rows; ++r) {
            const uint32_t y = uint32_t{y0} + r;
            oled::dither_row(rgb565 + size_t{r} * stride_px, width, y, static_cast<uint8_t>(1u << (y & 7u)), page_);
            if ((y & 7u) == 7u) {  // the page is complete (heights are multiples of 8)
                if (!send_page(static_cast<uint8_t>(y >> 3), page_)) {
                    frame_failed_ = true;
                    return refuse(BandStatus::not_ready);
                }
                for (uint32_t x = 0; x < width; ++x) page_[x] = 0;
            }
        }
        return true;
    }

    /// Closes the frame; false without an open frame (not_in_frame), when a page of it never reached the panel
    /// (not_ready) or a row is missing (incomplete).
    [[nodiscard]] bool end_frame() {
        const bool failed = frame_failed_ && band_.in_frame();
        last_band_status_ = band_.end_frame();
        if (failed) last_band_status_ = BandStatus::not_ready;
        return last_band_status_ == BandStatus::ok;
    }

    /// The three calls above as a BandSink for band renderers; it borrows this object, which must stay at one
    /// address and outlive the sink.
    BandSink sink() { return BandSink{this, &sink_begin_frame, &sink_write_rows, &sink_end_frame}; }
    /// Why the frame calls last refused (BandStatus::ok after an accepted one; not_ready for a failed transfer
    /// or before init).
    BandStatus last_band_status() const { return last_band_status_; }

private:
    bool geometry_ok() const {
        const bool sh = config_.controller == OledController::sh1106;
        if (!sh && config_.controller != OledController::ssd1306) return false;
        if (config_.height < 16 || config_.height > 64 || config_.height % 8 != 0) return false;
        return config_.width > 0 && uint32_t{config_.column_offset} + config_.width <= (sh ? 132u : 128u);
    }

    // write_page() without its frame check, for write_rows().
    bool send_page(uint8_t page, const uint8_t* bits) {
        if (!initialized_ || bits == nullptr || page >= config_.height / 8) return false;
        const uint8_t c = first_column();
        bool sent;
        if (config_.controller == OledController::sh1106) {
            const uint8_t address[] = {static_cast<uint8_t>(oled::kPageStart | page),
                                       static_cast<uint8_t>(oled::kColumnLow | (c & 0x0F)),
                                       static_cast<uint8_t>(oled::kColumnHigh | (c >> 4))};
            sent = hal_.write(hal_.user, oled::kCommands, address, sizeof address);
        } else {
            const uint8_t address[] = {oled::kColumnRange, c, static_cast<uint8_t>(c + config_.width - 1), oled::kPageRange,
                                       page, page};
            sent = hal_.write(hal_.user, oled::kCommands, address, sizeof address);
        }
        sent = sent && hal_.write(hal_.user, oled::kData, bits, config_.width);
        if (!sent) initialized_ = false;
        return sent;
    }

    // The RAM column written to the glass's left edge. A1 (upright) drives segment ram - 1 - c from RAM column
    // c, A0 (turned) segment c, so turned the glass's segments take the columns mirrored across the whole RAM.
    uint8_t first_column() const {
        const uint32_t ram = config_.controller == OledController::sh1106 ? 132u : 128u;
        return static_cast<uint8_t>(config_.flip ? ram - config_.column_offset - config_.width : config_.column_offset);
    }

    // Zeroes every page across the controller's whole RAM width (the glass's offset columns included).
    bool clear_ram() {
        for (uint8_t& b : page_) b = 0;
        const bool sh = config_.controller == OledController::sh1106;
        for (uint8_t page = 0; page < 8; ++page) {
            bool sent;
            if (sh) {
                const uint8_t address[] = {static_cast<uint8_t>(oled::kPageStart | page), oled::kColumnLow, oled::kColumnHigh};
                sent = hal_.write(hal_.user, oled::kCommands, address, sizeof address) &&
                       hal_.write(hal_.user, oled::kData, page_, 132);
            } else {
                const uint8_t address[] = {oled::kColumnRange, 0, 127, oled::kPageRange, page, page};
                sent = hal_.write(hal_.user, oled::kCommands, address, sizeof address) &&
                       hal_.write(hal_.user, oled::kData, page_, 128);
            }
            if (!sent) return false;
        }
        return true;
    }

    bool refuse(BandStatus why) {
        last_band_status_ = why;
        return false;
    }
    static bool sink_begin_frame(void* user, uint16_t width, uint16_t height) {
        return static_cast<Oled*>(user)->begin_frame(width, height);
    }
    static bool sink_write_rows(void* user, uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px) {
        return static_cast<Oled*>(user)->write_rows(y0, rows, rgb565, stride_px);
    }
    static bool sink_end_frame(void* user) { return static_cast<Oled*>(user)->end_frame(); }

    OledHal hal_;
    OledConfig config_;
    BandSequenceChecker band_;
    BandStatus last_band_status_ = BandStatus::ok;
    bool initialized_ = false;
    bool frame_failed_ = false;
    uint8_t page_[132] = {};
};

}  // namespace hider::port

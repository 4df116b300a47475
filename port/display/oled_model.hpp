// A simulated SSD1306 / SH1106 OLED module for PC simulation and tests: it takes the bytes an OledHal's
// write() sends (control byte, then commands or display data), keeps the controller's RAM (8 pages of
// 128 or 132 columns) and the state the image depends on as the datasheets describe them (addressing,
// segment and COM scan order, display offset, start line, multiplex, entire-display-on, inverse), and
// shows the pixel the module lights at (x, y). The module is wired for one COM pins configuration and
// multiplex; a controller set otherwise shows interleaved or missing rows. Whatever it does not accept
// counts in errors(): an unknown command or control byte, a parameter missing at the end of a transfer,
// an SSD1306 multiplex under 16, a data byte past the RAM, a display switched on with a setting that does
// not fit the module, a geometry no controller has. Freestanding, no heap, about 1.1 KB.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <display/ssd1306.hpp>

namespace hider::port {

class OledModel {
public:
    /// A module of `width` x `height` pixels whose first column is RAM column `column_offset` upright (A1),
    /// wired for COM pins configuration `com_pins` (0: 0x12 for 64 rows, 0x02 otherwise). A geometry the
    /// controller does not have (columns past its RAM, a height not a multiple of 8 in 16..64 on the SSD1306,
    /// whose multiplex starts at 16, or 8..64 on the SH1106) counts an error and shows nothing.
    OledModel(OledController controller, uint8_t width, uint8_t height, uint8_t column_offset, uint8_t com_pins = 0)
        : controller_(controller), width_(width), height_(height), offset_(column_offset),
          wired_com_(com_pins != 0 ? com_pins : (height == 64 ? 0x12 : 0x02)) {
        geometry_ok_ = width > 0 && uint32_t{column_offset} + width <= ram_columns() &&
                       height >= (sh1106() ? 8 : 16) && height <= 64 && height % 8 == 0;
        if (!geometry_ok_) ++errors_;
    }

    /// An OledHal whose write() feeds this model (no reset line, delays ignored); `fail_after` refuses every
    /// transfer after that many (a lost I2C acknowledge), -1 never.
    OledHal hal(int32_t fail_after = -1) {
        fail_after_ = fail_after;
        return OledHal{this, &bus_write, nullptr, [](void*, uint32_t) {}};
    }

    /// The bytes of one transfer: control 0x00 commands, 0x40 data (anything else counts as an error).
    bool receive(uint8_t control, const uint8_t* bytes, size_t len) {
        if (fail_after_ == 0) return false;
        if (fail_after_ > 0) --fail_after_;
        ++transfers_;
        for (size_t i = 0; i < len; ++i) {
            if (control == oled::kCommands) command_byte(bytes[i]);
            else if (control == oled::kData) data_byte(bytes[i]);
            else ++errors_;
        }
        if (pending_ != 0) {  // a command stream ends with its command's parameters
            ++errors_;
            pending_ = 0;
        }
        return true;
    }

    /// Whether the module lights pixel (x, y) of its glass (x < width, y < height).
    bool pixel(uint32_t x, uint32_t y) const {
        if (!geometry_ok_ || !on_ || x >= width_ || y >= height_) return false;
        if (entire_on_) return true;
        // glass row y is wired to COM `com`; with the configuration it is wired for, COM n shows row n
        uint32_t com = y;
        if (com_pins_ != wired_com_) {  // another configuration sends the rows to other COM pins
            const uint32_t half = height_ / 2;
            com = (com_pins_ & 0x10) != 0 ? (y % 2 == 0 ? y / 2 : half + y / 2) : (y < half ? 2 * y : 2 * (y - half) + 1);
        }
        if (!com_down_) com = height_ - 1 - com;                     // C0: COM0 at the bottom of the glass
        if (com >= multiplex_) return false;                         // rows past the multiplex are not driven
        const uint32_t ram_row = (com + display_offset_ + start_line_) % 64;
        // The glass sits on fixed segments: those RAM columns offset_ + x drive upright (A1: column c drives
        // segment ram - 1 - c); turned (A0: segment c) they are driven by columns mirrored across the whole RAM.
        const uint32_t column = seg_remap_ ? offset_ + x : ram_columns() - 1 - offset_ - x;
        const bool bit = ((ram_[ram_row / 8][column] >> (ram_row % 8)) & 1u) != 0;
        return bit != inverse_;
    }

    bool display_on() const { return on_; }
    uint8_t multiplex() const { return multiplex_; }
    uint8_t contrast() const { return contrast_; }
    uint8_t com_pins() const { return com_pins_; }
    bool pump_on() const { return pump_on_; }
    uint32_t errors() const { return errors_; }
    uint32_t transfers() const { return transfers_; }

private:
    static bool bus_write(void* user, uint8_t control, const uint8_t* bytes, size_t len) {
        return static_cast<OledModel*>(user)->receive(control, bytes, len);
    }
    bool sh1106() const { return controller_ == OledController::sh1106; }
    uint32_t ram_columns() const { return sh1106() ? 132u : 128u; }
    bool page_mode() const { return sh1106() || mode_ == 2; }

    // Parameter bytes a command takes, -1 for a code the controller does not have. SSD1306: Solomon Systech
    // datasheet rev 1.1 s.9 table 9-1 (scrolling: 26/27 6 bytes, 29/2A 5, 2E/2F none, A3 2; NOP E3) and the
    // charge pump 8D of its application note; SH1106: Sino Wealth datasheet v2.3 s.9 (pump voltage 30-33,
    // DC-DC AD, NOP E3; no 20-22, scrolling or 8D). SH1106 read-modify-write E0/EE is not modelled: an error.
    int parameters(uint8_t c) const {
        if (c <= 0x1F || (c >= 0x40 && c <= 0x7F) || (c >= 0xB0 && c <= 0xB7)) return 0;
        switch (c) {
        case 0xA0: case 0xA1: case 0xA4: case 0xA5: case 0xA6: case 0xA7: case 0xAE: case 0xAF: case 0xC0: case 0xC8:
        case 0xE3:
            return 0;
        case 0x81: case 0xA8: case 0xD3: case 0xD5: case 0xD9: case 0xDA: case 0xDB: return 1;
        case 0x30: case 0x31: case 0x32: case 0x33: return sh1106() ? 0 : -1;
        case 0xAD: return sh1106() ? 1 : -1;
        default: break;
        }
        if (sh1106()) return -1;
        switch (c) {
        case 0x2E: case 0x2F: return 0;
        case 0x20: case 0x8D: return 1;
        case 0x21: case 0x22: case 0xA3: return 2;
        case 0x29: case 0x2A: return 5;
        case 0x26: case 0x27: return 6;
        default: return -1;
        }
    }

    void command_byte(uint8_t b) {
        if (pending_ != 0) {  // a parameter of pending_
            if (got_ < sizeof params_) params_[got_] = b;  // only the first two take effect here
            ++got_;
            if (got_ == want_) apply(pending_);
            return;
        }
        const int n = parameters(b);
        if (n < 0) {
            ++errors_;
            return;
        }
        if (n == 0) {
            apply(b);
            return;
        }
        pending_ = b;
        want_ = static_cast<uint8_t>(n);
        got_ = 0;
    }

    void apply(uint8_t c) {
        pending_ = 0;
        const uint8_t p0 = params_[0], p1 = params_[1];
        if (c <= 0x1F || (c >= 0xB0 && c <= 0xB7)) {  // page addressing only (SSD1306 s.10.1.1-3)
            if (!page_mode()) return;
            if (c <= 0x0F) column_ = page_column_ = static_cast<uint8_t>((page_column_ & 0xF0) | c);
            else if (c <= 0x1F) column_ = page_column_ = static_cast<uint8_t>((page_column_ & 0x0F) | ((c & 0x0F) << 4));
            else page_ = static_cast<uint8_t>(c - 0xB0);
        } else if (c >= 0x40 && c <= 0x7F) {
            start_line_ = static_cast<uint8_t>(c - 0x40);
        } else if (c == 0xA0 || c == 0xA1) {
            seg_remap_ = c == 0xA1;
        } else if (c == 0xC0 || c == 0xC8) {
            com_down_ = c == 0xC8;
        } else if (c == 0xA4 || c == 0xA5) {
            entire_on_ = c == 0xA5;
        } else if (c == 0xA6 || c == 0xA7) {
            inverse_ = c == 0xA7;
        } else if (c == 0xAE || c == 0xAF) {
            on_ = c == 0xAF;
            if (on_ && (multiplex_ != height_ || com_pins_ != wired_com_)) ++errors_;  // set for another module
        } else if (c == 0x81) {
            contrast_ = p0;
        } else if (c == 0xA8) {
            if (!sh1106() && (p0 & 0x3F) < 15) ++errors_;  // SSD1306: 16MUX at least, 0-14 invalid
            else multiplex_ = static_cast<uint8_t>((p0 & 0x3F) + 1);
        } else if (c == 0xD3) {
            display_offset_ = static_cast<uint8_t>(p0 & 0x3F);
        } else if (c == 0xDA) {
            com_pins_ = p0;
        } else if (c == 0x8D) {
            pump_on_ = (p0 & 0x04) != 0;
        } else if (c == 0xAD) {
            pump_on_ = (p0 & 0x01) != 0;
        } else if (c == 0x20) {
            mode_ = static_cast<uint8_t>(p0 & 3);
        } else if (c == 0x21) {
            column_first_ = column_ = static_cast<uint8_t>(p0 & 0x7F);
            column_last_ = static_cast<uint8_t>(p1 & 0x7F);
        } else if (c == 0x22) {
            page_first_ = page_ = static_cast<uint8_t>(p0 & 7);
            page_last_ = static_cast<uint8_t>(p1 & 7);
        }
        // D5, D9, DB, 30-33, 26-2F, A3, E3: clock, precharge, VCOMH, pump voltage, scrolling and NOP, which
        // the image here does not show (an active scroll shows the unscrolled RAM)
    }

    void data_byte(uint8_t b) {
        if (column_ >= ram_columns()) {  // SH1106: past column 131
            ++errors_;
            return;
        }
        ram_[page_][column_] = b;
        if (page_mode()) {
            column_ = static_cast<uint8_t>(column_ + 1);  // the page stays; SSD1306 wraps to the start column
            if (!sh1106() && column_ == 128) column_ = page_column_;
        } else if (column_ == column_last_) {  // horizontal addressing: wrap within the ranges
            column_ = column_first_;
            page_ = page_ == page_last_ ? page_first_ : static_cast<uint8_t>((page_ + 1) & 7);
        } else {
            column_ = static_cast<uint8_t>(column_ + 1);
        }
    }

    OledController controller_;
    uint8_t width_, height_, offset_, wired_com_;
    bool geometry_ok_ = false;
    uint8_t ram_[8][132] = {};
    uint8_t params_[2] = {};
    uint8_t pending_ = 0, want_ = 0, got_ = 0;
    uint8_t mode_ = 2;  // reset state: page addressing
    uint8_t column_ = 0, page_column_ = 0, page_ = 0, column_first_ = 0, column_last_ = 127, page_first_ = 0, page_last_ = 7;
    uint8_t start_line_ = 0, display_offset_ = 0, contrast_ = 0x7F, multiplex_ = 64, com_pins_ = 0x12;
    bool seg_remap_ = false, com_down_ = false, on_ = false, pump_on_ = false, entire_on_ = false, inverse_ = false;
    int32_t fail_after_ = -1;
    uint32_t errors_ = 0, transfers_ = 0;
};

}  // namespace hider::port

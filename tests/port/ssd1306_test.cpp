// Tests for port/display/ssd1306.hpp (the OLED driver and its dithering sink) against the simulated
// module of port/display/oled_model.hpp, and of that model against byte sequences written out by hand
// from the datasheets. Expected images come from this file's own dither (the published 8x8 Bayer matrix
// and BT.601 luma), not from the driver's.
#include <display/oled_model.hpp>
#include <display/ssd1306.hpp>

#include <doctest/doctest.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

using hider::port::BandSink;
using hider::port::BandStatus;
using hider::port::Oled;
using hider::port::OledConfig;
using hider::port::OledController;
using hider::port::OledModel;

namespace {

// The 8x8 Bayer index matrix as printed (row y, column x).
constexpr int kBayer[8][8] = {{0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
                              {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
                              {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
                              {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21}};

bool expected_lit(uint16_t p, int x, int y) {
    const int r5 = p >> 11, g6 = (p >> 5) & 63, b5 = p & 31;
    const int r = (r5 << 3) | (r5 >> 2), g = (g6 << 2) | (g6 >> 4), b = (b5 << 3) | (b5 >> 2);
    const int luma = (77 * r + 150 * g + 29 * b) >> 8;
    return luma > kBayer[y & 7][x & 7] * 4 + 2;
}

OledConfig config(OledController c, uint8_t width, uint8_t height, uint8_t offset, bool flip = false, uint8_t com = 0) {
    return OledConfig{c, width, height, offset, 0xCF, flip, false, com};
}

// A HAL that writes down everything: R0/R1 reset level, W<ms> delay, C[..] a command transfer's bytes in
// hex, D<n> a data transfer of n bytes.
struct Recorder {
    std::string trace;
    hider::port::OledHal hal() {
        return {this,
                [](void* u, uint8_t control, const uint8_t* bytes, size_t len) {
                    auto& r = *static_cast<Recorder*>(u);
                    if (control == 0x40) {
                        r.trace += "D" + std::to_string(len) + " ";
                        return true;
                    }
                    r.trace += "C[";
                    for (size_t i = 0; i < len; ++i) {
                        char hex[4];
                        std::snprintf(hex, sizeof hex, i + 1 < len ? "%02X " : "%02X", bytes[i]);
                        r.trace += hex;
                    }
                    r.trace += "] ";
                    return true;
                },
                [](void* u, bool high) { static_cast<Recorder*>(u)->trace += high ? "R1 " : "R0 "; },
                [](void* u, uint32_t ms) { static_cast<Recorder*>(u)->trace += "W" + std::to_string(ms) + " "; }};
    }
};

std::string repeat_pages(const char* ssd_or_sh) {
    std::string out;
    for (int p = 0; p < 8; ++p) {
        char buf[64];
        if (ssd_or_sh[0] == 's' && ssd_or_sh[1] == 's')
            std::snprintf(buf, sizeof buf, "C[21 00 7F 22 %02X %02X] D128 ", p, p);
        else
            std::snprintf(buf, sizeof buf, "C[%02X 00 10] D132 ", 0xB0 + p);
        out += buf;
    }
    return out;
}

// Sends `frame` (width x height RGB565) through the sink in bands of `rows`.
bool send(BandSink sink, const std::vector<uint16_t>& frame, int width, int height, int rows) {
    if (!sink.begin_frame(sink.user, static_cast<uint16_t>(width), static_cast<uint16_t>(height))) return false;
    bool ok = true;
    for (int y = 0; y < height && ok; y += rows) {
        const int n = rows < height - y ? rows : height - y;
        ok = sink.write_rows(sink.user, static_cast<uint16_t>(y), static_cast<uint16_t>(n), frame.data() + y * width,
                             static_cast<uint32_t>(width));
    }
    return sink.end_frame(sink.user) && ok;
}

}  // namespace

TEST_CASE("the OLED dither threshold is the 8x8 Bayer matrix, 4 levels a step, centred") {
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            CHECK(int{hider::port::oled::dither_threshold(static_cast<uint32_t>(x), static_cast<uint32_t>(y))} ==
                  kBayer[y & 7][x & 7] * 4 + 2);
    // Flat greys light their share of an 8x8 tile: luma 0 none, 255 all, 128 half.
    for (const int grey : {0, 1, 64, 128, 200, 255}) {
        const uint16_t p = hider::Rgb565Format::pack({static_cast<uint8_t>(grey), static_cast<uint8_t>(grey), static_cast<uint8_t>(grey)});
        const int luma = hider::Grey8Format::pack(hider::Rgb565Format::unpack(p));
        int n = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) n += hider::port::oled::lit(p, static_cast<uint32_t>(x), static_cast<uint32_t>(y));
        CHECK(n == (luma + 1) / 4);  // thresholds 2, 6, .., 254: luma v exceeds (v + 1) / 4 of them
    }
}

TEST_CASE("the OLED sink's dither tables light exactly the pixels oled::lit() lights") {
    long n = 0, lit = 0;
    for (uint32_t p = 0; p < 65536; ++p)
        for (uint32_t y = 0; y < 8; ++y) {
            uint8_t pages[8] = {};
            uint16_t row[8];
            for (uint16_t& v : row) v = static_cast<uint16_t>(p);
            hider::port::oled::dither_row(row, 8, y, 0x10, pages);
            for (uint32_t x = 0; x < 8; ++x) {
                const bool want = hider::port::oled::lit(static_cast<uint16_t>(p), x, y);
                n += ((pages[x] == 0x10) != want);
                lit += want;
            }
        }
    CHECK(n == 0);
    CHECK(lit > 65536L * 64 / 4);
}

TEST_CASE("the OLED model follows hand-written datasheet sequences") {
    SUBCASE("SSD1306: horizontal addressing wraps within the column and page ranges") {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        const uint8_t cmds[] = {0xA8, 0x3F, 0xA1, 0xC8, 0x20, 0x00, 0x21, 10, 11, 0x22, 2, 3, 0xAF};
        REQUIRE(m.receive(0x00, cmds, sizeof cmds));
        const uint8_t data[] = {0x01, 0x80, 0xFF, 0x00, 0x02};  // (10,p2) (11,p2) (10,p3) (11,p3) (10,p2) again
        REQUIRE(m.receive(0x40, data, sizeof data));
        CHECK(m.errors() == 0);
        CHECK(m.display_on());
        CHECK(m.pixel(10, 17));   // 0x02 replaced 0x01 at column 10 page 2: bit 1 = row 17
        CHECK(!m.pixel(10, 16));
        CHECK(m.pixel(11, 23));   // 0x80 at column 11 page 2: row 23
        for (int y = 24; y < 32; ++y) CHECK(m.pixel(10, static_cast<uint32_t>(y)));
        CHECK(!m.pixel(11, 24));
    }
    SUBCASE("SSD1306: A0/C0 show the RAM rotated by 180 degrees") {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        const uint8_t cmds[] = {0xA0, 0xC0, 0x20, 0x00, 0x21, 0, 127, 0x22, 0, 7, 0xAF};
        REQUIRE(m.receive(0x00, cmds, sizeof cmds));
        const uint8_t one = 0x01;  // RAM column 0, row 0
        REQUIRE(m.receive(0x40, &one, 1));
        CHECK(m.pixel(127, 63));
        CHECK(!m.pixel(0, 0));
    }
    SUBCASE("SH1106: page addressing from the column nibbles, 132 RAM columns") {
        OledModel m(OledController::sh1106, 128, 64, 2);
        const uint8_t cmds[] = {0xA1, 0xC8, 0xB5, 0x02, 0x10, 0xAF};
        REQUIRE(m.receive(0x00, cmds, sizeof cmds));
        const uint8_t data[] = {0x10, 0x20};
        REQUIRE(m.receive(0x40, data, sizeof data));
        CHECK(m.pixel(0, 44));  // RAM column 2 = glass column 0; page 5 bit 4 = row 44
        CHECK(m.pixel(1, 45));
        CHECK(m.errors() == 0);
        const uint8_t horizontal[] = {0x20, 0x00};  // SSD1306 only
        REQUIRE(m.receive(0x00, horizontal, sizeof horizontal));
        CHECK(m.errors() >= 1);
    }
    SUBCASE("unknown control bytes, unknown commands and data past the RAM count as errors") {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        const uint8_t x = 0xFF;
        REQUIRE(m.receive(0x80, &x, 1));
        REQUIRE(m.receive(0x00, &x, 1));
        CHECK(m.errors() == 2);
    }
}

TEST_CASE("the OLED model takes every datasheet command with its parameters") {
    // Each sequence ends by writing one byte at page 0, column 5 (page addressing, the reset mode): a
    // parameter run as a command (0x00-0x0F set the column's low nibble) would move it.
    const auto lands_at_column_5 = [](OledModel& m, const uint8_t* cmds, size_t len) {
        const uint8_t on[] = {0xA1, 0xC8, 0xAF}, at5[] = {0xB0, 0x05, 0x10};
        REQUIRE(m.receive(0x00, on, sizeof on));
        REQUIRE(m.receive(0x00, at5, sizeof at5));
        REQUIRE(m.receive(0x00, cmds, len));
        const uint8_t one = 0x01;
        REQUIRE(m.receive(0x40, &one, 1));
        long lit = 0;
        for (uint32_t x = 0; x < 128; ++x) lit += m.pixel(x, 0);
        return lit == 1 && m.pixel(5, 0);
    };
    SUBCASE("SSD1306 (datasheet rev 1.1 table 9-1): scrolling, vertical scroll area and NOP") {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        const uint8_t cmds[] = {0x2E,                               // deactivate scroll
                                0x26, 0x00, 0x01, 0x07, 0x02, 0x00, 0xFF,  // right horizontal scroll: 6 bytes
                                0x27, 0x00, 0x00, 0x00, 0x07, 0x00, 0xFF,  // left
                                0x29, 0x00, 0x00, 0x03, 0x07, 0x01,  // vertical and right horizontal: 5 bytes
                                0x2A, 0x00, 0x02, 0x00, 0x05, 0x0F,  // vertical and left
                                0xA3, 0x00, 0x08,                    // vertical scroll area: 2 bytes
                                0x2F, 0x2E, 0xE3};                   // activate, deactivate, NOP
        CHECK(lands_at_column_5(m, cmds, sizeof cmds));
        CHECK(m.errors() == 0);
    }
    SUBCASE("SH1106 (datasheet v2.3 s.9): pump voltage 30-33 and NOP") {
        OledModel m(OledController::sh1106, 128, 64, 0);
        const uint8_t cmds[] = {0x30, 0x31, 0x32, 0x33, 0xE3};
        CHECK(lands_at_column_5(m, cmds, sizeof cmds));
        CHECK(m.errors() == 0);
    }
    SUBCASE("each controller refuses the other's commands") {
        OledModel ssd(OledController::ssd1306, 128, 64, 0), sh(OledController::sh1106, 128, 64, 0);
        for (const uint8_t c : {0x30, 0x31, 0x32, 0x33, 0xAD}) REQUIRE(ssd.receive(0x00, &c, 1));
        CHECK(ssd.errors() == 5);
        for (const uint8_t c : {0x26, 0x27, 0x29, 0x2A, 0x2E, 0x2F, 0xA3}) REQUIRE(sh.receive(0x00, &c, 1));
        CHECK(sh.errors() == 7);
    }
    SUBCASE("SSD1306 multiplex: 16 to 64 rows (A8 0-14 are invalid), SH1106: 1 to 64") {
        OledModel ssd(OledController::ssd1306, 128, 64, 0), sh(OledController::sh1106, 128, 64, 0);
        for (const uint8_t n : {0x00, 0x07, 0x0E}) {
            const uint8_t cmd[] = {0xA8, n};
            REQUIRE(ssd.receive(0x00, cmd, sizeof cmd));
            REQUIRE(sh.receive(0x00, cmd, sizeof cmd));
            CHECK(int{sh.multiplex()} == n + 1);
        }
        CHECK(ssd.errors() == 3);
        CHECK(int{ssd.multiplex()} == 64);  // an invalid entry leaves the ratio as it was
        CHECK(sh.errors() == 0);
        const uint8_t sixteen[] = {0xA8, 0x0F};
        REQUIRE(ssd.receive(0x00, sixteen, sizeof sixteen));
        CHECK(int{ssd.multiplex()} == 16);
        CHECK(ssd.errors() == 3);
    }
    SUBCASE("an 8-row SSD1306 module does not exist (16MUX minimum); the driver refuses it too") {
        OledModel m(OledController::ssd1306, 128, 8, 0);
        CHECK(m.errors() == 1);
        Oled oled(m.hal(), config(OledController::ssd1306, 128, 8, 0));
        CHECK(!oled.init());
        OledModel sh(OledController::sh1106, 128, 8, 0);  // SH1106 multiplex goes down to 1
        CHECK(sh.errors() == 0);
    }
}

TEST_CASE("the OLED driver sends the datasheets' bytes, in order") {
    {  // SSD1306 128x64: reset pulse, init, horizontal addressing, RAM cleared, display on
        Recorder r;
        Oled oled(r.hal(), config(OledController::ssd1306, 128, 64, 0));
        REQUIRE(oled.init());
        CHECK(r.trace == "R0 W2 R1 W2 C[AE D5 80 A8 3F D3 00 40 8D 14 A1 C8 DA 12 81 CF D9 F1 DB 40 A4 A6] C[20 00 2E] " +
                             repeat_pages("ssd") + "W100 C[AF] ");
        r.trace.clear();
        const uint8_t page[128] = {};
        REQUIRE(oled.write_page(5, page));
        CHECK(r.trace == "C[21 00 7F 22 05 05] D128 ");
    }
    {  // SSD1306 128x32, external VCC, turned: 32 rows, sequential COM pins, pump off, A0/C0
        Recorder r;
        OledConfig c = config(OledController::ssd1306, 128, 32, 0, true);
        c.external_vcc = true;
        Oled oled(r.hal(), c);
        REQUIRE(oled.init());
        CHECK(r.trace == "R0 W2 R1 W2 C[AE D5 80 A8 1F D3 00 40 8D 10 A0 C0 DA 02 81 CF D9 22 DB 40 A4 A6] C[20 00 2E] " +
                             repeat_pages("ssd") + "W100 C[AF] ");
    }
    {  // SH1106 128x64 at column 2: DC-DC on, page addressing, all 132 columns cleared
        Recorder r;
        Oled oled(r.hal(), config(OledController::sh1106, 128, 64, 2));
        REQUIRE(oled.init());
        CHECK(r.trace == "R0 W2 R1 W2 C[AE D5 80 A8 3F D3 00 40 AD 8B A1 C8 DA 12 81 CF D9 F1 DB 40 A4 A6] " +
                             repeat_pages("sh") + "W100 C[AF] ");
        r.trace.clear();
        const uint8_t page[128] = {};
        REQUIRE(oled.write_page(3, page));
        CHECK(r.trace == "C[B3 02 10] D128 ");
        r.trace.clear();
        const uint8_t contrast[] = {0x81, 0x10};
        REQUIRE(oled.send_commands(contrast, sizeof contrast));
        CHECK(r.trace == "C[81 10] ");
    }
    {  // a 64x32 module wired for alternative COM pins says so in its config
        Recorder r;
        Oled oled(r.hal(), config(OledController::ssd1306, 64, 32, 32, false, 0x12));
        REQUIRE(oled.init());
        CHECK(r.trace.find("A8 1F") != std::string::npos);
        CHECK(r.trace.find("DA 12") != std::string::npos);
    }
}

TEST_CASE("the OLED driver's init sequence sets up each controller and geometry") {
    struct Case {
        OledController c;
        uint8_t w, h, offset;
        bool external;
        uint8_t com;
    };
    for (const Case k : {Case{OledController::ssd1306, 128, 64, 0, false, 0}, Case{OledController::ssd1306, 128, 32, 0, false, 0},
                         Case{OledController::ssd1306, 96, 16, 0, true, 0}, Case{OledController::ssd1306, 64, 48, 32, false, 0x12},
                         Case{OledController::ssd1306, 64, 32, 32, false, 0x12}, Case{OledController::sh1106, 128, 64, 2, false, 0},
                         Case{OledController::sh1106, 132, 32, 0, true, 0}}) {
        OledModel m(k.c, k.w, k.h, k.offset, k.com);
        OledConfig cfg = config(k.c, k.w, k.h, k.offset, false, k.com);
        cfg.external_vcc = k.external;
        Oled oled(m.hal(), cfg);
        REQUIRE(oled.init());
        CHECK(oled.initialized());
        CHECK(m.errors() == 0);
        CHECK(m.display_on());
        CHECK(int{m.multiplex()} == k.h);
        CHECK(int{m.com_pins()} == (k.com != 0 ? k.com : (k.h == 64 ? 0x12 : 0x02)));
        CHECK(int{m.contrast()} == 0xCF);
        CHECK(m.pump_on() == !k.external);
    }
    // Geometries the controllers do not have: refused before any byte.
    for (const OledConfig bad : {config(OledController::ssd1306, 128, 36, 0), config(OledController::ssd1306, 128, 8, 0),
                                 config(OledController::ssd1306, 128, 72, 0), config(OledController::ssd1306, 129, 64, 0),
                                 config(OledController::ssd1306, 128, 64, 1), config(OledController::sh1106, 128, 64, 5),
                                 config(OledController::ssd1306, 0, 64, 0), config(static_cast<OledController>(7), 128, 64, 0)}) {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        Oled oled(m.hal(), bad);
        CHECK(!oled.init());
        CHECK(m.transfers() == 0);
    }
    // A module set up for another one's COM pins or multiplex shows its rows shuffled or missing, and says so.
    {
        OledModel m(OledController::ssd1306, 64, 32, 32, 0x12);
        Oled oled(m.hal(), config(OledController::ssd1306, 64, 32, 32));  // sends 0x02
        REQUIRE(oled.init());
        CHECK(m.errors() == 1);
    }
    // A geometry the model cannot have: an error, nothing shown, no read past its RAM.
    {
        OledModel m(OledController::ssd1306, 200, 64, 200);
        CHECK(m.errors() == 1);
        for (uint32_t x = 0; x < 200; ++x) CHECK(!m.pixel(x, 0));
    }
    hider::port::OledHal no_write{nullptr, nullptr, nullptr, [](void*, uint32_t) {}};
    Oled oled(no_write, config(OledController::ssd1306, 128, 64, 0));
    CHECK(!oled.init());
}

TEST_CASE("the OLED sink lights exactly the dithered pixels, for any band height, on every geometry") {
    std::mt19937 rng(0x0135u);
    struct Case {
        OledController c;
        uint8_t w, h, offset;
        bool flip;
        uint8_t com;
    };
    long compared = 0;
    for (const Case k : {Case{OledController::ssd1306, 128, 64, 0, false, 0}, Case{OledController::ssd1306, 128, 64, 0, true, 0},
                         Case{OledController::ssd1306, 128, 32, 0, false, 0}, Case{OledController::ssd1306, 64, 32, 32, false, 0x12},
                         Case{OledController::ssd1306, 64, 48, 32, true, 0x12}, Case{OledController::sh1106, 128, 64, 2, false, 0},
                         Case{OledController::sh1106, 128, 64, 2, true, 0}}) {
        std::vector<uint16_t> frame(size_t{k.w} * k.h);
        for (int trial = 0; trial < 3; ++trial) {
            // random pixels, then smooth gradients (where the dither pattern shows)
            for (size_t i = 0; i < frame.size(); ++i) {
                const int x = static_cast<int>(i % k.w), y = static_cast<int>(i / k.w);
                frame[i] = trial == 0 ? static_cast<uint16_t>(rng())
                                      : hider::Rgb565Format::pack({static_cast<uint8_t>(x * 2), static_cast<uint8_t>(y * 4),
                                                                   static_cast<uint8_t>(trial == 1 ? 0 : 255 - x)});
            }
            for (const int rows : {1, 3, 6, 8, 13, int{k.h}}) {
                OledModel m(k.c, k.w, k.h, k.offset, k.com);
                Oled oled(m.hal(), config(k.c, k.w, k.h, k.offset, k.flip, k.com));
                REQUIRE(oled.init());
                REQUIRE(send(oled.sink(), frame, k.w, k.h, rows));
                CHECK(oled.last_band_status() == BandStatus::ok);
                CHECK(m.errors() == 0);
                long wrong = 0;
                for (int y = 0; y < k.h; ++y)
                    for (int x = 0; x < k.w; ++x) {
                        // a flipped module shows the frame turned by 180 degrees on its glass
                        const int gx = k.flip ? k.w - 1 - x : x, gy = k.flip ? k.h - 1 - y : y;
                        wrong += m.pixel(static_cast<uint32_t>(gx), static_cast<uint32_t>(gy)) !=
                                 expected_lit(frame[static_cast<size_t>(y * k.w + x)], x, y);
                        ++compared;
                    }
                INFO("controller " << int(k.c) << " " << int(k.w) << "x" << int(k.h) << " flip " << k.flip << " rows " << rows);
                CHECK(wrong == 0);
            }
        }
    }
    CHECK(compared == 3 * 6 * (128 * 64 * 4 + 128 * 32 + 64 * 32 + 64 * 48));
}

TEST_CASE("the OLED model shows RAM columns on the glass's segments, not mirrored around the glass") {
    // A glass on segments that are not centred in the RAM: upright (A1) RAM column c drives segment
    // ram columns - 1 - c, turned (A0) segment c. The glass's column x is RAM column offset + x upright.
    SUBCASE("SSD1306 96x16 at column 0: turned, its columns are RAM columns 127 down to 32") {
        OledModel m(OledController::ssd1306, 96, 16, 0);
        const uint8_t cmds[] = {0xA8, 0x0F, 0xDA, 0x02, 0xA0, 0xC8, 0x20, 0x00, 0x21, 32, 127, 0x22, 0, 0, 0xAF};
        REQUIRE(m.receive(0x00, cmds, sizeof cmds));
        uint8_t data[96] = {};
        data[0] = 0x01;   // RAM column 32, row 0
        data[95] = 0x02;  // RAM column 127, row 1
        REQUIRE(m.receive(0x40, data, sizeof data));
        CHECK(m.errors() == 0);
        CHECK(m.pixel(95, 0));
        CHECK(m.pixel(0, 1));
        long lit = 0;
        for (uint32_t y = 0; y < 16; ++y)
            for (uint32_t x = 0; x < 96; ++x) lit += m.pixel(x, y);
        CHECK(lit == 2);
        const uint8_t upright = 0xA1;  // now RAM column 32 is glass column 32, and 127 is off the glass
        REQUIRE(m.receive(0x00, &upright, 1));
        CHECK(m.pixel(32, 0));
        CHECK(!m.pixel(95, 0));
        CHECK(!m.pixel(0, 1));
    }
    SUBCASE("SH1106 128x64 at column 0: turned, glass column 0 is RAM column 131") {
        OledModel m(OledController::sh1106, 128, 64, 0);
        const uint8_t cmds[] = {0xA0, 0xC8, 0xB0, 0x03, 0x18, 0xAF};
        REQUIRE(m.receive(0x00, cmds, sizeof cmds));
        const uint8_t one = 0x01;
        REQUIRE(m.receive(0x40, &one, 1));
        CHECK(m.errors() == 0);
        CHECK(m.pixel(0, 0));
        CHECK(!m.pixel(127, 0));
    }
    SUBCASE("SSD1306 64x32 at odd column 7: turned, glass column 0 is RAM column 120") {
        OledModel m(OledController::ssd1306, 64, 32, 7, 0x12);
        const uint8_t cmds[] = {0xA8, 0x1F, 0xDA, 0x12, 0xA0, 0xC8, 0x20, 0x00, 0x21, 120, 120, 0x22, 0, 0, 0xAF};
        REQUIRE(m.receive(0x00, cmds, sizeof cmds));
        const uint8_t one = 0x01;
        REQUIRE(m.receive(0x40, &one, 1));
        CHECK(m.errors() == 0);
        CHECK(m.pixel(0, 0));
        CHECK(!m.pixel(63, 0));
    }
}

TEST_CASE("turned, the OLED driver writes the RAM columns that drive the glass's segments") {
    // u8g2's ssd1306_96x16: default_x_offset 0, flipmode_x_offset 32.
    const uint8_t page[132] = {};
    struct Case {
        OledController c;
        uint8_t w, h, offset;
        bool flip;
        const char* bytes;
    };
    for (const Case k : {Case{OledController::ssd1306, 96, 16, 0, false, "C[21 00 5F 22 01 01] D96 "},
                         Case{OledController::ssd1306, 96, 16, 0, true, "C[21 20 7F 22 01 01] D96 "},
                         Case{OledController::ssd1306, 64, 32, 7, true, "C[21 39 78 22 01 01] D64 "},
                         Case{OledController::ssd1306, 128, 64, 0, true, "C[21 00 7F 22 01 01] D128 "},
                         Case{OledController::ssd1306, 64, 48, 32, true, "C[21 20 5F 22 01 01] D64 "},
                         Case{OledController::sh1106, 128, 64, 2, true, "C[B1 02 10] D128 "},
                         Case{OledController::sh1106, 128, 64, 0, false, "C[B1 00 10] D128 "},
                         Case{OledController::sh1106, 128, 64, 0, true, "C[B1 04 10] D128 "},
                         Case{OledController::sh1106, 96, 32, 5, true, "C[B1 0F 11] D96 "}}) {
        Recorder r;
        Oled oled(r.hal(), config(k.c, k.w, k.h, k.offset, k.flip));
        REQUIRE(oled.init());
        r.trace.clear();
        REQUIRE(oled.write_page(1, page));
        CHECK(r.trace == k.bytes);
    }
}

TEST_CASE("the OLED sink lights exactly the dithered pixels on glasses not centred in the RAM, both ways up") {
    std::mt19937 rng(0x0A1Au);
    struct Case {
        OledController c;
        uint8_t w, h, offset, com;
    };
    long compared = 0;
    for (const Case k : {Case{OledController::ssd1306, 96, 16, 0, 0}, Case{OledController::ssd1306, 64, 32, 0, 0x12},
                         Case{OledController::ssd1306, 64, 32, 7, 0x12}, Case{OledController::ssd1306, 120, 48, 3, 0x12},
                         Case{OledController::ssd1306, 127, 64, 1, 0}, Case{OledController::sh1106, 128, 64, 0, 0},
                         Case{OledController::sh1106, 128, 64, 3, 0}, Case{OledController::sh1106, 96, 32, 5, 0},
                         Case{OledController::sh1106, 132, 16, 0, 0}})
        for (const bool flip : {false, true})
            for (int trial = 0; trial < 2; ++trial) {
                std::vector<uint16_t> frame(size_t{k.w} * k.h);
                for (size_t i = 0; i < frame.size(); ++i) {
                    const int x = static_cast<int>(i % k.w), y = static_cast<int>(i / k.w);
                    frame[i] = trial == 0 ? static_cast<uint16_t>(rng())
                                          : hider::Rgb565Format::pack({static_cast<uint8_t>(x * 2), static_cast<uint8_t>(y * 4), 0});
                }
                OledModel m(k.c, k.w, k.h, k.offset, k.com);
                Oled oled(m.hal(), config(k.c, k.w, k.h, k.offset, flip, k.com));
                REQUIRE(oled.init());
                REQUIRE(send(oled.sink(), frame, k.w, k.h, 5));
                CHECK(m.errors() == 0);
                long wrong = 0;
                for (int y = 0; y < k.h; ++y)
                    for (int x = 0; x < k.w; ++x) {
                        const int gx = flip ? k.w - 1 - x : x, gy = flip ? k.h - 1 - y : y;
                        wrong += m.pixel(static_cast<uint32_t>(gx), static_cast<uint32_t>(gy)) !=
                                 expected_lit(frame[static_cast<size_t>(y * k.w + x)], x, y);
                        ++compared;
                    }
                INFO("controller " << int(k.c) << " " << int(k.w) << "x" << int(k.h) << " at " << int(k.offset) << " flip " << flip);
                CHECK(wrong == 0);
            }
    CHECK(compared == 2 * 2 * (96 * 16 + 64 * 32 * 2 + 120 * 48 + 127 * 64 + 128 * 64 * 2 + 96 * 32 + 132 * 16));
}

TEST_CASE("the OLED driver stops at a refused transfer and refuses frames it cannot show") {
    const std::vector<uint16_t> white(128 * 64, 0xFFFF);
    // init: 19 transfers on the SSD1306 (sequence, addressing mode, 8 cleared pages of 2, display on), 18 on
    // the SH1106; a frame 2 per page. Every refusal stops the driver: no transfer follows it.
    for (const OledController c : {OledController::ssd1306, OledController::sh1106}) {
        const int init_transfers = c == OledController::ssd1306 ? 19 : 18;
        const uint8_t offset = c == OledController::ssd1306 ? 0 : 2;
        for (int fail_after = 0; fail_after < init_transfers + 16; ++fail_after) {
            OledModel m(c, 128, 64, offset);
            Oled oled(m.hal(fail_after), config(c, 128, 64, offset));
            INFO("controller " << int(c) << " fail after " << fail_after);
            if (fail_after < init_transfers) {
                CHECK(!oled.init());
                CHECK(!oled.initialized());
                CHECK(int(m.transfers()) == fail_after);
                continue;
            }
            REQUIRE(oled.init());
            CHECK(!send(oled.sink(), white, 128, 64, 8));
            CHECK(oled.last_band_status() == BandStatus::not_ready);
            CHECK(!oled.initialized());  // init() again before the next frame
            CHECK(int(m.transfers()) == fail_after);
            const uint8_t page[128] = {};
            CHECK(!oled.write_page(0, page));
            const uint8_t off = 0xAE;
            CHECK(!oled.send_commands(&off, 1));
        }
    }
    OledModel m(OledController::ssd1306, 128, 64, 0);
    Oled oled(m.hal(), config(OledController::ssd1306, 128, 64, 0));
    BandSink sink = oled.sink();
    CHECK(!sink.begin_frame(sink.user, 128, 64));  // before init
    CHECK(oled.last_band_status() == BandStatus::not_ready);
    REQUIRE(oled.init());
    CHECK(!sink.begin_frame(sink.user, 128, 32));  // not the panel's size
    CHECK(oled.last_band_status() == BandStatus::bad_size);
    REQUIRE(sink.begin_frame(sink.user, 128, 64));
    const uint8_t off = 0xAE;
    CHECK(!oled.send_commands(&off, 1));  // not during a frame
    REQUIRE(sink.write_rows(sink.user, 0, 4, white.data(), 128));
    CHECK(!sink.begin_frame(sink.user, 128, 64));  // refused while open: the open frame keeps its rows
    CHECK(oled.last_band_status() == BandStatus::frame_open);
    REQUIRE(sink.write_rows(sink.user, 4, 60, white.data() + 4 * 128, 128));
    REQUIRE(sink.end_frame(sink.user));
    long lit = 0;
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 128; ++x) lit += m.pixel(x, y);
    CHECK(lit == 4 * 128);
    REQUIRE(sink.begin_frame(sink.user, 128, 64));
    CHECK(!sink.write_rows(sink.user, 8, 8, white.data(), 128));  // out of order
    CHECK(oled.last_band_status() == BandStatus::out_of_order);
    CHECK(!sink.end_frame(sink.user));  // incomplete
    CHECK(oled.last_band_status() == BandStatus::incomplete);
    const uint8_t page[128] = {};
    CHECK(!oled.write_page(8, page));  // past the 8 pages
    CHECK(oled.write_page(7, page));
}

TEST_CASE("the OLED driver's frame calls keep the BandSink contract around open and failed frames") {
    const std::vector<uint16_t> white(128 * 64, 0xFFFF);
    const uint8_t page[128] = {};
    SUBCASE("write_page() is refused during a frame, as send_commands() is, and sends nothing") {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        Oled oled(m.hal(), config(OledController::ssd1306, 128, 64, 0));
        REQUIRE(oled.init());
        REQUIRE(oled.begin_frame(128, 64));
        REQUIRE(oled.write_rows(0, 4, white.data(), 128));
        const uint32_t sent = m.transfers();
        const uint8_t off = 0xAE;
        CHECK(!oled.send_commands(&off, 1));
        CHECK(!oled.write_page(0, page));
        CHECK(m.transfers() == sent);
        CHECK(oled.last_band_status() == BandStatus::ok);  // neither is a frame call
        CHECK(oled.initialized());
        REQUIRE(oled.write_rows(4, 60, white.data() + 4 * 128, 128));
        REQUIRE(oled.end_frame());
        for (uint32_t x = 0; x < 128; ++x) CHECK(m.pixel(x, 0));  // the frame's first page, not write_page()'s
        CHECK(oled.write_page(0, page));  // after the frame
        CHECK(!m.pixel(0, 0));
    }
    SUBCASE("begin_frame() during a frame says frame_open, whatever the size") {
        OledModel m(OledController::ssd1306, 128, 64, 0);
        Oled oled(m.hal(), config(OledController::ssd1306, 128, 64, 0));
        REQUIRE(oled.init());
        REQUIRE(oled.begin_frame(128, 64));
        CHECK(!oled.begin_frame(128, 32));
        CHECK(oled.last_band_status() == BandStatus::frame_open);
        CHECK(!oled.begin_frame(0, 0));
        CHECK(oled.last_band_status() == BandStatus::frame_open);
        REQUIRE(oled.write_rows(0, 64, white.data(), 128));  // the open frame goes on
        CHECK(oled.end_frame());
    }
    SUBCASE("after a failed frame, end_frame() without a frame says not_in_frame") {
        for (const bool reinit : {false, true}) {
            OledModel m(OledController::ssd1306, 128, 64, 0);
            Oled oled(m.hal(19 + 2), config(OledController::ssd1306, 128, 64, 0));  // init, then one page
            REQUIRE(oled.init());
            REQUIRE(oled.begin_frame(128, 64));
            CHECK(!oled.write_rows(0, 16, white.data(), 128));
            CHECK(oled.last_band_status() == BandStatus::not_ready);
            if (reinit) {
                CHECK(!oled.init());  // the bus still refuses; init() closes the frame anyway
            } else {
                CHECK(!oled.end_frame());
                CHECK(oled.last_band_status() == BandStatus::not_ready);
            }
            CHECK(!oled.end_frame());
            CHECK(oled.last_band_status() == BandStatus::not_in_frame);
        }
    }
}

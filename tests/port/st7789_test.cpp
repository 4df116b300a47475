// Tests for port/display/st7789.hpp against a fake HAL that records every pin level, byte and delay.
// Trace tokens: R0/R1 reset level, W<ms> delay, [ ] CS select/deselect, C<hex> command byte (DC low),
// <hex> data byte (DC high).
#include <display/st7789.hpp>

#include <doctest/doctest.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using hider::port::BandSink;
using hider::port::BandStatus;
using hider::port::Controller;
using hider::port::SpiTft;
using hider::port::SpiTftHal;
using hider::port::TftConfig;

namespace {

struct FakeBus {
    enum class Kind { command, data, cs, reset, delay };
    struct Event {
        Kind kind;
        uint32_t value;
    };
    std::vector<Event> events;
    std::vector<size_t> write_lengths;
    int dc = -1;  // unknown until the driver sets it
    bool cs = false;
    bool cs_wired = true;
    int bytes_without_cs = 0;
    int bytes_with_unknown_dc = 0;

    SpiTftHal hal(bool with_reset = true, bool with_cs = true) {
        cs_wired = with_cs;
        SpiTftHal h{};
        h.user = this;
        h.spi_write = [](void* user, const uint8_t* data, size_t len) {
            auto& bus = *static_cast<FakeBus*>(user);
            bus.write_lengths.push_back(len);
            for (size_t i = 0; i < len; ++i) {
                if (bus.cs_wired && !bus.cs) ++bus.bytes_without_cs;
                if (bus.dc < 0) ++bus.bytes_with_unknown_dc;
                bus.events.push_back({bus.dc == 0 ? Kind::command : Kind::data, data[i]});
            }
        };
        h.set_dc = [](void* user, bool data) { static_cast<FakeBus*>(user)->dc = data ? 1 : 0; };
        if (with_cs) {
            h.set_cs = [](void* user, bool selected) {
                auto& bus = *static_cast<FakeBus*>(user);
                bus.cs = selected;
                bus.events.push_back({Kind::cs, selected ? 1u : 0u});
            };
        }
        if (with_reset) {
            h.set_reset = [](void* user, bool high) {
                static_cast<FakeBus*>(user)->events.push_back({Kind::reset, high ? 1u : 0u});
            };
        }
        h.delay_ms = [](void* user, uint32_t ms) { static_cast<FakeBus*>(user)->events.push_back({Kind::delay, ms}); };
        return h;
    }

    void clear() {
        events.clear();
        write_lengths.clear();
    }

    std::string trace() const {
        std::string out;
        char token[16];
        for (const Event& e : events) {
            switch (e.kind) {
                case Kind::command: std::snprintf(token, sizeof token, "C%02X", static_cast<unsigned>(e.value)); break;
                case Kind::data: std::snprintf(token, sizeof token, "%02X", static_cast<unsigned>(e.value)); break;
                case Kind::cs: std::snprintf(token, sizeof token, "%s", e.value ? "[" : "]"); break;
                case Kind::reset: std::snprintf(token, sizeof token, "R%u", static_cast<unsigned>(e.value)); break;
                case Kind::delay: std::snprintf(token, sizeof token, "W%u", static_cast<unsigned>(e.value)); break;
            }
            out += out.empty() ? "" : " ";
            out += token;
        }
        return out;
    }

    std::vector<uint8_t> commands() const {
        std::vector<uint8_t> out;
        for (const Event& e : events) {
            if (e.kind == Kind::command) out.push_back(static_cast<uint8_t>(e.value));
        }
        return out;
    }

    // Data bytes that follow the n-th (0-based) occurrence of command `cmd`, up to the next command.
    std::vector<uint8_t> params_of(uint8_t cmd, int n = 0) const {
        std::vector<uint8_t> out;
        int seen = -1;
        bool inside = false;
        for (const Event& e : events) {
            if (e.kind == Kind::command) {
                inside = e.value == cmd && ++seen == n;
                if (seen > n) break;
            } else if (e.kind == Kind::data && inside) {
                out.push_back(static_cast<uint8_t>(e.value));
            }
        }
        return out;
    }

    size_t data_bytes() const {
        size_t n = 0;
        for (const Event& e : events) n += e.kind == Kind::data ? 1 : 0;
        return n;
    }

    // Milliseconds of delay between the first command `from` and the first later command `to` (or any command).
    uint32_t ms_after(uint8_t from, int to = -1) const {
        uint32_t ms = 0;
        bool counting = false;
        for (const Event& e : events) {
            if (e.kind == Kind::command) {
                if (counting && (to < 0 || e.value == static_cast<uint32_t>(to))) return ms;
                if (!counting && e.value == from) counting = true;
            } else if (e.kind == Kind::delay && counting) {
                ms += e.value;
            }
        }
        return 0;
    }
};

TftConfig st7789_240x240(bool invert = true) {
    return TftConfig{Controller::st7789, 240, 240, 0, 80, 0xC0, invert};
}

TftConfig ili9341_320x240() {
    return TftConfig{Controller::ili9341, 320, 240, 0, 0, hider::port::kMadctlMv | hider::port::kMadctlBgr, false};
}

std::vector<uint8_t> big_endian(const std::vector<uint16_t>& pixels) {
    std::vector<uint8_t> out;
    for (uint16_t p : pixels) {
        out.push_back(static_cast<uint8_t>(p >> 8));
        out.push_back(static_cast<uint8_t>(p & 0xFF));
    }
    return out;
}

std::vector<uint16_t> test_pattern(size_t count) {
    std::vector<uint16_t> out(count);
    for (size_t i = 0; i < count; ++i) out[i] = static_cast<uint16_t>((i * 40503u) ^ 0xA5C3u);
    return out;
}

// Every byte on the bus, commands and data alike, in order.
std::vector<uint8_t> sent_bytes(const FakeBus& bus) {
    std::vector<uint8_t> out;
    for (const auto& e : bus.events) {
        if (e.kind == FakeBus::Kind::command || e.kind == FakeBus::Kind::data) out.push_back(static_cast<uint8_t>(e.value));
    }
    return out;
}

// Each command byte opens its own CS transaction.
bool commands_each_open_a_transaction(const FakeBus& bus) {
    for (size_t i = 0; i < bus.events.size(); ++i) {
        if (bus.events[i].kind != FakeBus::Kind::command) continue;
        if (i == 0 || bus.events[i - 1].kind != FakeBus::Kind::cs || bus.events[i - 1].value != 1) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("ST7789 init pulses reset, then sends SWRESET, SLPOUT, COLMOD 0x55, MADCTL, INVON, NORON, DISPON") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    CHECK(tft.init());
    CHECK(tft.initialized());
    CHECK(bus.trace() == "R0 W10 R1 W120 [ C01 ] W150 [ C11 ] W120 [ C3A 55 ] [ C36 C0 ] [ C21 ] [ C13 ] [ C29 ]");
    CHECK(bus.bytes_without_cs == 0);
    CHECK(bus.bytes_with_unknown_dc == 0);
    CHECK_FALSE(bus.cs);
}

TEST_CASE("ST7789 init sends INVOFF when the config does not invert") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240(false));
    CHECK(tft.init());
    CHECK(bus.commands() == std::vector<uint8_t>{0x01, 0x11, 0x3A, 0x36, 0x20, 0x13, 0x29});
}

TEST_CASE("ILI9341 init sends SWRESET, COLMOD 0x55, MADCTL, INVOFF, SLPOUT and DISPON") {
    FakeBus bus;
    SpiTft tft(bus.hal(), ili9341_320x240());
    CHECK(tft.init());
    CHECK(bus.trace() == "R0 W10 R1 W120 [ C01 ] W150 [ C3A 55 ] [ C36 28 ] [ C20 ] [ C11 ] W120 [ C29 ]");
    CHECK(bus.bytes_without_cs == 0);
    CHECK_FALSE(bus.cs);
}

TEST_CASE("init waits at least the datasheet minimums after reset, SWRESET and SLPOUT") {
    FakeBus bus;
    TftConfig config = st7789_240x240();
    SUBCASE("ST7789") {}
    SUBCASE("ILI9341") { config = ili9341_320x240(); }
    SpiTft tft(bus.hal(), config);
    REQUIRE(tft.init());
    REQUIRE(bus.events.size() >= 4);
    CHECK(bus.events[0].kind == FakeBus::Kind::reset);
    CHECK(bus.events[0].value == 0);
    CHECK(bus.events[1].kind == FakeBus::Kind::delay);
    CHECK(bus.events[1].value >= 1);    // RESX low >= 10 us, with a whole tick of margin
    CHECK(bus.events[3].kind == FakeBus::Kind::delay);
    CHECK(bus.events[3].value >= 120);  // reset cancel: 120 ms when reset comes during sleep-out
    CHECK(bus.ms_after(0x01) >= 5);           // SWRESET: 5 ms before any command
    CHECK(bus.ms_after(0x01, 0x11) >= 120);   // SWRESET: 120 ms before SLPOUT
    CHECK(bus.ms_after(0x11) >= 5);           // SLPOUT: 5 ms before any command
}

TEST_CASE("init without a reset pin skips the pulse and relies on SWRESET") {
    FakeBus bus;
    SpiTft tft(bus.hal(false), st7789_240x240());
    CHECK(tft.init());
    CHECK(bus.trace().rfind("[ C01 ] W150 [ C11 ]", 0) == 0);
}

TEST_CASE("init without a CS pin sends the same bytes with no CS edges") {
    FakeBus with_cs;
    FakeBus without_cs;
    SpiTft a(with_cs.hal(), st7789_240x240());
    SpiTft b(without_cs.hal(true, false), st7789_240x240());
    CHECK(a.init());
    CHECK(b.init());
    std::string expected = with_cs.trace();
    for (const char* edge : {"[ ", " ]"}) {
        for (size_t at = expected.find(edge); at != std::string::npos; at = expected.find(edge)) expected.erase(at, 2);
    }
    CHECK(without_cs.trace() == expected);
    CHECK(without_cs.bytes_with_unknown_dc == 0);
}

TEST_CASE("init fails and sends nothing when a required HAL function is missing or the panel is empty") {
    FakeBus bus;
    SpiTftHal hal = bus.hal();
    TftConfig config = st7789_240x240();
    SUBCASE("spi_write") { hal.spi_write = nullptr; }
    SUBCASE("set_dc") { hal.set_dc = nullptr; }
    SUBCASE("delay_ms") { hal.delay_ms = nullptr; }
    SUBCASE("zero width") { config.width = 0; }
    SUBCASE("zero height") { config.height = 0; }
    SUBCASE("unknown controller") { config.controller = static_cast<Controller>(7); }
    SpiTft tft(hal, config);
    CHECK_FALSE(tft.init());
    CHECK_FALSE(tft.initialized());
    CHECK_FALSE(tft.set_window(0, 0, 0, 0));
    CHECK(bus.events.empty());
}

TEST_CASE("every command goes alone with DC low at the start of a CS transaction, parameters with DC high") {
    FakeBus bus;
    SpiTft tft(bus.hal(), ili9341_320x240());
    REQUIRE(tft.init());
    REQUIRE(tft.set_window(1, 2, 3, 4));
    const uint16_t pixels[9] = {};
    REQUIRE(tft.write_pixels(pixels, 9));
    tft.end_write();
    CHECK(commands_each_open_a_transaction(bus));
    CHECK(bus.bytes_without_cs == 0);
    CHECK(bus.bytes_with_unknown_dc == 0);
    CHECK_FALSE(bus.cs);
}

TEST_CASE("set_window sends CASET and RASET with the offsets as big-endian pairs, then RAMWR with CS held") {
    FakeBus bus;
    SUBCASE("ST7789 240x240 with y offset 80") {
        SpiTft tft(bus.hal(), st7789_240x240());
        REQUIRE(tft.init());
        bus.clear();
        CHECK(tft.set_window(10, 20, 200, 230));
        CHECK(bus.trace() == "[ C2A 00 0A 00 C8 ] [ C2B 00 64 01 36 ] [ C2C");
        CHECK(tft.writing());
        CHECK(tft.window_pixels_left() == 191u * 211u);
        tft.end_write();
        CHECK(bus.trace() == "[ C2A 00 0A 00 C8 ] [ C2B 00 64 01 36 ] [ C2C ]");
        CHECK(tft.window_pixels_left() == 0);
    }
    SUBCASE("135x240 panel at RAM offset (52, 40)") {
        SpiTft tft(bus.hal(), TftConfig{Controller::ili9341, 135, 240, 52, 40, 0, false});
        REQUIRE(tft.init());
        bus.clear();
        CHECK(tft.set_window(0, 0, 134, 239));
        CHECK(bus.trace() == "[ C2A 00 34 00 BA ] [ C2B 00 28 01 17 ] [ C2C");
    }
}

TEST_CASE("set_window refuses inverted or off-panel rectangles and sends nothing") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    CHECK_FALSE(tft.set_window(0, 0, 9, 9));  // before init
    REQUIRE(tft.init());
    bus.clear();
    CHECK_FALSE(tft.set_window(5, 0, 4, 9));
    CHECK_FALSE(tft.set_window(0, 5, 9, 4));
    CHECK_FALSE(tft.set_window(0, 0, 240, 9));
    CHECK_FALSE(tft.set_window(0, 0, 9, 240));
    CHECK(bus.events.empty());
    CHECK_FALSE(tft.writing());
    CHECK(tft.set_window(239, 239, 239, 239));
}

TEST_CASE("init refuses a panel whose offsets put a column or row past RAM address 0xFFFF, and sends nothing") {
    {
        FakeBus bus;  // the last column at 0xFFFF, the last row at 0xFFFF: fits
        SpiTft tft(bus.hal(), TftConfig{Controller::st7789, 16, 8, 0xFFF0, 0xFFF8, 0, true});
        REQUIRE(tft.init());
        bus.clear();
        CHECK(tft.set_window(0, 0, 15, 7));
        CHECK(bus.params_of(0x2A) == std::vector<uint8_t>{0xFF, 0xF0, 0xFF, 0xFF});
        CHECK(bus.params_of(0x2B) == std::vector<uint8_t>{0xFF, 0xF8, 0xFF, 0xFF});
    }
    for (const TftConfig& config : {TftConfig{Controller::st7789, 17, 8, 0xFFF0, 0, 0, true},
                                    TftConfig{Controller::st7789, 8, 9, 0, 0xFFF8, 0, true},
                                    TftConfig{Controller::ili9341, 240, 240, 65500, 0, 0, false}}) {
        FakeBus bus;
        SpiTft tft(bus.hal(), config);
        CHECK_FALSE(tft.init());
        CHECK(bus.events.empty());
        CHECK_FALSE(tft.set_window(0, 0, 0, 0));
        const BandSink sink = tft.sink();  // the sink too: it opens its window without set_window's checks
        CHECK_FALSE(sink.begin_frame(sink.user, 1, 1));
        CHECK(tft.last_band_status() == BandStatus::not_ready);
        CHECK(bus.events.empty());
    }
}

TEST_CASE("write_pixels sends RGB565 high byte first, in order") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    REQUIRE(tft.set_window(0, 0, 3, 0));
    bus.clear();
    const uint16_t pixels[4] = {0xF800, 0x07E0, 0x001F, 0x1234};
    CHECK(tft.write_pixels(pixels, 4));
    CHECK(bus.trace() == "F8 00 07 E0 00 1F 12 34");
    CHECK(tft.window_pixels_left() == 0);
}

TEST_CASE("write_pixels output does not depend on how pixels are split across calls and chunks") {
    const std::vector<uint16_t> pixels = test_pattern(200);
    for (const size_t piece : {1, 3, 31, 32, 33, 64, 199, 200}) {
        CAPTURE(piece);
        FakeBus bus;
        SpiTft tft(bus.hal(), st7789_240x240());
        REQUIRE(tft.init());
        REQUIRE(tft.set_window(0, 0, 199, 0));
        bus.clear();
        for (size_t at = 0; at < pixels.size(); at += piece) {
            const size_t n = pixels.size() - at < piece ? pixels.size() - at : piece;
            REQUIRE(tft.write_pixels(pixels.data() + at, n));
        }
        CHECK(bus.commands().empty());
        CHECK(sent_bytes(bus) == big_endian(pixels));
        for (size_t len : bus.write_lengths) CHECK(len <= hider::port::tft::kChunkBytes);
        CHECK(bus.bytes_without_cs == 0);
    }
}

TEST_CASE("write_pixels refuses without an open window or beyond the window and sends nothing") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    bus.clear();
    const uint16_t pixels[5] = {1, 2, 3, 4, 5};
    CHECK_FALSE(tft.write_pixels(pixels, 1));
    CHECK(bus.events.empty());
    REQUIRE(tft.set_window(0, 0, 1, 1));
    bus.clear();
    CHECK_FALSE(tft.write_pixels(pixels, 5));
    CHECK_FALSE(tft.write_pixels(nullptr, 1));
    CHECK(bus.events.empty());
    CHECK(tft.write_pixels(pixels, 3));
    CHECK_FALSE(tft.write_pixels(pixels, 2));
    CHECK(tft.write_pixels(pixels, 1));
    CHECK(tft.write_pixels(nullptr, 0));
    CHECK(bus.data_bytes() == 8);
    tft.end_write();
    CHECK_FALSE(tft.write_pixels(pixels, 1));
    CHECK_FALSE(bus.cs);
}

TEST_CASE("fill_pixels repeats one colour high byte first and respects the window") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    CHECK_FALSE(tft.fill_pixels(0xABCD, 1));
    REQUIRE(tft.set_window(0, 0, 9, 9));
    bus.clear();
    CHECK_FALSE(tft.fill_pixels(0xABCD, 101));
    CHECK(bus.events.empty());
    CHECK(tft.fill_pixels(0xABCD, 100));
    CHECK(bus.commands().empty());
    CHECK(sent_bytes(bus) == big_endian(std::vector<uint16_t>(100, 0xABCD)));
    for (size_t len : bus.write_lengths) CHECK(len <= hider::port::tft::kChunkBytes);
}

TEST_CASE("a command sent while a window is open closes the pixel write first") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    REQUIRE(tft.set_window(0, 0, 0, 0));
    bus.clear();
    const uint8_t madctl = 0x60;
    CHECK(tft.send_command(0x36, &madctl, 1));
    CHECK(bus.trace() == "] [ C36 60 ]");
    CHECK_FALSE(tft.writing());
    CHECK_FALSE(tft.send_command(0x36, nullptr, 1));
}

TEST_CASE("streaming a 40x30 frame in bands of 7 rows sends one window of the frame size and the frame's bytes") {
    const uint16_t width = 40;
    const uint16_t height = 30;
    const std::vector<uint16_t> frame = test_pattern(size_t{width} * height);
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    bus.clear();
    const BandSink sink = tft.sink();
    SUBCASE("calling the sink directly") {
        REQUIRE(sink.begin_frame(sink.user, width, height));
        for (uint16_t y = 0; y < height; y = static_cast<uint16_t>(y + 7)) {
            const uint16_t rows = static_cast<uint16_t>(height - y < 7 ? height - y : 7);
            REQUIRE(sink.write_rows(sink.user, y, rows, frame.data() + y * width, width));
        }
        CHECK(bus.cs);
        CHECK(sink.end_frame(sink.user));
    }
    SUBCASE("through send_frame_in_bands") {
        CHECK(hider::port::send_frame_in_bands(sink, frame.data(), width, height, width, 7));
    }
    CHECK(tft.last_band_status() == BandStatus::ok);
    CHECK(bus.commands() == std::vector<uint8_t>{0x2A, 0x2B, 0x2C});
    CHECK(bus.params_of(0x2A) == std::vector<uint8_t>{0x00, 0x00, 0x00, 39});
    CHECK(bus.params_of(0x2B) == std::vector<uint8_t>{0x00, 80, 0x00, 80 + 29});
    CHECK(bus.params_of(0x2C) == big_endian(frame));
    CHECK(commands_each_open_a_transaction(bus));
    CHECK(bus.bytes_without_cs == 0);
    CHECK_FALSE(bus.cs);
    CHECK(bus.events.back().kind == FakeBus::Kind::cs);
    for (size_t len : bus.write_lengths) CHECK(len <= hider::port::tft::kChunkBytes);
}

TEST_CASE("bands of a column window (write_columns) send the whole frame, the columns outside as the fill") {
    const uint16_t width = 40;
    const uint16_t height = 30;
    const uint16_t fill = 0x1234;
    for (const uint16_t x0 : {uint16_t{0}, uint16_t{1}, uint16_t{13}, uint16_t{39}}) {
        for (const uint16_t w : {uint16_t{1}, uint16_t{14}, uint16_t{40}}) {
            if (x0 + w > width) continue;
            CAPTURE(x0);
            CAPTURE(w);
            // The frame: a pattern in columns [x0, x0 + w), the fill elsewhere; the band memory holds only the
            // window, rows w + 3 apart.
            const std::vector<uint16_t> pattern = test_pattern(size_t{width} * height);
            std::vector<uint16_t> frame(size_t{width} * height, fill), window((size_t{w} + 3) * height, 0xFFFF);
            for (uint16_t y = 0; y < height; ++y)
                for (uint16_t x = x0; x < x0 + w; ++x) {
                    frame[size_t{y} * width + x] = pattern[size_t{y} * width + x];
                    window[size_t{y} * (w + 3) + (x - x0)] = pattern[size_t{y} * width + x];
                }
            FakeBus bus;
            SpiTft tft(bus.hal(), st7789_240x240());
            REQUIRE(tft.init());
            bus.clear();
            const BandSink sink = tft.sink();
            REQUIRE((sink.write_columns != nullptr));
            REQUIRE(sink.begin_frame(sink.user, width, height));
            for (uint16_t y = 0; y < height; y = static_cast<uint16_t>(y + 7)) {
                const uint16_t rows = static_cast<uint16_t>(height - y < 7 ? height - y : 7);
                REQUIRE(sink.write_columns(sink.user, y, rows, x0, w, fill, window.data() + size_t{y} * (w + 3), w + 3u));
            }
            CHECK(sink.end_frame(sink.user));
            CHECK(tft.last_band_status() == BandStatus::ok);
            CHECK(bus.commands() == std::vector<uint8_t>{0x2A, 0x2B, 0x2C});
            CHECK(bus.params_of(0x2C) == big_endian(frame));
            CHECK(bus.bytes_without_cs == 0);
            for (size_t len : bus.write_lengths) CHECK(len <= hider::port::tft::kChunkBytes);
        }
    }
    // A window past the frame's right side is refused with nothing sent.
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    const BandSink sink = tft.sink();
    REQUIRE(sink.begin_frame(sink.user, width, height));
    bus.clear();
    const std::vector<uint16_t> band(size_t{width} * 7, 0);
    CHECK_FALSE(sink.write_columns(sink.user, 0, 7, 30, 11, 0, band.data(), width));
    CHECK(tft.last_band_status() == BandStatus::bad_size);
    CHECK(bus.params_of(0x2C).empty());
    (void)sink.end_frame(sink.user);
}

TEST_CASE("a band whose stride is wider than the frame sends only the frame's columns") {
    const uint16_t width = 40;
    const uint16_t height = 30;
    const uint32_t stride = 48;
    const std::vector<uint16_t> frame = test_pattern(size_t{width} * height);
    std::vector<uint16_t> padded(stride * height, 0xFFFF);
    for (uint16_t y = 0; y < height; ++y) {
        for (uint16_t x = 0; x < width; ++x) padded[y * stride + x] = frame[y * width + x];
    }
    FakeBus bus;
    SpiTft tft(bus.hal(), ili9341_320x240());
    REQUIRE(tft.init());
    bus.clear();
    CHECK(hider::port::send_frame_in_bands(tft.sink(), padded.data(), width, height, stride, 7));
    CHECK(bus.params_of(0x2C) == big_endian(frame));
}

TEST_CASE("the sink refuses a frame larger than the panel or empty and sends nothing") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    bus.clear();
    const BandSink sink = tft.sink();
    CHECK_FALSE(sink.begin_frame(sink.user, 241, 10));
    CHECK(tft.last_band_status() == BandStatus::too_large);
    CHECK_FALSE(sink.begin_frame(sink.user, 10, 241));
    CHECK_FALSE(sink.begin_frame(sink.user, 0, 10));
    CHECK(tft.last_band_status() == BandStatus::bad_size);
    CHECK(bus.events.empty());
    CHECK(sink.begin_frame(sink.user, 240, 240));
}

TEST_CASE("the sink refuses out-of-order rows, sends no pixels for them and closes the frame at end_frame") {
    const std::vector<uint16_t> frame = test_pattern(40 * 30);
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    const BandSink sink = tft.sink();
    REQUIRE(sink.begin_frame(sink.user, 40, 30));
    bus.clear();
    CHECK_FALSE(sink.write_rows(sink.user, 7, 7, frame.data() + 7 * 40, 40));
    CHECK(tft.last_band_status() == BandStatus::out_of_order);
    CHECK(bus.events.empty());
    CHECK(sink.write_rows(sink.user, 0, 7, frame.data(), 40));
    CHECK(bus.data_bytes() == 7 * 40 * 2);
    bus.clear();
    CHECK_FALSE(sink.write_rows(sink.user, 0, 7, frame.data(), 40));
    CHECK_FALSE(sink.write_rows(sink.user, 8, 7, frame.data(), 40));
    CHECK_FALSE(sink.write_rows(sink.user, 7, 24, frame.data(), 40));
    CHECK(tft.last_band_status() == BandStatus::past_end);
    CHECK_FALSE(sink.write_rows(sink.user, 7, 7, frame.data(), 39));
    CHECK(tft.last_band_status() == BandStatus::bad_pixels);
    CHECK(bus.events.empty());
    CHECK_FALSE(sink.end_frame(sink.user));
    CHECK(tft.last_band_status() == BandStatus::incomplete);
    CHECK(bus.trace() == "]");
    CHECK_FALSE(tft.writing());
}

TEST_CASE("the sink refuses rows or end_frame before begin_frame and sends nothing") {
    const uint16_t pixels[40] = {};
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    bus.clear();
    const BandSink sink = tft.sink();
    CHECK_FALSE(sink.write_rows(sink.user, 0, 1, pixels, 40));
    CHECK(tft.last_band_status() == BandStatus::not_in_frame);
    CHECK_FALSE(sink.end_frame(sink.user));
    CHECK(bus.events.empty());
}

TEST_CASE("the sink refuses to start a frame before init") {
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    const BandSink sink = tft.sink();
    CHECK_FALSE(sink.begin_frame(sink.user, 40, 30));
    CHECK(tft.last_band_status() == BandStatus::not_ready);
    CHECK(bus.events.empty());
}

TEST_CASE("raw calls are refused while a sink frame is open") {
    const uint16_t pixels[4] = {};
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    const BandSink sink = tft.sink();
    REQUIRE(sink.begin_frame(sink.user, 2, 2));
    bus.clear();
    CHECK_FALSE(tft.set_window(0, 0, 1, 1));
    CHECK_FALSE(tft.send_command(0x29, nullptr, 0));
    CHECK_FALSE(tft.write_pixels(pixels, 4));
    CHECK_FALSE(tft.fill_pixels(0, 4));
    CHECK(bus.events.empty());
    CHECK(sink.write_rows(sink.user, 0, 2, pixels, 2));
    CHECK(sink.end_frame(sink.user));
    CHECK(tft.set_window(0, 0, 1, 1));
}

TEST_CASE("end_write during a sink frame does nothing: the frame's pixels still go out selected") {
    const uint16_t width = 24, height = 20;
    const std::vector<uint16_t> frame = test_pattern(size_t{width} * height);
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    const BandSink sink = tft.sink();
    bus.clear();
    REQUIRE(sink.begin_frame(sink.user, width, height));
    REQUIRE(sink.write_rows(sink.user, 0, 10, frame.data(), width));
    const uint32_t left = tft.window_pixels_left();
    tft.end_write();
    CHECK(tft.writing());
    CHECK(tft.window_pixels_left() == left);
    REQUIRE(sink.write_rows(sink.user, 10, 10, frame.data() + 10 * width, width));
    CHECK(sink.end_frame(sink.user));
    CHECK(bus.bytes_without_cs == 0);
    CHECK(bus.params_of(0x2C) == big_endian(frame));
    CHECK_FALSE(tft.writing());
    CHECK(tft.window_pixels_left() == 0);
}

TEST_CASE("init during an open sink frame closes the frame and starts over") {
    const uint16_t pixels[4] = {};
    FakeBus bus;
    SpiTft tft(bus.hal(), st7789_240x240());
    REQUIRE(tft.init());
    const BandSink sink = tft.sink();
    REQUIRE(sink.begin_frame(sink.user, 2, 2));
    bus.clear();
    CHECK(tft.init());
    CHECK(bus.trace().rfind("] R0 W10 R1", 0) == 0);
    CHECK_FALSE(sink.write_rows(sink.user, 0, 2, pixels, 2));
    CHECK(sink.begin_frame(sink.user, 2, 2));
}

TEST_CASE("display headers include only stdint.h, stddef.h, limits.h, each other and lib/, and use no float or std") {
    std::string dir = __FILE__;
    const size_t at = dir.rfind("tests/port/st7789_test.cpp");
    REQUIRE(at != std::string::npos);
    dir = dir.substr(0, at) + "port/display/";
    // hider/frame.hpp is lib/'s (freestanding by lib/'s own check); the OLED model runs on the firmware too.
    const std::vector<std::string> allowed = {"#include <stdint.h>", "#include <stddef.h>", "#include <limits.h>",
                                              "#include <display/sink.hpp>", "#include <display/ssd1306.hpp>",
                                              "#include <hider/frame.hpp>"};
    const std::vector<std::string> banned = {"float", "double", "std", "virtual", "new", "delete", "throw", "try"};
    std::string bad;  // "file:line: text" for each offending line
    for (const char* name : {"sink.hpp", "st7789.hpp", "ssd1306.hpp", "oled_model.hpp"}) {
        const std::string path = dir + name;
        std::ifstream file(path);
        REQUIRE_MESSAGE(file.good(), path);
        std::string line;
        for (int number = 1; std::getline(file, line); ++number) {
            const std::string code = line.substr(0, line.find("//"));
            bool ok = code.find("#include") == std::string::npos;
            for (const std::string& a : allowed) ok = ok || code == a;
            std::string word;
            for (const char c : code + " ") {
                if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
                    word += c;
                    continue;
                }
                for (const std::string& b : banned) ok = ok && word != b;
                word.clear();
            }
            if (!ok) bad += std::string(name) + ":" + std::to_string(number) + ": " + line + "\n";
        }
    }
    CHECK_MESSAGE(bad.empty(), bad);
}

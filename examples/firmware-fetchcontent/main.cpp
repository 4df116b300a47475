// Firmware consumer of hider (FetchContent): renders the example scene on a Cortex-M0+ in bands of 5 KB
// of colour + depth (instead of 80 KB: 8 rows of the full width, 13 of the scene's column window) and
// hands each band to hider's ST7789 driver through its BandSink. The board's SPI bus is simulated: the
// bytes the driver sends after RAMWR (RGB565, high byte first) are expanded to RGB888 the way hider's PPM
// writer does and written to frame.ppm on the host through semihosting. The program's own code is built with exceptions and RTTI on.
#include <display/st7789.hpp>
#include <hider/raster/zbuffer.hpp>
#include <semihost/semihost.hpp>

#include "example_scene.hpp"

static_assert(__cpp_exceptions, "this program is built with exceptions on");
static_assert(__cpp_rtti, "this program is built with RTTI on");

namespace {

constexpr int32_t kBandRows = 8;

uint16_t g_color[example::kWidth * kBandRows];
uint16_t g_depth[example::kWidth * kBandRows];
hider::ScreenVertex g_verts[16];

// The simulated panel: decodes the SPI stream into pixels and streams them into a PPM file.
struct SimulatedPanel {
    int32_t file = hider::semihost::kInvalidHandle;
    bool data_mode = false;     // DC high
    bool pixel_data = false;    // after RAMWR
    bool have_high = false;     // first byte of a pixel seen
    uint8_t high = 0;
    uint32_t pixels = 0;
    bool write_ok = true;
    uint8_t row[example::kWidth * 3] = {};
    int32_t row_fill = 0;

    void byte(uint8_t b) {
        if (!data_mode) {  // a command byte
            pixel_data = b == hider::port::tft::kMemoryWrite;
            have_high = false;
            return;
        }
        if (!pixel_data) return;  // a command parameter
        if (!have_high) {
            high = b;
            have_high = true;
            return;
        }
        have_high = false;
        const hider::Rgb c = hider::Rgb565Format::unpack(static_cast<uint16_t>((high << 8) | b));
        row[row_fill++] = c.r;
        row[row_fill++] = c.g;
        row[row_fill++] = c.b;
        ++pixels;
        if (row_fill == static_cast<int32_t>(sizeof(row))) {
            write_ok = hider::semihost::write(file, row, sizeof(row)) && write_ok;
            row_fill = 0;
        }
    }
};

SimulatedPanel g_panel;

void spi_write(void* user, const uint8_t* data, size_t len) {
    auto* panel = static_cast<SimulatedPanel*>(user);
    for (size_t i = 0; i < len; ++i) panel->byte(data[i]);
}
void set_dc(void* user, bool data) { static_cast<SimulatedPanel*>(user)->data_mode = data; }
void set_cs(void*, bool) {}
void delay_ms(void*, uint32_t) {}  // a real board waits here

// The band renderer: vertices projected once, then per band clear + draw + hand to the sink. Only the
// frame's centred column window is drawn (the columns the vertices can reach; the background elsewhere),
// so the same band memory holds more rows of it; the driver sends the columns outside as the fill colour.
int32_t g_bands = 0;
hider::ColumnWindow g_window;
bool render_in_bands(const hider::port::BandSink& sink) {
    hider::View view;
    if (hider::make_view(example::camera(), example::kWidth, example::kHeight, view) != hider::Status::ok) return false;
    if (hider::project_vertices(view, example::mesh().positions, {g_verts, 16}) != hider::Status::ok) return false;
    const hider::ColumnWindow window = g_window = hider::centred_window({g_verts, 16}, example::kWidth);
    hider::View drawn;
    if (hider::window_view(view, window, drawn) != hider::Status::ok || sink.write_columns == nullptr) return false;
    const int32_t rows = hider::min(example::kHeight, kBandRows * example::kWidth / window.width);
    if (!sink.begin_frame(sink.user, example::kWidth, example::kHeight)) return false;
    bool ok = true;
    for (int32_t y0 = 0; y0 < example::kHeight && ok; y0 += rows, ++g_bands) {
        const int32_t y1 = hider::min(example::kHeight, y0 + rows);
        const auto band = hider::band_view<hider::Rgb565Format, uint16_t>(g_color, g_depth, window.width,
                                                                          example::kHeight, y0, y1);
        ok = example::draw(drawn, {g_verts, 16}, band).ok() &&
             sink.write_columns(sink.user, static_cast<uint16_t>(y0), static_cast<uint16_t>(y1 - y0),
                                static_cast<uint16_t>(window.x0), static_cast<uint16_t>(window.width),
                                hider::Rgb565Format::pack(example::kBackground), g_color,
                                static_cast<uint32_t>(window.width));
    }
    return sink.end_frame(sink.user) && ok;
}

}  // namespace

extern "C" int firmware_main() {
    g_panel.file = hider::semihost::open_write("frame.ppm");
    if (g_panel.file == hider::semihost::kInvalidHandle) {
        hider::semihost::print("panel_demo: cannot open frame.ppm\n");
        return 1;
    }
    const char header[] = "P6\n160 128\n255\n";
    bool ok = hider::semihost::write(g_panel.file, header, sizeof(header) - 1);

    const hider::port::SpiTftHal hal{&g_panel, spi_write, set_dc, set_cs, nullptr, delay_ms};
    const hider::port::TftConfig config{hider::port::Controller::st7789, example::kWidth, example::kHeight, 0, 0, 0, false};
    hider::port::SpiTft panel(hal, config);
    ok = panel.init() && ok;
    ok = render_in_bands(panel.sink()) && ok;
    ok = hider::semihost::close(g_panel.file) && g_panel.write_ok && ok;
    if (!ok || g_panel.pixels != example::kWidth * example::kHeight) {
        hider::semihost::print("panel_demo: failed\n");
        return 1;
    }
    hider::semihost::print("panel_demo: ");
    hider::semihost::print_u32(static_cast<uint32_t>(g_bands));
    hider::semihost::print(" bands of columns ");
    hider::semihost::print_u32(static_cast<uint32_t>(g_window.x0));
    hider::semihost::print(" + ");
    hider::semihost::print_u32(static_cast<uint32_t>(g_window.width));
    hider::semihost::print(", ");
    hider::semihost::print_u32(g_panel.pixels);
    hider::semihost::print(" pixels\n");
    return 0;
}

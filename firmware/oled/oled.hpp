// The oled program, shared by the firmware and its host twin (tools/firmware-hosts/oled_reference.cpp):
// spin's torus (frame 0) at 128x64, drawn band by band (bands/bands.hpp) into the SSD1306 driver's
// dithering sink (port/display/ssd1306.hpp). On a board the driver's HAL is the I2C bus; here it feeds a
// simulated module (port/display/oled_model.hpp), whose glass is written as a PBM file.
#pragma once
#include "bands/bands.hpp"
#include "display/oled_model.hpp"
#include "display/ssd1306.hpp"

namespace oled {

constexpr uint8_t kWidth = 128, kHeight = 64;
/// A 0.96" 128x64 I2C module: SSD1306, internal charge pump, upright.
constexpr hider::port::OledConfig kConfig{hider::port::OledController::ssd1306, kWidth, kHeight, 0, 0xCF, false, false, 0};

/// Writes the module's glass as a binary PBM (P4: rows of bits, first pixel in the top bit; 1 is black,
/// so lit pixels come out white as on the panel).
template <class Io>
bool write_pbm(Io& io, const hider::port::OledModel& module) {
    static_assert(kWidth == 128 && kHeight == 64, "the header below");
    const char header[] = "P4\n128 64\n";
    if (!io.write(header, sizeof header - 1)) return false;
    for (uint32_t y = 0; y < kHeight; ++y) {
        uint8_t row[kWidth / 8] = {};
        for (uint32_t x = 0; x < kWidth; ++x)
            if (!module.pixel(x, y)) row[x / 8] = static_cast<uint8_t>(row[x / 8] | (0x80u >> (x % 8)));
        if (!io.write(row, sizeof row)) return false;
    }
    return true;
}

/// Draws frame 0 of `s` band by band through buf's band buffers, each band handed to panel.write_rows()
/// (a direct call: the panel's HAL write is then the program's only indirect call, which hider-stack
/// can bound). As bands::render_in_bands() otherwise, bench markers included.
inline hider::FrameStats render(const spin::Scene& s, const bands::BandBuffers& buf, hider::port::Oled& panel) {
    hider::FrameStats total;
    const size_t band_px = static_cast<size_t>(s.width) * static_cast<size_t>(buf.rows);
    if (buf.rows < 1 || buf.color.size() < band_px || buf.depth.size() < band_px ||
        !panel.begin_frame(static_cast<uint16_t>(s.width), static_cast<uint16_t>(s.height))) {
        total.status = hider::Status::invalid_argument;
        return total;
    }
    hider::View view;
    bench_begin();
    total.status = spin::frame_view(s, 0, view);
    if (total.status == hider::Status::ok) total.status = hider::project_vertices(view, s.mesh.positions, buf.verts);
    if (total.status == hider::Status::ok)
        total = hider::draw_zbuffer_binned(
            view, s.mesh, buf.verts,
            hider::band_view<hider::Rgb565Format, uint16_t>(buf.color.data(), buf.depth.data(), s.width, s.height, 0, buf.rows),
            spin::draw_options(), spin::kBackground, buf.scratch, [&panel](const spin::Frame& band) {
                bench_end();  // the bus's time is the display's, not the renderer's
                const bool sent = panel.write_rows(static_cast<uint16_t>(band.y0), static_cast<uint16_t>(band.rows()),
                                                   band.color, static_cast<uint32_t>(band.stride));
                bench_begin();
                return sent;
            });
    bench_end();
    if (!panel.end_frame() && total.status == hider::Status::ok) total.status = hider::Status::invalid_argument;
    return total;
}

/// Initialises the panel, draws frame 0 of `s` (kWidth x kHeight) into it band by band and writes what the
/// module shows to `path`. Returns the exit status (0 ok, 1 failure, with a message).
template <class Io>
int run(Io& io, const spin::Scene& s, const bands::BandBuffers& buf, hider::port::OledModel& module, const char* path) {
    hider::port::Oled panel(module.hal(), kConfig);
    if (!panel.init()) {
        io.print("oled: init failed\n");
        return 1;
    }
    const hider::FrameStats st = render(s, buf, panel);
    if (!st.ok() || panel.last_band_status() != hider::port::BandStatus::ok || module.errors() != 0) {
        io.print("oled: failed: ");
        io.print(hider::status_name(st.status));
        io.print(", sink status ");
        io.print_u32(static_cast<uint32_t>(panel.last_band_status()));
        io.print(", module errors ");
        io.print_u32(module.errors());
        io.print("\n");
        return 1;
    }
    if (!io.open(path)) {
        io.print("oled: cannot open ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    const bool written = write_pbm(io, module);
    if (!io.close() || !written) {
        io.print("oled: cannot write the PBM\n");
        return 1;
    }
    uint32_t lit = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) lit += module.pixel(x, y) ? 1u : 0u;
    io.print(path);
    io.print(": triangles drawn ");
    io.print_u32(st.triangles_drawn);
    io.print(", bus transfers ");
    io.print_u32(module.transfers());
    io.print(", pixels lit ");
    io.print_u32(lit);
    io.print("\n");
    return 0;
}

}  // namespace oled

// The band firmware's PPM sink (firmware/spin/ppm_sink.hpp): full-width bands and column-window bands
// (BandSink::write_columns) give the P6 file of the whole frame, the columns outside a window in the
// band's fill colour, for any chunk size; refused calls are reported and write nothing.
#include "spin/ppm_sink.hpp"

#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

namespace {

struct MemoryOut {
    std::vector<uint8_t> bytes;
    bool write(const void* data, size_t size) {
        const auto* p = static_cast<const uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
        return true;
    }
};

/// The P6 file of a width x height RGB565 frame, written out independently of the sink.
std::vector<uint8_t> expected_ppm(const std::vector<uint16_t>& frame, int width, int height) {
    const std::string header = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    std::vector<uint8_t> out(header.begin(), header.end());
    for (uint16_t p : frame) {
        const uint8_t r5 = p >> 11, g6 = (p >> 5) & 63, b5 = p & 31;
        out.push_back(static_cast<uint8_t>((r5 << 3) | (r5 >> 2)));
        out.push_back(static_cast<uint8_t>((g6 << 2) | (g6 >> 4)));
        out.push_back(static_cast<uint8_t>((b5 << 3) | (b5 >> 2)));
    }
    return out;
}

}  // namespace

TEST_CASE("PpmSink writes windowed and full-width bands as the whole frame, the margins in the fill colour") {
    const uint16_t width = 11, height = 7, fill = 0xF81F;
    for (size_t chunk_px : {size_t{1}, size_t{3}, size_t{4}, size_t{11}, size_t{16}}) {
        for (const auto& [x0, w] : {std::pair<uint16_t, uint16_t>{0, 11}, {1, 9}, {4, 3}, {10, 1}, {2, 4}}) {
            CAPTURE(chunk_px);
            CAPTURE(x0);
            CAPTURE(w);
            std::vector<uint16_t> frame(size_t{width} * height), window((size_t{w} + 2) * height, 0xDEAD);
            for (uint16_t y = 0; y < height; ++y)
                for (uint16_t x = 0; x < width; ++x) {
                    const bool inside = x >= x0 && x < x0 + w;
                    const uint16_t px = static_cast<uint16_t>(0x1000 + 37 * (y * width + x));
                    frame[size_t{y} * width + x] = inside || y < 2 ? px : fill;  // rows 0..1 go out full width
                    if (inside) window[size_t{y} * (w + 2) + (x - x0)] = px;
                }
            MemoryOut out;
            std::vector<uint8_t> chunk(3 * chunk_px);
            spin::PpmSink<MemoryOut> ppm(out, {chunk.data(), chunk.size()}, width);
            const hider::port::BandSink sink = ppm.sink();
            REQUIRE((sink.write_columns != nullptr));
            REQUIRE(sink.begin_frame(sink.user, width, height));
            REQUIRE(sink.write_rows(sink.user, 0, 2, frame.data(), width));
            REQUIRE(sink.write_columns(sink.user, 2, 3, x0, w, fill, window.data() + 2 * (w + 2), w + 2u));
            REQUIRE(sink.write_columns(sink.user, 5, 2, x0, w, fill, window.data() + 5 * (w + 2), w + 2u));
            REQUIRE(sink.end_frame(sink.user));
            CHECK(ppm.status() == hider::port::BandStatus::ok);
            CHECK(out.bytes == expected_ppm(frame, width, height));
        }
    }
}

TEST_CASE("PpmSink refuses a window past the frame's side and a sink without windows has none") {
    MemoryOut out;
    uint8_t chunk[12];
    spin::PpmSink<MemoryOut> ppm(out, chunk, 8);
    CHECK((ppm.sink(false).write_columns == nullptr));
    const hider::port::BandSink sink = ppm.sink();
    REQUIRE(sink.begin_frame(sink.user, 8, 4));
    const size_t header = out.bytes.size();
    const uint16_t band[8 * 4] = {};
    CHECK_FALSE(sink.write_columns(sink.user, 0, 4, 5, 4, 0, band, 8));
    CHECK(ppm.status() == hider::port::BandStatus::bad_size);
    CHECK(out.bytes.size() == header);
}

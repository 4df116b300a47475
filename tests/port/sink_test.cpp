// Tests for port/display/sink.hpp: the band-order contract checker and send_frame_in_bands.
#include <display/sink.hpp>

#include <doctest/doctest.h>

#include <vector>

using hider::port::BandSequenceChecker;
using hider::port::BandSink;
using hider::port::BandStatus;

namespace {

const uint16_t kPixels[8 * 10] = {};  // any valid pointer will do for the checker

// A sink that records each call and can be told to refuse one of them.
struct RecordingSink {
    struct Band {
        uint16_t y0;
        uint16_t rows;
        std::vector<uint16_t> pixels;  // rows x width, stride removed
    };
    BandSequenceChecker checker;
    std::vector<Band> bands;
    int begins = 0;
    int ends = 0;
    int refuse_band = -1;  // index of the write_rows call to refuse

    BandSink sink() {
        BandSink s{};
        s.user = this;
        s.begin_frame = [](void* user, uint16_t width, uint16_t height) {
            auto& self = *static_cast<RecordingSink*>(user);
            ++self.begins;
            return self.checker.begin_frame(width, height) == BandStatus::ok;
        };
        s.write_rows = [](void* user, uint16_t y0, uint16_t rows, const uint16_t* rgb565, uint32_t stride_px) {
            auto& self = *static_cast<RecordingSink*>(user);
            if (static_cast<int>(self.bands.size()) == self.refuse_band) return false;
            if (self.checker.write_rows(y0, rows, rgb565, stride_px) != BandStatus::ok) return false;
            Band band{y0, rows, {}};
            for (uint16_t r = 0; r < rows; ++r) {
                for (uint16_t x = 0; x < self.checker.width(); ++x) band.pixels.push_back(rgb565[r * stride_px + x]);
            }
            self.bands.push_back(band);
            return true;
        };
        s.end_frame = [](void* user) {
            auto& self = *static_cast<RecordingSink*>(user);
            ++self.ends;
            return self.checker.end_frame() == BandStatus::ok;
        };
        return s;
    }
};

}  // namespace

TEST_CASE("BandSequenceChecker accepts bands that cover the frame top to bottom exactly once") {
    BandSequenceChecker checker;
    CHECK(checker.begin_frame(8, 10) == BandStatus::ok);
    CHECK(checker.in_frame());
    CHECK(checker.write_rows(0, 3, kPixels, 8) == BandStatus::ok);
    CHECK(checker.next_row() == 3);
    CHECK(checker.write_rows(3, 3, kPixels, 8) == BandStatus::ok);
    CHECK(checker.write_rows(6, 4, kPixels, 8) == BandStatus::ok);
    CHECK(checker.end_frame() == BandStatus::ok);
    CHECK_FALSE(checker.in_frame());
    SUBCASE("a single band of the whole frame with a wider stride is also fine") {
        CHECK(checker.begin_frame(8, 10) == BandStatus::ok);
        CHECK(checker.write_rows(0, 10, kPixels, 12) == BandStatus::ok);
        CHECK(checker.end_frame() == BandStatus::ok);
    }
}

TEST_CASE("BandSequenceChecker rejects rows and end_frame without an open frame") {
    BandSequenceChecker checker;
    CHECK(checker.write_rows(0, 1, kPixels, 8) == BandStatus::not_in_frame);
    CHECK(checker.end_frame() == BandStatus::not_in_frame);
    CHECK(checker.begin_frame(8, 1) == BandStatus::ok);
    CHECK(checker.write_rows(0, 1, kPixels, 8) == BandStatus::ok);
    CHECK(checker.end_frame() == BandStatus::ok);
    CHECK(checker.write_rows(1, 1, kPixels, 8) == BandStatus::not_in_frame);
    CHECK(checker.end_frame() == BandStatus::not_in_frame);
}

TEST_CASE("BandSequenceChecker rejects an empty frame and an empty band") {
    BandSequenceChecker checker;
    CHECK(checker.begin_frame(0, 10) == BandStatus::bad_size);
    CHECK(checker.begin_frame(8, 0) == BandStatus::bad_size);
    CHECK_FALSE(checker.in_frame());
    CHECK(checker.begin_frame(8, 10) == BandStatus::ok);
    CHECK(checker.write_rows(0, 0, kPixels, 8) == BandStatus::bad_size);
    CHECK(checker.next_row() == 0);
}

TEST_CASE("BandSequenceChecker rejects a frame past its limits") {
    BandSequenceChecker checker(240, 135);
    CHECK(checker.begin_frame(241, 135) == BandStatus::too_large);
    CHECK(checker.begin_frame(240, 136) == BandStatus::too_large);
    CHECK_FALSE(checker.in_frame());
    CHECK(checker.begin_frame(240, 135) == BandStatus::ok);
}

TEST_CASE("BandSequenceChecker rejects a gap, an overlap or a repeat and keeps its place") {
    BandSequenceChecker checker;
    REQUIRE(checker.begin_frame(8, 10) == BandStatus::ok);
    REQUIRE(checker.write_rows(0, 4, kPixels, 8) == BandStatus::ok);
    SUBCASE("gap") { CHECK(checker.write_rows(5, 2, kPixels, 8) == BandStatus::out_of_order); }
    SUBCASE("overlap") { CHECK(checker.write_rows(3, 2, kPixels, 8) == BandStatus::out_of_order); }
    SUBCASE("repeat") { CHECK(checker.write_rows(0, 4, kPixels, 8) == BandStatus::out_of_order); }
    CHECK(checker.next_row() == 4);
    CHECK(checker.write_rows(4, 6, kPixels, 8) == BandStatus::ok);
    CHECK(checker.end_frame() == BandStatus::ok);
}

TEST_CASE("BandSequenceChecker rejects rows past the bottom of the frame") {
    BandSequenceChecker checker;
    REQUIRE(checker.begin_frame(8, 10) == BandStatus::ok);
    REQUIRE(checker.write_rows(0, 7, kPixels, 8) == BandStatus::ok);
    CHECK(checker.write_rows(7, 4, kPixels, 8) == BandStatus::past_end);
    CHECK(checker.write_rows(7, UINT16_MAX, kPixels, 8) == BandStatus::past_end);
    CHECK(checker.next_row() == 7);
    CHECK(checker.write_rows(7, 3, kPixels, 8) == BandStatus::ok);
}

TEST_CASE("BandSequenceChecker rejects a null pixel pointer and a stride narrower than the frame") {
    BandSequenceChecker checker;
    REQUIRE(checker.begin_frame(8, 10) == BandStatus::ok);
    CHECK(checker.write_rows(0, 2, nullptr, 8) == BandStatus::bad_pixels);
    CHECK(checker.write_rows(0, 2, kPixels, 7) == BandStatus::bad_pixels);
    CHECK(checker.next_row() == 0);
}

TEST_CASE("BandSequenceChecker takes windowed bands (write_columns) mixed with full rows, and refuses bad windows") {
    BandSequenceChecker checker;
    REQUIRE(checker.begin_frame(8, 10) == BandStatus::ok);
    CHECK(checker.write_columns(0, 3, 2, 4, kPixels, 4) == BandStatus::ok);  // columns 2..5 of rows 0..2
    CHECK(checker.write_rows(3, 2, kPixels, 8) == BandStatus::ok);
    // Refused, leaving the place at row 5: an empty window, one past the right side, a stride narrower
    // than the window, no pixels, no rows, out of order, past the bottom, outside a frame.
    CHECK(checker.write_columns(5, 2, 2, 0, kPixels, 4) == BandStatus::bad_size);
    CHECK(checker.write_columns(5, 2, 5, 4, kPixels, 4) == BandStatus::bad_size);
    CHECK(checker.write_columns(5, 2, UINT16_MAX, 2, kPixels, 4) == BandStatus::bad_size);
    CHECK(checker.write_columns(5, 2, 2, 4, kPixels, 3) == BandStatus::bad_pixels);
    CHECK(checker.write_columns(5, 2, 2, 4, nullptr, 4) == BandStatus::bad_pixels);
    CHECK(checker.write_columns(5, 0, 2, 4, kPixels, 4) == BandStatus::bad_size);
    CHECK(checker.write_columns(6, 2, 2, 4, kPixels, 4) == BandStatus::out_of_order);
    CHECK(checker.write_columns(5, 6, 2, 4, kPixels, 4) == BandStatus::past_end);
    CHECK(checker.next_row() == 5);
    CHECK(checker.write_columns(5, 5, 0, 8, kPixels, 8) == BandStatus::ok);  // the whole width as a window
    CHECK(checker.end_frame() == BandStatus::ok);
    CHECK(checker.write_columns(0, 1, 0, 1, kPixels, 1) == BandStatus::not_in_frame);
}

TEST_CASE("BandSink::write_columns is optional: a sink built without it has none, and is still complete") {
    BandSink s{nullptr, [](void*, uint16_t, uint16_t) { return true; },
               [](void*, uint16_t, uint16_t, const uint16_t*, uint32_t) { return true; }, [](void*) { return true; }};
    CHECK((s.write_columns == nullptr));
    CHECK(hider::port::is_complete(s));
    BandSink d;
    CHECK((d.write_columns == nullptr));
}

TEST_CASE("BandSequenceChecker reports an incomplete frame at end_frame and then takes the next frame") {
    BandSequenceChecker checker;
    REQUIRE(checker.begin_frame(8, 10) == BandStatus::ok);
    REQUIRE(checker.write_rows(0, 5, kPixels, 8) == BandStatus::ok);
    CHECK(checker.end_frame() == BandStatus::incomplete);
    CHECK_FALSE(checker.in_frame());
    CHECK(checker.begin_frame(4, 2) == BandStatus::ok);
    CHECK(checker.next_row() == 0);
    CHECK(checker.write_rows(0, 2, kPixels, 4) == BandStatus::ok);
    CHECK(checker.end_frame() == BandStatus::ok);
}

TEST_CASE("BandSequenceChecker rejects begin_frame while a frame is open and keeps the open frame") {
    BandSequenceChecker checker;
    REQUIRE(checker.begin_frame(8, 10) == BandStatus::ok);
    REQUIRE(checker.write_rows(0, 2, kPixels, 8) == BandStatus::ok);
    CHECK(checker.begin_frame(4, 4) == BandStatus::frame_open);
    CHECK(checker.width() == 8);
    CHECK(checker.height() == 10);
    CHECK(checker.next_row() == 2);
}

TEST_CASE("send_frame_in_bands sends every row once, top to bottom, with the last band shorter") {
    const uint16_t width = 5;
    const uint16_t height = 11;
    const uint32_t stride = 7;  // two padding pixels per row that must not arrive
    std::vector<uint16_t> frame(stride * height, 0xDEAD);
    for (uint16_t y = 0; y < height; ++y) {
        for (uint16_t x = 0; x < width; ++x) frame[y * stride + x] = static_cast<uint16_t>(y * 100 + x);
    }
    RecordingSink rec;
    CHECK(hider::port::send_frame_in_bands(rec.sink(), frame.data(), width, height, stride, 4));
    CHECK(rec.begins == 1);
    CHECK(rec.ends == 1);
    REQUIRE(rec.bands.size() == 3);
    CHECK(rec.bands[0].y0 == 0);
    CHECK(rec.bands[0].rows == 4);
    CHECK(rec.bands[1].y0 == 4);
    CHECK(rec.bands[1].rows == 4);
    CHECK(rec.bands[2].y0 == 8);
    CHECK(rec.bands[2].rows == 3);
    std::vector<uint16_t> got;
    for (const auto& band : rec.bands) got.insert(got.end(), band.pixels.begin(), band.pixels.end());
    std::vector<uint16_t> want;
    for (uint16_t y = 0; y < height; ++y) {
        for (uint16_t x = 0; x < width; ++x) want.push_back(static_cast<uint16_t>(y * 100 + x));
    }
    CHECK(got == want);
}

TEST_CASE("send_frame_in_bands stops at the first refused band and still ends the frame") {
    std::vector<uint16_t> frame(4 * 9, 0);
    RecordingSink rec;
    rec.refuse_band = 1;
    CHECK_FALSE(hider::port::send_frame_in_bands(rec.sink(), frame.data(), 4, 9, 4, 3));
    CHECK(rec.bands.size() == 1);
    CHECK(rec.ends == 1);
}

TEST_CASE("send_frame_in_bands refuses an incomplete sink, null pixels or zero band height without calls") {
    std::vector<uint16_t> frame(4 * 4, 0);
    RecordingSink rec;
    BandSink partial = rec.sink();
    partial.end_frame = nullptr;
    CHECK_FALSE(hider::port::is_complete(partial));
    CHECK_FALSE(hider::port::send_frame_in_bands(partial, frame.data(), 4, 4, 4, 2));
    CHECK_FALSE(hider::port::send_frame_in_bands(rec.sink(), nullptr, 4, 4, 4, 2));
    CHECK_FALSE(hider::port::send_frame_in_bands(rec.sink(), frame.data(), 4, 4, 4, 0));
    CHECK(rec.begins == 0);
    SUBCASE("a sink that refuses the frame gets no rows and no end_frame") {
        CHECK_FALSE(hider::port::send_frame_in_bands(rec.sink(), frame.data(), 0, 4, 4, 2));
        CHECK(rec.begins == 1);
        CHECK(rec.bands.empty());
        CHECK(rec.ends == 0);
    }
}

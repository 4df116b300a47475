// The coverage bits of raster/coverage.hpp against a plain per-pixel reference: covered() on random
// rectangles over random partial coverage (every width class: one word column, two, many; short and
// odd row counts), and paint_span() writing exactly the pixels not covered yet.
#include <hider/raster/coverage.hpp>

#include <random>
#include <vector>

#include <doctest/doctest.h>

using namespace hider;

namespace {

/// One bool per pixel of the band: the independent reference.
struct Reference {
    int32_t width, y0, y1;
    std::vector<bool> set;
    bool at(int32_t x, int32_t y) const { return set[static_cast<size_t>((y - y0) * width + x)]; }
    bool covered(const PixelRect& r) const {
        for (int32_t y = r.y0; y < r.y1; ++y)
            for (int32_t x = r.x0; x < r.x1; ++x)
                if (!at(x, y)) return false;
        return true;
    }
};

/// A random rectangle inside the band, sometimes empty, biased towards small ones.
PixelRect random_rect(std::mt19937& rng, int32_t width, int32_t y0, int32_t y1) {
    auto pick = [&](int32_t lo, int32_t hi) { return std::uniform_int_distribution<int32_t>(lo, hi)(rng); };
    const int32_t x0 = pick(0, width - 1), y = pick(y0, y1 - 1);
    const int32_t wmax = pick(0, 3) == 0 ? width - x0 : std::min(width - x0, 40);
    const int32_t hmax = pick(0, 3) == 0 ? y1 - y : std::min(y1 - y, 9);
    return {x0, x0 + pick(0, wmax), y, y + pick(0, hmax)};
}

}  // namespace

TEST_CASE("Coverage::covered and paint_span agree with a per-pixel reference on random coverage") {
    const int32_t widths[] = {1, 31, 32, 33, 64, 100, 160, 320};
    for (uint32_t run = 0; run < 24; ++run) {
        const uint32_t seed = 1 + run;
        std::mt19937 rng(seed);
        const int32_t width = widths[run % 8];
        const int32_t y0 = static_cast<int32_t>(seed * 5), y1 = y0 + 1 + static_cast<int32_t>(seed * 7 % 23);
        INFO("width ", width, " rows ", y0, "..", y1);
        std::vector<uint32_t> words(static_cast<size_t>(coverage_words(width) * (y1 - y0)), 0xDEADBEEFu);
        Coverage cov;
        REQUIRE(cov.reset({words.data(), words.size()}, width, y0, y1));
        Reference ref{width, y0, y1, std::vector<bool>(static_cast<size_t>(width * (y1 - y0)), false)};
        std::vector<uint16_t> pixels(static_cast<size_t>(width * (y1 - y0)), 0);
        uint32_t answered_true = 0, answered_false = 0;
        for (int step = 0; step < 400 && !cov.full(); ++step) {
            for (int q = 0; q < 20; ++q) {
                const PixelRect r = random_rect(rng, width, y0, y1);
                const bool want = ref.covered(r);
                REQUIRE(cov.covered(r) == want);
                ++(want ? answered_true : answered_false);
            }
            // Paint one span: exactly the pixels not covered yet, each once.
            const PixelRect s = random_rect(rng, width, y0, y1);
            uint16_t* row = pixels.data() + static_cast<ptrdiff_t>((s.y0 - y0) * width);
            const uint16_t colour = static_cast<uint16_t>(step + 1);
            uint32_t expected = 0;
            for (int32_t x = s.x0; x < s.x1; ++x) expected += ref.at(x, s.y0) ? 0u : 1u;
            const uint32_t before = cov.remaining();
            const uint32_t written = cov.paint_span(row, s.y0, s.x0, s.x1, 0u, 0u,
                                                    [colour](uint32_t) { return colour; });
            REQUIRE(written == expected);
            REQUIRE(cov.remaining() == before - written);
            for (int32_t x = 0; x < width; ++x) {
                const bool inside = x >= s.x0 && x < s.x1;
                const size_t i = static_cast<size_t>((s.y0 - y0) * width + x);
                if (inside && !ref.set[i]) {
                    REQUIRE(row[x] == colour);
                    ref.set[i] = true;
                } else if (inside) {
                    REQUIRE(row[x] != colour);
                }
            }
        }
        // Both answers were exercised (the random spans fill the band gradually).
        CHECK(answered_true > 20);
        CHECK(answered_false > (width > 1 ? 20u : 0u));
        // Whatever is left, filling every row covers the band exactly.
        for (int32_t y = y0; y < y1; ++y)
            cov.paint_span(pixels.data() + static_cast<ptrdiff_t>((y - y0) * width), y, 0, width, 0u, 0u,
                           [](uint32_t) { return uint16_t{1}; });
        CHECK(cov.full());
        CHECK(cov.covered({0, width, y0, y1}));
    }
}

TEST_CASE("Coverage::reset refuses sizes out of range without overflowing on them") {
    // width + 31 and y1 - y0 overflowed int32 (UBSan) for the frame sizes draw_bsp_front() passes on
    // before it checks the frame (red-team pass over the public API).
    std::vector<uint32_t> words(64);
    Coverage cov;
    CHECK(cov.reset({words.data(), words.size()}, 64, 0, 32));
    CHECK_FALSE(cov.reset({words.data(), words.size()}, 64, 0, 33));
    CHECK_FALSE(cov.reset({words.data(), words.size()}, INT32_MAX, 0, 1));
    CHECK_FALSE(cov.reset({words.data(), words.size()}, 1025, 0, 1));
    CHECK_FALSE(cov.reset({words.data(), words.size()}, 1, INT32_MIN, 1));
    CHECK_FALSE(cov.reset({words.data(), words.size()}, 1, INT32_MIN, INT32_MAX));
    CHECK_FALSE(cov.reset({words.data(), words.size()}, 1, 0, 0));
    CHECK(cov.reset({words.data(), words.size()}, 1, -5, 59));  // rows count, not where they lie
    // The largest frame side is accepted in both directions.
    std::vector<uint32_t> big(static_cast<size_t>(coverage_words(kMaxFrameSide)) * kMaxFrameSide);
    CHECK(cov.reset({big.data(), big.size()}, kMaxFrameSide, 0, kMaxFrameSide));
    CHECK_FALSE(cov.reset({big.data(), big.size()}, kMaxFrameSide, 0, kMaxFrameSide + 1));
}

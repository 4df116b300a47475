// Pieces (raster/piece.hpp): narrow_to_cut(), the one-row form sort/pixel_order.hpp uses, against
// cut_keeps() at every pixel centre, and PieceRaster's stepped rows against the triangle's spans
// narrowed with it.
#include <hider/raster/piece.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include <doctest/doctest.h>

using namespace hider;

namespace {

/// A random cut line of a w x h frame (subpixel grid, within the coordinate limits): near the frame, one
/// end far away, horizontal, vertical, one subpixel of rise, or through pixel centres.
CutLine random_cut(std::mt19937& rng, int w, int h) {
    auto in = [&](int32_t lo, int32_t hi) { return std::uniform_int_distribution<int32_t>(lo, hi)(rng); };
    const int32_t rx = w * kSubpixel / 2 + 2 * kSubpixel, ry = h * kSubpixel / 2 + 2 * kSubpixel;
    CutLine c{};
    do {
        c.x0 = static_cast<int16_t>(in(-rx, rx));
        c.y0 = static_cast<int16_t>(in(-ry, ry));
        c.x1 = static_cast<int16_t>(in(-rx, rx));
        c.y1 = static_cast<int16_t>(in(-ry, ry));
        switch (in(0, 5)) {
            case 0: break;
            case 1:
                c.x1 = static_cast<int16_t>(in(-kCoordLimit, kCoordLimit));
                c.y1 = static_cast<int16_t>(in(-kCoordLimit, kCoordLimit));
                break;
            case 2: c.y1 = c.y0; break;
            case 3: c.x1 = c.x0; break;
            case 4: c.y1 = static_cast<int16_t>(c.y0 + (in(0, 1) ? 1 : -1)); break;
            default: {  // both ends on pixel centres
                const int32_t ox = pixel_centre_origin(w), oy = pixel_centre_origin(h);
                c.x0 = static_cast<int16_t>(ox + kSubpixel * in(-2, w + 1));
                c.y0 = static_cast<int16_t>(oy + kSubpixel * in(-2, h + 1));
                c.x1 = static_cast<int16_t>(ox + kSubpixel * in(-2, w + 1));
                c.y1 = static_cast<int16_t>(oy + kSubpixel * in(-2, h + 1));
            }
        }
    } while (c.x0 == c.x1 && c.y0 == c.y1);
    return c;
}

}  // namespace

TEST_CASE("narrow_to_cut() leaves of a row's span exactly the pixel centres cut_keeps() keeps") {
    static constexpr int kSizes[][2] = {{1, 1}, {2, 3}, {7, 5}, {16, 16}, {17, 9}, {64, 48}, {160, 128}, {321, 241}};
    long rows = 0, kept = 0, dropped = 0, wrong = 0, full = 0, empty = 0, keeps_line_cuts = 0;
    for (uint32_t seed = 1; seed <= 4000; ++seed) {
        std::mt19937 rng(seed * 2654435761u);
        const auto& size = kSizes[seed % 8];
        const int w = size[0], h = size[1];
        const int32_t ox = pixel_centre_origin(w), oy = pixel_centre_origin(h);
        const CutLine c = random_cut(rng, w, h);
        keeps_line_cuts += keeps_line(c);
        for (int y = 0; y < h; ++y) {
            // A span to narrow: the whole row, or a random part of it.
            int32_t lo0 = 0, hi0 = w;
            if (rng() % 2) {
                lo0 = static_cast<int32_t>(rng() % static_cast<uint32_t>(w + 1));
                hi0 = static_cast<int32_t>(rng() % static_cast<uint32_t>(w + 1));
            }
            int32_t lo = lo0, hi = hi0;
            narrow_to_cut(c, y, ox, oy, lo, hi);
            ++rows;
            long in_row = 0;
            for (int x = 0; x < w; ++x) {
                const bool expect = x >= lo0 && x < hi0 && cut_keeps(c, ox + x * kSubpixel, oy + y * kSubpixel);
                const bool got = x >= lo && x < hi;
                wrong += expect != got;
                kept += got;
                dropped += !got && x >= lo0 && x < hi0;
                in_row += expect;
            }
            full += lo0 == 0 && hi0 == w && in_row == w;
            empty += in_row == 0;
        }
    }
    MESSAGE("rows " << rows << ", centres kept " << kept << ", dropped " << dropped << ", wrong " << wrong);
    CHECK(wrong == 0);
    CHECK(rows > 100000);
    // Both sides and both tie rules were exercised, with rows kept whole and rows emptied.
    CHECK(kept > 1000000);
    CHECK(dropped > 1000000);
    CHECK(full > 1000);
    CHECK(empty > 1000);
    CHECK(keeps_line_cuts > 1000);
    CHECK(keeps_line_cuts < 3000);
}

TEST_CASE("PieceRaster's rows are the triangle's spans narrowed cut by cut with narrow_to_cut()") {
    long rows = 0, pixels = 0, wrong_rows = 0, pieces = 0, emptied = 0;
    for (uint32_t seed = 1; seed <= 6000; ++seed) {
        std::mt19937 rng(seed * 40503u + 7u);
        const int w = 1 + static_cast<int>(rng() % 80), h = 1 + static_cast<int>(rng() % 60);
        const int32_t ox = pixel_centre_origin(w), oy = pixel_centre_origin(h);
        auto vertex = [&]() {
            ScreenVertex v;
            v.x = static_cast<int16_t>(static_cast<int32_t>(rng() % static_cast<uint32_t>(w * kSubpixel + 64)) - w * kSubpixel / 2 - 32);
            v.y = static_cast<int16_t>(static_cast<int32_t>(rng() % static_cast<uint32_t>(h * kSubpixel + 64)) - h * kSubpixel / 2 - 32);
            v.z = 1000;
            return v;
        };
        const ScreenVertex a = vertex(), b = vertex(), c = vertex();
        CutLine cuts[4];
        const int n = 1 + static_cast<int>(rng() % 4);
        for (int i = 0; i < n; ++i) cuts[i] = random_cut(rng, w, h);
        TriangleRaster tr;
        PieceRaster pr;
        const bool tri_ok = tr.setup(a, b, c, w, h);
        const bool piece_ok = pr.setup(a, b, c, {cuts, static_cast<size_t>(n)}, w, h);
        if (!tri_ok) {
            CHECK_FALSE(piece_ok);
            continue;
        }
        // Reference rows: the triangle's spans, each narrowed by every cut.
        std::vector<int32_t> ref_lo(static_cast<size_t>(h), 0), ref_hi(static_cast<size_t>(h), 0);
        long ref_pixels = 0;
        tr.spans(0, h, [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
            int32_t lo = x0, hi = x1;
            for (int i = 0; i < n; ++i) narrow_to_cut(cuts[i], y, ox, oy, lo, hi);
            ref_lo[static_cast<size_t>(y)] = lo;
            ref_hi[static_cast<size_t>(y)] = max(lo, hi);
            ref_pixels += max(0, hi - lo);
        });
        if (!piece_ok) {  // horizontal cuts left no row (setup() says so): nothing to draw
            CHECK(ref_pixels == 0);
            ++emptied;
            continue;
        }
        ++pieces;
        std::vector<int32_t> got_lo(static_cast<size_t>(h), 0), got_hi(static_cast<size_t>(h), 0);
        const auto record = [&](int32_t y, int32_t x0, int32_t x1, uint32_t) {
            got_lo[static_cast<size_t>(y)] = x0;
            got_hi[static_cast<size_t>(y)] = x1;
        };
        pr.spans(0, h, record);  // an lvalue functor (spans() takes Fn&&)
        for (size_t y = 0; y < static_cast<size_t>(h); ++y) {
            const bool ref_empty = ref_lo[y] >= ref_hi[y], got_empty = got_lo[y] >= got_hi[y];
            ++rows;
            pixels += got_empty ? 0 : got_hi[y] - got_lo[y];
            wrong_rows += ref_empty != got_empty || (!ref_empty && (ref_lo[y] != got_lo[y] || ref_hi[y] != got_hi[y]));
        }
    }
    MESSAGE("pieces " << pieces << " (and " << emptied << " left no row), rows " << rows << ", pixels " << pixels << ", rows that differ "
                       << wrong_rows);
    CHECK(wrong_rows == 0);
    CHECK(pieces > 4000);
    CHECK(emptied > 100);
    CHECK(pixels > 100000);
}

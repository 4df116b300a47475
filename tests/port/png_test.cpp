// port/host/png.*: the PNG writer, decoded by an independent reader written here (chunk lengths and
// CRCs, IDAT concatenation, zlib header, stored deflate blocks with their complements, Adler-32, filter
// bytes), on odd sizes, on rows that cross the 65,535-byte block boundary, and with IDAT split in small
// chunks (the 2^31 - 1 limit of a chunk, at a testable size). Also the size checks of both writers.
#include "host/png.hpp"
#include "host/ppm.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

uint32_t read32(const std::vector<uint8_t>& b, size_t at) {
    return uint32_t{b[at]} << 24 | uint32_t{b[at + 1]} << 16 | uint32_t{b[at + 2]} << 8 | b[at + 3];
}

// CRC-32 (ISO 3309, reflected 0xEDB88320) from its table, not the writer's bitwise loop.
uint32_t crc_of(const uint8_t* p, size_t n) {
    static uint32_t table[256];
    static bool made = false;
    if (!made) {
        for (uint32_t i = 0; i < 256; ++i) {
            uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
        made = true;
    }
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; ++i) c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

struct Decoded {
    bool ok = false;
    std::string why;
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;
    int idat_chunks = 0;
    size_t largest_idat = 0;
};

Decoded decode(const std::vector<uint8_t>& png) {
    Decoded d;
    auto fail = [&d](const std::string& why) {
        d.why = why;
        return d;
    };
    const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (png.size() < 8 || !std::equal(signature, signature + 8, png.begin())) return fail("signature");
    std::vector<uint8_t> z;
    bool ihdr = false, iend = false;
    for (size_t at = 8; at < png.size();) {
        if (iend) return fail("bytes after IEND");
        if (png.size() - at < 12) return fail("truncated chunk");
        const uint32_t n = read32(png, at);
        if (n > 0x7FFFFFFFu || png.size() - at - 12 < n) return fail("chunk length");
        const std::string type(png.begin() + static_cast<long>(at + 4), png.begin() + static_cast<long>(at + 8));
        if (crc_of(png.data() + at + 4, n + 4) != read32(png, at + 8 + n)) return fail("CRC of " + type);
        const uint8_t* body = png.data() + at + 8;
        if (type == "IHDR") {
            if (ihdr || n != 13) return fail("IHDR");
            ihdr = true;
            d.width = static_cast<int>(read32(png, at + 8));
            d.height = static_cast<int>(read32(png, at + 12));
            if (body[8] != 8 || body[9] != 2 || body[10] != 0 || body[11] != 0 || body[12] != 0) return fail("IHDR format");
        } else if (type == "IDAT") {
            if (!ihdr) return fail("IDAT before IHDR");
            z.insert(z.end(), body, body + n);
            ++d.idat_chunks;
            d.largest_idat = std::max<size_t>(d.largest_idat, n);
        } else if (type == "IEND") {
            if (n != 0) return fail("IEND length");
            iend = true;
        } else {
            return fail("unexpected chunk " + type);
        }
        at += 12 + n;
    }
    if (!iend) return fail("no IEND");
    if (z.size() < 6 || z[0] != 0x78 || (z[0] * 256 + z[1]) % 31 != 0 || (z[1] & 0x20)) return fail("zlib header");
    std::vector<uint8_t> raw;
    size_t at = 2;
    for (bool last = false; !last;) {
        if (z.size() - at < 5) return fail("truncated deflate block");
        if (z[at] & 0x06) return fail("not a stored block");
        last = z[at] & 1;
        const unsigned len = z[at + 1] | z[at + 2] << 8, nlen = z[at + 3] | z[at + 4] << 8;
        if ((len ^ 0xFFFFu) != nlen) return fail("stored block length complement");
        at += 5;
        if (z.size() - at < len) return fail("stored block past the data");
        raw.insert(raw.end(), z.begin() + static_cast<long>(at), z.begin() + static_cast<long>(at + len));
        at += len;
    }
    if (z.size() - at != 4) return fail("Adler-32 missing or trailing data");
    uint32_t a = 1, b = 0;
    for (uint8_t c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    if ((b << 16 | a) != read32(z, at)) return fail("Adler-32");
    const size_t row = static_cast<size_t>(d.width) * 3;
    if (raw.size() != (row + 1) * static_cast<size_t>(d.height)) return fail("image data size");
    for (int y = 0; y < d.height; ++y) {
        const size_t start = static_cast<size_t>(y) * (row + 1);
        if (raw[start] != 0) return fail("filter type");
        d.rgb.insert(d.rgb.end(), raw.begin() + static_cast<long>(start + 1), raw.begin() + static_cast<long>(start + 1 + row));
    }
    d.ok = true;
    return d;
}

std::vector<uint8_t> pattern(int width, int height, uint32_t seed) {
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
    uint32_t s = seed;
    for (uint8_t& v : rgb) {
        s = s * 1664525u + 1013904223u;
        v = static_cast<uint8_t>(s >> 24);
    }
    return rgb;
}

}  // namespace

TEST_CASE("png_bytes decodes to its pixels: odd sizes, rows across the 65,535-byte deflate blocks") {
    // 21845 x 2: a row of 65,535 bytes plus its filter byte; 1 x 65535; 1024 x 1024 (the tools' largest).
    const int sizes[][2] = {{1, 1}, {2, 1}, {1, 3}, {7, 5}, {320, 240}, {21845, 2}, {21846, 1}, {1, 65535}, {1024, 1024}};
    uint32_t seed = 1;
    for (const auto& size : sizes) {
        const std::vector<uint8_t> rgb = pattern(size[0], size[1], seed++);
        const Decoded d = decode(hider::port::png_bytes(size[0], size[1], rgb));
        INFO(size[0], "x", size[1], ": ", d.why);
        REQUIRE(d.ok);
        CHECK(d.width == size[0]);
        CHECK(d.height == size[1]);
        CHECK(d.rgb == rgb);
        CHECK(d.idat_chunks == 1);  // everything below 2^31 - 1 bytes stays one chunk
    }
}

TEST_CASE("the image data is split into IDAT chunks of at most the limit, and decodes the same") {
    const std::vector<uint8_t> rgb = pattern(97, 61, 7);
    const std::vector<uint8_t> whole = hider::port::png_bytes(97, 61, rgb);
    for (const size_t limit : {size_t{1}, size_t{1000}, size_t{4096}, size_t{17770}, size_t{17771}}) {
        const Decoded d = decode(hider::port::detail::png_bytes(97, 61, rgb, limit));
        INFO("limit ", limit, ": ", d.why);
        REQUIRE(d.ok);
        CHECK(d.rgb == rgb);
        CHECK(d.largest_idat <= limit);
        CHECK(d.idat_chunks == static_cast<int>((decode(whole).largest_idat + limit - 1) / limit));
    }
    CHECK(hider::port::detail::png_bytes(97, 61, rgb, hider::port::kPngMaxChunk) == whole);
    CHECK(hider::port::detail::png_bytes(97, 61, rgb, 0).empty());
}

TEST_CASE("the PNG and PPM writers refuse sizes that do not match the pixels, also where W x H x 3 wraps") {
    const std::vector<uint8_t> rgb = pattern(4, 3, 3);
    CHECK(hider::port::rgb_size_ok(4, 3, rgb.size()));
    CHECK_FALSE(hider::port::rgb_size_ok(4, 3, rgb.size() - 1));
    CHECK_FALSE(hider::port::rgb_size_ok(0, 3, 0));
    CHECK_FALSE(hider::port::rgb_size_ok(-4, -3, 36));
    // 65536 x 21846 x 3 = 2^32 + 131072: a 32-bit size_t product would wrap to 131072.
    CHECK_FALSE(hider::port::rgb_size_ok(65536, 21846, 131072));
    CHECK_FALSE(hider::port::rgb_size_ok(0x7FFFFFFF, 0x7FFFFFFF, 36));
    CHECK(hider::port::png_bytes(4, 4, rgb).empty());
    std::string error;
    const std::string path = "png_test_refused.png";
    std::remove(path.c_str());
    CHECK_FALSE(hider::port::write_png(path, 4, 4, rgb, error));
    CHECK(error.find("does not match") != std::string::npos);
    CHECK_FALSE(hider::port::write_ppm("png_test_refused.ppm", 65536, 21846, std::vector<uint8_t>(131072), error));
    std::FILE* f = std::fopen(path.c_str(), "rb");
    CHECK(f == nullptr);
    if (f != nullptr) std::fclose(f);
}

TEST_CASE("read_ppm reads what write_ppm wrote, and refuses a file shorter than its header claims") {
    const std::vector<uint8_t> rgb = pattern(5, 3, 7);
    std::string error;
    const std::string path = "png_test_roundtrip.ppm";
    REQUIRE(hider::port::write_ppm(path, 5, 3, rgb, error));
    int w = 0, h = 0;
    std::vector<uint8_t> back;
    CHECK(hider::port::read_ppm(path, w, h, back));
    CHECK(w == 5);
    CHECK(h == 3);
    CHECK(back == rgb);
    // A header claiming 16384 x 16384 (805 MB) over 3 bytes: refused before the pixels are allocated.
    const std::string short_path = "png_test_short.ppm";
    REQUIRE(hider::port::write_file(short_path, std::string("P6\n16384 16384\n255\n") + "abc", error));
    back.clear();
    CHECK_FALSE(hider::port::read_ppm(short_path, w, h, back));
    CHECK(back.empty());
    // One byte short of a 5 x 3 image.
    std::string bytes = "P6\n5 3\n255\n";
    bytes.append(rgb.begin(), rgb.end() - 1);
    REQUIRE(hider::port::write_file(short_path, bytes, error));
    CHECK_FALSE(hider::port::read_ppm(short_path, w, h, back));
}

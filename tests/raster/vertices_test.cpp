// The projection's fast path for targets with a 32-bit divide (project_common, ratio_q31) against
// outcode() and project(), on random views and view points: every point it accepts must give exactly
// project()'s vertex, and it must accept every point inside the view volume with w < 2^30. And the
// range every projected vertex keeps (screen_vertex_valid()), which the draw calls assert of theirs
// (zbuffer_test.cpp, binned_test.cpp, sort_test.cpp).
#include <doctest/doctest.h>

#include <hider/raster/vertices.hpp>

#include <random>
#include <vector>

namespace hider {
namespace {

TEST_CASE("leading_zeros_smeared is clz32") {
    for (int b = 0; b < 32; ++b)
        for (uint32_t low : {0u, 1u, 0x55555555u, 0xFFFFFFFFu}) {
            const uint32_t v = (uint32_t{1} << b) | (low & ((uint32_t{1} << b) - 1));
            CHECK(detail::leading_zeros_smeared(v) == clz32(v));
            CHECK(detail::leading_zeros(v) == clz32(v));
        }
}

TEST_CASE("ratio_q31 is floor(n 2^31 / w) for every n < w") {
    std::mt19937_64 rng(31);
    auto check = [](uint32_t n, uint32_t w) {
        uint32_t r = 0;
        const uint32_t want = udiv64_32(uint64_t{n} << 31, w, r);
        const uint32_t got = detail::ratio_q31(n, w, clz32(w));
        if (got != want) {
            FAIL_CHECK("ratio_q31(" << n << ", " << w << ") = " << got << ", want " << want);
            return false;
        }
        return true;
    };
    const uint32_t edges[] = {1u, 2u, 3u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFFu};
    for (uint32_t w : edges)
        for (uint32_t n : {1u, 2u, w / 2, w - 2, w - 1})
            if (n > 0 && n < w) check(n, w);
    for (int i = 0; i < 400000; ++i) {
        const uint32_t w = static_cast<uint32_t>(rng() >> (rng() % 63)) | 2u;
        uint32_t n = static_cast<uint32_t>(rng() % w);
        if (i % 4 == 0) n = w - 1 - static_cast<uint32_t>(rng() % 8 % w);  // quotients near 2^31
        if (n == 0) n = 1;
        if (n >= w) continue;
        if (!check(n, w)) break;
    }
    // A normalised divisor and an odd n: the only case where the low half-digit of n 2^31 decides the
    // first quotient digit's correction (about one in 100,000).
    for (int i = 0; i < 1000000; ++i) {
        const uint32_t w = static_cast<uint32_t>(rng()) | 0x80000000u;
        const uint32_t n = static_cast<uint32_t>(rng() % w) | 1u;
        if (n < w && !check(n, w)) break;
    }
}

TEST_CASE("project_common gives project()'s vertex for every point inside the view volume") {
    std::mt19937_64 rng(2024);
    int accepted = 0, refused_inside = 0, failures = 0;
    for (int v = 0; v < 300 && failures < 5; ++v) {
        Camera cam;
        cam.eye = {Q16::from_raw(0), Q16::from_raw(0), Q16::from_raw(static_cast<int32_t>(rng() % (1u << 28)) + 65536)};
        cam.target = {Q16::from_raw(0), Q16::from_raw(0), Q16::from_raw(0)};
        cam.up = {Q16::from_raw(0), Q16::from_raw(65536), Q16::from_raw(0)};
        cam.fovy = Angle::from_bam(0x01000000u + static_cast<uint32_t>(rng() % 0x70000000u));
        // near from 1/256 unit up; far up to past 2^30 (the fast path's limit) now and then
        const int32_t near = kMinNearRaw + static_cast<int32_t>(rng() >> (rng() % 64) & 0x3FFFFFF);
        const int64_t far = near + 1 + static_cast<int64_t>(rng() >> (rng() % 64) % 0x7FFFFFFFull);
        cam.near = Q16::from_raw(near);
        cam.far = Q16::from_raw(static_cast<int32_t>(far > INT32_MAX ? INT32_MAX : far));
        const int32_t width = 1 + static_cast<int32_t>(rng() % 640), height = 1 + static_cast<int32_t>(rng() % 480);
        View view;
        if (make_view(cam, width, height, view) != Status::ok) continue;
        for (int i = 0; i < 4000; ++i) {
            ViewPoint p{};
            // w: around near and far, small, large, or anywhere between
            switch (rng() % 6) {
                case 0: p.w = view.near_raw + static_cast<int32_t>(rng() % 5) - 2; break;
                case 1: {  // far + 2 may pass INT32_MAX: clamped in 64 bits (ASan/UBSan build)
                    const int64_t w = int64_t{view.far_raw} - static_cast<int64_t>(rng() % 5) + 2;
                    p.w = static_cast<int32_t>(w > INT32_MAX ? INT32_MAX : w);
                    break;
                }
                case 2: p.w = static_cast<int32_t>(rng() % 0x20000u); break;
                case 3: p.w = (int32_t{1} << 30) + static_cast<int32_t>(rng() % 5) - 2; break;
                default: p.w = view.near_raw + static_cast<int32_t>(rng() % static_cast<uint32_t>(view.far_raw - view.near_raw + 1));
            }
            if (p.w < 1) p.w = 1;
            // x, y: screen positions up to a little past the guard band, as view-space numerators
            auto coord = [&]() {
                const int64_t screen = static_cast<int64_t>(rng() % (2 * (kGuardBand + 40) + 1)) - (kGuardBand + 40);
                int64_t c = screen * 256 * p.w / view.k_q8 + static_cast<int64_t>(rng() % 7) - 3;
                if (rng() % 8 == 0) c = static_cast<int64_t>(rng() % 2001) - 1000;
                return static_cast<int32_t>(c > INT32_MAX ? INT32_MAX : (c < INT32_MIN ? INT32_MIN : c));
            };
            p.x = coord();
            p.y = coord();
            const bool inside = outcode(view, p) == 0;
            ScreenVertex fast;
            fast.x = 0x5555;
            const bool took = detail::project_common(view, p, fast);
            if (took) {
                ++accepted;
                const ScreenVertex want = project(view, p);
                if (!inside || fast.x != want.x || fast.y != want.y || fast.z != want.z) {
                    ++failures;
                    FAIL_CHECK("view " << v << " point (" << p.x << ", " << p.y << ", " << p.w << "): inside " << inside
                                       << ", fast (" << fast.x << ", " << fast.y << ", " << fast.z << "), project() ("
                                       << want.x << ", " << want.y << ", " << want.z << ")");
                }
            } else {
                CHECK(fast.x == 0x5555);  // untouched
                if (inside && p.w < (int32_t{1} << 30)) ++refused_inside;
            }
        }
    }
    CHECK(refused_inside == 0);
    CHECK(accepted > 100000);
    MESSAGE("accepted " << accepted);
}

TEST_CASE("project_vertices() gives only vertices screen_vertex_valid() accepts; hand-made ones past the limits fail it") {
    std::mt19937_64 rng(77);
    std::vector<Vec3q16> positions(2000);
    std::vector<ScreenVertex> out(positions.size());
    size_t outside = 0, inside = 0;
    for (int v = 0; v < 60; ++v) {
        Camera cam;
        cam.eye = {Q16::from_int(0), Q16::from_int(0), Q16::from_int(1 + static_cast<int32_t>(rng() % 40))};
        cam.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
        cam.fovy = Angle::from_bam(0x01000000u + static_cast<uint32_t>(rng() % 0x70000000u));
        cam.near = Q16::from_raw(kMinNearRaw + static_cast<int32_t>(rng() % 65536));
        cam.far = Q16::from_int(20 + static_cast<int32_t>(rng() % 100));
        View view;
        REQUIRE(make_view(cam, 1 + static_cast<int32_t>(rng() % 640), 1 + static_cast<int32_t>(rng() % 480), view) ==
                Status::ok);
        for (Vec3q16& p : positions)  // around the view volume: behind the eye, past the far plane, off the sides
            p = {Q16::from_raw(static_cast<int32_t>(rng() % (160u << 16)) - (80 << 16)),
                 Q16::from_raw(static_cast<int32_t>(rng() % (160u << 16)) - (80 << 16)),
                 Q16::from_raw(static_cast<int32_t>(rng() % (200u << 16)) - (150 << 16))};
        REQUIRE(project_vertices(view, {positions.data(), positions.size()}, {out.data(), out.size()}) == Status::ok);
        for (const ScreenVertex& sv : out) (sv.z == 0 ? outside : inside) += 1;
        CHECK(screen_vertices_valid(out.data(), out.size()));
    }
    CHECK(outside > 1000);
    CHECK(inside > 1000);
    auto vertex = [](int32_t x, int32_t y, uint32_t z) {
        ScreenVertex sv;
        sv.x = static_cast<int16_t>(x);
        sv.y = static_cast<int16_t>(y);
        sv.z = z;
        return sv;
    };
    CHECK(screen_vertex_valid(vertex(kCoordLimit, -kCoordLimit, kDepthNear)));
    CHECK(screen_vertex_valid(vertex(-kCoordLimit, kCoordLimit, kDepthFar)));
    CHECK(screen_vertex_valid(vertex(kClipNear, 0, 0)));  // outside a clip plane: x holds the planes
    CHECK(screen_vertex_valid(vertex(0x3F, 0, 0)));
    // z == 0 with no plane in x's low byte counts as drawable: its x and y are then read.
    CHECK_FALSE(screen_vertex_valid(vertex(0, 0, 0)));
    CHECK_FALSE(screen_vertex_valid(vertex(-32768, 32767, 0)));
    CHECK_FALSE(screen_vertex_valid(vertex(256, 32767, 0)));
    CHECK_FALSE(screen_vertex_valid(vertex(kCoordLimit + 1, 0, kDepthNear)));
    CHECK_FALSE(screen_vertex_valid(vertex(0, -kCoordLimit - 1, kDepthNear)));
    CHECK_FALSE(screen_vertex_valid(vertex(-32768, -32768, 1u << 30)));
    CHECK_FALSE(screen_vertex_valid(vertex(0, 0, kDepthNear - 1)));
    CHECK_FALSE(screen_vertex_valid(vertex(0, 0, kDepthFar + 1)));
    ScreenVertex three[3] = {vertex(0, 0, kDepthNear), vertex(1, 1, kDepthFar), vertex(kClipNear, 0, 0)};
    CHECK(screen_vertices_valid(three, 3));
    three[1].x = kCoordLimit + 1;
    CHECK_FALSE(screen_vertices_valid(three, 3));
    CHECK(screen_vertices_valid(three, 1));  // only the first n
}

}  // namespace
}  // namespace hider

// Random triangle set-ups shared by the kernelcheck firmware and its host twin: each case is a band of a
// frame (random size, rows and stride) and three vertices (tiny to huge, inside and past the frame, flat
// and steep depth, some on the first or last column centre, some spanning the whole guard band in y),
// set up through `setup` (kernel_setup() on the chip, kernel_setup_portable() on the host). setup_digest() folds the outcome and every field the row kernel will read into one 32-bit
// digest per case.
#pragma once
#include <hider/raster/kernel_triangle.hpp>
#include <hider/raster/triangle.hpp>

#include "kernelcheck/cases.hpp"

namespace kernelcheck {

constexpr int kSetupCases = 1000;
constexpr uint32_t kSetupSeed = 0x2545F491u;

/// One set-up: its band and vertices.
struct SetupCase {
    hider::KernelBand band;
    hider::ScreenVertex v[3];
    int32_t area;
};

/// The next case; its area is never 0. Three in four lie inside the frame's columns (the set-up's own
/// work), the rest reach past them or miss the band.
inline SetupCase make_setup_case(Rng& rng) {
    SetupCase c{};
    for (;;) {
        const int32_t width = rng.range(1, 400), height = rng.range(1, 300);
        const int32_t r0 = rng.range(0, height - 1), r1 = rng.range(r0 + 1, height);
        c.band = hider::kernel_band(width, height, r0, r1, 2 * width + 2 * rng.range(0, 3));
        const hider::KernelBand& b = c.band;
        const bool inside = (rng.next() & 3u) != 0;
        // Sizes from a fraction of a pixel to the whole frame (areas past 0xFFFF take the long division).
        int32_t size = rng.range(1, (rng.next() & 1u) != 0 ? 48 : 8 * (width + height));
        int32_t cx = 0;
        if (inside) {
            size = hider::min(size, (b.x_last - b.x_origin) / 2);
            cx = rng.range(b.x_origin + size, b.x_last - size);
        } else {
            cx = rng.range(-hider::kCoordLimit / 2, hider::kCoordLimit / 2);
        }
        const int32_t cy = rng.range(b.y_first - 16 * 8, b.y_last + 16 * 8);
        const uint32_t z0 = hider::kDepthNear + (rng.next() >> 1);
        for (hider::ScreenVertex& v : c.v) {
            v.x = static_cast<int16_t>(hider::clamp(cx + rng.range(-size, size), -hider::kCoordLimit, hider::kCoordLimit));
            v.y = static_cast<int16_t>(hider::clamp(cy + rng.range(-4 * size, 4 * size), -hider::kCoordLimit,
                                                    hider::kCoordLimit));
            switch (rng.next() & 3u) {  // near depths, the whole range (steep planes), or one depth (flat)
                case 0: v.z = z0 + (rng.next() >> 12); break;
                case 1: v.z = hider::kDepthNear + rng.next() % (hider::kDepthFar - hider::kDepthNear); break;
                default: v.z = z0; break;
            }
        }
        // Edge cases: a vertex exactly on the first or last column centre; a triangle reaching far past
        // the band above and below (depth differences over y spans near 2^15).
        const uint32_t extra = rng.next();
        if ((extra & 7u) == 0) {
            hider::ScreenVertex& v = c.v[(extra >> 3) % 3];
            v.x = static_cast<int16_t>((extra & 0x100u) != 0 ? b.x_origin : b.x_last);
        }
        if (((extra >> 9) & 7u) == 0) {
            c.v[(extra >> 12) % 3].y = static_cast<int16_t>(-hider::kCoordLimit + static_cast<int32_t>((extra >> 16) & 0xFF));
            c.v[(extra >> 14) % 3].y = static_cast<int16_t>(hider::kCoordLimit - static_cast<int32_t>((extra >> 24) & 0xFF));
        }
        c.area = hider::TriangleRaster::signed_area(c.v[0], c.v[1], c.v[2]);
        if (c.area != 0) return c;
    }
}

/// FNV-1a of a set-up's outcome and the fields the kernel reads (those the outcome defines).
inline uint32_t setup_digest(hider::KernelSetup s, const hider::KernelTriangle& t) {
    Fnv fnv;
    fnv.add(static_cast<uint32_t>(s));
    if (s != hider::KernelSetup::kernel) return fnv.h;
    const int32_t rows[] = {t.top, t.row, t.mid, t.end};
    for (int32_t r : rows) fnv.add(static_cast<uint32_t>(r));
    if (t.row >= t.end) return fnv.h;
    const hider::RowKernel& k = t.k;
    const uint32_t fields[] = {static_cast<uint32_t>(k.lx),    static_cast<uint32_t>(k.lg), k.lz,
                               static_cast<uint32_t>(k.rx),    static_cast<uint32_t>(k.rg), static_cast<uint32_t>(k.la),
                               static_cast<uint32_t>(k.lm),    static_cast<uint32_t>(k.lstep), k.ldz,
                               static_cast<uint32_t>(k.ra),    static_cast<uint32_t>(k.rm), static_cast<uint32_t>(k.rstep),
                               k.dzdx, t.next_left ? 1u : 0u};
    for (uint32_t f : fields) fnv.add(f);
    if (t.row < t.mid && t.mid < t.end) {  // the lower short edge takes over inside the rows
        const uint32_t next[] = {static_cast<uint32_t>(t.next_x), static_cast<uint32_t>(t.next_g),
                                 static_cast<uint32_t>(t.next_a), static_cast<uint32_t>(t.next_m),
                                 static_cast<uint32_t>(t.next_step)};
        for (uint32_t f : next) fnv.add(f);
    }
    return fnv.h;
}

/// Digest of every set-up case through `setup` (a function of (a, b, c, KernelSetupIo&) returning a
/// KernelSetup) into out[kSetupCases], each case also through `twin`; returns the first case whose
/// digests differ, or -1.
template <class Setup, class Twin>
int run_setup_cases(Setup&& setup, Twin&& twin, uint32_t* out) {
    Rng rng{kSetupSeed};
    int first_difference = -1;
    for (int i = 0; i < kSetupCases; ++i) {
        const SetupCase c = make_setup_case(rng);
        hider::KernelTriangle t{};
        hider::KernelSetupIo io{&c.band, c.area, &t};
        out[i] = setup_digest(setup(c.v[0], c.v[1], c.v[2], io), t);
        hider::KernelTriangle u{};
        io.out = &u;
        if (setup_digest(twin(c.v[0], c.v[1], c.v[2], io), u) != out[i] && first_difference < 0) first_difference = i;
    }
    return first_difference;
}

constexpr int kDivrCases = 200000;

/// The set-up's rounded quotient (n / d rounded half away from zero, |result| < 2^31) against
/// div_round(): random numerators and divisors of every size, and ones built as q d + r with q's 16-bit
/// digits and r at their edges and divisors whose low half is near 0 or 0xFFFF, where the long
/// division's digit estimates need their corrections. `divr` is (lo, hi, d) -> the quotient, or
/// INT32_MIN when it says the quotient is 2^31 or more. Returns the first case that differs, or -1.
template <class Divr>
int run_divr_cases(Divr&& divr) {
    Rng rng{0xD1A5C0DEu};
    for (int i = 0; i < kDivrCases; ++i) {
        uint32_t d = rng.next() >> (rng.next() % 32);
        if (d == 0) d = 1;
        if ((i & 3) == 1) d = (d | 0x80000000u) >> (rng.next() % 16);                       // a full top half
        if ((i & 3) == 2) {  // a low half near 0 or 0xFFFF
            const uint32_t low = rng.next() % 3 == 0 ? 0xFFFFu : rng.next() % 4;
            d = ((rng.next() | 0x8000u) << 16 | low) >> (rng.next() % 16);
        }
        if (d == 0) d = 1;
        uint64_t q = (uint64_t{rng.next()} << 32 | rng.next()) >> (33 + rng.next() % 32);  // below 2^31
        if ((i & 7) >= 4) {                                                                 // digits at their edges
            const uint32_t edges[] = {0u, 1u, 0x7FFEu, 0x7FFFu, 0xFFFEu, 0xFFFFu};
            q = uint64_t{edges[rng.next() % 6] & 0x7FFFu} << 16 | edges[rng.next() % 6];
        }
        uint64_t r = rng.next() % d;
        if ((i & 1) != 0) r = (rng.next() & 1u) != 0 ? d - 1 : d / 2;
        const uint64_t m = q * d + r;
        const int64_t n = (rng.next() & 1u) != 0 ? -static_cast<int64_t>(m) : static_cast<int64_t>(m);
        const int64_t want = hider::div_round(n, static_cast<int64_t>(d));
        const uint64_t un = static_cast<uint64_t>(n);
        const int32_t got = divr(static_cast<uint32_t>(un), static_cast<uint32_t>(un >> 32), d);
        if (want >= 2147483648 || want <= -2147483648) {
            if (got != INT32_MIN) return i;
        } else if (got != want) {
            return i;
        }
    }
    return -1;
}

/// Digest of both buffers of `b`.
inline uint32_t buffers_digest(const Buffers& b) {
    Fnv fnv;
    for (int32_t i = 0; i < kMaxRows * kWidth; ++i) fnv.add(b.depth[i] | uint32_t{b.color[i]} << 16);
    return fnv.h;
}

constexpr int kSteepCases = 8;

/// Directed set-ups whose depth step rounds to 2^31 or more (generic, the set-up's exit for a plane
/// quotient too large), which random vertices reach only by chance: in a 32 x 8 frame, a triangle one
/// subpixel wide through a column centre (a step in x) or one subpixel tall through a row centre (a step
/// in y), with its depth going from near to far across that subpixel; case i picks the axis (bit 0), the
/// vertex order, so the sign of the area (bit 1), and which end is far (bit 2).
inline SetupCase make_steep_case(int i) {
    SetupCase c{};
    c.band = hider::kernel_band(32, 8, 0, 8, 64);
    const int32_t x = c.band.x_origin + 5 * hider::kSubpixel, y = c.band.y_origin + 2 * hider::kSubpixel;
    const bool in_x = (i & 1) == 0;
    const uint32_t near = hider::kDepthNear, far = hider::kDepthFar;
    const uint32_t z0 = (i & 4) != 0 ? far : near, z1 = (i & 4) != 0 ? near : far;
    hider::ScreenVertex v[3];
    v[0] = {static_cast<int16_t>(x), static_cast<int16_t>(y), z0};
    v[1] = in_x ? hider::ScreenVertex{static_cast<int16_t>(x + 1), static_cast<int16_t>(y), z1}
                : hider::ScreenVertex{static_cast<int16_t>(x), static_cast<int16_t>(y + 1), z1};
    v[2] = in_x ? hider::ScreenVertex{static_cast<int16_t>(x), static_cast<int16_t>(y + 3 * hider::kSubpixel), z0}
                : hider::ScreenVertex{static_cast<int16_t>(x + 3 * hider::kSubpixel), static_cast<int16_t>(y), z0};
    const int order = (i & 2) != 0 ? 1 : 0;
    c.v[0] = v[0];
    c.v[1] = v[1 + order];
    c.v[2] = v[2 - order];
    c.area = hider::TriangleRaster::signed_area(c.v[0], c.v[1], c.v[2]);
    return c;
}

/// A set-up that also draws (kernel_draw_v7m() on ARMv7-M) against kernel_setup_portable() and then
/// run_kernel_triangle_portable(): set-up cases of frames at most kWidth wide, whose band stops from a row
/// above the first one to kMaxRows rows below it (so that the middle row falls before, on and after the
/// stop), drawn into `b` (random contents, the first row to draw on its first row), the first
/// kSteepCases of them make_steep_case()'s: same outcome, record
/// (setup_digest() of the state left) and buffers. `draw` is (a, b, c, io) -> KernelSetup with io.out's
/// colour set. Returns the first case that differs, or -1.
template <class Draw>
int run_setup_draw_cases(Draw&& draw, Buffers& b) {
    Rng rng{kSetupSeed ^ 0x9E3779B9u};
    for (int i = 0; i < kSetupCases; ++i) {
        SetupCase c{};
        if (i < kSteepCases) {
            c = make_steep_case(i);
        } else {
            do c = make_setup_case(rng);
            while ((c.band.x_last - c.band.x_origin) / hider::kSubpixel + 1 > kWidth);
        }
        hider::KernelBand& band = c.band;
        band.stride_bytes = kWidth * 2;
        hider::KernelTriangle u{};
        u.k.color = rng.next() & 0xFFFFu;
        hider::KernelTriangle t = u;
        const hider::KernelSetup su = hider::kernel_setup_portable(c.v[0], c.v[1], c.v[2], c.area, band, u);
        const int32_t first = su == hider::KernelSetup::kernel ? u.row : band.row_from;
        band.stop = rng.range(first - 1, first + kMaxRows);
        band.depth_origin = reinterpret_cast<uintptr_t>(b.depth) - static_cast<uintptr_t>(first) * (kWidth * 2);
        const uintptr_t color_bytes = reinterpret_cast<uintptr_t>(b.color) - reinterpret_cast<uintptr_t>(b.depth);
        band.color_less_2 = static_cast<intptr_t>(color_bytes) - 2;
        const uint32_t seed = rng.next();
        auto fill = [&] {
            Rng r{seed | 1u};
            for (int32_t k = 0; k < kMaxRows * kWidth; ++k) {
                b.depth[k] = static_cast<uint16_t>(r.next());
                b.color[k] = static_cast<uint16_t>(r.next());
            }
        };
        fill();
        if (su == hider::KernelSetup::kernel && u.row < u.end)
            (void)hider::run_kernel_triangle_portable(u, b.depth, band.stop,
                                                      {band.color_less_2 + 2, band.stride_bytes});
        const uint32_t expect = setup_digest(su, u) ^ buffers_digest(b);
        fill();
        hider::KernelSetupIo io{&band, c.area, &t};
        const hider::KernelSetup s = draw(c.v[0], c.v[1], c.v[2], io);
        if (s != su || (setup_digest(s, t) ^ buffers_digest(b)) != expect) return i;
    }
    return -1;
}

}  // namespace kernelcheck

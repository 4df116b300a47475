// Random vertex batches shared by the kernelcheck firmware and its host twin: each case is a view (random
// camera, frame size, field of view, near and far, the far plane sometimes past the assembly loop's
// 2^29 limit) and kVertexBatch positions placed around its view volume (screen positions up to a little
// past the guard band, depths at the near and far planes, at 2^29, or anywhere between, some behind the
// eye). run_vertex_cases() projects each batch through `project` (project_vertices() on the chip) and
// through `twin` (the general per-position path), one digest per case.
#pragma once
#include <hider/raster/vertices.hpp>

#include "kernelcheck/cases.hpp"

namespace kernelcheck {

constexpr int kVertexCases = 253;
constexpr int kVertexBatch = 16;
constexpr uint32_t kVertexSeed = 0x68E31DA4u;

struct VertexCase {
    hider::View view;
    hider::Vec3q16 p[kVertexBatch];
};

/// A camera at the origin looking down -z, y up, 60 degrees: its view transform is the identity (view
/// points are positions), for the directed cases.
inline hider::Camera axis_camera(int32_t near_raw, int32_t far_raw) {
    using hider::Q16;
    hider::Camera cam;
    cam.eye = {Q16::from_raw(0), Q16::from_raw(0), Q16::from_raw(0)};
    cam.target = {Q16::from_raw(0), Q16::from_raw(0), Q16::from_raw(-65536)};
    cam.up = {Q16::from_raw(0), Q16::from_raw(65536), Q16::from_raw(0)};
    cam.fovy = hider::Angle::from_bam(0x2AAAAAAAu);  // 60 degrees
    cam.near = Q16::from_raw(near_raw);
    cam.far = Q16::from_raw(far_raw);
    return cam;
}

/// A position whose view-space point is about (x, y, -w): the view rotation transposed, clamped to the
/// world range.
inline hider::Vec3q16 world_of(const hider::View& v, int64_t x, int64_t y, int64_t w) {
    const hider::Transform& t = v.to_view;
    const int64_t q[3] = {x - t.trans.x.raw(), y - t.trans.y.raw(), -w - t.trans.z.raw()};
    int32_t p[3];
    for (int j = 0; j < 3; ++j) {
        int64_t s = 0;
        for (int i = 0; i < 3; ++i) s += q[i] * t.rot.m[i][j].raw();
        p[j] = static_cast<int32_t>(hider::clamp<int64_t>(s >> 30, -(hider::kWorldLimitRaw - 1), hider::kWorldLimitRaw - 1));
    }
    return {hider::Q16::from_raw(p[0]), hider::Q16::from_raw(p[1]), hider::Q16::from_raw(p[2])};
}

inline void make_vertex_case(Rng& rng, VertexCase& c) {
    using hider::Q16;
    if (rng.next() % 8 == 0) {
        // Axis-aligned view (positions are view points) with depths at near times a power of two: there
        // w's top half ends in zeros and n 2^31 / w meets the equalities of its digit tests exactly.
        const int32_t near = int32_t{1} << rng.range(12, 20);
        hider::Camera cam = axis_camera(near, near << 9);
        const int32_t width = rng.range(1, 640);  // one draw per statement: the same order on every compiler
        const int32_t height = rng.range(1, 480);
        if (hider::make_view(cam, width, height, c.view) == hider::Status::ok) {
            for (hider::Vec3q16& p : c.p) {
                const int64_t w = int64_t{near} << rng.range(0, 9);
                const int32_t limit = hider::kGuardBand;
                const int64_t x = int64_t{rng.range(-limit, limit)} * 256 * w / c.view.k_q8;
                const int64_t y = int64_t{rng.range(-limit, limit)} * 256 * w / c.view.k_q8;
                p = {Q16::from_raw(static_cast<int32_t>(x)), Q16::from_raw(static_cast<int32_t>(y)),
                     Q16::from_raw(static_cast<int32_t>(-w))};
            }
            return;
        }
    }
    for (;;) {
        hider::Camera cam;
        auto coord = [&rng](int32_t limit) { return Q16::from_raw(rng.range(-limit, limit)); };
        cam.eye = {coord(1 << 26), coord(1 << 26), coord(1 << 26)};
        cam.target = {coord(1 << 26), coord(1 << 26), coord(1 << 26)};
        cam.up = (rng.next() & 3u) != 0 ? hider::Vec3q16{Q16::from_raw(0), Q16::from_raw(65536), Q16::from_raw(0)}
                                        : hider::Vec3q16{coord(65536), coord(65536), coord(65536)};
        cam.fovy = hider::Angle::from_bam(0x01000000u + rng.next() % 0x70000000u);
        const uint32_t near_bits = rng.next(), near_shift = rng.next() % 32;
        const int32_t near = hider::kMinNearRaw + static_cast<int32_t>((near_bits >> near_shift) & 0x3FFFFFFu);
        const uint32_t depth_bits = rng.next(), depth_shift = rng.next() % 32;
        const uint32_t depth = (depth_bits >> depth_shift) & 0x7FFFFFFFu;
        cam.near = Q16::from_raw(near);
        cam.far = Q16::from_raw(static_cast<int32_t>(hider::min<int64_t>(int64_t{near} + 1 + depth, INT32_MAX)));
        const int32_t width = rng.range(1, 640);
        const int32_t height = rng.range(1, 480);
        if (hider::make_view(cam, width, height, c.view) != hider::Status::ok) continue;
        break;
    }
    const hider::View& v = c.view;
    for (hider::Vec3q16& p : c.p) {
        int64_t w = 0;
        switch (rng.next() % 8) {
            case 0: w = v.near_raw + rng.range(-2, 2); break;
            case 1: w = v.far_raw + rng.range(-2, 2); break;
            case 2: w = (int64_t{1} << 29) + rng.range(-2, 2); break;
            case 3: w = rng.range(-(1 << 20), 1 << 20); break;
            default: w = v.near_raw + static_cast<int64_t>(rng.next() % static_cast<uint32_t>(v.far_raw - v.near_raw + 1));
        }
        auto screen = [&rng, &v, w]() {  // one draw per statement: the same order on every compiler
            const int32_t limit = hider::kGuardBand + 40;
            const int64_t at = int64_t{rng.range(-limit, limit)} * 256 * (w < 1 ? 1 : w) / v.k_q8;
            return at + rng.range(-3, 3);
        };
        const int64_t x = screen(), y = screen();
        p = world_of(v, x, y, w);
    }
}

/// The first case, not random: an axis-aligned 160 x 120 view with near 4096 (raw) where view point
/// (+-44,089, +-44,089, -65,543) makes project_common()'s screen quotient estimate one too low by exactly
/// w (remainder = w: the correction's boundary, which random positions practically never reach), and
/// depths at near times powers of two for n 2^31 / w's digit tests.
inline void make_directed_case(VertexCase& c) {
    using hider::Q16;
    hider::Camera cam = axis_camera(4096, 4096 << 9);
    (void)hider::make_view(cam, 160, 120, c.view);
    const int32_t q[4][2] = {{44089, 0}, {-44089, 0}, {0, 44089}, {44089, -44089}};
    for (int i = 0; i < kVertexBatch; ++i) {
        const bool quotient = i < 4;
        const int32_t w = quotient ? 65543 : 4096 << (i - 4) % 10;
        c.p[i] = {Q16::from_raw(quotient ? q[i][0] : i * 97), Q16::from_raw(quotient ? q[i][1] : -i * 89), Q16::from_raw(-w)};
    }
}

/// The second case, not random: make_directed_case()'s view with far 2^29 and screen coordinates on
/// the rounding ties (c k = (256 m - 128) w: w = k, |c| = 640 and 255,872, either sign), on the guard
/// band's boundary (|c| k = kGuardBand 256 w and one past it, at w = k and w = 37 k) and a little past it
/// (16,340 subpixels at w = 2^24, where a high word lies close to w / 2^10).
inline void make_edge_case(VertexCase& c) {
    using hider::Q16;
    hider::Camera cam = axis_camera(4096, 1 << 29);
    (void)hider::make_view(cam, 160, 120, c.view);
    const int32_t k = c.view.k_q8;
    const int32_t g = hider::kGuardBand * 256;
    const int32_t at = static_cast<int32_t>(int64_t{16340} * 256 * (1 << 24) / k);
    const int32_t q[16][3] = {{640, 0, k},         {-640, 0, k},         {0, 640, k},       {0, -640, k},
                              {255872, -255872, k}, {-255872, 255872, k}, {g, 0, k},         {g + 1, 0, k},
                              {-g, 0, k},           {-g - 1, 0, k},       {0, g, k},         {0, -g - 1, k},
                              {at, 0, 1 << 24},     {0, -at, 1 << 24},    {37 * g, -37 * g, 37 * k},
                              {-37 * g - 1, 0, 37 * k}};
    for (int i = 0; i < kVertexBatch; ++i)
        c.p[i] = {Q16::from_raw(q[i][0]), Q16::from_raw(q[i][1]), Q16::from_raw(-q[i][2])};
}

/// The third case, not random: an axis-aligned view with near 256 and 2^30 - 1 on the rotation's
/// diagonal, a translation to w = 1,024 (a raw unit of x or y moves the screen by 1.6 subpixels), and
/// positions of -2 to 2 raw units: row sums of 2^30 - 1 (one below a multiple of 2^30) and its small
/// multiples, where the transform's floors (and w's ceiling) turn.
inline void make_transform_case(VertexCase& c) {
    using hider::Q16;
    hider::Camera cam = axis_camera(256, 1 << 20);
    (void)hider::make_view(cam, 160, 120, c.view);
    for (int i = 0; i < 3; ++i) c.view.to_view.rot.m[i][i] = hider::Q30::from_raw(hider::Q30::kOne - 1);
    c.view.to_view.trans = {Q16::from_raw(300), Q16::from_raw(-200), Q16::from_raw(-1024)};
    for (int i = 0; i < kVertexBatch; ++i)
        c.p[i] = {Q16::from_raw(i % 5 - 2), Q16::from_raw((i / 5) % 5 - 2), Q16::from_raw(i % 3 == 0 ? 1 : i % 5 - 2)};
}

/// The fourth case, not random: an axis-aligned view with near 2^30 + 12,345 (every w project_common()
/// takes is below 2^30, so it takes none) and its translation moved to put w from 2^30 - 2 to 2^30 + 2^28
/// (around near).
inline void make_far_near_case(VertexCase& c) {
    using hider::Q16;
    const int32_t near = (1 << 30) + 12345;
    hider::Camera cam = axis_camera(near, INT32_MAX);
    (void)hider::make_view(cam, 160, 120, c.view);
    const int32_t base = (1 << 30) + (1 << 20);  // w = base - z
    c.view.to_view.trans.z = Q16::from_raw(-base);
    const int32_t w[8] = {near - 2, near - 1, near, near + 1, (1 << 30) - 2, 1 << 30, (1 << 30) + (1 << 28), near + 99};
    for (int i = 0; i < kVertexBatch; ++i)
        c.p[i] = {Q16::from_raw((i - 8) * 1000), Q16::from_raw((5 - i) * 700), Q16::from_raw(base - w[i % 8])};
}

/// FNV-1a of a batch's projected vertices.
inline uint32_t vertex_digest(const hider::ScreenVertex* s) {
    Fnv fnv;
    for (int i = 0; i < kVertexBatch; ++i) {
        fnv.add(static_cast<uint32_t>(static_cast<uint16_t>(s[i].x)) |
                (static_cast<uint32_t>(static_cast<uint16_t>(s[i].y)) << 16));
        fnv.add(s[i].z);
    }
    return fnv.h;
}

/// The general per-position path (clip codes, then project()): the twin of the assembly loops.
inline void project_each(const hider::View& v, const hider::Vec3q16* p, hider::ScreenVertex* out) {
    for (int i = 0; i < kVertexBatch; ++i) hider::detail::project_one(v, hider::to_view_point(v, p[i]), out[i]);
}

/// VertexProjector (a walk's projection on first use: the assembly loop for one position on ARMv7-M, the
/// general path for those it refuses) position by position over case c against project_each(): true when
/// every vertex is the same.
inline bool projector_matches(const VertexCase& c) {
    static hider::ScreenVertex one[kVertexBatch], each[kVertexBatch];
    const hider::VertexProjector project(c.view);
    for (int i = 0; i < kVertexBatch; ++i) project(c.p[i], one[i]);
    project_each(c.view, c.p, each);
    for (int i = 0; i < kVertexBatch; ++i)
        if (one[i].x != each[i].x || one[i].y != each[i].y || one[i].z != each[i].z) return false;
    return true;
}

/// Walks an assembly vertex loop (`loop` with constants `prep`, as project_vertices() drives it) over case
/// c: adds the positions it projected to `accepted`, and to `refused_inside` those it stopped at although
/// `projectable(view point)` says it should have projected them.
template <class Prep, class Loop, class Projectable>
void walk_vertex_loop(const VertexCase& c, const Prep& prep, Loop loop, Projectable projectable, uint32_t& accepted,
                      uint32_t& refused_inside) {
    static hider::ScreenVertex out[kVertexBatch];
    const hider::Vec3q16* const end = c.p + kVertexBatch;
    for (const hider::Vec3q16* p = c.p; p != end; ++p) {
        const hider::Vec3q16* const stop = loop(&prep, p, out + (p - c.p), end);
        accepted += static_cast<uint32_t>(stop - p);
        if ((p = stop) == end) break;
        refused_inside += projectable(hider::to_view_point(c.view, *p)) ? 1u : 0u;
    }
}

/// Digest of every vertex case through `project` (a function of (view, positions, out)) into
/// out[kVertexCases], each case also through `twin`; returns the first case whose digests differ, or -1.
/// `check` sees each case after it ran (the chip counts what its loop refused).
template <class Project, class Twin, class Check>
int run_vertex_cases(Project&& project, Twin&& twin, Check&& check, uint32_t* out) {
    Rng rng{kVertexSeed};
    int first_difference = -1;
    static VertexCase c;
    static hider::ScreenVertex a[kVertexBatch], b[kVertexBatch];
    for (int i = 0; i < kVertexCases; ++i) {
        if (i == 0) make_directed_case(c);
        else if (i == 1) make_edge_case(c);
        else if (i == 2) make_transform_case(c);
        else if (i == 3) make_far_near_case(c);
        else make_vertex_case(rng, c);
        project(c.view, c.p, a);
        twin(c.view, c.p, b);
        out[i] = vertex_digest(a);
        if (vertex_digest(b) != out[i] && first_difference < 0) first_difference = i;
        check(c);
    }
    return first_difference;
}

}  // namespace kernelcheck

// The scene every consumer example draws: a cube pierced by a long bar, seen from above one corner,
// 160x128 RGB565 with 16-bit depth, hider-render's defaults (headlight shading, back faces culled).
// The host example renders it as one frame, the firmware example in 8-row bands on a Cortex-M0+;
// CI requires the two frames to be byte-identical. Uses only hider's public headers.
#pragma once
#include <hider/raster/zbuffer.hpp>

namespace example {

constexpr int32_t kWidth = 160;
constexpr int32_t kHeight = 128;

/// Q16 from a value in hundredths (world units).
constexpr hider::Q16 cu(int32_t hundredths) { return hider::Q16::from_ratio(hundredths, 100); }
constexpr hider::Vec3q16 point(int32_t x, int32_t y, int32_t z) { return {cu(x), cu(y), cu(z)}; }

// Two boxes: the cube [-1, 1]^3 (vertices 0-7) and a bar 3.6 long through it along x (8-15).
// Vertex i of a box has x from bit 0, y from bit 1, z from bit 2.
constexpr hider::Vec3q16 kPositions[16] = {
    point(-100, -100, -100), point(100, -100, -100), point(-100, 100, -100), point(100, 100, -100),
    point(-100, -100, 100),  point(100, -100, 100),  point(-100, 100, 100),  point(100, 100, 100),
    point(-180, -30, -40),   point(180, -30, -40),   point(-180, 30, -40),   point(180, 30, -40),
    point(-180, -30, 40),    point(180, -30, 40),    point(-180, 30, 40),    point(180, 30, 40),
};

/// The twelve triangles of box `b` (first vertex 8 b), counter-clockwise seen from outside.
constexpr hider::Tri box_tri(int b, int t) {
    constexpr uint16_t kFaces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                        {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    const uint16_t o = static_cast<uint16_t>(8 * b);
    return {{static_cast<uint16_t>(o + kFaces[t][0]), static_cast<uint16_t>(o + kFaces[t][1]),
             static_cast<uint16_t>(o + kFaces[t][2])}};
}

constexpr hider::Tri kTris[24] = {
    box_tri(0, 0), box_tri(0, 1), box_tri(0, 2), box_tri(0, 3), box_tri(0, 4),  box_tri(0, 5),
    box_tri(0, 6), box_tri(0, 7), box_tri(0, 8), box_tri(0, 9), box_tri(0, 10), box_tri(0, 11),
    box_tri(1, 0), box_tri(1, 1), box_tri(1, 2), box_tri(1, 3), box_tri(1, 4),  box_tri(1, 5),
    box_tri(1, 6), box_tri(1, 7), box_tri(1, 8), box_tri(1, 9), box_tri(1, 10), box_tri(1, 11),
};

constexpr hider::Normal14 normal_of(int t) {
    return hider::face_normal(kPositions[kTris[t].v[0]], kPositions[kTris[t].v[1]], kPositions[kTris[t].v[2]]);
}

/// Face normals, computed at compile time (constant data in flash on a chip).
constexpr hider::Normal14 kNormals[24] = {
    normal_of(0),  normal_of(1),  normal_of(2),  normal_of(3),  normal_of(4),  normal_of(5),
    normal_of(6),  normal_of(7),  normal_of(8),  normal_of(9),  normal_of(10), normal_of(11),
    normal_of(12), normal_of(13), normal_of(14), normal_of(15), normal_of(16), normal_of(17),
    normal_of(18), normal_of(19), normal_of(20), normal_of(21), normal_of(22), normal_of(23),
};

inline hider::Mesh mesh() { return {{kPositions, 16}, {kTris, 24}, {kNormals, 24}, {}}; }

/// Eye above one corner, looking at the centre; 50 degrees vertical field of view.
inline hider::Camera camera() {
    hider::Camera c;
    c.eye = point(170, 250, 470);
    c.target = point(0, 0, 0);
    c.up = point(0, 100, 0);
    c.fovy = hider::Angle::from_degrees(hider::Q16::from_int(50));
    c.near = cu(100);
    c.far = cu(1200);
    return c;
}

using Frame = hider::FrameView<hider::Rgb565Format, uint16_t>;
constexpr hider::Rgb kBackground{16, 24, 48};

/// Draws the scene into `band` (any band of rows of the 160x128 frame, or the whole frame) for
/// `view`, whose vertices were projected into `verts`. Clears the band first.
inline hider::FrameStats draw(const hider::View& view, hider::Span<const hider::ScreenVertex> verts,
                              const Frame& band) {
    hider::clear(band, kBackground);
    return hider::draw_zbuffer(view, mesh(), verts, band, hider::DrawOptions{});
}

}  // namespace example

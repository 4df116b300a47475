// One hand-made screen triangle over a 16 x 16 frame (its ScreenVertex values set by the test, not by
// project_vertices()), for tests of what the draw calls accept as vertices.
#pragma once
#include <hider/mesh.hpp>
#include <hider/screen.hpp>
#include <hider/view.hpp>

namespace hider::test {

struct HandMadeTriangle {
    static constexpr int kSize = 16;
    View view;
    Vec3q16 positions[3] = {};
    ScreenVertex verts[3];
    Tri tri{{0, 1, 2}};
    Mesh mesh;

    /// A right triangle over half the frame and its diagonal (corners +-320 subpixels from its centre,
    /// depth 2^30).
    HandMadeTriangle() {
        Camera cam;
        cam.eye = {Q16::from_int(0), Q16::from_int(0), Q16::from_int(5)};
        cam.up = {Q16::from_int(0), Q16::from_int(1), Q16::from_int(0)};
        cam.fovy = Angle::from_degrees(Q16::from_int(60));
        cam.near = Q16::from_int(1);
        cam.far = Q16::from_int(100);
        (void)make_view(cam, kSize, kSize, view);
        const int16_t xs[3] = {-320, 320, 320}, ys[3] = {-320, -320, 320};
        for (int i = 0; i < 3; ++i) {
            verts[i].x = xs[i];
            verts[i].y = ys[i];
            verts[i].z = uint32_t{1} << 30;
        }
        mesh.positions = {positions, 3};
        mesh.tris = {&tri, 1};
    }
    /// The corners past kCoordLimit a red team drew with (an edge function then overflows int32).
    void past_the_limit() {
        verts[0].x = verts[0].y = -32768;
        verts[1].x = 32767;
        verts[1].y = -32768;
        verts[2].x = verts[2].y = 32767;
    }
};

}  // namespace hider::test

// The spin example's frames: a baked scene (firmware/common/scenes/) whose model turns about the world
// y axis through the camera target by kTurnBam per frame, z-buffered (16-bit depth), headlight-shaded,
// RGB565 on black. Shared by spin, spin320, bands and their host references so all run the same lib/ code.
#pragma once
#include <hider/raster/zbuffer.hpp>

namespace spin {

/// Binary angle the model turns between frames: 1/32 turn (11.25 degrees).
constexpr uint32_t kTurnBam = 0x08000000u;
/// Background colour of every frame.
constexpr hider::Rgb kBackground{0, 0, 0};

using Frame = hider::FrameView<hider::Rgb565Format, uint16_t>;

/// A baked scene as the examples use it (arrays borrowed from flash).
struct Scene {
    hider::Camera camera;
    int32_t width, height;
    hider::Mesh mesh;
};

/// Draw options of every example: hider-render's defaults (headlight, back-face culling, white).
inline hider::DrawOptions draw_options() { return hider::DrawOptions{}; }

/// Model transform of frame n: rotation about the y axis through `centre` (p -> R (p - c) + c).
/// Frame 0 is exactly the identity, so frame 0 equals an unrotated render.
inline hider::Transform turn(hider::Vec3q16 centre, uint32_t frame) {
    hider::Transform t;
    t.rot = hider::rotation_y(hider::Angle::from_bam(frame * kTurnBam));
    hider::Transform rot_only;
    rot_only.rot = t.rot;
    t.trans = centre - hider::apply(rot_only, centre);
    return t;
}

/// The view of frame n: make_view() of the baked camera, then with_model(turn(...)).
inline hider::Status frame_view(const Scene& s, uint32_t frame, hider::View& out) {
    hider::View base;
    const hider::Status st = hider::make_view(s.camera, s.width, s.height, base);
    if (st != hider::Status::ok) return st;
    out = hider::with_model(base, turn(s.camera.target, frame));
    return hider::Status::ok;
}

/// Clears `band` and draws the mesh into it; verts were projected for `view`.
inline hider::FrameStats draw_band(const hider::View& view, const hider::Mesh& mesh,
                                   hider::Span<const hider::ScreenVertex> verts, const Frame& band) {
    hider::clear(band, kBackground);
    return hider::draw_zbuffer<false>(view, mesh, verts, band, draw_options());
}

/// Renders frame n into the whole-frame view `frame`: view setup, projection into `verts` (one per
/// mesh vertex), clear and draw. Borrows everything for the call.
inline hider::FrameStats render_frame(const Scene& s, uint32_t frame, hider::Span<hider::ScreenVertex> verts,
                                      const Frame& out) {
    hider::FrameStats st;
    hider::View view;
    st.status = frame_view(s, frame, view);
    if (st.status == hider::Status::ok) st.status = hider::project_vertices(view, s.mesh.positions, verts);
    if (st.status != hider::Status::ok) return st;
    return draw_band(view, s.mesh, verts, out);
}

}  // namespace spin

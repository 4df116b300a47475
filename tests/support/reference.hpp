// Independent double-precision hidden-surface reference for tests: per-pixel-centre ray casting against the
// exact triangle planes, bucketed by near/far-clipped screen bounding boxes. Conventions as hider's: gluLookAt,
// gluPerspective, right-handed, row 0 on top, pixel centres sampled, CCW front, visible iff near <= -z_view <= far.
#pragma once

#include <stdint.h>

#include <vector>

namespace hider::ref {

struct Vec3d {
    double x, y, z;
};

struct RefTriangle {
    Vec3d v[3];   // world space
    uint32_t id;  // face id, > 0; 0 is the background
};

struct RefCamera {
    Vec3d eye, target, up;  // gluLookAt arguments, world space
    double fovy_deg;        // vertical field of view in degrees; aspect = width / height
    double near, far;       // view-space distances d = -z_view, 0 < near < far
    int width, height;      // image size in pixels
};

/// World point to view space (camera at the origin looking down -Z), built exactly as gluLookAt builds its matrix.
Vec3d to_view(const RefCamera& cam, const Vec3d& p_world);

/// Face id visible at each pixel centre (row-major, width*height), 0 = background.
/// Nearest d wins; on an exact depth tie the smaller id wins. Edges count as inside (a pixel centre exactly on an
/// edge is covered by both triangles sharing it). A triangle whose plane contains the eye covers nothing, and so does
/// a triangle with a non-finite view-space vertex. Returns an empty vector when width or height is not positive,
/// and all background when the camera is degenerate (eye == target, up parallel to the view direction,
/// near <= 0, far < near or fovy outside (0, 180)). Cost: O(triangles + sum of clipped bounding-box areas).
std::vector<uint32_t> render_ids(const std::vector<RefTriangle>& tris, const RefCamera& cam, bool cull);

struct Agreement {
    long off_edge = 0;           // pixels that are not on an edge in either image
    long off_edge_mismatch = 0;  // of those, pixels whose ids differ
    long total_mismatch = 0;     // all pixels whose ids differ
    /// 1 - off_edge_mismatch / off_edge, or 1.0 when off_edge == 0.
    double rate() const;
};

/// Compares two id images; a pixel is "on an edge" if any of its 8 neighbours in EITHER image has a different id
/// than the pixel has in that image. rate() = 1 - mismatch/off_edge (1.0 if off_edge==0). Neighbours outside the
/// image do not exist (a border pixel has 3 or 5 neighbours).
/// If either size differs from width*height (or a dimension is not positive) the result reports total failure:
/// off_edge = off_edge_mismatch = 1, total_mismatch = the larger size, so rate() == 0.
Agreement compare_ids(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b, int width, int height);

}  // namespace hider::ref

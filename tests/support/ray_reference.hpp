// Independent double-precision Whitted ray tracer for tests (no lib/ code): the same scene model as
// lib/hider/ray/trace.hpp (README.md, "Scene files (`hider-render --scene`)") computed exactly, plus a signature per pixel
// of everything discrete along its path (objects met, checker squares, lights blocked) so tests can
// leave out pixels next to a discontinuity (silhouettes, checker edges, shadow edges, their mirror images).
#pragma once

#include <stdint.h>

#include <vector>

namespace hider::ref {

struct RtVec {
    double x, y, z;
};

struct RtSurface {
    double color[3];          ///< 0..255
    double checker_color[3];  ///< 0..255
    double checker_size;      ///< 0: plain
    double reflect;           ///< 0..1
};

struct RtSphere {
    RtVec centre;
    double radius;
    int surface;
};

struct RtPlane {
    RtVec normal;  ///< unit
    double offset;
    int surface;
};

struct RtTriangle {
    RtVec v[3];
    RtVec normal;  ///< unit, for shading (lib/ uses the mesh's Q14 normal)
    int surface;
    int mesh;      ///< mesh index (for the skip rule: a ray ignores the triangle it leaves)
};

struct RtLight {
    bool point;
    RtVec position;   ///< point light
    RtVec direction;  ///< directional: unit, toward the light
    double color[3];  ///< 0..255
};

struct RtScene {
    std::vector<RtSphere> spheres;
    std::vector<RtPlane> planes;
    std::vector<RtTriangle> triangles;
    std::vector<RtLight> lights;
    std::vector<RtSurface> surfaces;
    double ambient[3] = {0, 0, 0};     ///< 0..255
    double background[3] = {0, 0, 0};  ///< 0..255
    int max_bounces = 0;
    double max_distance = 1e300;
    double epsilon = 16 / 65536.0;  ///< lib/'s kRayEpsilonRaw
    double world = 8192;            ///< plane hits outside |coordinate| < world are misses
    // gluLookAt + gluPerspective
    RtVec eye, target, up;
    double fovy_deg = 60;
    int width = 0, height = 0;
};

struct RtImage {
    std::vector<double> rgb;          ///< width * height * 3, 0..255 (not rounded or clamped)
    std::vector<uint64_t> signature;  ///< per pixel: hash of the path's discrete events
    std::vector<uint64_t> objects;    ///< per pixel: hash of the objects met only (silhouettes)
};

/// Ray traces `s` through the pixel centres.
RtImage ray_trace(const RtScene& s);

}  // namespace hider::ref

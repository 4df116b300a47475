// raytrace_demo: baked by hider-bake-ray from spheres.txt; do not edit, re-bake instead.
// 4 spheres, 1 planes, 0 meshes, 2 lights; values are raw Q16 (positions) and Q30 (unit vectors).
#pragma once
#include <hider/ray/scene.hpp>
#include <hider/view.hpp>

namespace hider::scenes::raytrace_demo {

inline constexpr int32_t kWidth = 160;
inline constexpr int32_t kHeight = 128;
/// BVH stack entries the scene's meshes need (validate_scene()).
inline constexpr size_t kStackDepth = 1;
/// Spheres in the scene (at least 1, for array sizes).
inline constexpr size_t kSphereCount = 4;

/// gluLookAt + gluPerspective camera (make_primary_rays()).
inline constexpr Camera kCamera{{Q16::from_raw(0), Q16::from_raw(157286), Q16::from_raw(524288)}, {Q16::from_raw(0), Q16::from_raw(58982), Q16::from_raw(0)}, {Q16::from_raw(0), Q16::from_raw(65536), Q16::from_raw(0)}, Angle::from_bam(0x20000000u), Q16::from_raw(256), Q16::from_raw(1073676288)};

inline constexpr ray::Surface kSurfaces[] = {
    {{235, 230, 214}, {41, 46, 61}, Q16::from_raw(65536), 6554},
    {{230, 56, 41}, {0, 0, 0}, Q16::from_raw(0), 11469},
    {{51, 191, 82}, {0, 0, 0}, Q16::from_raw(0), 9830},
    {{204, 204, 217}, {0, 0, 0}, Q16::from_raw(0), 24576},
    {{242, 199, 51}, {0, 0, 0}, Q16::from_raw(0), 8192},
};
inline constexpr ray::Sphere kSpheres[] = {
    {{Q16::from_raw(-111411), Q16::from_raw(65536), Q16::from_raw(-39322)}, Q16::from_raw(65536), 1},
    {{Q16::from_raw(58982), Q16::from_raw(49152), Q16::from_raw(52429)}, Q16::from_raw(49152), 2},
    {{Q16::from_raw(19661), Q16::from_raw(91750), Q16::from_raw(-183501)}, Q16::from_raw(91750), 3},
    {{Q16::from_raw(163840), Q16::from_raw(32768), Q16::from_raw(-58982)}, Q16::from_raw(32768), 4},
};
inline constexpr ray::Plane kPlanes[] = {
    {{Q30::from_raw(0), Q30::from_raw(1073741824), Q30::from_raw(0)}, Q16::from_raw(0), 0},
};
inline constexpr ray::Light kLights[] = {
    {ray::LightKind::point, {Q16::from_raw(393216), Q16::from_raw(393216), Q16::from_raw(-65536)}, {Q30::from_raw(0), Q30::from_raw(0), Q30::from_raw(0)}, {255, 242, 217}},
    {ray::LightKind::directional, {Q16::from_raw(0), Q16::from_raw(0), Q16::from_raw(0)}, {Q30::from_raw(641047829), Q30::from_raw(747889134), Q30::from_raw(427365219)}, {46, 46, 61}},
};


/// The scene for lib/ (validate_scene() once, with a stack of kStackDepth entries).
constexpr ray::Scene scene() {
    ray::Scene s;
    s.spheres = {kSpheres};
    s.planes = {kPlanes};
    s.lights = {kLights};
    s.surfaces = {kSurfaces};
    s.ambient = {26, 26, 31};
    s.background = {115, 158, 217};
    s.max_bounces = 2;
    s.max_distance = Q16::from_raw(3932160);
    s.sphere_bound = {{Q16::from_raw(9830), Q16::from_raw(91750), Q16::from_raw(-86835)}, Q16::from_raw(202857), 0};
    return s;
}

}  // namespace hider::scenes::raytrace_demo

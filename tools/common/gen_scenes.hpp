// Deterministic generated scenes for tests and benchmarks: random soups, sticks, boxes, cities, a ground
// grid through the near plane, a huge polygon. Geometry in double with its camera (gluLookAt +
// gluPerspective, as hider-render takes it); written as OBJ for the tools. Only +, -, *, / and sqrt touch
// the random numbers (correctly rounded in IEEE 754), and the draws come from std::mt19937 through our own
// mapping (no std::*_distribution), so a seed gives the same scene with any standard library.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "common/obj.hpp"
#include "common/scene.hpp"

namespace hider::tool::gen {

struct P3 {
    double x, y, z;
};

/// A planar (or nearly planar) polygon face, three or more vertices, with its id (> 0).
struct Face {
    std::vector<P3> v;
    uint32_t id;
};

struct GenScene {
    std::string name;         ///< kind-seed-count, for messages and file names
    std::vector<Face> faces;  ///< ids run 1..faces.size() in order
    P3 eye, target, up;       ///< gluLookAt
    double fovy_deg = 60.0;
    double near = 0.5, far = 10.0;
    int width = 320, height = 240;
};

/// `count` random interpenetrating triangles of mixed sizes (0.02..0.8) in the cube [-1, 1]^3, seen from outside.
GenScene soup(uint32_t seed, int count);
/// `count` large random triangles (vertices within 0.25..0.6 of a centre in [-0.7, 0.7]^3): many pierce each other.
GenScene dense_soup(uint32_t seed, int count);
/// `count` long thin triangles (length 1.2..2.2, altitude/length 1/200 to 1/1000) crossing near the origin.
GenScene slivers(uint32_t seed, int count);
/// 32 triangles, eye at the origin looking down -Z: six random triangles hundreds of units across, a floor and a
/// tilted wall that cross the near plane (0.5) and pass behind the eye, and 24 small ones at d in [2, 8].
GenScene huge_triangles(uint32_t seed);
/// Three thin bars (12 triangles each, ids 1-12, 13-24, 25-36), each lying over the next where they cross: a cycle.
GenScene cyclic_bars();
/// Five triangles: two large ones crossing through each other (ids 1, 2), a quad (3, 4) pierced by a triangle (5).
GenScene piercing();
/// `count` interpenetrating closed boxes (12 triangles each, outward CCW winding) around the origin.
GenScene boxes(uint32_t seed, int count);
/// `count` long thin quads (sticks 2..3 long, 0.04..0.1 wide, one face each) through a ball of radius 0.4: "mikado".
GenScene mikado(uint32_t seed, int count);
/// A tower of `count` closed boxes, each sunk into the one below it and turned about the vertical.
GenScene stacked_boxes(uint32_t seed, int count);
/// A ground grid of n x n quads passing under and behind the eye (so the near plane cuts it), with
/// `posts` boxes standing on it in front of the eye.
GenScene ground_grid(uint32_t seed, int n, int posts);
/// Where the city is seen from.
enum class CityView { above, street };
/// nx x nz blocks, each a closed box building of random height on a tiled ground (two triangles a tile):
/// from above (an oblique aerial view) or from street level looking along a street.
GenScene city(uint32_t seed, int nx, int nz, CityView view);
/// One polygon face with n vertices on a tilted circle (OBJ fans it into n - 2 triangles).
GenScene big_face(int n);
/// One star-shaped polygon face with n vertices at random radii (its fan from the first vertex overlaps itself).
GenScene star_face(uint32_t seed, int n);

/// The scene named like the GenScene names: soup-SEED-N, dense-SEED-N, slivers-SEED-N, huge-SEED, cyclic-bars, piercing,
/// boxes-SEED-N, mikado-SEED-N, stacked-SEED-N, grid-SEED-N-POSTS, city-SEED-NX-NZ-above|street, bigface-N, star-SEED-N.
/// False with a reason for an unknown name or a count out of range.
bool by_name(const std::string& name, GenScene& out, std::string& why);
/// The names by_name() accepts, as patterns (for usage messages).
std::string name_patterns();

/// Writes the scene as OBJ: shared vertices once (exact doubles, 17 significant digits), one `f` per face.
void write_obj(const GenScene& s, std::ostream& out);
/// The hider-render options that give the scene's camera and size (--eye ... --size WxH).
std::string camera_flags(const GenScene& s);
/// The scene as the OBJ reader would load write_obj()'s text (faces kept whole, ids 1..n), and its camera.
ObjModel obj_model(const GenScene& s);
CameraArgs camera_args(const GenScene& s);

}  // namespace hider::tool::gen

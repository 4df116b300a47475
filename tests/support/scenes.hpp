// Deterministic hard scenes for checking hider against the double reference (support/reference.hpp): the
// generators of tools/common/gen_scenes.hpp as reference triangles (faces fanned, ids kept).
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "common/gen_scenes.hpp"
#include "support/reference.hpp"

namespace hider::ref {

struct RefScene {
    std::vector<RefTriangle> tris;
    RefCamera cam;
    std::string name;  // kind plus seed and count, for failure messages
};

/// A generated scene as reference triangles: each face fanned from its first vertex, keeping its id.
RefScene from_gen(const tool::gen::GenScene& g);

inline RefScene soup(uint32_t seed, int count) { return from_gen(tool::gen::soup(seed, count)); }
inline RefScene slivers(uint32_t seed, int count) { return from_gen(tool::gen::slivers(seed, count)); }
inline RefScene huge_triangles(uint32_t seed) { return from_gen(tool::gen::huge_triangles(seed)); }
inline RefScene cyclic_bars() { return from_gen(tool::gen::cyclic_bars()); }
inline RefScene piercing() { return from_gen(tool::gen::piercing()); }
inline RefScene boxes(uint32_t seed, int count) { return from_gen(tool::gen::boxes(seed, count)); }

}  // namespace hider::ref

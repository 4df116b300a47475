// Random triangle soups for the tests that compare renderers on scenes nobody chose: a xorshift64
// generator (the same sequence on every host) and a soup of faces over random vertices.
#pragma once
#include <cstdint>

#include "common/obj.hpp"

namespace hider::test {

struct Xorshift64 {
    uint64_t state;
    uint64_t next() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    }
    /// Uniform in [lo, hi), from the top 53 bits.
    double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) / 9007199254740992.0; }
};

/// 3 to max_verts + 2 vertices in [-spread_xz, spread_xz] x [-1, 1] x [-spread_xz, spread_xz] and 1 to
/// max_faces triangles over them (any three, repeats and degenerate ones included), ids and lines from 1.
inline tool::ObjModel random_soup(Xorshift64& rng, int max_verts, int max_faces, double spread_xz = 1) {
    tool::ObjModel m;
    const int verts = 3 + static_cast<int>(rng.next() % static_cast<uint64_t>(max_verts));
    const int faces = 1 + static_cast<int>(rng.next() % static_cast<uint64_t>(max_faces));
    for (int i = 0; i < verts; ++i)
        m.vertices.push_back({rng.uniform(-spread_xz, spread_xz), rng.uniform(-1, 1), rng.uniform(-spread_xz, spread_xz)});
    for (int f = 0; f < faces; ++f) {
        tool::ObjFace face;
        for (int k = 0; k < 3; ++k) face.v.push_back(static_cast<int32_t>(rng.next() % static_cast<uint64_t>(verts)));
        face.id = static_cast<uint32_t>(f + 1);
        face.line = f + 1;
        m.faces.push_back(face);
    }
    return m;
}

}  // namespace hider::test

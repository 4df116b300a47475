// Generated scenes as reference triangles.
#include "support/scenes.hpp"

namespace hider::ref {

RefScene from_gen(const tool::gen::GenScene& g) {
    RefScene s;
    s.name = g.name;
    auto v = [](const tool::gen::P3& p) { return Vec3d{p.x, p.y, p.z}; };
    s.cam = RefCamera{v(g.eye), v(g.target), v(g.up), g.fovy_deg, g.near, g.far, g.width, g.height};
    for (const tool::gen::Face& f : g.faces)
        for (size_t i = 1; i + 1 < f.v.size(); ++i) s.tris.push_back(RefTriangle{{v(f.v[0]), v(f.v[i]), v(f.v[i + 1])}, f.id});
    return s;
}

}  // namespace hider::ref

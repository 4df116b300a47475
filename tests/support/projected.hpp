// A test scene's view and projected vertices with draw options, as the draw calls take them.
#pragma once
#include <hider/raster/zbuffer.hpp>

#include <vector>

#include <doctest/doctest.h>

#include "common/scene.hpp"

namespace hider::test {

struct Projected {
    View view;
    std::vector<ScreenVertex> verts;
    DrawOptions opt;
};

/// The view of `s` and its vertices projected (REQUIREd), with culling, shading and the depth range set.
inline Projected project(const tool::Scene& s, bool cull, Shade shade) {
    Projected p;
    REQUIRE(make_view(s.camera, s.width, s.height, p.view) == Status::ok);
    const Mesh mesh = s.mesh();
    p.verts.resize(mesh.positions.size());
    p.opt.cull = cull;
    p.opt.shade = shade;
    REQUIRE(project_vertices(p.view, mesh.positions, {p.verts.data(), p.verts.size()}, &p.opt.depth_range) == Status::ok);
    return p;
}

}  // namespace hider::test

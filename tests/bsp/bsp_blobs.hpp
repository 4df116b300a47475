// Test helpers for BSP blobs: compiled ones (an OBJ through hider-bsp's code, a generated scene through
// build_bsp + bsp_blob), hand-made trees of given shape, and field-level edits with the checksum
// recomputed, so a corruption can target a check that comes after the checksum.
#pragma once
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/bsp_build.hpp"
#include "support/scene_util.hpp"

namespace hider::test {

/// A blob and typed access to its fields by the format's offsets (memcpy: no alignment assumed).
struct BlobEdit {
    std::vector<uint8_t> bytes;

    template <class T>
    T get(size_t offset) const {
        T v;
        REQUIRE(offset + sizeof(T) <= bytes.size());
        std::memcpy(&v, bytes.data() + offset, sizeof(T));
        return v;
    }
    template <class T>
    void set(size_t offset, const T& v) {
        REQUIRE(offset + sizeof(T) <= bytes.size());
        std::memcpy(bytes.data() + offset, &v, sizeof(T));
    }
    BspHeader header() const { return get<BspHeader>(0); }
    BspLayout layout() const {
        const BspHeader h = header();
        return bsp_layout(h.node_count, h.triangle_count, h.vertex_count);
    }
    size_t node_at(uint32_t i) const { return layout().nodes + size_t{i} * sizeof(BspNode); }
    size_t triangle_at(uint32_t i) const { return layout().triangles + size_t{i} * sizeof(BspTriangle); }
    size_t vertex_at(uint32_t i) const { return layout().vertices + size_t{i} * sizeof(BspVertex); }
    BspNode node(uint32_t i) const { return get<BspNode>(node_at(i)); }
    void set_node(uint32_t i, const BspNode& n) { set(node_at(i), n); }
    BspTriangle triangle(uint32_t i) const { return get<BspTriangle>(triangle_at(i)); }
    void set_triangle(uint32_t i, const BspTriangle& t) { set(triangle_at(i), t); }
    void set_header(const BspHeader& h) { set(0, h); }

    /// Recomputes the checksum field, as a writer of a consistent (if wrong) blob would.
    void reseal() {
        BspHeader h = header();
        h.checksum = bsp_checksum(bytes.data(), bytes.size());
        set_header(h);
    }
};

/// The blob hider-bsp makes of an OBJ file under tests/data (default heuristic).
inline std::vector<uint8_t> blob_of_obj(const std::string& relative_path, const tool::BspOptions& opt = {}) {
    std::vector<uint8_t> blob;
    tool::BspStats stats;
    std::string why;
    const bool ok = tool::bsp_from_obj(std::string(HIDER_TEST_DATA) + "/" + relative_path, opt, blob, stats, why);
    REQUIRE_MESSAGE(ok, why);
    return blob;
}

/// The blob of a built tree of a scene (its world positions and face ids), fitted as the scene was.
inline std::vector<uint8_t> blob_of_scene(const tool::Scene& s, const tool::BspOptions& opt = {}) {
    tool::BspBuilt built;
    tool::BspStats stats;
    std::string why;
    const bool ok = tool::build_bsp(s.positions, s.tris, s.ids, opt, built, stats, why);
    REQUIRE_MESSAGE(ok, why);
    return tool::bsp_blob(built, tool::BspFit{s.centre, s.scale});
}

/// A hand-made tree: node i has children[i], the plane z = 0 through vertex 0 and a box around the
/// three vertices; node 0 holds the one triangle. `max_depth` is written as given (not measured).
inline std::vector<uint8_t> hand_blob(const std::vector<std::array<uint32_t, 2>>& children, uint32_t max_depth) {
    tool::BspBuilt t;
    t.vertices = {{0, 0, 0}, {65536, 0, 0}, {0, 65536, 0}};
    t.triangles = {{{0, 1, 2}, 1}};
    for (size_t i = 0; i < children.size(); ++i) {
        BspNode n{};
        n.n[2] = int64_t{1} << 32;
        n.child[0] = children[i][0];
        n.child[1] = children[i][1];
        n.count = i == 0 ? 1 : 0;
        for (int k = 0; k < 3; ++k) n.box_max[k] = 16;  // 1 world unit in 2^12 raw steps
        n.normal[2] = 1 << 14;
        t.nodes.push_back(n);
    }
    t.max_depth = max_depth;
    return tool::bsp_blob(t, tool::BspFit{});
}

/// A chain of `n` nodes: each node's front child is the next (a tree `n` deep).
inline std::vector<uint8_t> chain_blob(uint32_t n) {
    std::vector<std::array<uint32_t, 2>> c(n, {kBspNone, kBspNone});
    for (uint32_t i = 0; i + 1 < n; ++i) c[i][0] = i + 1;
    return hand_blob(c, n);
}

}  // namespace hider::test

// bsp_load() against corrupt blobs: each kind of damage (truncation, flipped bytes, header fields,
// counts that do not match the size or overflow 32 bits, out-of-range indices, backward and self
// children, nodes with two parents or none, trees deeper than the stack or than the header says, bad
// checksum, misalignment, vertices outside the world, bad plane normals, reserved face bits) is
// rejected with its Status. Corruptions start from compiled blobs and recompute the checksum when they
// aim at a later check. Every blob bsp_load accepts is walked both ways (tests/bsp/bsp_exercise.hpp)
// into exactly sized buffers, so under the host-asan preset an out-of-bounds access fails the test.
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "bsp/bsp_blobs.hpp"
#include "bsp/bsp_exercise.hpp"
#include "common/bsp_build.hpp"

using namespace hider;
using test::BlobEdit;

namespace {

Status load(const std::vector<uint8_t>& bytes, size_t stack_entries = bsp_stack_entries(64)) {
    std::vector<uint64_t> storage;
    BspTree tree;
    return test::load_bsp(test::aligned_copy(bytes.data(), bytes.size(), storage), stack_entries, tree);
}

test::BspExercise exercise(const std::vector<uint8_t>& bytes, uint32_t max_depth = 64) {
    return test::exercise_bsp(bytes.data(), bytes.size(), max_depth);
}

/// The walks of an accepted blob all returned ok, and bsp-front wrote no pixel twice.
void check_walks_safe(const test::BspExercise& r) {
    CHECK(r.walks > 0);
    CHECK(r.walk_failures == 0);
    CHECK(r.overdraw_failures == 0);
}

BlobEdit cube() { return BlobEdit{test::blob_of_obj("obj/cube.obj")}; }

}  // namespace

TEST_CASE("bsp_load accepts the compiled cube, measures its depth, and both walks draw it") {
    const BlobEdit b = cube();
    const BspHeader h = b.header();
    REQUIRE(h.node_count > 1);
    REQUIRE(h.triangle_count >= 12);
    std::vector<uint64_t> storage;
    BspTree tree;
    REQUIRE(test::load_bsp(test::aligned_copy(b.bytes.data(), b.bytes.size(), storage), bsp_stack_entries(h.max_depth), tree) ==
            Status::ok);
    CHECK(tree.max_depth == h.max_depth);
    CHECK(tree.nodes.size() == h.node_count);
    CHECK(tree.triangles.size() == h.triangle_count);
    CHECK(tree.vertices.size() == h.vertex_count);
    const test::BspExercise r = exercise(b.bytes);
    REQUIRE(r.load == Status::ok);
    check_walks_safe(r);
    CHECK(r.triangles_drawn > 0);
}

TEST_CASE("bsp_load rejects every truncation of a valid blob and a blob with bytes appended") {
    const BlobEdit b = cube();
    for (size_t n = 0; n < b.bytes.size(); ++n) {
        INFO("length ", n, " of ", b.bytes.size());
        const std::vector<uint8_t> cut(b.bytes.begin(), b.bytes.begin() + static_cast<std::ptrdiff_t>(n));
        CHECK(load(cut) == Status::bad_data);
    }
    for (size_t extra : {1, 8, 12}) {
        std::vector<uint8_t> longer = b.bytes;
        longer.resize(longer.size() + extra, 0);
        CHECK(load(longer) == Status::bad_data);
    }
}

TEST_CASE("bsp_load rejects a blob with any one byte flipped; resealed, the flip is rejected or the tree walks safely") {
    const BlobEdit b = cube();
    size_t accepted = 0, rejected = 0;
    for (size_t i = 0; i < b.bytes.size(); ++i)
        for (uint8_t mask : {uint8_t{0x01}, uint8_t{0x80}, uint8_t{0xFF}}) {
            INFO("byte ", i, " xor ", int{mask});
            BlobEdit f = b;
            f.bytes[i] ^= mask;
            CHECK(load(f.bytes) != Status::ok);  // the checksum covers every byte but its own field
            if (i >= offsetof(BspHeader, checksum) && i < offsetof(BspHeader, checksum) + 4) continue;
            if (f.bytes.size() < sizeof(BspHeader)) continue;
            f.reseal();
            const test::BspExercise r = exercise(f.bytes);
            if (r.load != Status::ok) {
                ++rejected;
                continue;
            }
            ++accepted;
            check_walks_safe(r);
        }
    MESSAGE("resealed single-byte flips of the cube: " << accepted << " accepted and walked, " << rejected << " rejected");
    CHECK(rejected > 0);
}

TEST_CASE("bsp_load rejects a wrong magic, version or header size") {
    const BlobEdit b = cube();
    SUBCASE("magic") {
        BlobEdit f = b;
        BspHeader h = f.header();
        h.magic = 0x50534249u;
        f.set_header(h);
        f.reseal();
        CHECK(load(f.bytes) == Status::bad_data);
    }
    SUBCASE("version") {
        for (uint16_t v : {uint16_t{0}, uint16_t{1}, uint16_t{kBspVersion + 1}, uint16_t{0xFFFF}}) {  // 1: the old format
            BlobEdit f = b;
            BspHeader h = f.header();
            h.version = v;
            f.set_header(h);
            f.reseal();
            CHECK(load(f.bytes) == Status::bad_data);
        }
    }
    SUBCASE("header size") {
        for (uint16_t s : {uint16_t{0}, uint16_t{63}, uint16_t{65}, uint16_t{128}}) {
            BlobEdit f = b;
            BspHeader h = f.header();
            h.header_size = s;
            f.set_header(h);
            f.reseal();
            CHECK(load(f.bytes) == Status::bad_data);
        }
    }
}

TEST_CASE("bsp_load rejects counts that do not match the size, also when their byte sizes wrap 32 bits") {
    const BlobEdit b = cube();
    const BspHeader h0 = b.header();
    struct Case {
        const char* what;
        uint32_t nodes, triangles, vertices;
    };
    const Case cases[] = {
        {"one node more", h0.node_count + 1, h0.triangle_count, h0.vertex_count},
        {"one triangle fewer", h0.node_count, h0.triangle_count - 1, h0.vertex_count},
        {"one vertex more", h0.node_count, h0.triangle_count, h0.vertex_count + 1},
        {"one node fewer, four triangles more (the same size)", h0.node_count - 1, h0.triangle_count + 4, h0.vertex_count},
        {"2^26 nodes more (64 * 2^26 = 2^32)", h0.node_count + (1u << 26), h0.triangle_count, h0.vertex_count},
        {"2^28 triangles more (16 * 2^28 = 2^32)", h0.node_count, h0.triangle_count + (1u << 28), h0.vertex_count},
        {"2^30 vertices more (12 * 2^30 = 3 * 2^32)", h0.node_count, h0.triangle_count, h0.vertex_count + (1u << 30)},
        {"all counts at 2^32 - 1", 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu},
        {"2^31 nodes (the walk's draw flag)", 0x80000000u, h0.triangle_count, h0.vertex_count},
        {"2^30 nodes (the walk's eye-side flag)", 0x40000000u, h0.triangle_count, h0.vertex_count},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        for (bool fix_total : {false, true}) {
            BlobEdit f = b;
            BspHeader h = f.header();
            h.node_count = c.nodes;
            h.triangle_count = c.triangles;
            h.vertex_count = c.vertices;
            if (fix_total) {  // total_size as a 32-bit writer would compute it: wraps to the true size
                const uint32_t total = static_cast<uint32_t>(64u + 64u * c.nodes + 16u * c.triangles + 12u * c.vertices);
                h.total_size = total;
            }
            f.set_header(h);
            f.reseal();
            CHECK(load(f.bytes) == Status::bad_data);
        }
    }
    SUBCASE("total_size alone") {
        BlobEdit f = b;
        BspHeader h = f.header();
        h.total_size += 4;
        f.set_header(h);
        f.reseal();
        CHECK(load(f.bytes) == Status::bad_data);
    }
}

TEST_CASE("bsp_load rejects out-of-range vertex, triangle, child and origin indices") {
    const BlobEdit b = cube();
    const BspHeader h = b.header();
    auto rejects_node = [&](const char* what, auto edit) {
        for (uint32_t i = 0; i < h.node_count; ++i) {
            INFO(what, " at node ", i);
            BlobEdit f = b;
            BspNode n = f.node(i);
            edit(n);
            f.set_node(i, n);
            f.reseal();
            CHECK(load(f.bytes) == Status::bad_data);
        }
    };
    rejects_node("origin == vertex_count", [&](BspNode& n) { n.origin = h.vertex_count; });
    rejects_node("origin 2^32 - 1", [&](BspNode& n) { n.origin = 0xFFFFFFFFu; });
    rejects_node("front child == node_count", [&](BspNode& n) { n.child[0] = h.node_count; });
    rejects_node("back child == node_count", [&](BspNode& n) { n.child[1] = h.node_count; });
    rejects_node("back child 2^31", [&](BspNode& n) { n.child[1] = 0x80000000u; });
    rejects_node("first past the triangles", [&](BspNode& n) { n.first = h.triangle_count + 1; });
    rejects_node("count past the triangles", [&](BspNode& n) { n.count = h.triangle_count - n.first + 1; });
    rejects_node("first + count wrapping 32 bits", [&](BspNode& n) {
        n.first = 1;
        n.count = 0xFFFFFFFFu;
    });
    for (uint32_t t = 0; t < h.triangle_count; ++t)
        for (int k = 0; k < 3; ++k)
            for (uint32_t bad : {h.vertex_count, 0xFFFFFFFFu}) {
                INFO("triangle ", t, " corner ", k, " = ", bad);
                BlobEdit f = b;
                BspTriangle tri = f.triangle(t);
                tri.v[k] = bad;
                f.set_triangle(t, tri);
                f.reseal();
                CHECK(load(f.bytes) == Status::bad_data);
            }
}

TEST_CASE("bsp_load rejects backward and self child indices (a cycle)") {
    const BlobEdit b = cube();
    const BspHeader h = b.header();
    for (uint32_t i = 0; i < h.node_count; ++i)
        for (int side = 0; side < 2; ++side)
            for (uint32_t target : {i, uint32_t{0}, i == 0 ? 0u : i - 1}) {
                INFO("node ", i, " child ", side, " -> ", target);
                BlobEdit f = b;
                BspNode n = f.node(i);
                n.child[side] = target;
                f.set_node(i, n);
                f.reseal();
                CHECK(load(f.bytes) == Status::bad_data);
            }
}

TEST_CASE("bsp_load rejects a node with two parents or none: every node is reached once from the root") {
    const uint32_t none = kBspNone;
    SUBCASE("the hand-made trees are valid without the damage") {
        CHECK(load(test::hand_blob({{1, 2}, {none, none}, {none, none}}, 2)) == Status::ok);
        CHECK(load(test::chain_blob(5)) == Status::ok);
    }
    SUBCASE("both children of the root are the same node") {
        CHECK(load(test::hand_blob({{1, 1}, {none, none}}, 2)) == Status::bad_data);
    }
    SUBCASE("two parents, one node unreachable: as many visits as nodes") {
        CHECK(load(test::hand_blob({{2, 2}, {none, none}, {none, none}}, 2)) == Status::bad_data);
    }
    SUBCASE("a node below two parents") {
        CHECK(load(test::hand_blob({{1, 2}, {2, none}, {none, none}}, 3)) == Status::bad_data);
    }
    SUBCASE("a node no parent points to") {
        CHECK(load(test::hand_blob({{1, none}, {none, none}, {none, none}}, 2)) == Status::bad_data);
    }
    SUBCASE("both children of every node are the next: 2^63 paths, rejected after a bounded walk") {
        for (uint32_t n : {2u, 3u, 20u, 64u}) {
            INFO(n, " nodes");
            std::vector<std::array<uint32_t, 2>> c(n, {none, none});
            for (uint32_t i = 0; i + 1 < n; ++i) c[i] = {i + 1, i + 1};
            const std::vector<uint8_t> dag = test::hand_blob(c, n);
            CHECK(load(dag, bsp_stack_entries(n)) == Status::bad_data);
            CHECK(load(dag, bsp_stack_entries(1024)) == Status::bad_data);
        }
    }
    SUBCASE("the same in a compiled scene: a node's back child replaced by its front child") {
        const BlobEdit b{test::blob_of_scene(test::generated_scene("boxes-6-3"))};
        const BspHeader h = b.header();
        size_t damaged = 0;
        for (uint32_t i = 0; i < h.node_count; ++i) {
            BlobEdit f = b;
            BspNode n = f.node(i);
            if (n.child[0] == kBspNone || n.child[1] == kBspNone) continue;
            n.child[1] = n.child[0];
            f.set_node(i, n);
            f.reseal();
            INFO("node ", i);
            CHECK(load(f.bytes) == Status::bad_data);
            ++damaged;
        }
        CHECK(damaged > 0);
    }
}

TEST_CASE("bsp_load: a tree deeper than the caller's stack is capacity_exceeded, deeper than the header says bad_data") {
    SUBCASE("a chain 40 nodes deep: stack for 40 levels and one entry less") {
        const std::vector<uint8_t> chain = test::chain_blob(40);
        CHECK(load(chain, bsp_stack_entries(40)) == Status::ok);
        CHECK(load(chain, bsp_stack_entries(40) - 1) == Status::capacity_exceeded);
        CHECK(load(chain, bsp_stack_entries(39)) == Status::capacity_exceeded);
        CHECK(load(chain, 0) == Status::capacity_exceeded);
        const test::BspExercise r = exercise(chain, 40);
        REQUIRE(r.load == Status::ok);
        CHECK(r.depth == 40);
        check_walks_safe(r);
    }
    SUBCASE("the compiled cube at its depth N and N - 1") {
        const BlobEdit b = cube();
        const uint32_t d = b.header().max_depth;
        REQUIRE(d >= 2);
        CHECK(load(b.bytes, bsp_stack_entries(d)) == Status::ok);
        CHECK(load(b.bytes, bsp_stack_entries(d) - 1) == Status::capacity_exceeded);
        CHECK(load(b.bytes, bsp_stack_entries(d - 1)) == Status::capacity_exceeded);
    }
    SUBCASE("max_depth in the header smaller or larger than the tree's") {
        const BlobEdit b = cube();
        const uint32_t d = b.header().max_depth;
        for (uint32_t wrong : {uint32_t{0}, d - 1, d + 1, 0xFFFFFFFFu}) {
            INFO("header max_depth ", wrong, ", tree ", d);
            BlobEdit f = b;
            BspHeader h = f.header();
            h.max_depth = wrong;
            f.set_header(h);
            f.reseal();
            CHECK(load(f.bytes) == Status::bad_data);
        }
        CHECK(load(test::hand_blob({{1, kBspNone}, {kBspNone, kBspNone}}, 1)) == Status::bad_data);
        CHECK(load(test::hand_blob({{1, kBspNone}, {kBspNone, kBspNone}}, 2)) == Status::ok);
    }
}

TEST_CASE("bsp_load rejects a bad checksum") {
    const BlobEdit b = cube();
    for (uint32_t delta : {1u, 0x80000000u, 0xFFFFFFFFu}) {
        BlobEdit f = b;
        BspHeader h = f.header();
        h.checksum += delta;
        f.set_header(h);
        CHECK(load(f.bytes) == Status::bad_data);
    }
    SUBCASE("the checksum covers the header's counts, depth and world transform, not only the arrays") {
        for (size_t offset : {offsetof(BspHeader, max_depth), offsetof(BspHeader, centre), offsetof(BspHeader, scale),
                              offsetof(BspHeader, scale) + 4}) {
            INFO("header byte ", offset);
            BlobEdit f = b;
            f.bytes[offset] ^= 0x04;
            CHECK(load(f.bytes) == Status::bad_data);
        }
    }
}

TEST_CASE("bsp_load rejects a blob not 8-byte aligned with invalid_argument") {
    const BlobEdit b = cube();
    std::vector<uint64_t> storage(b.bytes.size() / 8 + 2);
    uint8_t* base = reinterpret_cast<uint8_t*>(storage.data());
    for (size_t shift : {0, 1, 2, 4, 7, 8}) {
        INFO("shift ", shift);
        std::memcpy(base + shift, b.bytes.data(), b.bytes.size());
        BspTree tree;
        const Status s = test::load_bsp({base + shift, b.bytes.size()}, bsp_stack_entries(64), tree);
        CHECK(s == (shift % 8 == 0 ? Status::ok : Status::invalid_argument));
    }
    SUBCASE("also when the blob is too short to hold a header") {
        BspTree tree;
        CHECK(test::load_bsp({base + 1, 10}, bsp_stack_entries(64), tree) == Status::invalid_argument);
        CHECK(test::load_bsp({base, 10}, bsp_stack_entries(64), tree) == Status::bad_data);
    }
}

TEST_CASE("bsp_load rejects a vertex outside kBspWorldLimitRaw with out_of_range; inside, the tree walks safely") {
    const BlobEdit b = cube();
    const uint32_t last = b.header().vertex_count - 1;
    for (int k = 0; k < 3; ++k)
        for (int32_t c : {kBspWorldLimitRaw, -kBspWorldLimitRaw, INT32_MIN, INT32_MAX, kBspWorldLimitRaw - 1, -kBspWorldLimitRaw + 1}) {
            INFO("coordinate ", k, " = ", c);
            BlobEdit f = b;
            f.set<int32_t>(f.vertex_at(last) + 4 * static_cast<size_t>(k), c);
            f.reseal();
            const bool inside = c > -kBspWorldLimitRaw && c < kBspWorldLimitRaw;
            const test::BspExercise r = exercise(f.bytes);
            CHECK(r.load == (inside ? Status::ok : Status::out_of_range));
            if (inside) check_walks_safe(r);
        }
}

TEST_CASE("bsp_load says out_of_range for a vertex outside the world even when a node's plane is also out of bounds") {
    // A tree built over points beyond the world has planes to match; the vertices are the cause, so they
    // are checked first (a red team's tree spanning +-8,000 units got bad_data).
    const BlobEdit b = cube();
    BlobEdit f = b;
    f.set<int32_t>(f.vertex_at(b.header().vertex_count - 1), kBspWorldLimitRaw);
    BspNode n = f.node(0);
    n.n[0] = int64_t{1} << 62;
    f.set_node(0, n);
    f.reseal();
    CHECK(load(f.bytes) == Status::out_of_range);
}

TEST_CASE("build_bsp refuses vertices beyond the BSP world with the vertex and the limit") {
    auto q = [](double v) { return Q16::from_raw(static_cast<int32_t>(v * 65536)); };
    const std::vector<Vec3q16> far{{q(3000), q(0), q(0)}, {q(3001), q(0), q(0)}, {q(3000), q(1), q(0)}};
    const std::vector<Tri> tris{{{0, 1, 2}}};
    tool::BspBuilt built;
    tool::BspStats stats;
    std::string why;
    CHECK(!tool::build_bsp(far, tris, {1}, tool::BspOptions{}, built, stats, why));
    CHECK(why.find("vertex 0 lies 3000") == 0);
    CHECK(why.find("beyond the BSP world of +-") != std::string::npos);
    const std::vector<Vec3q16> near{{q(30), q(0), q(0)}, {q(31), q(0), q(0)}, {q(30), q(1), q(0)}};
    CHECK_MESSAGE(tool::build_bsp(near, tris, {1}, tool::BspOptions{}, built, stats, why), why);
}

TEST_CASE("bsp_load rejects zero and oversized plane normals; the largest accepted ones walk safely") {
    const BlobEdit b = cube();
    const uint32_t nodes = b.header().node_count;
    const int64_t limit = int64_t{1} << 62;
    for (uint32_t i = 0; i < nodes; ++i) {
        INFO("node ", i);
        BlobEdit f = b;
        BspNode n = f.node(i);
        n.n[0] = n.n[1] = n.n[2] = 0;
        f.set_node(i, n);
        f.reseal();
        CHECK(load(f.bytes) == Status::bad_data);
        for (int k = 0; k < 3; ++k)
            for (int64_t c : {limit, -limit, INT64_MIN, INT64_MAX, limit - 1, -limit + 1}) {
                INFO("n[", k, "] = ", c);
                BlobEdit g = b;
                BspNode m = g.node(i);
                m.n[k] = c;
                g.set_node(i, m);
                g.reseal();
                const test::BspExercise r = exercise(g.bytes);
                const bool fits = c > -limit && c < limit;
                CHECK(r.load == (fits ? Status::ok : Status::bad_data));
                if (fits) check_walks_safe(r);
            }
    }
}

TEST_CASE("bsp_load rejects reserved face bits and an inside-out node box") {
    const BlobEdit b = cube();
    for (uint32_t bit : {30u, 31u}) {
        INFO("face bit ", bit);
        BlobEdit f = b;
        BspTriangle t = f.triangle(0);
        t.face ^= uint32_t{1} << bit;
        f.set_triangle(0, t);
        f.reseal();
        const test::BspExercise r = exercise(f.bytes);
        CHECK(r.load == (bit == 31 ? Status::ok : Status::bad_data));  // bit 31: the triangle faces against n
        if (r.load == Status::ok) check_walks_safe(r);
    }
    for (int k = 0; k < 3; ++k) {
        BlobEdit f = b;
        BspNode n = f.node(0);
        n.box_min[k] = static_cast<int16_t>(n.box_max[k] + 1);
        f.set_node(0, n);
        f.reseal();
        CHECK(load(f.bytes) == Status::bad_data);
    }
}

TEST_CASE("bsp_load accepts an empty tree, and its walks draw nothing") {
    const std::vector<uint8_t> empty = tool::bsp_blob(tool::BspBuilt{}, tool::BspFit{});
    CHECK(empty.size() == sizeof(BspHeader));
    const test::BspExercise r = exercise(empty);
    REQUIRE(r.load == Status::ok);
    check_walks_safe(r);
    CHECK(r.triangles_drawn == 0);
}

TEST_CASE("every blob bsp_load accepts walks safely: random field damage to compiled trees, resealed") {
    // Seeds: the cube, a closed box scene, open crossing triangles and a small city; the damage writes
    // values chosen to sit on the checks' edges into random 4- and 8-byte fields of every region.
    std::vector<std::pair<std::string, std::vector<uint8_t>>> seeds;
    seeds.push_back({"cube", test::blob_of_obj("obj/cube.obj")});
    for (const char* name : {"boxes-6-3", "piercing", "cyclic-bars", "city-1-3-3-street"})
        seeds.push_back({name, test::blob_of_scene(test::generated_scene(name))});
    for (const auto& [name, blob] : seeds) {
        const BlobEdit b{blob};
        const BspHeader h = b.header();
        const uint32_t edges[] = {0, 1, 2, h.node_count - 1, h.node_count, h.triangle_count, h.vertex_count - 1, h.vertex_count,
                                  kBspNone, 0x80000000u, static_cast<uint32_t>(kBspWorldLimitRaw), 0x3FFFFFFFu, 0x7FFF7FFFu};
        std::mt19937 rng(0xB5B0u + static_cast<uint32_t>(blob.size()));
        size_t accepted = 0;
        const int rounds = 400;
        for (int round = 0; round < rounds; ++round) {
            BlobEdit f = b;
            const int edits = 1 + static_cast<int>(rng() % 3);
            for (int e = 0; e < edits; ++e) {
                const size_t offset = sizeof(BspHeader) + (rng() % ((f.bytes.size() - sizeof(BspHeader)) / 4)) * 4;
                const uint32_t v = rng() % 4 == 0 ? static_cast<uint32_t>(rng()) : edges[rng() % std::size(edges)];
                f.set<uint32_t>(offset, rng() % 2 == 0 ? v : f.get<uint32_t>(offset) ^ (uint32_t{1} << (rng() % 32)));
            }
            f.reseal();
            const test::BspExercise r = exercise(f.bytes);
            if (r.load != Status::ok) continue;
            ++accepted;
            const std::string& seed_name = name;  // INFO cannot capture a structured binding (clang)
            INFO(seed_name, " round ", round);
            check_walks_safe(r);
        }
        MESSAGE(name << ": " << accepted << " of " << rounds << " damaged blobs accepted and walked safely");
        CHECK(accepted > 0);
    }
}

TEST_CASE("bsp_checksum is FNV-1a of every byte but the checksum field, for every length and alignment") {
    // The reference: the published FNV-1a, one byte at a time.
    auto reference = [](const uint8_t* p, size_t n, uint32_t h) {
        for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 16777619u;
        return h;
    };
    std::mt19937 rng(5);
    std::vector<uint8_t> bytes(300);
    for (auto& b : bytes) b = static_cast<uint8_t>(rng());
    CHECK(fnv1a(reinterpret_cast<const uint8_t*>("a"), 1) == 0xE40C292Cu);  // the published test vector
    CHECK(fnv1a(reinterpret_cast<const uint8_t*>("foobar"), 6) == 0xBF9CF968u);
    for (size_t start = 0; start < 8; ++start)
        for (size_t n = 0; start + n <= bytes.size(); n += 1 + n / 16)
            REQUIRE(fnv1a(bytes.data() + start, n, 12345u + static_cast<uint32_t>(n)) ==
                    reference(bytes.data() + start, n, 12345u + static_cast<uint32_t>(n)));
    for (size_t size = 64; size <= bytes.size(); size += 7) {
        const uint32_t want = reference(bytes.data() + 32, size - 32, reference(bytes.data(), 28, 2166136261u));
        REQUIRE(bsp_checksum(bytes.data(), size) == want);
    }
}

TEST_CASE("bsp_load's BspLoadInfo names each refusal and where it was found") {
    auto info_of = [](const std::vector<uint8_t>& bytes, size_t stack_entries = bsp_stack_entries(64)) {
        std::vector<uint64_t> storage;
        std::vector<uint32_t> stack(stack_entries);
        BspTree tree;
        BspLoadInfo info;
        info.problem = BspProblem::node;  // overwritten by every call
        const Span<const uint8_t> blob = test::aligned_copy(bytes.data(), bytes.size(), storage);
        const Status s = bsp_load(blob, {stack.data(), stack.size()}, tree, &info);
        return std::make_pair(s, info);
    };
    const BlobEdit b = cube();
    const BspHeader h0 = b.header();
    {
        const auto [s, info] = info_of(b.bytes);
        CHECK(s == Status::ok);
        CHECK(info.problem == BspProblem::none);
    }
    auto expect = [&](const std::vector<uint8_t>& bytes, Status status, BspProblem problem, uint32_t index, uint32_t value,
                      size_t stack_entries = bsp_stack_entries(64)) {
        const auto [s, info] = info_of(bytes, stack_entries);
        CHECK(s == status);
        CHECK(info.problem == problem);
        CHECK(info.index == index);
        CHECK(info.value == value);
        CHECK(std::string(bsp_problem_text(info.problem)) != "unknown");
    };
    expect({b.bytes.begin(), b.bytes.begin() + 10}, Status::bad_data, BspProblem::short_blob, 0, 0);
    BlobEdit f = b;
    f.bytes[0] ^= 1;
    expect(f.bytes, Status::bad_data, BspProblem::magic, 0, 0);
    BspHeader h = h0;
    h.version = kBspVersion + 7;
    f = b;
    f.set_header(h);
    expect(f.bytes, Status::bad_data, BspProblem::version, 0, kBspVersion + 7);
    h = h0;
    h.header_size = 65;
    f = b;
    f.set_header(h);
    expect(f.bytes, Status::bad_data, BspProblem::header_size, 0, 65);
    expect({b.bytes.begin(), b.bytes.end() - 8}, Status::bad_data, BspProblem::size, 0, h0.total_size);
    h = h0;
    h.node_count = 0x40000000u;
    f = b;
    f.set_header(h);
    expect(f.bytes, Status::bad_data, BspProblem::too_many_nodes, 0, 0x40000000u);
    f = b;
    f.bytes[f.bytes.size() - 1] ^= 1;
    expect(f.bytes, Status::bad_data, BspProblem::checksum, 0, 0);
    const uint32_t v = h0.vertex_count - 1;
    f = b;
    f.set<int32_t>(f.vertex_at(v) + 4, kBspWorldLimitRaw);
    f.reseal();
    expect(f.bytes, Status::out_of_range, BspProblem::vertex_range, v, 0);
    const uint32_t last_node = h0.node_count - 1;
    f = b;
    BspNode n = f.node(last_node);
    n.origin = h0.vertex_count;
    f.set_node(last_node, n);
    f.reseal();
    expect(f.bytes, Status::bad_data, BspProblem::node, last_node, 0);
    const uint32_t t = h0.triangle_count - 1;
    f = b;
    BspTriangle tri = f.triangle(t);
    tri.face |= 0x40000000u;  // a reserved bit
    f.set_triangle(t, tri);
    f.reseal();
    expect(f.bytes, Status::bad_data, BspProblem::triangle, t, 0);
    // Node 1 without a parent (the root's children skip it): met out of preorder.
    expect(test::hand_blob({{2, kBspNone}, {kBspNone, kBspNone}, {kBspNone, kBspNone}}, 2), Status::bad_data, BspProblem::shape, 2, 0);
    expect(test::hand_blob({{kBspNone, kBspNone}, {kBspNone, kBspNone}}, 1), Status::bad_data, BspProblem::shape, 1, 0);  // node 1: no parent
    expect(test::hand_blob({{1, kBspNone}, {kBspNone, kBspNone}}, 1), Status::bad_data, BspProblem::depth, 2, 1);
    expect(test::hand_blob({{1, kBspNone}, {kBspNone, kBspNone}}, 3), Status::bad_data, BspProblem::depth, 2, 3);
    expect(test::chain_blob(40), Status::capacity_exceeded, BspProblem::too_deep, 39, 40, bsp_stack_entries(39));
    {  // misaligned: invalid_argument
        std::vector<uint64_t> storage(b.bytes.size() / 8 + 2);
        uint8_t* base = reinterpret_cast<uint8_t*>(storage.data()) + 4;
        std::memcpy(base, b.bytes.data(), b.bytes.size());
        std::vector<uint32_t> stack(bsp_stack_entries(64));
        BspTree tree;
        BspLoadInfo info;
        CHECK(bsp_load({base, b.bytes.size()}, {stack.data(), stack.size()}, tree, &info) == Status::invalid_argument);
        CHECK(info.problem == BspProblem::misaligned);
    }
}

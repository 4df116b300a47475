// Validating a BSP blob (format.hpp) once, so the walks can trust every index: magic, version, sizes,
// checksum, each index in range, children only forward (no cycle), the nodes in preorder from the root
// (so every node has one parent: a tree, not a DAG), cell labels only on empty children and one each,
// the depth as the header says and within the caller's stack. (It cannot check that a label is true:
// hider-bsp proved it, and the checksum guards it.)
// Nothing is copied: the tree reads the blob in place (flash on a device).
#pragma once
#include <hider/bsp/format.hpp>
#include <hider/status.hpp>
#include <hider/view.hpp>

namespace hider {

/// A validated tree: spans into its blob (borrowed for as long as the tree is used). Filled by bsp_load()
/// only: the walks rely on what it checked (indices in range, vertices within kBspWorldLimitRaw, normals
/// below 2^62, depth).
struct BspTree {
    const BspHeader* header = nullptr;
    Span<const BspNode> nodes;
    Span<const BspTriangle> triangles;
    Span<const Vec3q16> vertices;  ///< the world positions, for project_vertices()
    uint32_t max_depth = 0;        ///< nodes on the longest path from the root, as measured by bsp_load
};
static_assert(sizeof(Vec3q16) == sizeof(BspVertex), "BSP vertices are read as Vec3q16");

/// Stack entries (uint32) a walk of a tree `depth` nodes deep needs (walk.hpp).
constexpr size_t bsp_stack_entries(uint32_t depth) { return size_t{kBspStackPerLevel} * depth + 1; }

namespace detail {
/// The T at byte `offset` of a blob whose start bsp_load() checked to be 8-byte aligned (the layout
/// keeps each part aligned), through void* since a byte pointer cast would claim no alignment.
template <class T> const T* blob_at(const uint8_t* blob, size_t offset) {
    return static_cast<const T*>(static_cast<const void*>(blob + offset));
}
}  // namespace detail

/// What bsp_load() refused, for a message (BspLoadInfo).
enum class BspProblem : uint8_t {
    none,
    misaligned,     ///< the blob does not start on an 8-byte boundary (invalid_argument)
    short_blob,     ///< fewer bytes than a header
    magic,          ///< not a hider BSP blob
    version,        ///< another format version (value: the blob's; this hider reads kBspVersion)
    header_size,    ///< the header's size field is not this version's
    size,           ///< the counts, the header's total size and the blob's length disagree (value: the total it gives)
    too_many_nodes, ///< 2^30 nodes or more (value: the count)
    checksum,       ///< the bytes do not match the checksum: corrupted or cut
    vertex_range,   ///< a vertex outside kBspWorldLimitRaw (index: the vertex; out_of_range)
    node,           ///< a node's index, child, box, cell label or normal is wrong (index: the node)
    triangle,       ///< a triangle's vertex index or face bits are wrong (index: the triangle)
    shape,          ///< the nodes are not a tree stored in preorder (index: the node met)
    depth,          ///< the header's depth is not the tree's (value: the header's; index: the tree's depth,
                    ///< or the first level past the header's where the walk met one)
    too_deep,       ///< the tree is deeper than the stack holds (index: the node, value: its level;
                    ///< capacity_exceeded)
};

/// Details of a refused blob: the problem, the node, triangle or vertex it was found at, and a value.
struct BspLoadInfo {
    BspProblem problem = BspProblem::none;
    uint32_t index = 0;
    uint32_t value = 0;
};

/// A short English phrase for a BspProblem (for the host tools' messages and a firmware's log).
constexpr const char* bsp_problem_text(BspProblem p) {
    switch (p) {
        case BspProblem::none: return "none";
        case BspProblem::misaligned: return "blob not 8-byte aligned";
        case BspProblem::short_blob: return "shorter than a BSP header";
        case BspProblem::magic: return "not a hider BSP blob (no HBSP magic)";
        case BspProblem::version: return "another BSP format version";
        case BspProblem::header_size: return "header size field wrong";
        case BspProblem::size: return "sizes disagree with the blob's length (cut or padded)";
        case BspProblem::too_many_nodes: return "2^30 nodes or more";
        case BspProblem::checksum: return "checksum mismatch (corrupted)";
        case BspProblem::vertex_range: return "vertex outside the BSP world range";
        case BspProblem::node: return "invalid node";
        case BspProblem::triangle: return "invalid triangle";
        case BspProblem::shape: return "nodes not a tree in preorder";
        case BspProblem::depth: return "header's depth is not the tree's";
        case BspProblem::too_deep: return "tree deeper than the stack holds";
    }
    return "unknown";
}

/// Checks `blob` and points `out` into it. `stack` is the caller's walk stack: it must hold
/// bsp_stack_entries(depth) entries for the tree's depth (load() uses it to measure that depth).
/// Returns bad_data for any inconsistency (out untouched), out_of_range for a vertex outside
/// kBspWorldLimitRaw, invalid_argument for a blob not 8-byte aligned, capacity_exceeded when the tree is deeper than
/// the stack holds; `info`, if given, says which check failed and where. Cost: one pass over the bytes
/// (checksum) and one over the nodes.
inline Status bsp_load(Span<const uint8_t> blob, Span<uint32_t> stack, BspTree& out, BspLoadInfo* info = nullptr) {
    auto refuse = [info](Status s, BspProblem p, uint32_t index = 0, uint32_t value = 0) {
        if (info != nullptr) *info = BspLoadInfo{p, index, value};
        return s;
    };
    if (info != nullptr) *info = BspLoadInfo{};
    if ((reinterpret_cast<uintptr_t>(blob.data()) & 7u) != 0) return refuse(Status::invalid_argument, BspProblem::misaligned);
    if (blob.size() < sizeof(BspHeader)) return refuse(Status::bad_data, BspProblem::short_blob);
    const BspHeader& h = *detail::blob_at<BspHeader>(blob.data(), 0);
    if (h.magic != kBspMagic) return refuse(Status::bad_data, BspProblem::magic);
    if (h.version != kBspVersion) return refuse(Status::bad_data, BspProblem::version, 0, h.version);
    if (h.header_size != sizeof(BspHeader)) return refuse(Status::bad_data, BspProblem::header_size, 0, h.header_size);
    // Sizes in 64 bits: the counts come from the blob and must not wrap a 32-bit size_t.
    const uint64_t total = uint64_t{sizeof(BspHeader)} + uint64_t{h.node_count} * sizeof(BspNode) +
                           uint64_t{h.triangle_count} * sizeof(BspTriangle) + uint64_t{h.vertex_count} * sizeof(BspVertex);
    if (h.node_count >= 0x40000000u) return refuse(Status::bad_data, BspProblem::too_many_nodes, 0, h.node_count);  // walks tag indices with two bits
    if (total != h.total_size || total != blob.size())
        return refuse(Status::bad_data, BspProblem::size, 0, total > UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(total));
    if (bsp_checksum(blob.data(), blob.size()) != h.checksum) return refuse(Status::bad_data, BspProblem::checksum);
    const BspLayout l = bsp_layout(h.node_count, h.triangle_count, h.vertex_count);
    const BspNode* nodes = detail::blob_at<BspNode>(blob.data(), l.nodes);
    const BspTriangle* tris = detail::blob_at<BspTriangle>(blob.data(), l.triangles);
    const Vec3q16* verts = detail::blob_at<Vec3q16>(blob.data(), l.vertices);
    // Vertices first: a tree built over points outside the BSP world says so (out_of_range), rather than
    // failing a node's checks on planes through them (bad_data).
    for (uint32_t i = 0; i < h.vertex_count; ++i) {
        const int32_t c[3] = {verts[i].x.raw(), verts[i].y.raw(), verts[i].z.raw()};
        for (int32_t e : c)
            if (e <= -kBspWorldLimitRaw || e >= kBspWorldLimitRaw) return refuse(Status::out_of_range, BspProblem::vertex_range, i);
    }
    for (uint32_t i = 0; i < h.node_count; ++i) {
        const BspNode& n = nodes[i];
        if (n.origin >= h.vertex_count || n.first > h.triangle_count || n.count > h.triangle_count - n.first) return refuse(Status::bad_data, BspProblem::node, i);
        for (uint32_t c : n.child)
            if (c != kBspNone && (c <= i || c >= h.node_count)) return refuse(Status::bad_data, BspProblem::node, i);  // forward only: no cycle
        for (int k = 0; k < 3; ++k)
            if (n.box_min[k] > n.box_max[k]) return refuse(Status::bad_data, BspProblem::node, i);
        if ((n.cells & ~kBspCellMask) != 0) return refuse(Status::bad_data, BspProblem::node, i);
        for (int c = 0; c < 2; ++c) {  // labels only on an empty child, one at most
            const bool lowest = (n.cells & (kBspCellLowest << c)) != 0, highest = (n.cells & (kBspCellHighest << c)) != 0;
            if ((lowest || highest) && (n.child[c] != kBspNone || (lowest && highest))) return refuse(Status::bad_data, BspProblem::node, i);
        }
        if (n.n[0] == 0 && n.n[1] == 0 && n.n[2] == 0) return refuse(Status::bad_data, BspProblem::node, i);
        // |n| < 2^62 keeps the eye test's three products and their sum inside 128 bits.
        for (int64_t c : n.n)
            if (c <= -(int64_t{1} << 62) || c >= (int64_t{1} << 62)) return refuse(Status::bad_data, BspProblem::node, i);
    }
    for (uint32_t i = 0; i < h.triangle_count; ++i) {
        const BspTriangle& t = tris[i];
        if (t.v[0] >= h.vertex_count || t.v[1] >= h.vertex_count || t.v[2] >= h.vertex_count) return refuse(Status::bad_data, BspProblem::triangle, i);
        if ((t.face & ~(kBspFaceMask | kBspFaceBack)) != 0) return refuse(Status::bad_data, BspProblem::triangle, i);
    }
    // Shape and depth: a preorder walk (front child first) keeping one entry per level above the node in
    // the caller's stack: the back child still to visit there (kBspNone once taken, or when there is
    // none), so the node's level is the entries plus one. The nodes must be stored in exactly that order,
    // so the k-th node met is node k: no node is met twice (two parents, a DAG: rejected at its second
    // visit, however many paths lead to it) and, with every node met, none is unreachable.
    uint32_t depth = 0;
    if (h.node_count != 0) {
        size_t top = 0;
        uint32_t node = 0, visits = 0;
        for (;;) {
            if (node != visits++) return refuse(Status::bad_data, BspProblem::shape, node);  // not in preorder: not a tree, or stored otherwise
            const uint32_t level = static_cast<uint32_t>(top) + 1;
            depth = max(depth, level);
            if (level > h.max_depth) return refuse(Status::bad_data, BspProblem::depth, level, h.max_depth);
            if (bsp_stack_entries(level) > stack.size()) return refuse(Status::capacity_exceeded, BspProblem::too_deep, node, level);
            const BspNode& n = nodes[node];
            if (n.child[0] != kBspNone || n.child[1] != kBspNone) {  // down: the front child if any
                stack[top++] = n.child[0] != kBspNone ? n.child[1] : kBspNone;
                node = n.child[0] != kBspNone ? n.child[0] : n.child[1];
                continue;
            }
            while (top != 0 && stack[top - 1] == kBspNone) --top;  // up to the nearest back child not taken
            if (top == 0) break;
            node = stack[top - 1];
            stack[top - 1] = kBspNone;  // taken: the entry now stands for the step down to it
        }
        if (visits != h.node_count) return refuse(Status::bad_data, BspProblem::shape, visits);  // nodes no parent points to
    }
    if (depth != h.max_depth) return refuse(Status::bad_data, BspProblem::depth, depth, h.max_depth);  // the header's depth is the tree's, not a bound
    out.header = &h;
    out.nodes = {nodes, h.node_count};
    out.triangles = {tris, h.triangle_count};
    out.vertices = {verts, h.vertex_count};
    out.max_depth = depth;
    return Status::ok;
}

}  // namespace hider

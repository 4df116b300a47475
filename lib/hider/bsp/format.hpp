// The flat BSP format shared by the offline compiler (tools/hider-bsp) and the device: a header, then
// nodes, triangles and vertices in little-endian arrays, const data in flash or a checked blob. Every
// node's plane is exact on the world grid: a triangle's (its normal the exact cross product of two edges)
// or an axis plane (a unit normal), through a vertex, so the device's eye-side test is exact and agrees
// with every side the compiler decided. Triangles carry their face id; the compiler fixed the T-junctions its
// cuts made, so the triangles of a face meet without cracks. Nodes and children are indices, children
// only forward (the tree has no cycle).
//
// Byte layout (all little-endian, the blob 8-byte aligned):
//   header    64 B  magic "HBSP", version, sizes, counts, the tree's depth, checksum, world transform; the
//                   checksum covers every byte of the blob but its own four (bsp_checksum)
//   nodes     64 B each, in preorder with the front child first: node 0 is the root (absent when
//             node_count == 0), a node's front child (if any) follows it, its back child follows the
//             front subtree
//     0  int64 n[3]          plane normal (x, y, z), exact; side(p) = n . (p - vertex[origin])
//    24  uint32 origin       a vertex on the plane
//    28  uint32 child[2]     front (side > 0) and back subtree, kBspNone when empty
//    36  uint32 first        triangles lying in the plane: [first, first + count)
//    40  uint32 count
//    44  int16 box_min[3]    world box of the subtree (triangles of the node and below), in units of
//    50  int16 box_max[3]    2^12 raw Q16 (kBspBoxShift), rounded outwards
//    56  int16 normal[3]     unit normal in Q14 (Normal14) for headlight shading, along n
//    62  uint16 cells        for an empty child c (0 front, 1 back), bit c: its cell has the lowest winding
//                            number of the tree's closed surface, bit 2 + c: the highest (hider-bsp proved
//                            it; bsp_visible_faces()); 0 when the compiler could not, or the mesh is open
//   triangles 16 B each: uint32 v[3] vertex indices, uint32 face (bits 0-29 face id, bit 31: the
//             triangle faces against n)
//   vertices  12 B each: int32 x, y, z world position, raw Q16, |coordinate| < 2^27 (kBspWorldLimitRaw)
#pragma once
#include <hider/vec.hpp>

namespace hider {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the BSP blob is little-endian and read in place");

constexpr uint32_t kBspMagic = 0x50534248u;  ///< "HBSP" as bytes
constexpr uint16_t kBspVersion = 2;  ///< 2: the checksum covers the header, nodes in preorder
constexpr uint32_t kBspNone = 0xFFFFFFFFu;   ///< no child
constexpr int kBspBoxShift = 12;             ///< node boxes in units of 2^12 raw Q16 (1/16 world unit)
/// |coordinate| of a BSP vertex stays below this (2048 world units): the int16 boxes then hold every
/// vertex. hider-bsp fits a model into +-512 units.
constexpr int kBspWorldLimitBits = 27;
constexpr int32_t kBspWorldLimitRaw = int32_t{1} << kBspWorldLimitBits;
constexpr uint32_t kBspFaceMask = 0x3FFFFFFFu;
constexpr uint32_t kBspFaceBack = 0x80000000u;  ///< the triangle faces against its node's normal

/// A number scale * 2^exponent with scale in Q30: how the compiler's world transform is stored (the
/// device never needs it; tools map a camera given in model units with it).
struct BspScaled {
    int32_t mantissa_q30;
    int32_t exponent;
};

struct __attribute__((may_alias)) BspHeader {
    uint32_t magic;
    uint16_t version;
    uint16_t header_size;   ///< sizeof(BspHeader)
    uint32_t node_count, triangle_count, vertex_count;
    uint32_t max_depth;     ///< nodes on the longest root-to-leaf path, exactly (bsp_load checks it)
    uint32_t total_size;    ///< bytes of the whole blob
    uint32_t checksum;      ///< bsp_checksum(): FNV-1a of the whole blob but this field
    BspScaled centre[3];    ///< world = (model - centre) * scale
    BspScaled scale;
};
static_assert(sizeof(BspHeader) == 64, "BSP header layout");

struct __attribute__((may_alias)) BspNode {
    int64_t n[3];
    uint32_t origin;
    uint32_t child[2];
    uint32_t first, count;
    int16_t box_min[3], box_max[3];
    int16_t normal[3];
    uint16_t cells;
};
static_assert(sizeof(BspNode) == 64, "BSP node layout");

struct __attribute__((may_alias)) BspTriangle {
    uint32_t v[3];
    uint32_t face;
};
static_assert(sizeof(BspTriangle) == 16, "BSP triangle layout");

struct __attribute__((may_alias)) BspVertex {
    int32_t x, y, z;
};
static_assert(sizeof(BspVertex) == 12, "BSP vertex layout");

/// FNV-1a over n bytes, continuing from `hash` (start with kFnvBasis). Four bytes a loop step: half the
/// loop overhead of a byte at a time, for the whole blob that bsp_load() checks at start-up.
constexpr uint32_t kFnvBasis = 0x811C9DC5u;
constexpr uint32_t fnv1a(const uint8_t* p, size_t n, uint32_t hash = kFnvBasis) {
    constexpr uint32_t kPrime = 0x01000193u;
    const uint8_t* const end4 = p + (n & ~size_t{3});
    for (; p != end4; p += 4) {
        hash = (hash ^ p[0]) * kPrime;
        hash = (hash ^ p[1]) * kPrime;
        hash = (hash ^ p[2]) * kPrime;
        hash = (hash ^ p[3]) * kPrime;
    }
    for (size_t i = 0; i < (n & 3); ++i) hash = (hash ^ p[i]) * kPrime;
    return hash;
}

/// The checksum of a blob of `size` >= sizeof(BspHeader) bytes: FNV-1a of every byte except the checksum
/// field, so the header's depth and world transform are covered as well as the arrays.
constexpr size_t kBspChecksumOffset = 28;
static_assert(offsetof(BspHeader, checksum) == kBspChecksumOffset, "BSP header layout");
constexpr uint32_t bsp_checksum(const uint8_t* blob, size_t size) {
    constexpr size_t after = kBspChecksumOffset + sizeof(uint32_t);
    return fnv1a(blob + after, size - after, fnv1a(blob, kBspChecksumOffset));
}

/// Byte offsets of the arrays in a blob with these counts (and its total size).
struct BspLayout {
    size_t nodes, triangles, vertices, total;
};
constexpr BspLayout bsp_layout(uint32_t nodes, uint32_t triangles, uint32_t vertices) {
    BspLayout l{};
    l.nodes = sizeof(BspHeader);
    l.triangles = l.nodes + size_t{nodes} * sizeof(BspNode);
    l.vertices = l.triangles + size_t{triangles} * sizeof(BspTriangle);
    l.total = l.vertices + size_t{vertices} * sizeof(BspVertex);
    return l;
}

/// BspNode::cells: an empty child's cell whose winding number is the lowest (highest) of the tree's closed
/// surface. From a point of such a cell the nearest surface along any ray is entered from its front
/// (left from its back), so only front (back) faces can be seen: an exact visibility rule, not culling.
constexpr uint16_t kBspCellLowest = 1;   ///< << c for child c
constexpr uint16_t kBspCellHighest = 4;  ///< << c for child c
constexpr uint16_t kBspCellMask = 0xF;
/// bsp_visible_faces() keeps the eye this much (raw Q16) farther from every triangle than the near
/// plane's reach; hider-bsp labels only trees whose triangles stray from their cells by a small fraction
/// of it (cut points are rounded to the grid).
constexpr int32_t kBspCellMarginRaw = int32_t{1} << 12;

/// Stack entries a walk needs per level of the tree (walk.hpp): a node waits for its second subtree.
constexpr uint32_t kBspStackPerLevel = 1;

}  // namespace hider

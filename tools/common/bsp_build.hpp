// The offline BSP compiler (host): splits a mesh's triangles by the planes of chosen triangles into a
// node tree (Fuchs, Kedem & Naylor 1980), fixes the T-junctions the cuts leave (each cut point joins every
// piece along the mesh edge or cut line it lies on, as Quake's qbsp tjunc.c does), triangulates the
// pieces and writes the flat format of lib/hider/bsp/format.hpp. Exact integer geometry on the world
// grid: planes through grid vertices, sides by 128-bit sums; only cut points are rounded (to the nearest
// grid point, the same point for every polygon sharing the cut edge).
#pragma once
#include <hider/bsp/load.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "common/obj.hpp"
#include "common/scene.hpp"

namespace hider::tool {

/// The splitter heuristic: among `candidates` polygons of a node (evenly spaced), the plane with the least
/// cost = split_weight x polygons cut + balance_weight x |front - back| (ZDBSP's form).
struct BspOptions {
    int split_weight = 8;
    int balance_weight = 1;
    int candidates = 32;
    /// 0 (default): off. Else a node of more polygons whose chosen plane leaves one side empty (a chain
    /// link: a convex surface makes the tree one chain, as deep as its polygons) is split instead by an
    /// axis-aligned plane through a median corner: a shallower tree (walk stack) for more cuts (README).
    int max_chain = 0;
};

/// What label_cells() made of a tree's cells.
enum class BspCells : uint8_t {
    labelled,   ///< every empty child's cell of the lowest or highest winding number is labelled
    empty,      ///< no nodes
    open,       ///< the surface is not closed: no winding numbers
    too_large,  ///< empty children x triangles beyond the ray casts' budget
    straying,   ///< a triangle strays more than kBspCellStrayRaw from its cell
    unclear,    ///< a ray starts on, or passes within the margin of, a second surface (touching solids)
    uniform,    ///< every cell has the same winding number
};

/// How far a tree triangle may stray from its cell's planes (raw Q16) for label_cells() to label it: cut
/// points rounded to the grid stray by about a raw unit (1.4 at most on the shared closed models);
/// kBspCellMarginRaw, the runtime's margin, is 256 times more, so only the tip of a wedge-shaped cell
/// narrower than 1/256 rad could hold a point of another winding number that far from every surface.
constexpr double kBspCellStrayRaw = 16;

/// The deepest tree hider-bsp and hider-render walk (their load stack: bsp_stack_entries() of it).
constexpr uint32_t kToolMaxBspDepth = 1u << 16;

struct BspStats {
    std::vector<int> badly_fanned;  ///< bsp_from_obj(): `f` lines badly_fanned_faces() names (for a warning)
    std::vector<int> collapsed;     ///< bsp_from_obj(): `f` lines collapsed_faces() names (for a warning)
    size_t input_triangles = 0;
    size_t degenerate = 0;        ///< input triangles of zero area, dropped
    size_t cuts = 0;              ///< polygons cut in two
    size_t polygons = 0;          ///< pieces after cutting (convex polygons)
    size_t tjunction_points = 0;  ///< points added to polygon edges to close T-junctions
    size_t triangles = 0;         ///< triangles in the tree
    size_t nodes = 0;
    size_t max_depth = 0;
    size_t largest_node = 0;      ///< most triangles in one node's plane
    size_t splitters = 0;         ///< nodes split by an axis plane (BspOptions::max_chain)
    size_t vertices = 0;
    size_t bytes = 0;             ///< blob size
    BspCells cells = BspCells::empty;  ///< whether the cells are labelled, or why not
    size_t cells_labelled = 0;    ///< empty children whose cell got a label (BspNode::cells), 0 when none
    int winding_low = 0, winding_high = 0;  ///< the closed surface's lowest and highest winding numbers
    double cells_stray_raw = 0;   ///< the farthest a triangle strays from its cell (closed surfaces)
    std::string cells_note;       ///< why the cells are not labelled (empty when they are)
};

/// A built tree in the format's layout (host vectors), ready for bsp_blob().
struct BspBuilt {
    std::vector<BspNode> nodes;
    std::vector<BspTriangle> triangles;
    std::vector<BspVertex> vertices;
    uint32_t max_depth = 0;
};

/// Builds the tree of world-space triangles (positions raw Q16 as build_scene makes them, `ids` the face
/// id of each triangle). False with a reason when the result cannot be stored (too many vertices, ...).
bool build_bsp(const std::vector<Vec3q16>& positions, const std::vector<Tri>& tris, const std::vector<uint32_t>& ids,
               const BspOptions& opt, BspBuilt& out, BspStats& stats, std::string& error);

/// Labels the cells of the empty children of a built tree (BspNode::cells) when its triangles form a
/// closed surface (every directed edge matched by its reverse), no triangle strays more than
/// kBspCellStrayRaw past its cell's planes, and every cell's winding number is found: by an exact ray
/// cast from the centre of the node's largest triangle into the child's side, counting signed crossings
/// of all the tree's triangles (a ray through an edge or vertex is cast again; a crossing nearer than the
/// margin, or another triangle through the start, leaves the cell unknown). A cell gets the lowest
/// (highest) label when its winding number is the surface's lowest (highest), counting 0 outside. Labels
/// all or none (stats.cells and cells_note say why none). Called by build_bsp().
void label_cells(BspBuilt& tree, BspStats& stats);

/// The world transform a BSP stores: world = (model - centre) * scale, each number as BspScaled.
struct BspFit {
    Vec3d centre{};
    double scale = 1.0;
};

/// The fit of a model alone (its bounding box into +-kFitHalfExtent world units), rounded to what the
/// blob stores, so a tree built from an OBJ and one loaded from a blob give the same world.
bool bsp_model_fit(const ObjModel& model, BspFit& out, std::string& error);

/// The blob of a built tree: header (with the fit and checksum), nodes, triangles, vertices.
std::vector<uint8_t> bsp_blob(const BspBuilt& tree, const BspFit& fit);

/// The fit stored in a blob's header.
BspFit bsp_fit_of(const BspHeader& h);

/// A C++ header holding the blob as hider::bsp_data::<name>::kBlob, an 8-byte aligned constexpr array,
/// followed by `extra` (more declarations in that namespace); `source` and `options` are recorded in its
/// opening comment. Deterministic (no dates, no directories).
std::string bsp_header_source(const std::vector<uint8_t>& blob, const std::string& name, const std::string& source,
                              const std::string& options = "", const std::string& extra = "");

/// Loads an OBJ model, fits it alone and builds its tree and blob (hider-bsp and hider-render --algo
/// bsp share this). Errors read like hider-render's ("file:line: what" or "file: what").
bool bsp_from_obj(const std::string& path, const BspOptions& opt, std::vector<uint8_t>& blob, BspStats& stats,
                  std::string& error);

/// The scene to draw a loaded tree with: its vertices mapped back to model units (for camera defaults,
/// exactly as for an OBJ) and the camera of `args` (model units) in the tree's world.
bool bsp_scene(const BspTree& tree, const CameraArgs& args, Scene& out, std::string& error);

}  // namespace hider::tool

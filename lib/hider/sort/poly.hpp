// Triangles in screen space for the object-space algorithms (painter, Newell, reverse painter): snapped
// x, y and the same affine depth z the z-buffer interpolates, so their planes are exactly the planes the
// z-buffer steps through. A polygon is a whole triangle or a piece of one: its parent triangle plus a
// chain of cuts in a caller pool (raster/piece.hpp draws it exactly, without cracks).
#pragma once
#include <hider/raster/paint.hpp>
#include <hider/raster/piece.hpp>
#include <hider/raster/vertices.hpp>

namespace hider {

constexpr uint32_t kNoCut = 0xFFFFFFFFu;    ///< end of a cut chain: a whole triangle
constexpr uint32_t kNotMoved = 0xFFFFFFFFu;
constexpr uint8_t kPolyFront = 1;           ///< counter-clockwise on the image

/// One triangle, or a piece of one, in screen space: 56 bytes on every target.
struct ScreenPoly {
    ScreenVertex v[3];               ///< the triangle; for a piece, its parent's exact triangle
    uint32_t zmin, zmax;             ///< depth extent (of the piece)
    int16_t xmin, xmax, ymin, ymax;  ///< bounding box in subpixels (a piece's is one subpixel wider each way)
    uint32_t tri;                    ///< mesh triangle it comes from (colour, id), below kMaxPolyTriangles
    uint32_t moved_at;               ///< Newell: the chain of moves it was last moved in (kNotMoved if never)
    uint32_t cut;                    ///< newest cut of a piece in the cut pool, kNoCut for a whole triangle
    uint8_t flags;                   ///< kPolyFront
    uint8_t part;                    ///< which of the screen triangles clipping made of `tri` (0..13)
};
static_assert(sizeof(ScreenPoly) == 56, "ScreenPoly layout is documented in README.md");
static_assert(ClipPolygon::kMaxVertices - 2 <= 16, "a clipped triangle's parts must fit plane_name()'s 4 bits");

/// Mesh triangles the object-space algorithms accept (build_polys() drops the rest): below 2^27, so
/// that a plane's name fits 31 bits.
constexpr uint32_t kMaxPolyTriangles = uint32_t{1} << 27;

/// The name of p's plane, bits 0-26 its mesh triangle, bits 27-30 its clipped part (bit 31 stays free
/// for kCutFar). The parts of a clipped triangle lie in slightly different planes (their clip vertices
/// are rounded), so a side found against one part must not be taken for another's. A piece keeps its
/// parent's plane. Precondition: p.tri < kMaxPolyTriangles, p.part < 16 (as build_polys() makes them).
inline uint32_t plane_name(const ScreenPoly& p) {
    HIDER_ASSERT(p.tri < kMaxPolyTriangles && p.part < 16);
    return p.tri | uint32_t{p.part} << 27;
}

/// One cut of a piece: the half-plane it keeps, the older cut before it and the plane that made it.
/// Two records per cut (one for each side), 16 bytes each:
///   line      x0 y0 x1 y1 (int16 each, subpixels)   bytes 0-7
///   prev      older cut of the same piece, or kNoCut  bytes 8-11
///   plane     bits 0-30: plane_name() of the polygon that cut it (0-26 its mesh triangle, 27-30 its
///             clipped part); bit 31 (kCutFar): the piece lies on the far side
struct PieceCut {
    CutLine line;
    uint32_t prev;
    uint32_t plane;
};
static_assert(sizeof(PieceCut) == 16, "PieceCut layout is documented above");
constexpr uint32_t kCutFar = 0x80000000u;

/// Fills the extents of a whole triangle from its vertices.
inline void update_extents(ScreenPoly& p) {
    p.zmin = min(p.v[0].z, min(p.v[1].z, p.v[2].z));
    p.zmax = max(p.v[0].z, max(p.v[1].z, p.v[2].z));
    p.xmin = min(p.v[0].x, min(p.v[1].x, p.v[2].x));
    p.xmax = max(p.v[0].x, max(p.v[1].x, p.v[2].x));
    p.ymin = min(p.v[0].y, min(p.v[1].y, p.v[2].y));
    p.ymax = max(p.v[0].y, max(p.v[1].y, p.v[2].y));
}

/// Appends the drawable screen triangles of `mesh` to `out`: clipped pieces, back faces removed when
/// cull is set, zero-area triangles and those covering no pixel centre of the frame skipped. Every
/// mesh triangle lands in exactly one count of st: drawn (a polygon in `out`), culled, degenerate
/// (zero area) or outside (clipped away or no pixel centre). When `out` fills, the rest are dropped
/// and counted (st.status = capacity_exceeded); so are the triangles from kMaxPolyTriangles on (as outside).
/// Fewer verts than mesh positions: nothing appended, st.status = invalid_argument (as draw_zbuffer()).
/// `verts` as for draw_zbuffer(): from project_vertices(), or hand-made ones that pass
/// screen_vertex_valid() (HIDER_ASSERT checks).
inline void build_polys(const View& view, const Mesh& mesh, Span<const ScreenVertex> verts, bool cull,
                        BoundedList<ScreenPoly>& out, FrameStats& st) {
    if (verts.size() < mesh.positions.size()) {
        st.status = Status::invalid_argument;
        return;
    }
    HIDER_ASSERT(screen_vertices_valid(verts.data(), mesh.positions.size()));
    FrameView<Grey8Format> whole;  // geometry only: bounds of the full frame
    whole.width = view.width;
    whole.height = view.height;
    whole.y0 = 0;
    whole.y1 = view.height;
    const BandBounds bb = band_bounds(whole);
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        ++st.triangles_in;
        if (t >= kMaxPolyTriangles) {  // no plane name left for it
            ++st.triangles_outside;
            st.status = Status::capacity_exceeded;
            continue;
        }
        bool drawn = false, culled = false, degenerate = false;
        uint8_t part = 0;
        FrameStats clip;
        for_each_clipped(view, mesh, verts, t, clip, [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
            ++part;
            const int32_t area = TriangleRaster::signed_area(a, b, c);
            if (area == 0) { degenerate = true; return; }
            if (cull && area > 0) { culled = true; return; }
            if (misses_band(screen_box(a, b, c), bb)) return;
            ScreenPoly p{{a, b, c}, 0, 0, 0, 0, 0, 0, static_cast<uint32_t>(t), kNotMoved, kNoCut,
                         static_cast<uint8_t>(area < 0 ? kPolyFront : 0),
                         static_cast<uint8_t>(part - 1)};
            update_extents(p);
            if (out.push_back(p)) drawn = true;
            else st.status = Status::capacity_exceeded;
        });
        st.triangles_clipped += clip.triangles_clipped;
        if (drawn) ++st.triangles_drawn;
        else if (culled) ++st.triangles_culled;
        else if (degenerate) ++st.triangles_degenerate;
        else ++st.triangles_outside;
    }
}

/// The cut lines of polygon p (newest first) into out; returns their count, or -1 when the chain is
/// longer than kMaxPieceCuts (never for chains newell_order() builds).
inline int piece_lines(const ScreenPoly& p, Span<const PieceCut> cuts, CutLine (&out)[kMaxPieceCuts]) {
    int n = 0;
    for (uint32_t c = p.cut; c != kNoCut; c = cuts[c].prev) {
        if (n == kMaxPieceCuts || c >= cuts.size()) return -1;
        out[n++] = cuts[c].line;
    }
    return n;
}

/// Calls draw(raster, y0, y1) with polygon p set up for the band: a TriangleRaster for a whole
/// triangle, a PieceRaster (its parent's edges plus its cut lines) for a piece. Returns draw's result,
/// or 0 when p has no pixel centre in the band.
template <class Frame, class Draw>
__attribute__((always_inline)) inline uint32_t with_poly_raster(const ScreenPoly& p, Span<const PieceCut> cuts, const BandBounds& bb,
                                                                const Frame& frame, Draw&& draw) {
    if (p.ymax < bb.y_first || p.ymin > bb.y_last) return 0;
    if (p.cut == kNoCut) {
        TriangleRaster tr;
        if (!tr.setup(p.v[0], p.v[1], p.v[2], frame.width, frame.height)) return 0;
        const int32_t y0 = max(frame.y0, tr.first_row()), y1 = min(frame.y1, tr.end_row());
        return y0 < y1 ? draw(tr, y0, y1) : 0;
    }
    CutLine lines[kMaxPieceCuts];
    const int n = piece_lines(p, cuts, lines);
    PieceRaster pr;
    if (n < 0 || !pr.setup(p.v[0], p.v[1], p.v[2], {lines, static_cast<size_t>(n)}, frame.width, frame.height)) return 0;
    const int32_t y0 = max(frame.y0, pr.first_row()), y1 = min(frame.y1, pr.end_row());
    return y0 < y1 ? draw(pr, y0, y1) : 0;
}

}  // namespace hider

// A hierarchical grid of polygon boxes over caller memory, so Newell compares a polygon only with those
// whose screen boxes can overlap its own and whose depth ranges reach its own. Level 0 has cells of
// kGridCellPixels; each level doubles the side until one cell covers the frame. A polygon sits in exactly
// one cell: on the finest level whose cells are at least as large as its box, in the cell holding the
// box's top-left corner, so its box lies within that cell and the next one right and down. Each cell's
// list is sorted by zmax, farthest first, so a query stops in a cell at the first polygon wholly nearer
// than the box's zmin. Memory: two links per polygon plus one head per cell (grid_cells()); remove is
// O(1), insert walks its cell's list, a query visits the cells around the box on every level.
#pragma once
#include <hider/sort/poly.hpp>

namespace hider {

/// Side of a level-0 cell in pixels.
constexpr int32_t kGridCellPixels = 16;

namespace detail {
constexpr int32_t grid_cells_at(int32_t pixels, int level) {
    const int32_t side = kGridCellPixels << level;
    return (pixels + side - 1) / side;
}
constexpr int grid_levels(int32_t width, int32_t height) {
    int levels = 1;
    while ((kGridCellPixels << (levels - 1)) < max(width, height)) ++levels;
    return levels;
}
}  // namespace detail

/// Cell heads a ScreenGrid needs for a width x height frame (409 for 320x240, 109 for 160x128).
constexpr size_t grid_cells(int32_t width, int32_t height) {
    size_t n = 0;
    for (int l = 0; l < detail::grid_levels(width, height); ++l)
        n += static_cast<size_t>(detail::grid_cells_at(width, l)) * static_cast<size_t>(detail::grid_cells_at(height, l));
    return n;
}

/// The grid. Polygons are named by their index in the caller's pool (< links' size / 2).
class ScreenGrid {
public:
    static constexpr uint32_t kNone = 0xFFFFFFFFu;

    /// Takes `heads` (>= grid_cells(width, height)) and `links` (two per polygon) and empties the grid.
    /// False when either is too small or the frame size is out of range.
    bool reset(int32_t width, int32_t height, Span<uint32_t> heads, Span<uint32_t> links) {
        if (width < 1 || height < 1 || width > kMaxFrameSide || height > kMaxFrameSide ||
            heads.size() < grid_cells(width, height))
            return false;
        width_ = width;
        height_ = height;
        levels_ = detail::grid_levels(width, height);
        size_t offset = 0;
        for (int l = 0; l < levels_; ++l) {
            cols_[l] = detail::grid_cells_at(width, l);
            rows_[l] = detail::grid_cells_at(height, l);
            offset_[l] = static_cast<uint32_t>(offset);
            count_[l] = 0;
            offset += static_cast<size_t>(cols_[l]) * static_cast<size_t>(rows_[l]);
        }
        heads_ = heads.data();
        for (size_t i = 0; i < offset; ++i) heads_[i] = kNone;
        next_ = links.data();
        prev_ = links.data() + links.size() / 2;
        capacity_ = links.size() / 2;
        return true;
    }
    size_t capacity() const { return capacity_; }

    /// Adds polygon `id` (< capacity()) with box p; `polys` holds the polygons already in the grid (their
    /// zmax orders the cell's list).
    void insert(uint32_t id, const ScreenPoly& p, const ScreenPoly* polys) {
        const Cell c = cell_of(p);
        const uint32_t head = offset_[c.level] + static_cast<uint32_t>(c.cy * cols_[c.level] + c.cx);
        uint32_t before = kHeadTag | head, after = heads_[head];
        while (after != kNone && polys[after].zmax > p.zmax) {
            before = after;
            after = next_[after];
        }
        next_[id] = after;
        prev_[id] = before;
        if (after != kNone) prev_[after] = id;
        if ((before & kHeadTag) != 0) heads_[head] = id;
        else next_[before] = id;
        ++count_[c.level];
    }

    /// Removes polygon `id`, which is in the grid with box p (as inserted).
    void remove(uint32_t id, const ScreenPoly& p) {
        const uint32_t n = next_[id], before = prev_[id];
        if ((before & kHeadTag) != 0) heads_[before & ~kHeadTag] = n;
        else next_[before] = n;
        if (n != kNone) prev_[n] = before;
        --count_[cell_of(p).level];
    }

    /// Calls fn(id) for every polygon in the grid whose box may overlap p's and whose zmax is above p's
    /// zmin (a superset: the caller tests the boxes), until fn returns true; returns true if it did. fn
    /// must not change the grid.
    template <class Fn>
    bool query(const ScreenPoly& p, const ScreenPoly* polys, Fn&& fn) const {
        const PixelBox b = pixel_box(p);
        for (int l = 0; l < levels_; ++l) {
            if (count_[l] == 0) continue;  // most meshes use two or three levels
            const int shift = kCellShift + l;
            const int32_t cx0 = max<int32_t>(0, (b.x0 >> shift) - 1), cx1 = min<int32_t>(cols_[l] - 1, b.x1 >> shift);
            const int32_t cy0 = max<int32_t>(0, (b.y0 >> shift) - 1), cy1 = min<int32_t>(rows_[l] - 1, b.y1 >> shift);
            for (int32_t cy = cy0; cy <= cy1; ++cy)
                for (int32_t cx = cx0; cx <= cx1; ++cx)
                    for (uint32_t id = heads_[offset_[l] + static_cast<uint32_t>(cy * cols_[l] + cx)];
                         id != kNone && polys[id].zmax > p.zmin; id = next_[id])
                        if (fn(id)) return true;
        }
        return false;
    }

private:
    static constexpr uint32_t kHeadTag = 0x80000000u;  ///< prev_ of a list's first polygon: its head's index
    static constexpr int kCellShift = 4;               ///< log2(kGridCellPixels)
    static_assert((1 << kCellShift) == kGridCellPixels, "cell side is a power of two");
    static constexpr int kMaxLevels = 8;               ///< 16 << 7 = 2048 > kMaxFrameSide

    struct PixelBox {
        int32_t x0, x1, y0, y1;  ///< inclusive pixel range of a box, clamped to the frame
    };
    struct Cell {
        int level;
        int32_t cx, cy;
    };

    PixelBox pixel_box(const ScreenPoly& p) const {
        const int32_t ox = pixel_centre_origin(width_), oy = pixel_centre_origin(height_);
        auto px = [](int32_t sub, int32_t origin, int32_t n) { return clamp<int32_t>((sub - origin) >> kSubpixelBits, 0, n - 1); };
        return {px(p.xmin, ox, width_), px(p.xmax, ox, width_), px(p.ymin, oy, height_), px(p.ymax, oy, height_)};
    }

    Cell cell_of(const ScreenPoly& p) const {
        const PixelBox b = pixel_box(p);
        const int32_t size = max(b.x1 - b.x0, b.y1 - b.y0) + 1;
        int level = 0;
        while (level + 1 < levels_ && (kGridCellPixels << level) < size) ++level;
        return {level, b.x0 >> (kCellShift + level), b.y0 >> (kCellShift + level)};
    }

    uint32_t* heads_ = nullptr;
    uint32_t* next_ = nullptr;
    uint32_t* prev_ = nullptr;
    size_t capacity_ = 0;
    int32_t width_ = 0, height_ = 0;
    int levels_ = 0;
    int32_t cols_[kMaxLevels] = {}, rows_[kMaxLevels] = {};
    uint32_t offset_[kMaxLevels] = {};
    uint32_t count_[kMaxLevels] = {};  ///< polygons on each level
};

}  // namespace hider

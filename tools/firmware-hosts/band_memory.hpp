// Host side of the band renderer's buffers (what a band firmware declares statically), for the host
// twins of the band firmware (bands_reference.cpp, oled_reference.cpp).
#pragma once
#include <algorithm>
#include <vector>

#include "bands/bands.hpp"

namespace host {

/// Band renderer memory for `rows` rows of the full width (`pixels`, if more, for a column window) and
/// `carried_slots` carried slots.
struct BandMemory {
    std::vector<hider::ScreenVertex> verts;
    std::vector<uint16_t> color, depth, next, head;
    std::vector<hider::KernelTriangle> carried;
    std::vector<uint8_t> slots;
    int32_t rows;
    BandMemory(const spin::Scene& s, int32_t band_rows, size_t carried_slots, size_t pixels = 0)
        : verts(s.mesh.positions.size()),
          color(std::max(static_cast<size_t>(s.width) * static_cast<size_t>(band_rows), pixels)), depth(color.size()),
          next(s.mesh.tris.size()), head(static_cast<size_t>((s.height + band_rows - 1) / band_rows)),
          carried(carried_slots), slots(3 * carried_slots), rows(band_rows) {}
    bands::BandBuffers buffers() {
        return {{verts.data(), verts.size()}, {color.data(), color.size()}, {depth.data(), depth.size()}, rows,
                {{next.data(), next.size()}, {head.data(), head.size()}, {carried.data(), carried.size()},
                 {slots.data(), slots.size()}}};
    }
};

}  // namespace host

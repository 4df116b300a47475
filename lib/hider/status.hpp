// Status values returned by lib/ entry points (no exceptions) and the per-frame statistics.
#pragma once
#include <hider/base.hpp>

namespace hider {

enum class Status : uint8_t {
    ok = 0,
    capacity_exceeded,  ///< a fixed pool filled; output is valid but incomplete
    invalid_argument,   ///< caller broke a documented precondition (checked at API entry)
    bad_data,           ///< baked asset or input data failed validation
    out_of_range,       ///< a coordinate lies outside the documented fixed-point range
};

/// Short lowercase name of a status, for messages.
constexpr const char* status_name(Status s) {
    switch (s) {
        case Status::ok: return "ok";
        case Status::capacity_exceeded: return "capacity exceeded";
        case Status::invalid_argument: return "invalid argument";
        case Status::bad_data: return "bad data";
        case Status::out_of_range: return "out of range";
    }
    return "unknown";
}

/// What one draw call did.
struct [[nodiscard]] FrameStats {
    Status status = Status::ok;
    uint32_t triangles_in = 0;       ///< triangles looked at
    uint32_t triangles_drawn = 0;    ///< triangles (or clipped pieces) that reached the rasterizer; a band
                                     ///< counts those whose first row it holds, so bands add up
    uint32_t triangles_culled = 0;   ///< back faces removed (counted like triangles_drawn)
    uint32_t triangles_clipped = 0;  ///< triangles that needed near/far/guard clipping
    uint32_t triangles_outside = 0;  ///< wholly outside one clip plane (sorted algorithms: or no pixel centre)
    uint32_t triangles_degenerate = 0;  ///< zero area on the screen (sorted algorithms)
    uint64_t fragments = 0;       ///< pixel centres covered (z-buffer: counted by draw_zbuffer<true> only); 64 bits,
                                  ///< since a frame of many overlapping triangles can pass 2^32
    uint64_t pixels_written = 0;  ///< colour writes (only counted when the variant counts them)
    uint32_t nodes_visited = 0;     ///< BSP walks: nodes entered
    uint32_t subtrees_skipped = 0;  ///< BSP walks: subtrees not entered (outside the band, or covered)

    constexpr bool ok() const { return status == Status::ok; }
    /// Adds another call's counts (a band of the same frame); the first non-ok status wins.
    void merge(const FrameStats& o) {
        if (status == Status::ok) status = o.status;
        triangles_in += o.triangles_in;
        triangles_drawn += o.triangles_drawn;
        triangles_culled += o.triangles_culled;
        triangles_clipped += o.triangles_clipped;
        triangles_outside += o.triangles_outside;
        triangles_degenerate += o.triangles_degenerate;
        fragments += o.fragments;
        pixels_written += o.pixels_written;
        nodes_visited += o.nodes_visited;
        subtrees_skipped += o.subtrees_skipped;
    }
};

}  // namespace hider

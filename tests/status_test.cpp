// Status names and FrameStats: band statistics merge into frame totals, and the pixel counters do not
// wrap at 2^32 (a frame of thousands of full-screen triangles at 1024x1024 writes more pixels than that).
#include <hider/status.hpp>

#include <doctest/doctest.h>

#include <string>

using namespace hider;

TEST_CASE("FrameStats merges bands without wrapping the pixel counters at 2^32") {
    FrameStats frame;
    FrameStats band;
    band.fragments = 3000000000u;  // 6,000 quads of 500,000 pixels: one band's worth, twice
    band.pixels_written = 2900000000u;
    band.triangles_drawn = 6000;
    frame.merge(band);
    frame.merge(band);
    CHECK(frame.fragments == 6000000000u);
    CHECK(frame.pixels_written == 5800000000u);
    CHECK(frame.triangles_drawn == 12000);
    CHECK(frame.ok());
    FrameStats full;
    full.status = Status::capacity_exceeded;
    frame.merge(full);
    CHECK(frame.status == Status::capacity_exceeded);  // the first non-ok status wins
    frame.merge(FrameStats{});
    CHECK(frame.status == Status::capacity_exceeded);
}

TEST_CASE("every status has a name") {
    for (Status s : {Status::ok, Status::capacity_exceeded, Status::invalid_argument, Status::bad_data, Status::out_of_range})
        CHECK(std::string(status_name(s)) != "unknown");
}

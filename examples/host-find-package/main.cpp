// Host consumer of an installed hider (find_package): renders the example scene as one 160x128
// RGB565 frame and writes it as a PPM with hider::port_host. The program's own code uses exceptions
// and RTTI, which hider must leave on. Usage: render_scene OUT.ppm
#include <hider/raster/zbuffer.hpp>
#include <host/ppm.hpp>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

#include "example_scene.hpp"

static_assert(__cpp_exceptions, "this program is built with exceptions on");
static_assert(__cpp_rtti, "this program is built with RTTI on");

namespace {

struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void expect_ok(hider::Status s, const char* what) {
    if (s != hider::Status::ok) throw RenderError(std::string(what) + ": " + hider::status_name(s));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: render_scene OUT.ppm\n");
        return 2;
    }
    try {
        std::vector<uint16_t> color(example::kWidth * example::kHeight), depth(color.size());
        std::vector<hider::ScreenVertex> verts(example::mesh().positions.size());
        hider::View view;
        expect_ok(hider::make_view(example::camera(), example::kWidth, example::kHeight, view), "make_view");
        expect_ok(hider::project_vertices(view, example::mesh().positions, {verts.data(), verts.size()}), "project");
        const auto frame = hider::frame_view<hider::Rgb565Format, uint16_t>(color.data(), depth.data(), example::kWidth,
                                                                           example::kHeight);
        const hider::FrameStats st = example::draw(view, {verts.data(), verts.size()}, frame);
        expect_ok(st.status, "draw");
        if (st.triangles_drawn == 0) throw RenderError("nothing drawn");
        std::string error;
        if (!hider::port::write_ppm(argv[1], frame, error)) throw RenderError(error);
        std::printf("%s: %u triangles drawn\n", argv[1], static_cast<unsigned>(st.triangles_drawn));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_scene: %s (%s)\n", e.what(), typeid(e).name());
        return 1;
    }
    return 0;
}

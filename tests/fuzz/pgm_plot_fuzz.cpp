// libFuzzer target (clang, ASan, UBSan): arbitrary bytes as a PGM height map (hider-plot --heightmap)
// through read_pgm(), heightmap_grid() (the image's own grid; 7x11 with the mesh), the default camera and
// the floating horizon at 32x24, whole and in 3-row bands. Fails on a crash or sanitizer report, a failure
// without a reason, or bands whose bytes differ from the whole frame's (ctest pgm_plot_fuzz).
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "hider-plot/plot.hpp"
#include "hider-plot/surface.hpp"

namespace {

using namespace hider::plot;

std::string g_path;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "pgm_plot_fuzz: %s\n", what);
    std::abort();
}

void remove_file() { std::remove(g_path.c_str()); }

void plot(const HeightGrid& grid, bool mesh) {
    ViewArgs args;
    args.width = 32;
    args.height = 24;
    CameraD cam;
    std::string why;
    if (!resolve_camera(grid, args, cam, why)) {
        if (why.empty()) fail("resolve_camera failed without a reason");
        return;
    }
    Options opt;
    opt.shade = Shade::height;
    opt.mesh = mesh;
    Result whole, banded;
    std::string why_whole, why_banded;
    const bool ok = render(grid, cam, opt, whole, why_whole);
    if (!ok && why_whole.empty()) fail("render failed without a reason");
    opt.band_rows = 3;
    const bool ok_banded = render(grid, cam, opt, banded, why_banded);
    if (ok != ok_banded) fail("whole frame and bands disagree on success");
    if (ok && (whole.rgb.size() != 32 * 24 * 3 || whole.rgb != banded.rgb)) fail("bands differ from the whole frame");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const char* tmp = std::getenv("TMPDIR");
    std::string path = std::string(tmp != nullptr && *tmp != 0 ? tmp : "/tmp") + "/hider-pgm-fuzz-XXXXXX";
    const int fd = mkstemp(path.data());
    if (fd < 0) fail("cannot make a temporary file");
    close(fd);
    g_path = path;
    std::atexit(remove_file);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::FILE* f = std::fopen(g_path.c_str(), "wb");
    if (f == nullptr || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0) fail("cannot write the input");
    Pgm pgm;
    std::string why;
    if (!read_pgm(g_path, pgm, why)) {
        if (why.empty()) fail("read_pgm failed without a reason");
        return 0;
    }
    if (pgm.width > 64 || pgm.height > 64) return 0;  // larger grids only cost time here
    plot(heightmap_grid(pgm, 0.5, 0, 0), false);
    plot(heightmap_grid(pgm, 0.4, 7, 11), true);
    return 0;
}

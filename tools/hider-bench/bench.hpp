// hider-bench internals shared by its commands: argument helpers, the commands themselves, the
// process and callgrind runners and the host-side scene preparation. Exit codes: 0 ok, 2 usage or run
// error, kExitSkipped (77) when valgrind or every cross build tree is missing.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

#include <hider/sort/newell.hpp>

#include "common/cli.hpp"
#include "common/scene.hpp"

namespace hider::tool::bench {

/// Exit status when a command cannot run here (77 = "skipped" for ctest's SKIP_RETURN_CODE): no
/// valgrind, or (targets) no cross build tree.
constexpr int kExitSkipped = 77;
constexpr int kExitNoValgrind = kExitSkipped;

using Args = std::vector<std::string>;

[[noreturn]] void fail(const std::string& msg);

/// Consumes a camera option (--size --eye --target --up --fov --near --far) at args[i] and its value;
/// returns false if args[i] is not one. Exits with a message on a bad value.
bool parse_camera_option(const Args& args, size_t& i, CameraArgs& cam);

/// Value of the option at args[i] (advances i); exits if it is missing.
const std::string& option_value(const Args& args, size_t& i);

int frame_command(const Args& args);      ///< hider-bench frame ...
int carry_command(const Args& args);      ///< hider-bench carry ...
int table_command(const Args& args);      ///< hider-bench table ...
int span_command(const Args& args);       ///< hider-bench span ...
int span_run_command(const Args& args);   ///< internal: the span loop that span runs under callgrind
int targets_command(const Args& args);    ///< hider-bench targets ...
int sort_command(const Args& args);       ///< hider-bench sort ...
int sort_run_command(const Args& args);   ///< internal: one painter_order call that sort runs under callgrind
int newell_command(const Args& args);     ///< hider-bench newell ...
int newell_run_command(const Args& args); ///< internal: painter_order then newell_order, run under callgrind
int waterfall_command(const Args& args);  ///< hider-bench waterfall ... (waterfall.cpp)
int raytrace_command(const Args& args);      ///< hider-bench raytrace ... (ray.cpp)
int raytrace_run_command(const Args& args);  ///< internal: the demo's rows, one measured call each
int raycast_command(const Args& args);       ///< hider-bench raycast ... (ray.cpp)
int raycast_run_command(const Args& args);   ///< internal: a ray-cast frame, or sampled rays (BVH / brute force)
int bsp_command(const Args& args);           ///< hider-bench bsp ... (bsp.cpp)

/// Directory of the benchmark models: HIDER_BENCH_MODELS_DIR (the source tree's tests/data/models).
std::string default_models_dir();
/// Top of the source tree, derived from default_models_dir() ("." when that is relative and short).
std::filesystem::path source_root();

/// Camera options of the torus standard view (tests/data/models/README.md) at `size` ("WxH"): the view
/// firmware/common/scenes/torus_*.hpp are baked with (tools/hider-bake/scenes.cmake).
Args torus_view(const std::string& size);

/// CameraArgs from camera options (parse_camera_option); exits on anything else.
CameraArgs camera_from(const Args& options);

/// Per-frame statistics of `hider-bench frame` (the last of `frames` identical frames).
struct FrameSummary {
    int width = 0, height = 0;
    FrameStats stats{};
    uint32_t covered = 0;  ///< pixels whose depth is no longer the clear value
    size_t pixels = 0;
};

/// Runs the frame command's measured frame `frames` times on the model and returns its statistics.
/// Exits with a message on a load, scene or lib/ error.
FrameSummary run_frames(const std::string& model_path, const CameraArgs& cam, int depth_bits, long frames);

/// Drawable screen polygons of a model (build_polys), in storage with room for cuts.
struct ScreenPolys {
    Scene scene;
    View view{};
    std::vector<ScreenPoly> store;  ///< capacity of the pool; the first `built` entries are the polygons
    size_t built = 0;
    FrameStats stats{};  ///< build_polys statistics (triangles in, culled, clipped)
};

/// Loads the model (an .obj path, or a generated scene's name: common/gen_scenes.hpp, with its own
/// camera unless `cam` sets one), projects it and builds its screen polygons (back faces removed when
/// cull) into a pool of triangles * 7 entries (7 = most pieces of one clipped triangle), plus, with
/// cut_room, hider-render's default room for Newell's cuts (default_split_pool). Exits on errors.
ScreenPolys build_screen_polys(const std::string& model_path, const CameraArgs& cam, bool cull, bool cut_room);

/// n zero-filled elements of T at a 64-byte boundary, so counts inside memset and friends do not
/// depend on where the allocator happened to place a buffer.
template <class T>
class AlignedBuffer {
    static_assert(std::is_trivially_destructible<T>::value, "freed without destructors");

public:
    explicit AlignedBuffer(size_t n) : size_(n) {
        if (n > (size_t{1} << 32)) fail("buffer of " + std::to_string(n) + " elements is too large");
        const size_t bytes = (n * sizeof(T) + 63) / 64 * 64;
        data_.reset(static_cast<T*>(std::aligned_alloc(64, bytes == 0 ? 64 : bytes)));
        if (!data_) fail("out of memory");
        for (size_t i = 0; i < n; ++i) new (data_.get() + i) T{};  // T is trivially destructible
    }
    T* data() const { return data_.get(); }
    size_t size() const { return size_; }

private:
    struct Free {
        void operator()(T* p) const { std::free(p); }
    };
    std::unique_ptr<T, Free> data_;
    size_t size_;
};

/// A fresh private directory under $TMPDIR (or /tmp), removed with its contents by the destructor.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

/// Whole contents of a file ("" when it cannot be read).
std::string read_text(const std::filesystem::path& path);

/// How a child process ended.
struct ProcessResult {
    bool exited = false;  ///< false: killed by a signal
    int status = 0;       ///< exit status when exited
    std::string describe() const;  ///< "exit N" or "killed by a signal"
};

/// Runs argv[0] (a path, or a name looked up on PATH) with `argv` in directory `cwd` (empty: this
/// one), the environment plus `env` ("NAME=value" entries, which override), stdout and stderr into the
/// given files. On a spawn or wait failure returns false with `error` set.
bool run_process(const Args& argv, const std::string& cwd, const Args& env, const std::string& stdout_file,
                 const std::string& stderr_file, ProcessResult& result, std::string& error);

/// The .obj files of a models directory, sorted by name; exits when there are none.
std::vector<std::string> model_files(const std::string& dir);

/// The insncount plugin's counts of one firmware run (tools/qemu-insncount/run.sh).
struct TargetCount {
    uint64_t region = 0, pairs = 0, max = 0;  ///< bench_begin..bench_end summed, pairs, the largest pair
};

/// Runs `elf` (relative to build tree `tree` of `preset`) on `machine` (big|small) under QEMU with the
/// plugin of that tree. False when the ELF is not there; exits with a message when the run fails.
bool firmware_count(const std::filesystem::path& tree, const std::string& preset, const std::string& elf,
                    const std::string& machine, TargetCount& c);

/// What one callgrind run produced.
struct CallgrindRun {
    uint64_t ir = 0;     ///< total Ir collected (only inside the toggled function)
    std::string out;     ///< the program's stdout
};

/// Path of valgrind: `given` if not empty (must be executable), else the first one on PATH. Exits with
/// kExitNoValgrind and an install hint when there is none.
std::string find_valgrind(const std::string& given);

/// Runs this executable with `args` under callgrind, collecting only inside `function`. Exits with a
/// message (and the program's stderr) if the run fails or collects nothing.
CallgrindRun run_callgrind(const std::string& valgrind, const std::string& function, const Args& args);

}  // namespace hider::tool::bench

// hider-bench targets: instruction counts on the cross targets (docs/targets.md s.6). For each preset
// build tree that exists (DIR/cm0plus, DIR/cm3, DIR/rv32imac) it runs the spin and spanbench firmware
// under QEMU with the insncount plugin through tools/qemu-insncount/run.sh (which picks the machine per
// target), reads the bench_begin..bench_end region and prints a Markdown table. The covered pixels per
// frame come from the host: the frame command's code (run_frames) on the same torus view.
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <map>

#include "bench.hpp"

namespace hider::tool::bench {
namespace {

namespace fs = std::filesystem;

const char* const kPresets[] = {"cm0plus", "cm3", "rv32imac"};

/// The firmware run per target, relative to the build tree. spanbench ELFs hold one span call each.
struct Firmware {
    const char* key;
    const char* path;
    bool one_pair;  ///< the region must be exactly one bench_begin..bench_end pair
};
const Firmware kFirmware[] = {
    {"spin320", "firmware/spin/spin320.elf", true},
    {"spin", "firmware/spin/spin.elf", false},
    {"pass320", "firmware/spanbench/spanbench_pass320.elf", true},
    {"pass1", "firmware/spanbench/spanbench_pass1.elf", true},
    {"fail320", "firmware/spanbench/spanbench_fail320.elf", true},
    {"fail1", "firmware/spanbench/spanbench_fail1.elf", true},
    {"kpass320", "firmware/spanbench/spanbench_kpass320.elf", true},
    {"kpass1", "firmware/spanbench/spanbench_kpass1.elf", true},
    {"kfail320", "firmware/spanbench/spanbench_kfail320.elf", true},
    {"kfail1", "firmware/spanbench/spanbench_kfail1.elf", true},
};
constexpr uint64_t kSpanPixels = 320;

struct Count {
    uint64_t total = 0, region = 0, pairs = 0;
};

/// NAME -> value of a CMakeCache.txt ("NAME:TYPE=value" lines).
std::map<std::string, std::string> read_cache(const fs::path& file) {
    std::map<std::string, std::string> cache;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line[0] == '/') continue;
        const size_t colon = line.find(':'), eq = line.find('=');
        if (colon == std::string::npos || eq == std::string::npos || colon > eq) continue;
        cache[line.substr(0, colon)] = line.substr(eq + 1);
    }
    return cache;
}

/// Runs one ELF with run.sh in a private directory (the firmware's semihosted files land there).
Count run_firmware(const fs::path& run_sh, const std::string& preset, const fs::path& elf, const Args& env) {
    const TempDir tmp;
    const fs::path counts = tmp.path() / "counts.txt";
    const std::string out_file = (tmp.path() / "stdout").string(), err_file = (tmp.path() / "stderr").string();
    ProcessResult result;
    std::string error;
    const Args argv = {"sh", run_sh.string(), preset, elf.string(), counts.string(), "big"};
    if (!run_process(argv, tmp.path().string(), env, out_file, err_file, result, error)) fail(error);
    if (!result.exited || result.status != 0)
        fail(elf.string() + ": run under QEMU failed (" + result.describe() + "):\n" + read_text(err_file));
    Count c;
    const std::string line = read_text(counts);
    unsigned long long total = 0, region = 0, pairs = 0;
    if (std::sscanf(line.c_str(), "insncount total=%llu region=%llu pairs=%llu", &total, &region, &pairs) != 3)
        fail(elf.string() + ": no counts from the insncount plugin: '" + line + "'");
    c.total = total;
    c.region = region;
    c.pairs = pairs;
    return c;
}

std::string decimals(double v, int places) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", places, v);
    return buf;
}

/// Instructions per frame: exact when the frames divide the region, else one decimal.
std::string per_frame(const Count& c) {
    return c.region % c.pairs == 0 ? std::to_string(c.region / c.pairs)
                                   : decimals(static_cast<double>(c.region) / static_cast<double>(c.pairs), 1);
}

std::string per_covered(const Count& c, uint32_t covered) {
    return decimals(static_cast<double>(c.region) / static_cast<double>(c.pairs) / covered, 1);
}

std::string per_span_pixel(const Count& full, const Count& one, const std::string& what) {
    if (full.region < one.region) fail("targets: span count at 320 px is below the 1-px count (" + what + ")");
    return decimals(static_cast<double>(full.region - one.region) / static_cast<double>(kSpanPixels - 1), 2);
}

}  // namespace

int targets_command(const Args& args) {
    fs::path root = source_root() / "build";
    std::string models = default_models_dir();
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--build-root") root = option_value(args, i);
        else if (args[i] == "--models") models = option_value(args, i);
        else fail("targets: unknown argument '" + args[i] + "'");
    }
    std::vector<std::string> presets, missing;
    for (const char* preset : kPresets)
        (fs::is_regular_file(root / preset / "CMakeCache.txt") ? presets : missing).push_back(preset);
    if (presets.empty()) {
        std::fprintf(stderr,
                     "hider-bench: no cross build tree under %s (none of cm0plus, cm3, rv32imac); build one with "
                     "cmake --workflow --preset cm0plus (or cm3, rv32imac)\n",
                     root.string().c_str());
        return kExitSkipped;
    }

    // Every ELF must be there before anything runs, so a partial build fails early and says what to do.
    for (const std::string& preset : presets)
        for (const Firmware& fw : kFirmware)
            if (!fs::is_regular_file(root / preset / fw.path))
                fail((root / preset / fw.path).string() + " is missing; build it: cmake --build " +
                     (root / preset).string());

    const std::string torus = models + "/torus.obj";
    const FrameSummary large = run_frames(torus, camera_from(torus_view("320x240")), 16, 1);
    const FrameSummary small = run_frames(torus, camera_from(torus_view("160x128")), 16, 1);
    if (large.covered == 0 || small.covered == 0) fail("targets: the host torus covers no pixel");

    std::map<std::string, std::map<std::string, Count>> counts;
    for (const std::string& preset : presets) {
        const fs::path tree = root / preset;
        std::map<std::string, std::string> cache = read_cache(tree / "CMakeCache.txt");
        const fs::path source =
            cache.count("CMAKE_HOME_DIRECTORY") != 0 ? fs::path(cache["CMAKE_HOME_DIRECTORY"]) : source_root();
        const fs::path run_sh = source / "tools/qemu-insncount/run.sh";
        if (!fs::is_regular_file(run_sh)) fail(run_sh.string() + ": not found (source tree of " + tree.string() + ")");
        Args env;
        // The tree's own plugin and nm; without them run.sh builds the plugin and guesses nm itself.
        const std::string plugin = cache["HIDER_INSNCOUNT_PLUGIN"];
        if (!plugin.empty() && fs::is_regular_file(plugin)) env.push_back("INSNCOUNT_PLUGIN=" + plugin);
        if (!cache["CMAKE_NM"].empty()) env.push_back("NM=" + cache["CMAKE_NM"]);
        for (const Firmware& fw : kFirmware) {
            const Count c = run_firmware(run_sh, preset, tree / fw.path, env);
            if (c.pairs == 0 || (fw.one_pair && c.pairs != 1))
                fail((tree / fw.path).string() + ": " + std::to_string(c.pairs) + " bench pairs, expected " +
                     (fw.one_pair ? "1" : "at least 1"));
            counts[preset][fw.key] = c;
        }
    }

    const uint64_t spin_frames = counts[presets.front()]["spin"].pairs;
    std::printf("Instructions counted by QEMU's insncount plugin from bench_begin to bench_end (not cycles; compare\n"
                "within a target). Machines: mps2-an385 (cm0plus runs its ARMv6-M code on the Cortex-M3 model, cm3),\n"
                "virt (rv32imac). Firmware from the MinSizeRel build trees under the build root.\n"
                "- torus 320x240: spin320, one frame (view setup, projection, clear, draw_zbuffer).\n"
                "- torus 160x128: spin, mean over its %" PRIu64 " frames: frame 0 is the standard view, the\n"
                "  others turn the model about the vertical axis (firmware/spin/render.hpp). instr/covered px\n"
                "  divides that mean by the covered pixels of frame 0.\n"
                "- covered px from the host (hider-bench frame code, same view, 16-bit depth): 320x240 %" PRIu32
                ", 160x128 %" PRIu32 ".\n"
                "- span: span_depth_test_paired<false> (the z-buffer's out-of-line span for RGB565 + 16-bit depth);\n"
                "  kernel: run_row_kernel() on one row (the z-buffer's loop for flat triangles inside the frame's\n"
                "  columns); flat colour (firmware/spanbench); instr/px =\n"
                "  (count of a 320-px call - count of a 1-px call) / 319.\n",
                spin_frames, large.covered, small.covered);
    if (!missing.empty()) {
        std::printf("- not measured (no build tree):");
        for (const std::string& m : missing) std::printf(" %s", m.c_str());
        std::printf("\n");
    }
    std::printf("\n| target | torus 320x240 instr/frame | instr/covered px | torus 160x128 instr/frame "
                "| instr/covered px | kernel instr/px (all pass) | kernel instr/px (none pass) "
                "| span instr/px (all pass) | span instr/px (none pass) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& preset : presets) {
        std::map<std::string, Count>& c = counts[preset];
        if (c["spin"].pairs != spin_frames) fail("targets: spin renders a different number of frames per target");
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", preset.c_str(), per_frame(c["spin320"]).c_str(),
                    per_covered(c["spin320"], large.covered).c_str(), per_frame(c["spin"]).c_str(),
                    per_covered(c["spin"], small.covered).c_str(),
                    per_span_pixel(c["kpass320"], c["kpass1"], "kernel pass").c_str(),
                    per_span_pixel(c["kfail320"], c["kfail1"], "kernel fail").c_str(),
                    per_span_pixel(c["pass320"], c["pass1"], "pass").c_str(),
                    per_span_pixel(c["fail320"], c["fail1"], "fail").c_str());
    }
    std::printf("\nRegion counts (instructions; spin: all %" PRIu64 " frames):\n\n", spin_frames);
    std::printf("| target | spin320 | spin | span 320 px pass | span 1 px pass | span 320 px fail "
                "| span 1 px fail | kernel 320 px pass | kernel 1 px pass | kernel 320 px fail | kernel 1 px fail |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& preset : presets) {
        std::map<std::string, Count>& c = counts[preset];
        std::printf("| %s | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " | %" PRIu64
                    " | %" PRIu64 " | %" PRIu64 " | %" PRIu64 " |\n",
                    preset.c_str(), c["spin320"].region, c["spin"].region, c["pass320"].region, c["pass1"].region,
                    c["fail320"].region, c["fail1"].region, c["kpass320"].region, c["kpass1"].region,
                    c["kfail320"].region, c["kfail1"].region);
    }
    return 0;
}

}  // namespace hider::tool::bench

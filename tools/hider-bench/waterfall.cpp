// hider-bench waterfall: instruction counts of the floating-horizon waterfall (firmware/waterfall) on
// the cross targets. For each preset build tree that exists it runs waterfall_mono (128x64 1-bit, each
// frame's clear + plot measured), waterfall_projection (the 64 curves' projection alone) and
// waterfall_colour (160x128 RGB565 in 8-row bands, each band measured) on the small machine they are
// linked for, under QEMU with the insncount plugin, and prints per frame and per curve sample.
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <map>

#include "bench.hpp"

namespace hider::tool::bench {
namespace {

namespace fs = std::filesystem;

const char* const kPresets[] = {"cm0plus", "cm3", "rv32imac"};
constexpr uint64_t kSamplesPerFrame = 64 * 128;  // waterfall::kCurves x kSamples
constexpr uint64_t kBandsPerFrame = 16;          // 128 rows in bands of 8

struct Count {
    uint64_t total = 0, region = 0, pairs = 0;
};

std::map<std::string, std::string> cache_of(const fs::path& tree) {
    std::map<std::string, std::string> cache;
    std::ifstream in(tree / "CMakeCache.txt");
    for (std::string line; std::getline(in, line);) {
        const size_t colon = line.find(':'), eq = line.find('=');
        if (line.empty() || line[0] == '#' || line[0] == '/' || colon == std::string::npos || eq == std::string::npos ||
            colon > eq)
            continue;
        cache[line.substr(0, colon)] = line.substr(eq + 1);
    }
    return cache;
}

Count run_small(const fs::path& run_sh, const std::string& preset, const fs::path& elf, const Args& env) {
    const TempDir tmp;
    const fs::path counts = tmp.path() / "counts.txt";
    const std::string out_file = (tmp.path() / "stdout").string(), err_file = (tmp.path() / "stderr").string();
    ProcessResult result;
    std::string error;
    if (!run_process({"sh", run_sh.string(), preset, elf.string(), counts.string(), "small"}, tmp.path().string(), env,
                     out_file, err_file, result, error))
        fail(error);
    if (!result.exited || result.status != 0)
        fail(elf.string() + ": run under QEMU failed (" + result.describe() + "):\n" + read_text(err_file));
    unsigned long long total = 0, region = 0, pairs = 0;
    const std::string line = read_text(counts);
    if (std::sscanf(line.c_str(), "insncount total=%llu region=%llu pairs=%llu", &total, &region, &pairs) != 3 || pairs == 0)
        fail(elf.string() + ": no counts from the insncount plugin: '" + line + "'");
    return {total, region, pairs};
}

std::string with_commas(uint64_t v) {
    std::string s = std::to_string(v);
    for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<size_t>(i), ",");
    return s;
}

std::string per_sample(uint64_t per_frame) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", static_cast<double>(per_frame) / kSamplesPerFrame);
    return buf;
}

}  // namespace

int waterfall_command(const Args& args) {
    fs::path root = source_root() / "build";
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--build-root") root = option_value(args, i);
        else fail("waterfall: unknown argument '" + args[i] + "'");
    }
    root = fs::absolute(root);  // run.sh runs in another directory
    const char* const firmware[] = {"waterfall_mono", "waterfall_projection", "waterfall_colour"};
    std::vector<std::string> presets;
    for (const char* preset : kPresets) {
        bool all = fs::is_regular_file(root / preset / "CMakeCache.txt");
        for (const char* fw : firmware) all = all && fs::is_regular_file(root / preset / "firmware/waterfall" / (std::string(fw) + ".elf"));
        if (all) presets.push_back(preset);
    }
    if (presets.empty()) {
        std::fprintf(stderr, "hider-bench: no cross build tree under %s with the waterfall firmware; build one with "
                             "cmake --workflow --preset cm0plus (or cm3, rv32imac)\n", root.string().c_str());
        return kExitSkipped;
    }
    std::printf("Instructions counted by QEMU's insncount plugin (not cycles; compare within a target), firmware from\n"
                "the MinSizeRel (-Os) build trees under %s, run on the 16 KB machines they are linked for. The\n"
                "waterfall: 64 curves of 128 samples (8-bit heights), 4 frames after the history fills.\n"
                "- frame: clear + plot of one 128x64 1-bit frame (the new spectrum excluded), mean of the frames;\n"
                "- projection: the 64 curves projected alone (waterfall_projection); drawing = frame - projection\n"
                "  (the walk along the curves, the horizons, the pixels, the side edges, the 1 KB clear);\n"
                "- per sample: divided by 8192; colour: one 160x128 RGB565 frame plotted in 16 bands of 8 rows.\n\n",
                root.string().c_str());
    std::printf("| target | frame | per sample | projection | per sample | drawing | per sample | 160x128 RGB565 frame (16 bands) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& preset : presets) {
        const fs::path tree = root / preset;
        std::map<std::string, std::string> cache = cache_of(tree);
        const fs::path source = cache.count("CMAKE_HOME_DIRECTORY") != 0 ? fs::path(cache["CMAKE_HOME_DIRECTORY"]) : source_root();
        const fs::path run_sh = source / "tools/qemu-insncount/run.sh";
        Args env;
        const std::string plugin = cache["HIDER_INSNCOUNT_PLUGIN"];
        if (!plugin.empty() && fs::is_regular_file(plugin)) env.push_back("INSNCOUNT_PLUGIN=" + plugin);
        if (!cache["CMAKE_NM"].empty()) env.push_back("NM=" + cache["CMAKE_NM"]);
        const fs::path dir = tree / "firmware/waterfall";
        const Count mono = run_small(run_sh, preset, dir / "waterfall_mono.elf", env);
        const Count proj = run_small(run_sh, preset, dir / "waterfall_projection.elf", env);
        const Count colour = run_small(run_sh, preset, dir / "waterfall_colour.elf", env);
        if (proj.pairs != mono.pairs || colour.pairs != mono.pairs * kBandsPerFrame)
            fail(preset + ": the waterfall firmware measured different numbers of frames");
        const uint64_t frame = mono.region / mono.pairs, projection = proj.region / proj.pairs;
        const uint64_t drawing = frame > projection ? frame - projection : 0;
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", preset.c_str(), with_commas(frame).c_str(),
                    per_sample(frame).c_str(), with_commas(projection).c_str(), per_sample(projection).c_str(),
                    with_commas(drawing).c_str(), per_sample(drawing).c_str(), with_commas(colour.region / mono.pairs).c_str());
    }
    return 0;
}

}  // namespace hider::tool::bench

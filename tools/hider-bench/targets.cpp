// hider-bench targets: instruction counts (and, on the Cortex-M targets, the insncount plugin's cycle
// estimates) on the cross targets. For each preset build tree that exists
// (DIR/cm0plus, DIR/cm3, DIR/rv32imac) it runs the spin, bands, teapot and spanbench firmware under QEMU
// with the insncount plugin through tools/qemu-insncount/run.sh (which picks the machine per target and
// turns the cycle model on for cm0plus and cm3), reads the bench_begin..bench_end regions (and each
// pair) and prints Markdown tables: the torus, frames per second, the band renderer against the full
// frame and by band height, the teapot per vertex and per triangle. The covered pixels per frame come
// from the host: the frame command's code (run_frames) on the same torus view.
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <map>
#include <vector>

#include "bench.hpp"

namespace hider::tool::bench {
namespace {

namespace fs = std::filesystem;

const char* const kPresets[] = {"cm0plus", "cm3", "rv32imac"};

/// The firmware run per target, relative to the build tree. spanbench ELFs hold one span call each.
struct Firmware {
    const char* key;
    const char* path;
    bool one_pair;        ///< the region must be exactly one bench_begin..bench_end pair
    const char* machine;  ///< run.sh's machine: big, or small (16 KB RAM)
};
const Firmware kFirmware[] = {
    {"spin320", "firmware/spin/spin320.elf", true, "big"},
    {"spin", "firmware/spin/spin.elf", false, "big"},
    {"bands", "firmware/bands/bands.elf", false, "small"},
    {"bands320", "firmware/bands/bands320.elf", false, "small"},
    {"bands320_rows2", "firmware/bands/bands320_rows2.elf", false, "big"},
    {"bands320_rows3", "firmware/bands/bands320_rows3.elf", false, "big"},
    {"bands320_rows4", "firmware/bands/bands320_rows4.elf", false, "big"},
    {"bands320_rows6", "firmware/bands/bands320_rows6.elf", false, "big"},
    {"bands320_rows8", "firmware/bands/bands320_rows8.elf", false, "big"},
    {"bands320_rows16", "firmware/bands/bands320_rows16.elf", false, "big"},
    {"teapot320", "firmware/spin/teapot320.elf", false, "big"},
    {"pass320", "firmware/spanbench/spanbench_pass320.elf", true, "big"},
    {"pass1", "firmware/spanbench/spanbench_pass1.elf", true, "big"},
    {"fail320", "firmware/spanbench/spanbench_fail320.elf", true, "big"},
    {"fail1", "firmware/spanbench/spanbench_fail1.elf", true, "big"},
    {"kpass320", "firmware/spanbench/spanbench_kpass320.elf", true, "big"},
    {"kpass1", "firmware/spanbench/spanbench_kpass1.elf", true, "big"},
    {"kfail320", "firmware/spanbench/spanbench_kfail320.elf", true, "big"},
    {"kfail1", "firmware/spanbench/spanbench_kfail1.elf", true, "big"},
};
constexpr uint64_t kSpanPixels = 320;
/// Band heights of the bands320 builds in rows of the torus's 194-column window (5: bands320 itself,
/// 16 KB; the others on the big machine).
const int kBandRows[] = {2, 3, 4, 5, 6, 8, 16};
constexpr uint32_t kTeapotVertices = 3644, kTeapotTriangles = 6320;

/// One region pair: instructions and the cycle model's estimate (0 without a model; lo..hi on the M3).
struct Pair {
    uint64_t insns = 0, cycles = 0, cycles_max = 0;
};

struct Count {
    uint64_t total = 0, region = 0, pairs = 0;
    uint64_t cycles = 0, cycles_max = 0;  ///< the whole region's estimate (0: no cycle model)
    std::vector<Pair> pair;
    std::string output;  ///< the firmware's stdout
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

/// Runs one ELF with run.sh in a private directory (the firmware's semihosted files land there), every
/// region pair listed.
Count run_firmware(const fs::path& run_sh, const std::string& preset, const fs::path& elf, const char* machine,
                   const Args& env_in) {
    const TempDir tmp;
    const fs::path counts = tmp.path() / "counts.txt";
    const std::string out_file = (tmp.path() / "stdout").string(), err_file = (tmp.path() / "stderr").string();
    ProcessResult result;
    std::string error;
    Args env = env_in;
    env.push_back("INSNCOUNT_ARGS=pairs=1");
    const Args argv = {"sh", run_sh.string(), preset, elf.string(), counts.string(), machine};
    if (!run_process(argv, tmp.path().string(), env, out_file, err_file, result, error)) fail(error);
    if (!result.exited || result.status != 0)
        fail(elf.string() + ": run under QEMU failed (" + result.describe() + "):\n" + read_text(err_file));
    Count c;
    const std::string text = read_text(counts);
    unsigned long long total = 0, region = 0, pairs = 0;
    if (std::sscanf(text.c_str(), "insncount total=%llu region=%llu pairs=%llu", &total, &region, &pairs) != 3)
        fail(elf.string() + ": no counts from the insncount plugin: '" + text + "'");
    c.total = total;
    c.region = region;
    c.pairs = pairs;
    const size_t rc = text.find("region_cycles=");
    unsigned long long lo = 0, hi = 0;
    if (rc != std::string::npos && std::sscanf(text.c_str() + rc, "region_cycles=%llu region_cycles_max=%llu", &lo, &hi) == 2) {
        c.cycles = lo;
        c.cycles_max = hi;
    }
    for (size_t at = text.find("\npair "); at != std::string::npos; at = text.find("\npair ", at + 1)) {
        unsigned int index = 0;
        unsigned long long insns = 0, cyc = 0, cyc_max = 0;
        if (std::sscanf(text.c_str() + at + 1, "pair %u insns=%llu cycles=%llu cycles_max=%llu", &index, &insns, &cyc,
                        &cyc_max) != 4 ||
            index != c.pair.size())
            fail(elf.string() + ": unreadable pair line in the insncount report");
        c.pair.push_back({insns, cyc, cyc_max});
    }
    if (c.pair.size() != c.pairs) fail(elf.string() + ": the insncount report lists " + std::to_string(c.pair.size()) +
                                       " of " + std::to_string(c.pairs) + " pairs");
    c.output = read_text(out_file) + read_text(err_file);  // semihosted console output goes to stderr
    return c;
}

/// The number after `key` in a firmware's output (`key` must occur).
uint64_t output_number(const Count& c, const std::string& key, const std::string& what) {
    const size_t at = c.output.find(key);
    unsigned long long v = 0;
    if (at == std::string::npos || std::sscanf(c.output.c_str() + at + key.size(), "%llu", &v) != 1)
        fail(what + ": no '" + key + "' in its output");
    return v;
}

/// The stack the firmware reserved, from the start-up's "stack high-water N of S bytes".
uint64_t stack_size(const Count& c, const std::string& what) {
    const size_t at = c.output.find("stack high-water ");
    unsigned long long used = 0, size = 0;
    if (at == std::string::npos || std::sscanf(c.output.c_str() + at, "stack high-water %llu of %llu", &used, &size) != 2)
        fail(what + ": no 'stack high-water N of S' in its output");
    return size;
}

/// A number with thousands separators.
std::string grouped(uint64_t v) {
    std::string s = std::to_string(v);
    for (size_t i = s.size(); i > 3; i -= 3) s.insert(i - 3, ",");
    return s;
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
        if (args[i] == "--build-root") root = fs::absolute(option_value(args, i));  // QEMU runs in a scratch directory
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
            const Count c = run_firmware(run_sh, preset, tree / fw.path, fw.machine, env);
            if (c.pairs == 0 || (fw.one_pair && c.pairs != 1))
                fail((tree / fw.path).string() + ": " + std::to_string(c.pairs) + " bench pairs, expected " +
                     (fw.one_pair ? "1" : "at least 1"));
            counts[preset][fw.key] = c;
        }
    }

    const uint64_t spin_frames = counts[presets.front()]["spin"].pairs;
    auto target_name = [](const std::string& preset) {
        return std::string(preset == "cm0plus" ? "Cortex-M0+" : preset == "cm3" ? "Cortex-M3" : "RV32IMAC");
    };
    std::printf("Instructions counted by QEMU's insncount plugin from bench_begin to bench_end (compare within a\n"
                "target). Machines: mps2-an385 (cm0plus runs its ARMv6-M code on the Cortex-M3 model, cm3) or\n"
                "microbit for the 16 KB cm0plus firmware, virt or sifive_e (16 KB) for rv32imac. Firmware from the\n"
                "MinSizeRel build trees under the build root.\n"
                "- torus 320x240: spin320, one frame (view setup, projection, clear, draw_zbuffer).\n"
                "- torus 160x128: spin, mean over its %" PRIu64 " frames: frame 0 is the standard view, the\n"
                "  others turn the model about the vertical axis (firmware/spin/render.hpp). instr/covered px\n"
                "  divides that mean by the covered pixels of frame 0.\n"
                "- covered px from the host (hider-bench frame code, same view, 16-bit depth): 320x240 %" PRIu32
                ", 160x128 %" PRIu32 ".\n"
                "- span: span_depth_test_paired<false> (the z-buffer's out-of-line span for RGB565 + 16-bit depth);\n"
                "  kernel: run_kernel_triangle() on one row (the z-buffer's loop for flat triangles inside the\n"
                "  frame's columns); flat colour (firmware/spanbench); instr/px =\n"
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

    // Frames per second from the cycle model (ARM only): cycles lo..hi of one frame.
    std::printf("\nCycles from the plugin's cycle model (model=m0plus: exact per its manual; model=m3: a lower and an\n"
                "upper bound, see tools/qemu-insncount/arm_cycles.h for what it leaves out), one frame each: the torus\n"
                "320x240 (spin320), the torus 160x128 (spin's frame 0), bands (160x128 in 10-row bands of its window) and\n"
                "bands320; frames per second at 48 MHz (Cortex-M0+) and 72 MHz (Cortex-M3). Estimates for\n"
                "zero wait-state memory: flash wait states (a real part at these clocks has them) lower them.\n\n");
    std::printf("| target | torus 320x240 cycles | fps | torus 160x128 cycles | fps | bands cycles | fps "
                "| bands320 cycles | fps |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& preset : presets) {
        if (preset == "rv32imac") continue;
        std::map<std::string, Count>& c = counts[preset];
        const double hz = preset == "cm0plus" ? 48e6 : 72e6;
        auto cell = [&](uint64_t lo, uint64_t hi) {
            std::string cyc = grouped(lo), fps = decimals(hz / static_cast<double>(lo), 1);
            if (hi != lo) {
                cyc += " .. " + grouped(hi);
                fps = decimals(hz / static_cast<double>(hi), 1) + " .. " + fps;
            }
            return cyc + " | " + fps;
        };
        const Pair& s0 = c["spin"].pair.at(0);
        std::printf("| %s | %s | %s | %s | %s |\n", target_name(preset).c_str(),
                    cell(c["spin320"].cycles, c["spin320"].cycles_max).c_str(), cell(s0.cycles, s0.cycles_max).c_str(),
                    cell(c["bands"].cycles, c["bands"].cycles_max).c_str(),
                    cell(c["bands320"].cycles, c["bands320"].cycles_max).c_str());
    }

    // The band renderer against the full frame.
    std::printf("\nBand renderer (draw_zbuffer_binned, 16 KB machines) against the full frame on the same chip: bands\n"
                "(160x128: 1,040 band pixels, 10-row bands of its 104-column window, 45 carried slots) against spin's\n"
                "frame 0, bands320 (320x240: 970 band pixels, 5-row bands of its 194-column window, 47 slots)\n"
                "against spin320. Each band's region excludes the display sink.\n\n");
    std::printf("| target | bands instr | spin frame 0 | ratio | bands320 instr | spin320 | ratio |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& preset : presets) {
        std::map<std::string, Count>& c = counts[preset];
        const uint64_t spin0 = c["spin"].pair.at(0).insns;
        std::printf("| %s | %s | %s | %sx | %s | %s | %sx |\n", target_name(preset).c_str(), grouped(c["bands"].region).c_str(),
                    grouped(spin0).c_str(), decimals(static_cast<double>(c["bands"].region) / static_cast<double>(spin0), 2).c_str(),
                    grouped(c["bands320"].region).c_str(), grouped(c["spin320"].region).c_str(),
                    decimals(static_cast<double>(c["bands320"].region) / static_cast<double>(c["spin320"].region), 2).c_str());
    }

    // Band height against RAM and cost (the torus at 320x240).
    const uint64_t band_stack = stack_size(counts[presets.front()]["bands320"], "bands320");
    std::printf("\nBand height of the torus at 320x240 against RAM and instructions: the renderer's static storage\n"
                "(vertex cache, bins, band buffers, carried slots, PPM chunk; printed by the firmware) plus its\n"
                "%" PRIu64 "-byte stack on %s (printed by its start-up; firmware/bands/CMakeLists.txt: hider-stack's\n"
                "bound and the start-up's 32 untouched bytes). Rows of the torus's 194-column window (a band memory of\n"
                "194 x rows pixels); 5 rows is bands320 (47 slots, the 16 KB machines), the others run on the big\n"
                "machine with 80 slots (no set-up repeated for want of one). Ratio: to spin320 on the same chip.\n\n",
                band_stack, target_name(presets.front()).c_str());
    std::printf("| rows | bands | RAM bytes |");
    for (const std::string& preset : presets) std::printf(" %s instr | ratio |", target_name(preset).c_str());
    std::printf("\n|---:|---:|---:|");
    for (size_t i = 0; i < presets.size(); ++i) std::printf("---:|---:|");
    std::printf("\n");
    for (int rows : kBandRows) {
        const std::string key = rows == 5 ? "bands320" : "bands320_rows" + std::to_string(rows);
        const Count& first = counts[presets.front()][key];
        const uint64_t storage = output_number(first, "storage ", key);
        std::printf("| %d | %d | %s |", rows, (240 + rows - 1) / rows, grouped(storage + band_stack).c_str());
        for (const std::string& preset : presets) {
            const Count& c = counts[preset][key];
            std::printf(" %s | %sx |", grouped(c.region).c_str(),
                        decimals(static_cast<double>(c.region) / static_cast<double>(counts[preset]["spin320"].region), 2).c_str());
        }
        std::printf("\n");
    }

    // The teapot at 320x240: per vertex, per culled and per drawn triangle.
    std::printf("\nThe teapot at 320x240 (firmware/spin/teapot320: %" PRIu32 " vertices, %" PRIu32 " triangles, hider-render's\n"
                "framing): projection (view set-up and project_vertices) per vertex; the draw with every face turned\n"
                "away (all culled) per triangle; per drawn triangle the normal draw less the other triangles at that\n"
                "per-culled cost, over the triangles drawn (pixels included).\n\n",
                kTeapotVertices, kTeapotTriangles);
    std::printf("| target | projection | per vertex | draw | drawn | per drawn triangle | draw, all culled | per culled triangle |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& preset : presets) {
        const Count& c = counts[preset]["teapot320"];
        if (c.pair.size() != 4) fail("targets: teapot320 lists " + std::to_string(c.pair.size()) + " pairs, expected 4");
        const uint64_t drawn = output_number(c, "triangles drawn ", "teapot320");
        const double per_vertex = static_cast<double>(c.pair[0].insns) / kTeapotVertices;
        const double per_culled = static_cast<double>(c.pair[3].insns) / kTeapotTriangles;
        const double per_drawn = (static_cast<double>(c.pair[2].insns) - per_culled * static_cast<double>(kTeapotTriangles - drawn)) /
                                 static_cast<double>(drawn);
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", target_name(preset).c_str(), grouped(c.pair[0].insns).c_str(),
                    decimals(per_vertex, 1).c_str(), grouped(c.pair[2].insns).c_str(), grouped(drawn).c_str(),
                    decimals(per_drawn, 1).c_str(), grouped(c.pair[3].insns).c_str(), decimals(per_culled, 1).c_str());
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

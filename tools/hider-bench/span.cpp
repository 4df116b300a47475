// hider-bench span: Ir per pixel of the z-buffer inner loop on this host (span_depth_test_paired<false> for
// RGB565 + 16-bit depth, span_depth_test<false> for 32-bit depth).
// Each case runs `span-run` under callgrind: the row is reset outside the measured call, then one
// hider_bench_span call draws it. Per pixel = (Ir of a 320-pixel call - Ir of a 1-pixel call) / 319,
// which removes the call and setup overhead (the span requires x0 < x1, so 1 pixel is the baseline).
#include <cinttypes>
#include <cstdio>

#include "bench.hpp"
#include "measured.hpp"

namespace hider::tool::bench {
namespace {

constexpr long kRowPixels = 320;
constexpr long kBasePixels = 1;  // the smallest span: the spans require x0 < x1
constexpr long kReps = 1000;
constexpr uint16_t kPixel = 0xF81F;

#if defined(__x86_64__)
constexpr const char* kHost = "x86-64";
#elif defined(__aarch64__)
constexpr const char* kHost = "aarch64";
#else
constexpr const char* kHost = "this host";
#endif

template <class Depth>
void reset(Depth* depth, uint16_t* color, long width, bool pass) {
    for (long x = 0; x < width; ++x) {
        depth[x] = pass ? DepthTraits<Depth>::kClear : Depth{0};  // 0 is nearer than any fragment
        color[x] = 0;
    }
}

bool row_ok(const uint16_t* color, long width, bool pass) {
    for (long x = 0; x < width; ++x)
        if (color[x] != (pass ? kPixel : 0)) return false;
    return true;
}

uint64_t ir_per_call(const std::string& valgrind, int depth_bits, bool pass, long width) {
    const CallgrindRun run = run_callgrind(
        valgrind, "hider_bench_span",
        {"span-run", "--depth-bits", std::to_string(depth_bits), "--pass", pass ? "all" : "none", "--width",
         std::to_string(width), "--reps", std::to_string(kReps)});
    if (run.ir % kReps != 0) fail("span: calls differ in cost (" + std::to_string(run.ir) + " Ir over " +
                                  std::to_string(kReps) + " calls)");
    return run.ir / kReps;
}

}  // namespace

int span_run_command(const Args& args) {
    int depth_bits = 16;
    bool pass = true;
    long width = kRowPixels, reps = 1;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const std::string& v = option_value(args, i);
        if (a == "--depth-bits" && (v == "16" || v == "32")) depth_bits = v == "16" ? 16 : 32;
        else if (a == "--pass" && (v == "all" || v == "none")) pass = v == "all";
        else if (a == "--width" && parse_int(v, width) && width >= 1 && width <= kMaxFrameSide) continue;
        else if (a == "--reps" && parse_int(v, reps) && reps >= 1) continue;
        else fail("span-run: bad option '" + a + " " + v + "'");
    }
    AlignedBuffer<uint16_t> color(static_cast<size_t>(width));
    AlignedBuffer<uint16_t> depth16(static_cast<size_t>(width));
    AlignedBuffer<uint32_t> depth32(static_cast<size_t>(width));
    SpanJob job;
    job.color = color.data();
    job.depth16 = depth16.data();
    job.depth32 = depth_bits == 32 ? depth32.data() : nullptr;
    job.x0 = 0;
    job.x1 = static_cast<int32_t>(width);
    job.z_q32 = kDepthNear;
    job.dz_q32 = uint32_t{1} << 16;  // one 16-bit depth step per pixel; stays far below the clear value
    job.pixel = kPixel;
    for (long r = 0; r < reps; ++r) {
        if (depth_bits == 32) reset(depth32.data(), color.data(), width, pass);
        else reset(depth16.data(), color.data(), width, pass);
        hider_bench_span(&job);
    }
    if (!row_ok(color.data(), width, pass)) fail("span-run: the row is not what the depth test should give");
    std::printf("span %d-bit %s %ld px x %ld\n", depth_bits, pass ? "all" : "none", width, reps);
    return 0;
}

int span_command(const Args& args) {
    std::string valgrind;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--valgrind") valgrind = option_value(args, i);
        else fail("span: unknown argument '" + args[i] + "'");
    }
    valgrind = find_valgrind(valgrind);
    std::printf("z-buffer span on %s: RGB565 row, flat colour, callgrind Ir per call over %ld calls;\n"
                "Ir/pixel = (Ir/call at %ld px - Ir/call at %ld px) / %ld.\n\n",
                kHost, kReps, kRowPixels, kBasePixels, kRowPixels - kBasePixels);
    std::printf("| depth | fragments | Ir/call, %ld px | Ir/call, %ld px | Ir/pixel |\n", kRowPixels, kBasePixels);
    std::printf("|---|---|---:|---:|---:|\n");
    std::fflush(stdout);
    for (int depth_bits : {16, 32}) {
        for (bool pass : {true, false}) {
            const uint64_t full = ir_per_call(valgrind, depth_bits, pass, kRowPixels);
            const uint64_t base = ir_per_call(valgrind, depth_bits, pass, kBasePixels);
            char per_pixel[32];
            std::snprintf(per_pixel, sizeof per_pixel, "%.2f",
                          (static_cast<double>(full) - static_cast<double>(base)) /
                              static_cast<double>(kRowPixels - kBasePixels));
            std::printf("| %d-bit | %s | %" PRIu64 " | %" PRIu64 " | %s |\n", depth_bits,
                        pass ? "all pass" : "none pass", full, base, per_pixel);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace hider::tool::bench

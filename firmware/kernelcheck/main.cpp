// kernelcheck firmware: the chip's assembly against its portable twins, on random states.
// - kernelcheck::kCases kernel states (cases.hpp) through run_kernel_triangle() (Thumb-2, Thumb-1 or RV32
//   assembly) and run_kernel_triangle_portable(), two calls each: same buffers and final state.
// - kernelcheck::kSetupCases triangle set-ups (setup_cases.hpp) through kernel_setup() (the Thumb-2 set-up
//   on ARMv7-M) and kernel_setup_portable(): same outcome and kernel fields for every case.
// - On ARMv7-M, kernelcheck::kDivrCases quotients through the set-up's rounded 64/32 division alone
//   against div_round(), with numerators built to need the long division's digit corrections.
// - On ARMv7-M, kernelcheck::kSetupCases set-ups of narrow frames through kernel_draw_v7m() (set-up and
//   rows in one call) and through kernel_setup_portable() and run_kernel_triangle_portable(), with the
//   band's stop above, inside and below the rows: same outcome, record and buffers (on the chip only).
// - kernelcheck::kVertexCases batches of positions (vertex_cases.hpp) through project_vertices() (on
//   ARMv6-M the Thumb-1 loop, on ARMv7-M the Thumb-2 loop, elsewhere project_common()) and the general
//   per-position path: same vertices; the Thumb-1 loop must also refuse no position inside the view
//   volume with w < 2^29, the Thumb-2 loop none that project_common() projects; VertexProjector (draw_bsp()'s
//   projection on first use) position by position must give the same vertices.
// - kernelcheck::kDrawCases random small scenes (draw_cases.hpp) through draw_flat_kernel() with and
//   without the assembly draw loop (Thumb-1 on ARMv6-M, Thumb-2 on ARMv7-M; on RV32 both are the C++
//   loop): same frame and counts.
// - kernelcheck::kBandCases random small scenes (band_cases.hpp) through the band renderer with and
//   without the assembly band loop and binning pass (Thumb-2 on ARMv7-M; on ARMv6-M and RV32 the C++
//   loop with the resumes in assembly, resume_carried_v6m() and resume_carried_rv32(), and on ARMv6-M
//   the Thumb-1 binning pass, bin_triangles_v6m()), in bands of 1 to 6 rows with 0 to 5 carried
//   slots: same bands and counts.
// - kernelcheck::kResumeCases random runs of carried set-ups (resume_cases.hpp) through the M0+ and RV32
//   assembly resumes (resume_carried_v6m(), resume_carried_rv32(); elsewhere resume_carried() twice) and
//   resume_carried(): same buffers, slot lists, pending triangle and onward states.
// - The frame clear (detail::fill, store-multiples on Cortex-M) against a plain loop for every length up
//   to kFillMax.
// The chip's digests go to kernelcheck.bin, which the host twin writes from the portable code (ctest
// kernelcheck.matches_host).
#include "common/bench.hpp"
#include "kernelcheck/cases.hpp"
#include "kernelcheck/setup_cases.hpp"
#include "kernelcheck/band_cases.hpp"
#include "kernelcheck/draw_cases.hpp"
#include "kernelcheck/resume_cases.hpp"
#include "kernelcheck/vertex_cases.hpp"
#include "semihost/semihost.hpp"

namespace {

#if defined(HIDER_ARMV7M)
/// The Thumb-2 set-up's rounded quotient (its hider_divr and hider_divr_far macros) on its own:
/// n = hi:lo, d in r2; INT32_MIN where the set-up would call the triangle generic.
HIDER_NAKED int32_t divr_v7m(uint32_t, uint32_t, uint32_t) {
    using namespace hider;  // the operands' names
    __asm__ volatile(
        ".syntax unified\n\t"
        "push   {r4-r11, lr}\n\t"
        "mov    r9, r2\n\t"
        "mov    r3, r1\n\t"
        HIDER_V7M_SETUP_MACROS
        "hider_divr r0, r3, 60, 61\n\t"
        "pop    {r4-r11, pc}\n"
        "93:\n\t"
        "mov    r0, #0x80000000\n\t"
        "pop    {r4-r11, pc}\n\t"
        "hider_divr_far r0, r3, 60, 61\n\t"
        HIDER_V7M_SETUP_PURGE
        :
        : HIDER_V7M_SETUP_OPERANDS);
}
#endif

constexpr int kDrawAt = kernelcheck::kCases + kernelcheck::kSetupCases + kernelcheck::kVertexCases;
constexpr int kBandAt = kDrawAt + kernelcheck::kDrawCases;
constexpr int kResumeAt = kBandAt + kernelcheck::kBandCases;
constexpr int kWords = kResumeAt + 2;  // the last word: the fill digest
kernelcheck::Buffers g_buffers;
uint32_t g_digests[kWords];

}  // namespace

int main() {
    namespace sh = hider::semihost;
    const int kernel_case = kernelcheck::run_cases(
        [](hider::KernelTriangle& t, uint16_t* zrow, int32_t stop, const hider::KernelTarget& target) {
            return hider::run_kernel_triangle(t, zrow, stop, target);
        },
        [](hider::KernelTriangle& t, uint16_t* zrow, int32_t stop, const hider::KernelTarget& target) {
            return hider::run_kernel_triangle_portable(t, zrow, stop, target);
        },
        g_buffers, g_digests);
    if (kernel_case >= 0) {
        sh::print("kernelcheck: run_kernel_triangle differs from the portable kernel in case ");
        sh::print_u32(static_cast<uint32_t>(kernel_case));
        sh::print("\n");
        return 1;
    }
    const int setup_case = kernelcheck::run_setup_cases(
        [](const hider::ScreenVertex& a, const hider::ScreenVertex& b, const hider::ScreenVertex& c,
           hider::KernelSetupIo& io) { return hider::kernel_setup(a, b, c, io); },
        [](const hider::ScreenVertex& a, const hider::ScreenVertex& b, const hider::ScreenVertex& c,
           hider::KernelSetupIo& io) { return hider::kernel_setup_portable(a, b, c, io.area, *io.band, *io.out); },
        g_digests + kernelcheck::kCases);
    if (setup_case >= 0) {
        sh::print("kernelcheck: kernel_setup differs from kernel_setup_portable in case ");
        sh::print_u32(static_cast<uint32_t>(setup_case));
        sh::print("\n");
        return 1;
    }
#if defined(HIDER_ARMV7M)
    const int divr_case = kernelcheck::run_divr_cases(divr_v7m);
    if (divr_case >= 0) {
        sh::print("kernelcheck: the set-up's rounded quotient differs from div_round in case ");
        sh::print_u32(static_cast<uint32_t>(divr_case));
        sh::print("\n");
        return 1;
    }
    const int draw_setup_case = kernelcheck::run_setup_draw_cases(
        [](const hider::ScreenVertex& a, const hider::ScreenVertex& b, const hider::ScreenVertex& c,
           hider::KernelSetupIo& io) {
            return static_cast<hider::KernelSetup>(hider::kernel_draw_v7m(&a, &b, &c, &io));
        },
        g_buffers);
    if (draw_setup_case >= 0) {
        sh::print("kernelcheck: kernel_draw_v7m differs from the portable set-up and kernel in case ");
        sh::print_u32(static_cast<uint32_t>(draw_setup_case));
        sh::print("\n");
        return 1;
    }
#endif
    uint32_t refused_inside = 0, accepted = 0, projector_differs = 0;
    const int vertex_case = kernelcheck::run_vertex_cases(
        [](const hider::View& v, const hider::Vec3q16* p, hider::ScreenVertex* out) {
            (void)hider::project_vertices(v, {p, kernelcheck::kVertexBatch}, {out, kernelcheck::kVertexBatch});
        },
        kernelcheck::project_each,
        [&](const kernelcheck::VertexCase& c) {
            projector_differs += kernelcheck::projector_matches(c) ? 0u : 1u;
#if defined(HIDER_ARMV6M)
            // The Thumb-1 loop may stop only outside the view volume or at w >= 2^29.
            kernelcheck::walk_vertex_loop(c, hider::detail::vertex_prep(c.view), hider::project_common_v6m,
                                          [&](const hider::ViewPoint& q) {
                                              return hider::outcode(c.view, q) == 0 && q.w < (int32_t{1} << 29);
                                          },
                                          accepted, refused_inside);
#elif defined(HIDER_ARMV7M)
            // The Thumb-2 loop may stop only at a position project_common() refuses.
            kernelcheck::walk_vertex_loop(c, hider::detail::vertex_prep_v7m(c.view), hider::project_common_v7m,
                                          [&](const hider::ViewPoint& q) {
                                              hider::ScreenVertex v;
                                              return hider::detail::project_common(c.view, q, v);
                                          },
                                          accepted, refused_inside);
#else
            (void)c;
            (void)accepted;
#endif
        },
        g_digests + kernelcheck::kCases + kernelcheck::kSetupCases);
    if (vertex_case >= 0 || refused_inside != 0 || projector_differs != 0) {
        if (vertex_case >= 0) {
            sh::print("kernelcheck: project_vertices differs from the per-position path in case ");
            sh::print_u32(static_cast<uint32_t>(vertex_case));
            sh::print("\n");
        }
        if (refused_inside != 0) {
            sh::print("kernelcheck: the vertex loop refused ");
            sh::print_u32(refused_inside);
            sh::print(" positions inside the view volume\n");
        }
        if (projector_differs != 0) {
            sh::print("kernelcheck: VertexProjector differs from the per-position path in ");
            sh::print_u32(projector_differs);
            sh::print(" cases\n");
        }
        return 1;
    }
    const int draw_case = kernelcheck::run_draw_cases(
        [](const hider::View& v, const hider::Mesh& m, const hider::ScreenVertex* verts,
           const hider::FrameView<hider::Rgb565Format, uint16_t>& f, const hider::DrawOptions& o, hider::FrameStats& st) {
            hider::detail::draw_flat_kernel<hider::Rgb565Format, true>(v, m, {verts, kernelcheck::kVertexBatch}, f, o, st);
        },
        [](const hider::View& v, const hider::Mesh& m, const hider::ScreenVertex* verts,
           const hider::FrameView<hider::Rgb565Format, uint16_t>& f, const hider::DrawOptions& o, hider::FrameStats& st) {
            hider::detail::draw_flat_kernel<hider::Rgb565Format, false>(v, m, {verts, kernelcheck::kVertexBatch}, f, o, st);
        },
        g_buffers, g_digests + kDrawAt);
    if (draw_case >= 0) {
        sh::print("kernelcheck: the draw loop differs from the C++ loop in case ");
        sh::print_u32(static_cast<uint32_t>(draw_case));
        sh::print("\n");
        return 1;
    }
    const int band_case = kernelcheck::run_band_cases(
        [](const hider::View& v, const hider::Mesh& m, const hider::ScreenVertex* verts, kernelcheck::BandSetup& s,
           auto& done, hider::BinnedStats& bs) {
            return hider::detail::draw_binned<true>(v, m, {verts, kernelcheck::kVertexBatch}, s.buffers, s.opt, {1, 2, 3},
                                                    s.scratch, done, &bs);
        },
        [](const hider::View& v, const hider::Mesh& m, const hider::ScreenVertex* verts, kernelcheck::BandSetup& s,
           auto& done, hider::BinnedStats& bs) {
            return hider::detail::draw_binned<false>(v, m, {verts, kernelcheck::kVertexBatch}, s.buffers, s.opt, {1, 2, 3},
                                                     s.scratch, done, &bs);
        },
        g_buffers, g_digests + kBandAt);
    if (band_case >= 0) {
        sh::print("kernelcheck: the band loop differs from the C++ loop in case ");
        sh::print_u32(static_cast<uint32_t>(band_case));
        sh::print("\n");
        return 1;
    }
    const int resume_case = kernelcheck::run_resume_cases(
        [](hider::detail::CarriedSlots& cs, uint32_t limit, const hider::detail::KernelBandTarget& bt) {
#if defined(HIDER_RV32_ASM)
            return hider::resume_carried_rv32(&cs, limit, &bt);
#elif defined(HIDER_ARMV6M)
            return hider::resume_carried_v6m(&cs, limit, &bt);
#else
            return hider::detail::resume_carried(cs, limit, bt);
#endif
        },
        [](hider::detail::CarriedSlots& cs, uint32_t limit, const hider::detail::KernelBandTarget& bt) {
            return hider::detail::resume_carried(cs, limit, bt);
        },
        g_buffers, g_digests + kResumeAt);
    if (resume_case >= 0) {
        sh::print("kernelcheck: the resume run differs from resume_carried() in case ");
        sh::print_u32(static_cast<uint32_t>(resume_case));
        sh::print("\n");
        return 1;
    }
    g_digests[kWords - 1] = kernelcheck::fill_digest(
        [](uint16_t* p, uint32_t n, uint16_t v) { hider::detail::fill<uint16_t>(p, n, v); }, g_buffers);
    if (g_digests[kWords - 1] != kernelcheck::fill_digest(kernelcheck::fill_plain, g_buffers)) {
        sh::print("kernelcheck: the frame clear (detail::fill) differs from a plain loop\n");
        return 1;
    }
    if (!sh::write_file("kernelcheck.bin", g_digests, sizeof g_digests)) {
        sh::print("kernelcheck: cannot write kernelcheck.bin\n");
        return 1;
    }
    sh::print("kernelcheck: ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kCases));
    sh::print(" kernel cases and ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kSetupCases));
    sh::print(" set-ups equal the portable code, ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kVertexCases * kernelcheck::kVertexBatch));
    sh::print(" positions the per-position path, ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kDrawCases));
    sh::print(" scenes the C++ draw loop, ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kBandCases));
    sh::print(" banded scenes the C++ band loop, ");
    sh::print_u32(static_cast<uint32_t>(kernelcheck::kResumeCases));
    sh::print(" resume runs resume_carried()");
#if defined(HIDER_ARMV6M) || defined(HIDER_ARMV7M)
    sh::print(" (the assembly vertex loop projected ");
    sh::print_u32(accepted);
    sh::print(")");
#endif
    sh::print("; the clear equals a plain loop\n");
    return 0;
}

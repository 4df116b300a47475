// Host twin of the kernelcheck firmware: writes kernelcheck.bin (one digest per kernel case, cases.hpp,
// per set-up case, setup_cases.hpp, per vertex case, vertex_cases.hpp, per scene, draw_cases.hpp, per
// banded scene, band_cases.hpp, and per resume run, resume_cases.hpp, then the fill digest) from the
// portable kernel, the portable set-up, the per-position projection, the C++ draw, band and resume loops
// and a plain fill loop, as the reference for the kernelcheck.matches_host ctest.
#include "kernelcheck/band_cases.hpp"
#include "kernelcheck/cases.hpp"
#include "kernelcheck/setup_cases.hpp"
#include "kernelcheck/draw_cases.hpp"
#include "kernelcheck/vertex_cases.hpp"
#include "kernelcheck/resume_cases.hpp"
#include "stdio_io.hpp"

int main() {
    static kernelcheck::Buffers buffers;
    constexpr int kDrawAt = kernelcheck::kCases + kernelcheck::kSetupCases + kernelcheck::kVertexCases;
    constexpr int kBandAt = kDrawAt + kernelcheck::kDrawCases;
    constexpr int kResumeAt = kBandAt + kernelcheck::kBandCases;
    static uint32_t digests[kResumeAt + 2];
    auto kernel = [](hider::KernelTriangle& t, uint16_t* zrow, int32_t stop, const hider::KernelTarget& target) {
        return hider::run_kernel_triangle_portable(t, zrow, stop, target);
    };
    auto setup = [](const hider::ScreenVertex& a, const hider::ScreenVertex& b, const hider::ScreenVertex& c,
                    hider::KernelSetupIo& io) { return hider::kernel_setup_portable(a, b, c, io.area, *io.band, *io.out); };
    if (kernelcheck::run_cases(kernel, kernel, buffers, digests) >= 0) return 1;
    if (kernelcheck::run_setup_cases(setup, setup, digests + kernelcheck::kCases) >= 0) return 1;
    if (kernelcheck::run_vertex_cases(kernelcheck::project_each, kernelcheck::project_each, [](const kernelcheck::VertexCase&) {},
                                      digests + kernelcheck::kCases + kernelcheck::kSetupCases) >= 0)
        return 1;
    auto draw = [](const hider::View& v, const hider::Mesh& m, const hider::ScreenVertex* verts,
                   const hider::FrameView<hider::Rgb565Format, uint16_t>& f, const hider::DrawOptions& o,
                   hider::FrameStats& st) {
        hider::detail::draw_flat_kernel<hider::Rgb565Format, false>(v, m, {verts, kernelcheck::kVertexBatch}, f, o, st);
    };
    if (kernelcheck::run_draw_cases(draw, draw, buffers, digests + kDrawAt) >= 0) return 1;
    auto band = [](const hider::View& v, const hider::Mesh& m, const hider::ScreenVertex* verts, kernelcheck::BandSetup& s,
                   auto& done, hider::BinnedStats& bs) {
        return hider::detail::draw_binned<false>(v, m, {verts, kernelcheck::kVertexBatch}, s.buffers, s.opt, {1, 2, 3},
                                                 s.scratch, done, &bs);
    };
    if (kernelcheck::run_band_cases(band, band, buffers, digests + kBandAt) >= 0) return 1;
    auto resume = [](hider::detail::CarriedSlots& cs, uint32_t limit, const hider::detail::KernelBandTarget& bt) {
        return hider::detail::resume_carried(cs, limit, bt);
    };
    if (kernelcheck::run_resume_cases(resume, resume, buffers, digests + kResumeAt) >= 0) return 1;
    digests[kResumeAt + 1] = kernelcheck::fill_digest(kernelcheck::fill_plain, buffers);
    return host::write_file("kernelcheck.bin", digests, sizeof digests) ? 0 : 1;
}

// Emits every assembly routine of lib/ for the target (their addresses in a table) so that
// check_naked_uninstrumented.sh can compare their code with and without a user's instrumentation flags.
// The script checks the table's size against the HIDER_NAKED definitions in lib/: a new routine must be
// listed here.
#include <hider/frame.hpp>
#include <hider/horizon/level_pass.hpp>
#include <hider/horizon/row_pass.hpp>
#include <hider/horizon/walk_kernel.hpp>
#include <hider/raster/band_bin_asm.hpp>
#include <hider/raster/band_loop_asm.hpp>
#include <hider/raster/band_resume.hpp>
#include <hider/raster/draw_loop_asm.hpp>
#include <hider/raster/kernel_setup_asm.hpp>
#include <hider/raster/row_kernel_asm.hpp>
#include <hider/raster/vertices.hpp>

using namespace hider;

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
#define HIDER_NAKED_ROUTINES                                                                           \
    X(kernel_setup_v7m) X(kernel_draw_v7m) X(draw_flat_v7m) X(bin_triangles_v7m) X(project_common_v7m)  \
    X(run_kernel_triangle_v7m) X(draw_band_v7m) X(detail::fill_words_v7m)
#elif defined(__ARM_ARCH_6M__)
#define HIDER_NAKED_ROUTINES                                                                           \
    X(kernel_setup_v6m) X(draw_flat_v6m) X(project_common_v6m) X(run_kernel_triangle_v6m)    \
    X(horizon::walk_kernel_v6m) X(horizon::level_pass_v6m) X(horizon::reciprocal_pass_v6m)            \
    X(horizon::coordinate_pass_v6m) X(detail::fill_words_v6m) X(resume_carried_v6m) X(bin_triangles_v6m)
#elif defined(HIDER_RV32_ASM)
#define HIDER_NAKED_ROUTINES X(kernel_setup_rv32) X(run_kernel_triangle_rv32) X(resume_carried_rv32)
#else
#error "naked_probe.cpp: no assembly routines on this target"
#endif

#define X(f) reinterpret_cast<const void*>(&f),
extern "C" const void* const hider_naked_routines[] = {HIDER_NAKED_ROUTINES};
#undef X

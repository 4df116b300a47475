// run_kernel_triangle_portable() (row_kernel.hpp) in assembly for the chips: Thumb-2 (ARMv7-M), Thumb-1
// (ARMv6-M) and RV32. One call draws a triangle's rows up to a stop row, switching to the lower short
// edge on the middle row. Both edges are kept as pointers into the current depth row (x + the row's
// start, stepped by x's step, which holds the stride), so a row costs the span's set-up, two edge steps
// and the loop: no depth-row pointer of its own. Spans index back from their end with a negative byte
// count up to 0 (Thumb-1) or walk a pointer (Thumb-2, post-incremented; RV32, which has no
// register-offset addressing). The kernels are in row_kernel_v7m.hpp, row_kernel_v6m.hpp and
// row_kernel_rv32.hpp; this header defines run_kernel_triangle(), which picks the kernel for the target,
// and row_kernel.hpp includes it at its end. firmware/kernelcheck compares each with the portable twin
// on random states.
#pragma once
#include <hider/raster/row_kernel.hpp>
#include <hider/raster/row_kernel_rv32.hpp>
#include <hider/raster/row_kernel_v6m.hpp>
#include <hider/raster/row_kernel_v7m.hpp>

namespace hider {

/// Draws rows [t.row, min(t.end, row_stop)) of a set-up triangle into target `target` from depth row
/// `zrow` (that of t.row), switching to the lower short edge on the middle row, and leaves t on the next
/// row; returns the depth pointer of that row (Thumb-2 on ARMv7-M, Thumb-1 on ARMv6-M, RV32, else
/// run_kernel_triangle_portable()).
__attribute__((always_inline)) inline uint16_t* run_kernel_triangle(KernelTriangle& t, uint16_t* zrow, int32_t row_stop,
                                                                    const KernelTarget& target) {
#if defined(HIDER_ARMV7M)
    return run_kernel_triangle_v7m(&t, zrow, row_stop, &target);
#elif defined(HIDER_ARMV6M)
    return run_kernel_triangle_v6m(&t, zrow, row_stop, &target);
#elif defined(HIDER_RV32_ASM)
    return run_kernel_triangle_rv32(&t, zrow, row_stop, &target);
#else
    return run_kernel_triangle_portable(t, zrow, row_stop, target);
#endif
}

}  // namespace hider

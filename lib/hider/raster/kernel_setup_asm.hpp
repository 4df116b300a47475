// The triangle set-up in assembly for the chips: Thumb-2 (kernel_setup_v7m.hpp), Thumb-1
// (kernel_setup_v6m.hpp) and RV32 (kernel_setup_rv32.hpp), each with the same results as
// kernel_setup_portable() (kernel_triangle.hpp), field for field: firmware/kernelcheck compares them on
// random triangles. Here: what they share (the slow division, the record layout they write as numbers)
// and kernel_setup(), which picks the set-up for the target; kernel_triangle.hpp includes this header at
// its end.
#pragma once
#include <hider/raster/kernel_triangle.hpp>

// The Cortex-M routines address their subroutines and tables absolutely (a clear stop here instead of
// GCC's "impossible constraint in 'asm'" deep inside them).
#if defined(__PIC__) && (defined(HIDER_ARMV6M) || defined(HIDER_ARMV7M))
#error "hider: the Cortex-M assembly routines are not position-independent: compile hider's code without -fPIC, -fpic, -fPIE or -fpie"
#endif

namespace hider {

namespace detail {
/// floor(hi:lo / d) for a quotient below 2^32: the set-up's slow path for areas above 0xFFFF.
extern "C" __attribute__((used, noinline)) inline uint32_t hider_kernel_udiv64(uint32_t lo, uint32_t hi, uint32_t d) {
    uint32_t rem = 0;
    return udiv64_32((uint64_t{hi} << 32) | lo, d, rem);
}
}  // namespace detail

// The kernel record's offsets the Thumb-1 and RV32 set-ups write as numbers (an asm statement takes
// at most 30 operands).
static_assert(sizeof(void*) != 4 || (offsetof(KernelTriangle, top) == 56 && offsetof(KernelTriangle, row) == 58 &&
                  offsetof(KernelTriangle, mid) == 60 && offsetof(KernelTriangle, end) == 62 &&
                  offsetof(RowKernel, lx) == 0 && offsetof(RowKernel, lg) == 4 && offsetof(RowKernel, lz) == 8 &&
                  offsetof(RowKernel, rx) == 12 && offsetof(RowKernel, rg) == 16 && offsetof(RowKernel, la) == 20 &&
                  offsetof(RowKernel, lm) == 24 && offsetof(RowKernel, lstep) == 28 && offsetof(RowKernel, ldz) == 32 &&
                  offsetof(RowKernel, ra) == 36 && offsetof(RowKernel, rm) == 40 && offsetof(RowKernel, rstep) == 44 &&
                  offsetof(RowKernel, dzdx) == 48 && offsetof(KernelTriangle, next_x) == 64 &&
                  offsetof(KernelTriangle, next_g) == 68 && offsetof(KernelTriangle, next_a) == 72 &&
                  offsetof(KernelTriangle, next_m) == 76 && offsetof(KernelTriangle, next_step) == 80 &&
                  offsetof(KernelTriangle, next_left) == 86),
              "kernel record layout (the Thumb-1 and RV32 set-ups)");

}  // namespace hider

#include <hider/raster/kernel_setup_rv32.hpp>
#include <hider/raster/kernel_setup_v6m.hpp>
#include <hider/raster/kernel_setup_v7m.hpp>

namespace hider {

/// Sets up (a, b, c) with signed_area io.area != 0 (either winding) for the rows of *io.band into
/// *io.out, leaving out.k.color to the caller: the target's assembly set-up, else
/// kernel_setup_portable() (identical results). On `none` and `generic`, *io.out is unspecified.
/// Cost: the two plane quotients and one division per edge walker (two for flat edges).
__attribute__((always_inline)) inline KernelSetup kernel_setup(const ScreenVertex& a, const ScreenVertex& b,
                                                               const ScreenVertex& c, KernelSetupIo& io) {
#if defined(HIDER_ARMV7M)
    return static_cast<KernelSetup>(kernel_setup_v7m(&a, &b, &c, &io));
#elif defined(HIDER_ARMV6M)
    return static_cast<KernelSetup>(kernel_setup_v6m(&a, &b, &c, &io));
#elif defined(HIDER_RV32_ASM)
    return static_cast<KernelSetup>(kernel_setup_rv32(&a, &b, &c, &io));
#else
    return kernel_setup_portable(a, b, c, io.area, *io.band, *io.out);
#endif
}

}  // namespace hider

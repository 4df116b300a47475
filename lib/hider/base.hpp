// The few freestanding helpers lib/ needs instead of the C++ standard library: Span, BoundedList,
// min/max/swap_values/clamp, and HIDER_ASSERT. Only <stdint.h>, <stddef.h>, <limits.h> are allowed.
#pragma once
#include <stddef.h>
#include <stdint.h>
#include <limits.h>

static_assert((-3 >> 1) == -2, "lib/ relies on arithmetic right shift of negative values");
static_assert(sizeof(int32_t) == 4 && sizeof(int64_t) == 8, "lib/ needs exact-width integers");

/// Called when HIDER_ASSERT fails (only with HIDER_ENABLE_ASSERTS defined): define it, or link the weak
/// default of hider::port_host (host) or of hider's firmware (firmware/common/assert_hook.cpp).
extern "C" void hider_assert_fail(const char* file, int line);

#if defined(HIDER_ENABLE_ASSERTS)
#define HIDER_ASSERT(cond) ((cond) ? (void)0 : hider_assert_fail(__FILE__, __LINE__))
#else
#define HIDER_ASSERT(cond) ((void)0)
#endif

// HIDER_NAKED marks the assembly routines: naked (the asm is the whole body), out of line, and kept
// free of the code a user's -fstack-protector-all, -finstrument-functions, -fprofile-arcs, -pg,
// -fsanitize-coverage or -fzero-call-used-regs would add around a body that manages its own registers
// and stack (a call before its push overwrites lr). firmware.naked_uninstrumented checks each routine.
#define HIDER_ATTR_NO_STACK_PROTECTOR_
#define HIDER_ATTR_NO_PROFILE_
#define HIDER_ATTR_NO_COVERAGE_
#define HIDER_ATTR_NO_ZERO_REGS_
#if defined(__has_attribute)
#if __has_attribute(no_stack_protector)
#undef HIDER_ATTR_NO_STACK_PROTECTOR_
#define HIDER_ATTR_NO_STACK_PROTECTOR_ __attribute__((no_stack_protector))
#elif defined(__SSP_ALL__)
#error "hider: -fstack-protector-all needs a compiler with __attribute__((no_stack_protector)) (GCC 11, clang 7) for hider's assembly routines"
#endif
#if __has_attribute(no_profile_instrument_function)
#undef HIDER_ATTR_NO_PROFILE_
#define HIDER_ATTR_NO_PROFILE_ __attribute__((no_profile_instrument_function))
#endif
#if __has_attribute(no_sanitize_coverage)
#undef HIDER_ATTR_NO_COVERAGE_
#define HIDER_ATTR_NO_COVERAGE_ __attribute__((no_sanitize_coverage))
#endif
#if __has_attribute(zero_call_used_regs)
#undef HIDER_ATTR_NO_ZERO_REGS_
#define HIDER_ATTR_NO_ZERO_REGS_ __attribute__((zero_call_used_regs("skip")))
#endif
#endif
#define HIDER_NAKED                                                                                      \
    __attribute__((naked, noinline, no_instrument_function)) HIDER_ATTR_NO_STACK_PROTECTOR_ HIDER_ATTR_NO_PROFILE_ \
    HIDER_ATTR_NO_COVERAGE_ HIDER_ATTR_NO_ZERO_REGS_

// The core hider's assembly and core-specific arithmetic take: HIDER_ARMV7M for ARMv7-M (Cortex-M3, M4,
// M7: Thumb-2, 32-bit divide, 64-bit products), HIDER_ARMV6M for ARMv6-M (Cortex-M0, M0+, M1: Thumb-1,
// no divide, 32-bit products only). Other ARM cores take the portable C++, but for fill_words()'
// store-multiples, which every Thumb core runs (frame.hpp).
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
#define HIDER_ARMV7M 1
#endif
#if defined(__ARM_ARCH_6M__)
#define HIDER_ARMV6M 1
#endif

// HIDER_RV32_ASM selects the RV32 assembly routines: RV32I with multiply and divide (M; Zmmul alone has
// no divide) and all 32 registers. RV32E and cores without M take the portable C++ paths.
#if defined(__riscv) && defined(__riscv_xlen) && defined(__riscv_mul) && defined(__riscv_div) && \
    !defined(__riscv_32e) && !defined(__riscv_e)
#if __riscv_xlen == 32
#define HIDER_RV32_ASM 1
#endif
#endif

namespace hider {

template <class T> constexpr T min(T a, T b) { return b < a ? b : a; }
template <class T> constexpr T max(T a, T b) { return a < b ? b : a; }
template <class T> constexpr T clamp(T v, T lo, T hi) { return v < lo ? lo : (hi < v ? hi : v); }
template <class T> constexpr void swap_values(T& a, T& b) { T t = a; a = b; b = t; }
template <class T> constexpr T abs_value(T v) { return v < 0 ? -v : v; }
/// (i + 1) % 3 for i in [0, 3) without a division (a library call on ARMv6-M).
constexpr int next3(int i) { return i == 2 ? 0 : i + 1; }

/// Non-owning view of `size` contiguous elements (pointer + size). Borrowed, never freed.
template <class T>
class Span {
public:
    constexpr Span() = default;
    constexpr Span(T* data, size_t size) : data_(data), size_(size) {}
    template <size_t N> constexpr Span(T (&array)[N]) : data_(array), size_(N) {}
    /// A Span<const T> views the same elements as a Span<T>.
    template <class U, class = decltype(static_cast<T*>(static_cast<U*>(nullptr)))>
    constexpr Span(Span<U> other) : data_(other.data()), size_(other.size()) {}

    constexpr T* data() const { return data_; }
    constexpr size_t size() const { return size_; }
    constexpr bool empty() const { return size_ == 0; }
    constexpr T& operator[](size_t i) const {
        HIDER_ASSERT(i < size_);
        return data_[i];
    }
    constexpr T* begin() const { return data_; }
    constexpr T* end() const { return data_ + size_; }

private:
    T* data_ = nullptr;
    size_t size_ = 0;
};

/// Caller-owned storage of fixed capacity that lib/ fills: pointer + capacity + size, so functions
/// take it without a template on the capacity. Pushing into a full list fails and counts the drop.
template <class T>
class BoundedList {
public:
    constexpr BoundedList() = default;
    constexpr BoundedList(T* storage, size_t capacity) : data_(storage), capacity_(capacity) {}
    template <size_t N> constexpr BoundedList(T (&array)[N]) : data_(array), capacity_(N) {}

    /// Appends `v`; returns false (and counts a drop) when full.
    bool push_back(const T& v) {
        if (size_ == capacity_) { ++dropped_; return false; }
        data_[size_++] = v;
        if (size_ > high_water_) high_water_ = size_;
        return true;
    }
    /// Inserts `v` before position pos (<= size), shifting the rest; false (and a drop) when full.
    bool insert(size_t pos, const T& v) {
        if (!push_back(v)) return false;
        for (size_t k = size_ - 1; k > pos; --k) data_[k] = data_[k - 1];
        data_[pos] = v;
        return true;
    }
    /// Removes the element at pos (< size), shifting the rest down.
    void erase(size_t pos) {
        HIDER_ASSERT(pos < size_);
        for (size_t k = pos; k + 1 < size_; ++k) data_[k] = data_[k + 1];
        --size_;
    }
    void clear() { size_ = 0; dropped_ = 0; }
    size_t size() const { return size_; }
    size_t capacity() const { return capacity_; }
    size_t dropped() const { return dropped_; }
    size_t high_water() const { return high_water_; }
    T& operator[](size_t i) const {
        HIDER_ASSERT(i < size_);
        return data_[i];
    }
    T* data() const { return data_; }

private:
    T* data_ = nullptr;
    size_t capacity_ = 0;
    size_t size_ = 0;
    size_t dropped_ = 0;
    size_t high_water_ = 0;
};

}  // namespace hider

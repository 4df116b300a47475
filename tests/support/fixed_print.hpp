// doctest printing for lib/ types, so failures show value and raw hex.
#pragma once
#include <hider/fixed.hpp>

#include <doctest/doctest.h>

#include <cstdio>
#include <string>

namespace doctest {
template <int F>
struct StringMaker<hider::Fixed<F>> {
    static String convert(hider::Fixed<F> v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g (raw 0x%08x, Q%d)", static_cast<double>(v.raw()) / (1 << F),
                      static_cast<unsigned>(v.raw()), F);
        return buf;
    }
};
}  // namespace doctest

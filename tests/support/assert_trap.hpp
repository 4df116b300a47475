// Tests of checked preconditions (HIDER_ASSERT, in builds with HIDER_ENABLE_ASSERTS): assert_trap::fails(f)
// runs f with the host port's assert handler (port/host/assert.hpp) jumping back out of a failed
// assertion, so a test can require that a call checks its input, and where.
#pragma once
#include <csetjmp>
#include <string>

#include "host/assert.hpp"

namespace hider::test::assert_trap {

inline std::jmp_buf& jump() {
    static std::jmp_buf j;
    return j;
}

/// The file and line of the last assertion fails() caught.
inline std::string& file() {
    static std::string f;
    return f;
}
inline int& line() {
    static int l = 0;
    return l;
}

inline void jump_out(const char* failed_file, int failed_line) {
    file() = failed_file;
    line() = failed_line;
    std::longjmp(jump(), 1);
}

/// Whether f() fails a HIDER_ASSERT (f is left there, by longjmp: give it no object that needs a destructor).
template <class F>
bool fails(F&& f) {
    const port::AssertHandler previous = port::set_assert_handler(jump_out);
    if (setjmp(jump()) != 0) {  // no local changed since setjmp() is read here
        port::set_assert_handler(previous);
        return true;
    }
    f();
    port::set_assert_handler(previous);
    return false;
}

}  // namespace hider::test::assert_trap

// The host port's HIDER_ASSERT hook (assert.cpp): a program may have a failed assertion reported to its
// own handler first, e.g. a test that requires a draw call to check its input and jumps back out of it.
#pragma once

namespace hider::port {

/// Called with the failed assertion's file and line before the default message and abort; a handler that
/// does not return (longjmp) takes over. nullptr: none. Returns the previous handler.
using AssertHandler = void (*)(const char* file, int line);
AssertHandler set_assert_handler(AssertHandler handler);

}  // namespace hider::port

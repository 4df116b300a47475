// The host port's HIDER_ASSERT hook (assert.cpp): a program may have a failed assertion reported to its
// own handler first, e.g. a test that requires a draw call to check its input and jumps back out of it.
#pragma once

namespace hider::port {

/// A handler of failed assertions: their file and line.
using AssertHandler = void (*)(const char* file, int line);

/// Makes `handler` the first to hear of a failed assertion, before the default message and abort; a
/// handler that does not return (longjmp) takes over; nullptr: none. Returns the previous handler. Only
/// the host port's weak hider_assert_fail() calls it: a program that defines its own never does.
AssertHandler set_assert_handler(AssertHandler handler);

}  // namespace hider::port

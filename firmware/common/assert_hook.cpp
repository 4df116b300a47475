// Weak default for the HIDER_ASSERT hook declared in lib/hider/base.hpp: print file:line on the
// semihosting console and exit with status 2. A firmware overrides it by defining its own.
#include <hider/base.hpp>
#include "semihost/semihost.hpp"

extern "C" __attribute__((weak)) void hider_assert_fail(const char* file, int line) {
    namespace sh = hider::semihost;
    sh::print("hider: assertion failed at ");
    sh::print(file);
    sh::print(":");
    sh::print_u32(static_cast<uint32_t>(line));
    sh::print("\n");
    sh::exit(2);
}

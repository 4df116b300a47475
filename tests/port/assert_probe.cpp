// Probe of the hider.asserts_active test (tests/CMakeLists.txt): a programmer error inside lib/ (erase
// from an empty BoundedList) must reach the HIDER_ASSERT hook, which names the file and line and aborts.
#include <hider/base.hpp>

int main() {
    uint32_t storage[1];
    hider::BoundedList<uint32_t> list(storage);
    list.erase(0);
    return 0;  // reached only when asserts are compiled out
}

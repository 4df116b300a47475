// Firmware side of the examples' Io: one semihosted output file at a time plus console text.
#pragma once
#include "semihost/semihost.hpp"

namespace spin {

class SemihostIo {
public:
    bool open(const char* path) {
        handle_ = hider::semihost::open_write(path);
        return handle_ != hider::semihost::kInvalidHandle;
    }
    bool write(const void* data, size_t size) { return hider::semihost::write(handle_, data, size); }
    bool close() {
        const bool ok = hider::semihost::close(handle_);
        handle_ = hider::semihost::kInvalidHandle;
        return ok;
    }
    void print(const char* text) { hider::semihost::print(text); }
    void print_u32(uint32_t v) { hider::semihost::print_u32(v); }

private:
    int32_t handle_ = hider::semihost::kInvalidHandle;
};

}  // namespace spin

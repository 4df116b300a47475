// Host side of the examples' Io (host references only): files through <cstdio>, text on stdout.
// A host reference also defines bench_begin()/bench_end() as empty functions (once, in its .cpp).
#pragma once
#include <cstdint>
#include <cstdio>

namespace spin {

class StdioIo {
public:
    bool open(const char* path) {
        file_ = std::fopen(path, "wb");
        if (file_ == nullptr) std::perror(path);
        return file_ != nullptr;
    }
    bool write(const void* data, size_t size) { return std::fwrite(data, 1, size, file_) == size; }
    bool close() {
        const bool ok = std::fclose(file_) == 0;
        file_ = nullptr;
        return ok;
    }
    void print(const char* text) { std::fputs(text, stdout); }
    void print_u32(uint32_t v) { std::printf("%u", static_cast<unsigned>(v)); }

private:
    std::FILE* file_ = nullptr;
};

}  // namespace spin

namespace host {

/// Writes size bytes to a new file at path (the host side of semihost::write_file); reports a failure
/// with perror and returns false.
inline bool write_file(const char* path, const void* data, size_t size) {
    std::FILE* file = std::fopen(path, "wb");
    if (file == nullptr) {
        std::perror(path);
        return false;
    }
    const bool written = std::fwrite(data, 1, size, file) == size;
    if (std::fclose(file) != 0 || !written) {
        std::perror(path);
        return false;
    }
    return true;
}

}  // namespace host

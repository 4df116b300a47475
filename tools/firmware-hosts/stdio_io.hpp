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

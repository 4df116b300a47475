// Host side of the examples' Io (host references only): files through <cstdio>, text on stdout, and
// bench_begin()/bench_end() as no-ops so the shared program links unchanged.
#pragma once
#include <cstdint>
#include <cstdio>

extern "C" {
inline void bench_begin() {}
inline void bench_end() {}
}

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

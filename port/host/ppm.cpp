// Host port: PPM (P6) file writing and reading.
#include "host/ppm.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace hider::port {

std::vector<uint8_t> ppm_bytes(int width, int height, const std::vector<uint8_t>& rgb) {
    const std::string header = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    std::vector<uint8_t> out(header.begin(), header.end());
    out.insert(out.end(), rgb.begin(), rgb.end());
    return out;
}

namespace {

bool write_bytes(const std::string& path, const char* data, size_t size, std::string& error) {
    // POSIX lstat/access rather than <filesystem>, which the WebAssembly build's libc++ lacks.
    struct stat st {};
    const bool exists = ::lstat(path.c_str(), &st) == 0;
#if defined(__wasi__)
    const bool in_place = true;  // the web build's file system has no rename: written in place
#else
    const bool in_place = exists && !S_ISREG(st.st_mode);  // /dev/stdout, a pipe, a symlink
#endif
    if (exists && !in_place && ::access(path.c_str(), W_OK) != 0) {  // a read-only file stays refused
        error = path + ": " + std::strerror(errno);
        return false;
    }
    const std::string target = in_place ? path : path + ".partial";
    std::ofstream f(target, std::ios::binary);
    if (!f) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    f.write(data, static_cast<std::streamsize>(size));
    f.close();
    if (!f) {
        if (!in_place) std::remove(target.c_str());  // a truncated file: never left behind
        error = path + ": write failed";
        return false;
    }
    if (!in_place && std::rename(target.c_str(), path.c_str()) != 0) {
        error = path + ": " + std::strerror(errno);
        std::remove(target.c_str());
        return false;
    }
    return true;
}

}  // namespace

bool write_file(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error) {
    return write_bytes(path, reinterpret_cast<const char*>(bytes.data()), bytes.size(), error);
}

bool write_file(const std::string& path, const std::string& bytes, std::string& error) {
    return write_bytes(path, bytes.data(), bytes.size(), error);
}

bool write_ppm(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string& error) {
    if (width <= 0 || height <= 0 || rgb.size() != static_cast<size_t>(width) * height * 3) {
        error = path + ": image size does not match its pixel data";
        return false;
    }
    return write_file(path, ppm_bytes(width, height, rgb), error);
}

bool read_ppm(const std::string& path, int& width, int& height, std::vector<uint8_t>& rgb) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::string magic;
    int maxval = 0;
    f >> magic >> width >> height >> maxval;
    if (!f || magic != "P6" || maxval != 255 || width <= 0 || height <= 0 || width > 16384 || height > 16384)
        return false;
    f.get();  // the single whitespace byte after maxval
    rgb.assign(static_cast<size_t>(width) * height * 3, 0);
    f.read(reinterpret_cast<char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
    return static_cast<size_t>(f.gcount()) == rgb.size();
}

}  // namespace hider::port

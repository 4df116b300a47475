// Host port: PPM (P6) file writing and reading.
#include "host/ppm.hpp"

#include <sys/stat.h>

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

bool write_file(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error) {
    std::ofstream f(path, std::ios::binary);
    if (!f) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    f.close();
    if (!f) {
        // A truncated file holds a partial image: do not leave it behind (but never unlink a device).
        // POSIX stat rather than <filesystem>, which the WebAssembly build's libc++ lacks.
        struct stat st {};
        if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) std::remove(path.c_str());
        error = path + ": write failed";
        return false;
    }
    return true;
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

// Host port: PPM (P6) file writing and reading.
#include "host/ppm.hpp"

#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace hider::port {

bool rgb_size_ok(int width, int height, size_t rgb_bytes) {
    if (width <= 0 || height <= 0) return false;
    const uint64_t bytes = uint64_t{static_cast<uint32_t>(width)} * static_cast<uint32_t>(height) * 3u;
    return bytes <= SIZE_MAX / 2 && bytes == rgb_bytes;  // room for the PNG's row filters and chunks
}

std::vector<uint8_t> ppm_bytes(int width, int height, const std::vector<uint8_t>& rgb) {
    const std::string header = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    std::vector<uint8_t> out(header.begin(), header.end());
    out.insert(out.end(), rgb.begin(), rgb.end());
    return out;
}

namespace {

/// unsigned -> mode_t: the same type on Linux, 16 bits on macOS. A cast in a template, so that neither
/// -Wconversion (macOS) nor a user's -Wuseless-cast (Linux) has anything to say.
template <class Mode>
Mode narrow_mode(unsigned bits) {
    return static_cast<Mode>(bits);
}

/// In place, as ofstream writes: a device, a pipe, a symlink, a file with other hard links, the web build.
bool write_in_place(const std::string& path, const char* data, size_t size, bool existed, std::string& error) {
    std::ofstream f(path, std::ios::binary);
    if (!f) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    f.write(data, static_cast<std::streamsize>(size));
    f.close();
    if (!f) {
        // A truncated file we created holds a partial image: not left behind (a device is never unlinked).
        struct stat st {};
        if (!existed && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) std::remove(path.c_str());
        error = path + ": write failed";
        return false;
    }
    return true;
}

#if !defined(__wasi__)
/// All of [data, data + size) to descriptor fd; false on an error.
bool write_all(int fd, const char* data, size_t size) {
    for (size_t done = 0; done < size;) {
        const ssize_t n = ::write(fd, data + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}
#endif

bool write_bytes(const std::string& path, const char* data, size_t size, std::string& error) {
    // POSIX calls rather than <filesystem>, which the WebAssembly build's libc++ lacks.
    struct stat st {};
    const bool exists = ::lstat(path.c_str(), &st) == 0;
#if defined(__wasi__)
    return write_in_place(path, data, size, exists, error);  // the web build's file system: no mkstemp
#else
    if (is_standard_output(path)) {  // after what the tool printed before, at the descriptor's own offset
        if (std::fflush(stdout) != 0 || !write_all(STDOUT_FILENO, data, size)) {
            error = path + ": write failed: " + std::strerror(errno);
            return false;
        }
        return true;
    }
    if (exists && (!S_ISREG(st.st_mode) || st.st_nlink > 1)) return write_in_place(path, data, size, true, error);
    if (exists && ::access(path.c_str(), W_OK) != 0) {  // a read-only file stays refused
        error = path + ": " + std::strerror(errno);
        return false;
    }
    // A fresh, exclusive temporary file beside the output (never a link, never someone else's file),
    // renamed over it when every byte is written.
    std::vector<char> temp(path.begin(), path.end());
    for (const char c : std::string(".XXXXXX")) temp.push_back(c);
    temp.push_back('\0');
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) {
        if (exists) return write_in_place(path, data, size, true, error);  // a writable file in a closed directory
        error = path + ": " + std::strerror(errno);
        return false;
    }
    mode_t mode = st.st_mode & 07777;
    if (!exists) {
        const unsigned umask_bits = ::umask(0);
        ::umask(narrow_mode<mode_t>(umask_bits));
        mode = narrow_mode<mode_t>(0666u & ~umask_bits);
    }
    bool ok = ::fchmod(fd, mode) == 0 && write_all(fd, data, size);
    ok = (::close(fd) == 0) && ok;
    if (!ok) {
        ::unlink(temp.data());
        error = path + ": write failed";
        return false;
    }
    if (std::rename(temp.data(), path.c_str()) != 0) {
        error = path + ": cannot replace it: " + std::strerror(errno);
        ::unlink(temp.data());
        return false;
    }
    return true;
#endif
}

}  // namespace

bool is_standard_output(const std::string& path) {
#if defined(__wasi__)
    (void)path;
    return false;
#else
    struct stat out {}, target {};
    return ::fstat(STDOUT_FILENO, &out) == 0 && ::stat(path.c_str(), &target) == 0 && out.st_dev == target.st_dev &&
           out.st_ino == target.st_ino;
#endif
}

bool write_file(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error) {
    return write_bytes(path, reinterpret_cast<const char*>(bytes.data()), bytes.size(), error);
}

bool write_file(const std::string& path, const std::string& bytes, std::string& error) {
    return write_bytes(path, bytes.data(), bytes.size(), error);
}

bool write_ppm(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string& error) {
    if (!rgb_size_ok(width, height, rgb.size())) {
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
    // The pixels must be in the file before they are allocated (a 20-byte header may claim 805 MB).
    const size_t bytes = static_cast<size_t>(width) * static_cast<size_t>(height) * 3;
    const std::streampos start = f.tellg();
    f.seekg(0, std::ios::end);
    const std::streampos end = f.tellg();
    if (!f || start < 0 || end - start < static_cast<std::streamoff>(bytes)) return false;
    f.seekg(start);
    rgb.assign(bytes, 0);
    f.read(reinterpret_cast<char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
    return static_cast<size_t>(f.gcount()) == rgb.size();
}

}  // namespace hider::port

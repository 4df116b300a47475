// hider-bench internals shared by its commands: argument helpers, the commands themselves, and the
// callgrind runner. Exit codes: 0 ok, 2 usage or run error, kExitNoValgrind when valgrind is missing.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

#include "common/scene.hpp"

namespace hider::tool::bench {

/// Exit status when valgrind cannot be found (77 = "skipped" for ctest's SKIP_RETURN_CODE).
constexpr int kExitNoValgrind = 77;

using Args = std::vector<std::string>;

[[noreturn]] void fail(const std::string& msg);
bool parse_double(const std::string& s, double& out);
bool parse_long(const std::string& s, long& out);

/// Consumes a camera option (--size --eye --target --up --fov --near --far) at args[i] and its value;
/// returns false if args[i] is not one. Exits with a message on a bad value.
bool parse_camera_option(const Args& args, size_t& i, CameraArgs& cam);

/// Value of the option at args[i] (advances i); exits if it is missing.
const std::string& option_value(const Args& args, size_t& i);

int frame_command(const Args& args);      ///< hider-bench frame ...
int table_command(const Args& args);      ///< hider-bench table ...
int span_command(const Args& args);       ///< hider-bench span ...
int span_run_command(const Args& args);   ///< internal: the span loop that span runs under callgrind

/// n zero-filled elements of T at a 64-byte boundary, so counts inside memset and friends do not
/// depend on where the allocator happened to place a buffer.
template <class T>
class AlignedBuffer {
    static_assert(std::is_trivially_destructible<T>::value, "freed without destructors");

public:
    explicit AlignedBuffer(size_t n) : size_(n) {
        if (n > (size_t{1} << 32)) fail("buffer of " + std::to_string(n) + " elements is too large");
        const size_t bytes = (n * sizeof(T) + 63) / 64 * 64;
        data_.reset(static_cast<T*>(std::aligned_alloc(64, bytes == 0 ? 64 : bytes)));
        if (!data_) fail("out of memory");
        for (size_t i = 0; i < n; ++i) new (data_.get() + i) T{};  // T is trivially destructible
    }
    T* data() const { return data_.get(); }
    size_t size() const { return size_; }

private:
    struct Free {
        void operator()(T* p) const { std::free(p); }
    };
    std::unique_ptr<T, Free> data_;
    size_t size_;
};

/// What one callgrind run produced.
struct CallgrindRun {
    uint64_t ir = 0;     ///< total Ir collected (only inside the toggled function)
    std::string out;     ///< the program's stdout
};

/// Path of valgrind: `given` if not empty (must be executable), else the first one on PATH. Exits with
/// kExitNoValgrind and an install hint when there is none.
std::string find_valgrind(const std::string& given);

/// Runs this executable with `args` under callgrind, collecting only inside `function`. Exits with a
/// message (and the program's stderr) if the run fails or collects nothing.
CallgrindRun run_callgrind(const std::string& valgrind, const std::string& function, const Args& args);

}  // namespace hider::tool::bench

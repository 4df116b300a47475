// Runs hider-bench itself under valgrind's callgrind with collection switched on only inside one
// function (--toggle-collect, --collect-atstart=no) and reads the total Ir from the output file's
// "totals:" line (or "summary:" in older formats; callgrind_format(5) in the valgrind manual).
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "bench.hpp"

namespace hider::tool::bench {
namespace {

namespace fs = std::filesystem;

bool is_executable_file(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

std::string self_path() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    if (ec) fail("cannot find this executable through /proc/self/exe: " + ec.message());
    return p.string();
}

/// Total Ir of a callgrind output file; false if the file has no Ir event or no totals/summary line.
bool parse_total_ir(const std::string& text, uint64_t& ir) {
    std::istringstream in(text);
    std::string line;
    std::vector<std::string> events;
    std::string totals, summary;
    while (std::getline(in, line)) {
        if (line.rfind("events:", 0) == 0) {
            std::istringstream names(line.substr(7));
            events.clear();
            for (std::string n; names >> n;) events.push_back(n);
        } else if (line.rfind("totals:", 0) == 0) {
            totals = line.substr(7);
        } else if (line.rfind("summary:", 0) == 0) {
            summary = line.substr(8);
        }
    }
    size_t index = 0;
    while (index < events.size() && events[index] != "Ir") ++index;
    if (index == events.size()) return false;
    std::istringstream values(totals.empty() ? summary : totals);
    std::string v;
    for (size_t i = 0; i <= index; ++i)
        if (!(values >> v)) return false;
    if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos) return false;
    errno = 0;
    const unsigned long long parsed = std::strtoull(v.c_str(), nullptr, 10);
    if (errno != 0) return false;
    ir = static_cast<uint64_t>(parsed);
    return true;
}

}  // namespace

std::string find_valgrind(const std::string& given) {
    if (!given.empty()) {
        if (is_executable_file(given)) return given;
        std::fprintf(stderr, "hider-bench: valgrind '%s' is not an executable file\n", given.c_str());
        std::exit(kExitNoValgrind);
    }
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/valgrind";
        if (is_executable_file(candidate)) return candidate;
    }
    std::fprintf(stderr,
                 "hider-bench: valgrind not found on PATH; install it (Debian/Ubuntu: apt-get install valgrind) "
                 "or pass --valgrind PATH\n");
    std::exit(kExitNoValgrind);
}

namespace {

/// One run inside `tmp`; on failure returns false with `error` set (the caller removes tmp, then exits).
bool run_in(const TempDir& tmp, const std::string& valgrind, const std::string& self, const std::string& function,
            const Args& args, CallgrindRun& run, std::string& error) {
    const std::string out_file = (tmp.path() / "callgrind.out").string();
    const std::string stdout_file = (tmp.path() / "stdout").string();
    const std::string stderr_file = (tmp.path() / "stderr").string();
    Args argv_strings = {valgrind,
                         "-q",
                         "--tool=callgrind",
                         "--callgrind-out-file=" + out_file,
                         "--toggle-collect=" + function,
                         "--collect-atstart=no",
                         self};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    std::string command;
    for (size_t i = 0; i < argv_strings.size(); ++i) command += (i == 0 ? "" : " ") + argv_strings[i];
    ProcessResult result;
    if (!run_process(argv_strings, "", {}, stdout_file, stderr_file, result, error)) return false;
    if (!result.exited || result.status != 0) {
        error = "callgrind run failed (" + result.describe() + "): " + command + "\n" + read_text(stderr_file);
        return false;
    }
    run.out = read_text(stdout_file);
    if (!parse_total_ir(read_text(out_file), run.ir)) {
        error = "no Ir total in callgrind output of: " + command;
        return false;
    }
    if (run.ir == 0) {
        error = "callgrind collected nothing; is '" + function + "' in the binary? " + command;
        return false;
    }
    return true;
}

}  // namespace

CallgrindRun run_callgrind(const std::string& valgrind, const std::string& function, const Args& args) {
    CallgrindRun run;
    std::string error;
    bool ok = false;
    const std::string self = self_path();
    {
        const TempDir tmp;
        ok = run_in(tmp, valgrind, self, function, args, run, error);
    }
    if (!ok) fail(error);
    return run;
}

}  // namespace hider::tool::bench

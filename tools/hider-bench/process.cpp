// Child processes for hider-bench: posix_spawnp with the output in files, an optional working
// directory (glibc's posix_spawn_file_actions_addchdir_np) and extra environment entries, plus the
// private temporary directory the runs write into.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "bench.hpp"

extern char** environ;

namespace hider::tool::bench {

namespace fs = std::filesystem;

TempDir::TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base != nullptr && *base != '\0' ? base : "/tmp") + "/hider-bench.XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr)
        fail("cannot create a temporary directory: " + std::string(std::strerror(errno)));
    path_ = pattern;
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string ProcessResult::describe() const {
    return exited ? "exit " + std::to_string(status) : std::string("killed by a signal");
}

bool run_process(const Args& argv, const std::string& cwd, const Args& env, const std::string& stdout_file,
                 const std::string& stderr_file, ProcessResult& result, std::string& error) {
    if (argv.empty()) {
        error = "run_process: no program given";
        return false;
    }
    for (const std::string& x : env) {
        if (x.find('=') == std::string::npos || x[0] == '=') {
            error = "run_process: bad environment entry '" + x + "'";
            return false;
        }
    }
    Args argv_copy = argv;
    std::vector<char*> args;
    for (std::string& s : argv_copy) args.push_back(s.data());
    args.push_back(nullptr);

    // The environment: ours without the names `env` sets, then `env`.
    Args env_strings;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string entry = *e;
        bool overridden = false;
        for (const std::string& x : env) {
            const size_t name_end = x.find('=') + 1;  // env entries are checked to hold '=' below
            if (entry.compare(0, name_end, x, 0, name_end) == 0) overridden = true;
        }
        if (!overridden) env_strings.push_back(entry);
    }
    env_strings.insert(env_strings.end(), env.begin(), env.end());
    std::vector<char*> envp;
    for (std::string& s : env_strings) envp.push_back(s.data());
    envp.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
    posix_spawn_file_actions_addopen(&actions, 1, stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_addopen(&actions, 2, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = 0;
    const int spawn_error = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawn_error != 0) {
        error = "cannot run " + argv[0] + ": " + std::strerror(spawn_error);
        return false;
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            error = "waitpid: " + std::string(std::strerror(errno));
            return false;
        }
    }
    result.exited = WIFEXITED(status);
    result.status = result.exited ? WEXITSTATUS(status) : 0;
    return true;
}

}  // namespace hider::tool::bench

namespace hider::tool::bench {

bool firmware_count(const std::filesystem::path& tree, const std::string& preset, const std::string& elf_rel,
                    const std::string& machine, TargetCount& c) {
    namespace fs = std::filesystem;
    const fs::path elf = tree / elf_rel;
    if (!fs::is_regular_file(elf)) return false;
    const TempDir tmp;
    const fs::path counts = tmp.path() / "counts.txt";
    Args env;
    std::ifstream cache(tree / "CMakeCache.txt");
    for (std::string line; std::getline(cache, line);) {
        if (line.rfind("HIDER_INSNCOUNT_PLUGIN:", 0) == 0) {
            const std::string plugin = line.substr(line.find('=') + 1);
            if (fs::is_regular_file(plugin)) env.push_back("INSNCOUNT_PLUGIN=" + plugin);
        } else if (line.rfind("CMAKE_NM:", 0) == 0) {
            env.push_back("NM=" + line.substr(line.find('=') + 1));
        }
    }
    ProcessResult result;
    std::string error;
    const Args argv = {"sh", (source_root() / "tools/qemu-insncount/run.sh").string(), preset, elf.string(), counts.string(), machine};
    if (!run_process(argv, tmp.path().string(), env, (tmp.path() / "o").string(), (tmp.path() / "e").string(), result, error))
        fail(error);
    if (!result.exited || result.status != 0)
        fail(elf.string() + ": run under QEMU failed (" + result.describe() + "):\n" + read_text(tmp.path() / "e"));
    unsigned long long total = 0, region = 0, pairs = 0, max = 0;
    if (std::sscanf(read_text(counts).c_str(), "insncount total=%llu region=%llu pairs=%llu max=%llu", &total, &region, &pairs, &max) != 4)
        fail(elf.string() + ": no counts from the insncount plugin");
    c = {region, pairs, max};
    return true;
}

}  // namespace hider::tool::bench

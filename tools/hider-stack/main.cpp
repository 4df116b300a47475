// hider-stack: a static worst-case stack bound for a firmware ELF, from `objdump -t -s -d` output
// (stack_bound.hpp says how it bounds). Exit 0: bounded (and within --limit); 1: above --limit;
// 2: cannot be bounded (recursion, sp written by a register, a call that does not resolve) or bad usage.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <new>
#include <string>

#include "stack_bound.hpp"

namespace {

void print_usage(std::ostream& out) {
    out << "usage: hider-stack DUMP --entry FUNC [--limit BYTES] [--handler FUNC]... [--not-pointers OBJECT]...\n"
        << "  DUMP: the output of `objdump -t -s -d firmware.elf` (arm-none-eabi- or riscv64-unknown-elf-objdump;\n"
        << "  --no-show-raw-insn optional)\n"
        << "  --entry FUNC          the function the bound starts from (the reset handler)\n"
        << "  --limit BYTES         exit 1 when the bound exceeds BYTES\n"
        << "  --handler FUNC        an exception handler: never the target of an indirect call (repeatable)\n"
        << "  --not-pointers OBJECT a data object whose words are not code addresses (repeatable)\n"
        << "exit 0: bounded (within --limit); 1: above --limit; 2: no bound (recursion, sp moved by a register,\n"
        << "an unresolved call) or bad usage\n";
}

int usage(const char* why) {
    std::cerr << "hider-stack: " << why << "\n";
    print_usage(std::cerr);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::set_new_handler([] {  // built without exceptions: std::bad_alloc would abort
        std::fputs("hider-stack: out of memory\n", stderr);
        std::_Exit(2);
    });
    std::string dump;
    stackbound::Options opt;
    long limit = -1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            print_usage(std::cout);
            return 0;
        }
        if (a == "--entry" || a == "--handler" || a == "--not-pointers" || a == "--limit") {
            const char* v = i + 1 < argc ? argv[++i] : nullptr;
            if (v == nullptr) return usage((a + " needs a value").c_str());
            if (a == "--entry") opt.entry = v;
            else if (a == "--handler") opt.handlers.push_back(v);
            else if (a == "--not-pointers") opt.not_pointers.push_back(v);
            else {
                char* end = nullptr;
                limit = std::strtol(v, &end, 10);
                if (*v == '\0' || *end != '\0' || limit < 0) return usage((std::string("--limit '") + v + "' is not a byte count").c_str());
            }
        } else if (!a.empty() && a[0] == '-') {
            return usage(("unknown option " + a).c_str());
        } else if (dump.empty()) {
            dump = a;
        } else {
            return usage("more than one dump");
        }
    }
    if (dump.empty() || opt.entry.empty()) return usage("a dump and --entry are required");
    std::ifstream in(dump);
    if (!in) {
        std::cerr << "hider-stack: " << dump << ": cannot open\n";
        return 2;
    }
    stackbound::Program p;
    std::string why;
    if (!stackbound::parse_objdump(in, p, why)) {
        std::cerr << "hider-stack: " << dump << ": " << why << "\n";
        return 2;
    }
    const stackbound::Bound b = stackbound::bound(p, opt);
    if (!b.ok) {
        std::cerr << "hider-stack: " << dump << ": no bound from " << opt.entry << ": " << b.why << "\n";
        return 2;
    }
    std::cout << "stack bound from " << opt.entry << ": " << b.bytes << " bytes";
    if (limit >= 0) std::cout << " (limit " << limit << ")";
    std::cout << "\ndeepest chain (frame, depth after it):\n";
    uint32_t depth = 0;
    for (const auto& [name, frame] : b.path) {
        depth += frame;
        std::cout << "  " << frame << "\t" << depth << "\t" << name << "\n";
    }
    std::cout << "an indirect call may reach " << b.indirect_targets.size() << " function(s)";
    for (const std::string& t : b.indirect_targets) std::cout << "\n  " << t;
    std::cout << "\n";
    if (limit >= 0 && b.bytes > static_cast<uint32_t>(limit)) {
        std::cerr << "hider-stack: " << dump << ": the bound of " << b.bytes << " bytes exceeds the stack of " << limit << "\n";
        return 1;
    }
    return 0;
}

// A static worst-case stack bound of a firmware from its disassembly (`objdump -t -s -d`, Thumb and
// RV32): it reads what was linked, assembly and libgcc included, and refuses what it cannot bound
// (recursion, sp moved by an unknown amount, a call into the unknown) instead of guessing. How it
// bounds and what it leaves out: README.md, "Stack: a static bound".
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace stackbound {

enum class Isa { arm, riscv };

struct Function {
    std::vector<std::string> names;  ///< aliases share an address (e.g. __aeabi_uidiv, __udivsi3)
    uint32_t start = 0, size = 0;
    uint32_t frame = 0;              ///< bytes: every allocation in its body, summed
    std::vector<size_t> callees;     ///< direct calls and tail calls (function indices)
    uint32_t indirect_sites = 0;     ///< calls or jumps through a register
    std::vector<std::string> problems;  ///< what keeps it from being bounded (address: what)
    bool sets_sp = false;            ///< loads sp with a new value (allowed only in the entry)
};

struct Program {
    Isa isa = Isa::arm;
    std::vector<Function> funcs;              ///< sorted by start
    std::vector<bool> address_taken_by_code;  ///< per function: its address formed by an instruction (adr, la)
    struct PointerSite { uint32_t addr; size_t func; };
    std::vector<PointerSite> pointer_sites;   ///< aligned words holding a function's address (literal pools, data)
    struct Range { uint32_t start, size; std::string name; };
    std::vector<Range> objects;               ///< data symbols (for Options::ignore_objects)
};

/// Parses `objdump -t -s -d` output. False with a reason on text it cannot read.
bool parse_objdump(std::istream& in, Program& p, std::string& why);

struct Options {
    std::string entry;                      ///< the function the bound starts from
    std::vector<std::string> handlers;      ///< functions never reached by an indirect call (exception handlers)
    std::vector<std::string> not_pointers;  ///< data objects whose words are not function pointers ('*' globs)
};

struct Bound {
    bool ok = false;
    uint32_t bytes = 0;
    std::vector<std::pair<std::string, uint32_t>> path;  ///< the deepest chain: function, its frame
    std::vector<std::string> indirect_targets;           ///< what an indirect call may reach
    std::string why;                                     ///< when !ok
};

/// The worst-case stack from opt.entry.
Bound bound(const Program& p, const Options& opt);

/// The internals, exposed for the tests.
namespace detail {
/// `name` matches `pattern`, where '*' stands for any run of characters.
bool glob_match(const std::string& pattern, const std::string& name);
/// Registers in a list such as "{r4, r5, r6, lr}" or "{r4-r7, lr}"; -1 when it is not a list.
int register_count(const std::string& list);
}  // namespace detail

}  // namespace stackbound

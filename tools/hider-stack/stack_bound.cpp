#include "stack_bound.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>
#include <istream>
#include <set>
#include <sstream>

namespace stackbound {

namespace {

bool is_hex(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; });
}

uint32_t hex_value(const std::string& s) { return static_cast<uint32_t>(std::strtoul(s.c_str(), nullptr, 16)); }

std::string trim(const std::string& s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

/// Operands split at top-level commas ("{r4, r5}" and "[sp, #-4]!" stay whole).
std::vector<std::string> split_operands(const std::string& ops) {
    std::vector<std::string> out;
    std::string cur;
    int depth = 0;
    for (char c : ops) {
        if (c == '{' || c == '[' || c == '(') ++depth;
        if (c == '}' || c == ']' || c == ')') --depth;
        if (c == ',' && depth == 0) {
            out.push_back(trim(cur));
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!trim(cur).empty()) out.push_back(trim(cur));
    return out;
}

/// The address of a branch operand such as "5558 <__aeabi_uidivmod>" (the last hex number before " <").
bool branch_target(const std::string& ops, uint32_t& target) {
    const size_t lt = ops.find(" <");
    if (lt == std::string::npos) return false;
    size_t b = lt;
    while (b > 0 && std::isxdigit(static_cast<unsigned char>(ops[b - 1]))) --b;
    const std::string h = ops.substr(b, lt - b);
    if (!is_hex(h)) return false;
    target = hex_value(h);
    return true;
}

/// An immediate such as "#16", "#-8" or "-48" (decimal or 0x hex); false for a register.
bool immediate(const std::string& op, long& v) {
    std::string s = op;
    if (!s.empty() && s[0] == '#') s = s.substr(1);
    if (s.empty()) return false;
    char* end = nullptr;
    v = std::strtol(s.c_str(), &end, 0);
    return end != nullptr && *end == '\0';
}

bool arm_condition(const std::string& c) {
    static const char* const kConds[] = {"eq", "ne", "cs", "hs", "cc", "lo", "mi", "pl", "vs",
                                         "vc", "hi", "ls", "ge", "lt", "gt", "le", "al"};
    return std::any_of(std::begin(kConds), std::end(kConds), [&](const char* k) { return c == k; });
}

/// mnemonic == base, or base followed by a condition code (an IT block's "popeq", "bxne").
bool arm_is(const std::string& mn, const char* base) {
    const std::string b = base;
    return mn == b || (mn.size() == b.size() + 2 && starts_with(mn, base) && arm_condition(mn.substr(b.size())));
}

struct Parser {
    Program& p;
    std::map<uint32_t, uint32_t> words;  ///< aligned words of allocated sections, by address
    struct Pending {  ///< a function's instructions, classified once all symbols are known
        uint32_t addr;
        std::string mn, ops, comment;
    };
    std::vector<std::vector<Pending>> code;

    long containing(uint32_t addr) const {
        auto it = std::upper_bound(p.funcs.begin(), p.funcs.end(), addr, [](uint32_t a, const Function& f) { return a < f.start; });
        if (it == p.funcs.begin()) return -1;
        --it;
        return addr < it->start + it->size ? it - p.funcs.begin() : -1;
    }
    long starting_at(uint32_t addr) const {
        const long i = containing(addr);
        return i >= 0 && p.funcs[static_cast<size_t>(i)].start == addr ? i : -1;
    }
};

/// True when the register list ("{r4, r5, lr}", "{r4-r7}") names reg; unreadable lists name everything.
bool list_names(const std::string& list, const std::string& reg) {
    const std::string s = trim(list);
    if (s.size() < 2 || s.front() != '{' || s.back() != '}') return false;
    for (const std::string& r : split_operands(s.substr(1, s.size() - 2))) {
        if (r == reg) return true;
        const size_t dash = r.find('-');
        if (dash == std::string::npos) continue;
        const std::string a = r.substr(0, dash), b = r.substr(dash + 1);
        if (a.size() < 2 || b.size() < 2 || reg.size() < 2 || a[0] != 'r' || b[0] != 'r' || reg[0] != 'r') return true;
        const int n = std::atoi(reg.c_str() + 1);
        if (n >= std::atoi(a.c_str() + 1) && n <= std::atoi(b.c_str() + 1)) return true;
    }
    return false;
}

void add_callee(Function& f, size_t callee) {
    if (std::find(f.callees.begin(), f.callees.end(), callee) == f.callees.end()) f.callees.push_back(callee);
}

std::string where(uint32_t addr, const std::string& what) {
    std::ostringstream s;
    s << std::hex << addr << ": " << what;
    return s.str();
}

/// A call or jump to `target` from function fi: a callee, a local jump, or a problem.
void transfer(Parser& ps, size_t fi, uint32_t addr, uint32_t target, bool call) {
    Function& f = ps.p.funcs[fi];
    const long t = ps.containing(target);
    if (t == static_cast<long>(fi)) return;  // a branch or local subroutine inside the function
    if (t < 0) {
        if (call) f.problems.push_back(where(addr, "call to an address outside every function"));
        return;  // a jump into data would be a disassembly artefact; calls must resolve
    }
    add_callee(f, static_cast<size_t>(t));
}

/// The constant register `reg` holds before instruction k, when the few instructions before it built
/// it: a literal load, a move, shifts, negation, adds (Thumb-1 changes sp by a register for frames
/// above 508 bytes: "ldr r4, [pc, #8]; add sp, r4", "movs r3, #193; lsls r3, r3, #2; add sp, r3").
bool literal_value(const Parser& ps, const std::vector<Parser::Pending>& ins, size_t k, const std::string& reg, long& v, int depth = 0) {
    for (size_t j = k; j-- > 0 && j + 6 > k;) {
        const std::vector<std::string> ops = split_operands(ins[j].ops);
        if (!ops.empty() && list_names(ops[0], reg)) return false;  // loaded by a pop or load-multiple
        if (ops.empty() || ops[0] != reg) continue;
        std::string mn = ins[j].mn;
        if (mn.size() > 2 && (mn.compare(mn.size() - 2, 2, ".n") == 0 || mn.compare(mn.size() - 2, 2, ".w") == 0)) mn.resize(mn.size() - 2);
        if (depth > 6) return false;
        long a = 0, s = 0;
        uint32_t addr = 0;
        if (starts_with(mn, "ldr")) {
            if (ops.size() < 2 || !starts_with(ops[1], "[pc") || !branch_target(ins[j].comment, addr)) return false;
            const auto w = ps.words.find(addr);
            if (w == ps.words.end()) return false;
            v = static_cast<int32_t>(w->second);
            return true;
        }
        if ((mn == "movs" || mn == "mov" || mn == "movw") && ops.size() == 2 && immediate(ops[1], v)) return true;
        if ((mn == "adr" || (mn == "add" && ops.size() == 3 && ops[1] == "pc")) && branch_target(mn == "adr" ? ins[j].ops : ins[j].comment, addr)) {
            v = static_cast<long>(addr);  // "add r0, pc, #4 @ (adr r0, 2c8 <f+0x8>)"
            return true;
        }
        // The source of a shift, negation or add: the register itself (two operands) or the second.
        const std::string src = ops.size() == 3 ? ops[1] : reg;
        const std::string last = ops.back();
        if (mn == "lsls" || mn == "lsl") {
            if (!immediate(last, s) || s < 0 || s > 31 || !literal_value(ps, ins, j, src, a, depth + 1)) return false;
            v = static_cast<long>(static_cast<int32_t>(static_cast<uint32_t>(a) << s));
            return true;
        }
        if (mn == "negs" || mn == "rsbs" || mn == "neg") {
            if (!literal_value(ps, ins, j, ops.size() >= 2 ? ops[1] : reg, a, depth + 1)) return false;
            v = -a;
            return true;
        }
        if (mn == "adds" || mn == "subs" || mn == "add" || mn == "sub") {
            if (!immediate(last, s) || !literal_value(ps, ins, j, src, a, depth + 1)) return false;
            v = starts_with(mn, "add") ? a + s : a - s;
            return true;
        }
        return false;
    }
    return false;
}

void classify_arm(Parser& ps, size_t fi) {
    Function& f = ps.p.funcs[fi];
    const std::vector<Parser::Pending>& ins = ps.code[fi];
    for (size_t k = 0; k < ins.size(); ++k) {
        const Parser::Pending& in = ins[k];
        std::string mn = in.mn;
        if (mn.size() > 2 && (mn.compare(mn.size() - 2, 2, ".n") == 0 || mn.compare(mn.size() - 2, 2, ".w") == 0)) mn.resize(mn.size() - 2);
        const std::vector<std::string> ops = split_operands(in.ops);
        const std::string first = ops.empty() ? std::string() : ops[0];
        uint32_t target = 0;
        if (arm_is(mn, "push")) {
            const int n = detail::register_count(first);
            if (n < 0) f.problems.push_back(where(in.addr, "push of an unreadable list"));
            else f.frame += 4u * static_cast<uint32_t>(n);
        } else if ((mn == "stmdb" || mn == "stmfd") && first == "sp!") {
            const int n = ops.size() > 1 ? detail::register_count(ops[1]) : -1;
            if (n < 0) f.problems.push_back(where(in.addr, "store-multiple of an unreadable list"));
            else f.frame += 4u * static_cast<uint32_t>(n);
        } else if (arm_is(mn, "pop") || ((starts_with(mn, "ldm")) && first == "sp!")) {
            // a release, or a return when it loads pc
        } else if (starts_with(mn, "str") && ops.size() >= 2 && starts_with(ops.back(), "[sp, #-") && ops.back().back() == '!') {
            long v = 0;
            const std::string imm = ops.back().substr(5, ops.back().size() - 7);  // "#-N" of "[sp, #-N]!"
            if (!immediate(imm, v)) f.problems.push_back(where(in.addr, "unreadable pre-indexed store to the stack"));
            else f.frame += static_cast<uint32_t>(-v);
        } else if (first == "sp" && (arm_is(mn, "sub") || mn == "subw" || arm_is(mn, "add") || mn == "addw")) {
            long v = 0;
            const bool from_sp = ops.size() == 2 || (ops.size() == 3 && ops[1] == "sp");
            const bool known = from_sp && (immediate(ops.back(), v) || literal_value(ps, ins, k, ops.back(), v));
            if (!known) {
                f.problems.push_back(where(in.addr, "sp changed by a register: " + in.mn + " " + in.ops));
            } else {
                const long alloc = starts_with(mn, "sub") ? v : -v;
                if (alloc > 0) f.frame += static_cast<uint32_t>(alloc);
            }
        } else if (arm_is(mn, "bl")) {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, true);
            else f.problems.push_back(where(in.addr, "unreadable call"));
        } else if (arm_is(mn, "blx")) {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, true);
            else ++f.indirect_sites;
        } else if (arm_is(mn, "bx")) {
            if (first == "lr") continue;  // return
            long v = 0;
            if (literal_value(ps, ins, k, first, v)) {  // a jump to a known address: inside, or a tail call
                const uint32_t to = static_cast<uint32_t>(v) & ~1u;
                if (ps.containing(to) == static_cast<long>(fi)) continue;
                if (ps.starting_at(to) >= 0) {
                    add_callee(f, static_cast<size_t>(ps.starting_at(to)));
                    continue;
                }
            }
            // A return through a register the previous instruction loaded from the stack (Thumb-1's
            // "pop {r3}; add sp, #8; bx r3", a local subroutine's saved link); or a jump to a literal.
            bool handled = false;
            for (size_t j = k; j-- > 0 && j + 3 > k && !handled;) {
                const Parser::Pending& pr = ins[j];
                const std::vector<std::string> pops = split_operands(pr.ops);
                if (pops.empty()) continue;
                const bool pops_it = arm_is(pr.mn, "pop") && list_names(pops[0], first);
                const bool loads_from_stack = starts_with(pr.mn, "ldr") && pops[0] == first && pops.size() > 1 &&
                                              starts_with(pops[1], "[sp");
                if (pops_it || loads_from_stack) handled = true;
                else if (starts_with(pr.mn, "ldr") && pops[0] == first && pops.size() > 1 && starts_with(pops[1], "[pc") &&
                         branch_target(pr.comment, target)) {
                    const auto w = ps.words.find(target);
                    if (w != ps.words.end()) {
                        const long t = ps.starting_at(w->second & ~1u);
                        if (t >= 0) {
                            add_callee(f, static_cast<size_t>(t));
                            handled = true;
                        }
                    }
                } else if (pops[0] == first) {
                    break;  // set some other way
                }
            }
            if (!handled) ++f.indirect_sites;
        } else if (mn == "b" || (mn.size() == 3 && mn[0] == 'b' && arm_condition(mn.substr(1))) || mn == "cbz" || mn == "cbnz") {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, false);
        } else if (first == "pc") {
            const bool pops_pc = starts_with(mn, "ldr") && ops.size() > 1 && starts_with(ops[1], "[sp]");
            long v = 0;
            const bool known = arm_is(mn, "mov") && ops.size() == 2 && literal_value(ps, ins, k, ops[1], v) &&
                               ps.containing(static_cast<uint32_t>(v) & ~1u) == static_cast<long>(fi);
            if (!pops_pc && !known) ++f.indirect_sites;  // mov pc / ldr pc to an unknown place
        } else if (arm_is(mn, "msr") && (first == "MSP" || first == "PSP" || first == "msp" || first == "psp")) {
            f.sets_sp = true;
        } else if (first == "sp" || first == "sp!") {
            static const char* const kNoWrite[] = {"cmp", "cmn", "tst", "teq", "stm", "stmia", "stmea", "ldm", "ldmia", "ldmfd"};  // no writeback
            const bool reads = starts_with(mn, "str") ||
                               std::any_of(std::begin(kNoWrite), std::end(kNoWrite), [&](const char* w) { return arm_is(mn, w); });
            if (!reads) {
                if (arm_is(mn, "mov") || starts_with(mn, "ldr")) f.sets_sp = true;
                else f.problems.push_back(where(in.addr, "sp written by " + in.mn + " " + in.ops));
            }
        }
        if (in.mn == "adr" || starts_with(in.mn, "adr.")) {
            if (branch_target(in.ops, target) && ps.starting_at(target & ~1u) >= 0)
                ps.p.address_taken_by_code[static_cast<size_t>(ps.starting_at(target & ~1u))] = true;
        }
    }
}

void classify_riscv(Parser& ps, size_t fi) {
    Function& f = ps.p.funcs[fi];
    std::set<std::string> local_links;  // registers a local subroutine call links through (jal t2, label)
    for (const Parser::Pending& in : ps.code[fi]) {
        const std::vector<std::string> ops = split_operands(in.ops);
        uint32_t target = 0;
        if (in.mn == "jal" && ops.size() == 2 && branch_target(in.ops, target) && ps.containing(target) == static_cast<long>(fi))
            local_links.insert(ops[0]);
    }
    bool sp_formed = false;  // the previous instruction was auipc or lui sp: an addi completes the address
    for (const Parser::Pending& in : ps.code[fi]) {
        const std::string& mn = in.mn;
        const std::vector<std::string> ops = split_operands(in.ops);
        const std::string first = ops.empty() ? std::string() : ops[0];
        uint32_t target = 0;
        const bool annotated = branch_target(in.comment, target);
        const bool completes_sp = sp_formed;
        sp_formed = first == "sp" && (mn == "auipc" || mn == "lui");
        if (mn == "jal") {
            const bool link_ra = ops.size() == 1 || first == "ra";
            if (!branch_target(in.ops, target)) f.problems.push_back(where(in.addr, "unreadable call"));
            else transfer(ps, fi, in.addr, target, link_ra || ps.containing(target) != static_cast<long>(fi));
        } else if (mn == "j" || (mn[0] == 'b' && mn != "bset" && mn != "bclr" && mn != "binv" && mn != "bext")) {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, false);
        } else if (mn == "jalr") {
            uint32_t t = 0;
            if (annotated && ps.starting_at(t = target) >= 0) add_callee(f, static_cast<size_t>(ps.starting_at(t)));
            else ++f.indirect_sites;
        } else if (mn == "jr") {
            if (first != "ra" && local_links.count(first) == 0) ++f.indirect_sites;  // else a return
        } else if (mn == "ret") {
        } else if (first == "sp") {
            long v = 0;
            const bool reads = mn == "sw" || mn == "sh" || mn == "sb" || starts_with(mn, "csr");
            if (reads) {
            } else if (completes_sp || sp_formed) {
                f.sets_sp = true;  // la sp, sym: a new stack whose depth starts here
                f.frame = 0;
            } else if ((mn == "addi" || mn == "add" || mn == "c.addi16sp" || mn == "c.addi") && ops.size() == 3 && ops[1] == "sp" &&
                       immediate(ops[2], v)) {
                if (v < 0) f.frame += static_cast<uint32_t>(-v);
            } else if ((mn == "addi" || mn == "add") && ops.size() == 3 && ops[1] != "sp" && immediate(ops[2], v)) {
                f.sets_sp = true;  // la sp, relaxed to gp + offset
                f.frame = 0;
            } else if (mn == "add" || mn == "sub") {
                f.problems.push_back(where(in.addr, "sp changed by a register: " + mn + " " + in.ops));
            } else {
                f.sets_sp = true;  // mv, lw, li
                f.frame = 0;
            }
        }
        static const char* const kForms[] = {"addi", "add", "c.addi", "auipc", "lui", "li", "mv"};  // address formation, not loads
        if (annotated && std::any_of(std::begin(kForms), std::end(kForms), [&](const char* w) { return mn == w; })) {
            const long t = ps.starting_at(target);
            if (t >= 0) ps.p.address_taken_by_code[static_cast<size_t>(t)] = true;  // la / lui+addi of a function
        }
    }
}

}  // namespace

namespace detail {
bool glob_match(const std::string& pattern, const std::string& name) {
    size_t p = 0, n = 0, star = std::string::npos, mark = 0;
    while (n < name.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            mark = n;
        } else if (p < pattern.size() && pattern[p] == name[n]) {
            ++p;
            ++n;
        } else if (star != std::string::npos) {
            p = star + 1;
            n = ++mark;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

int register_count(const std::string& list) {
    const std::string s = trim(list);
    if (s.size() < 2 || s.front() != '{' || s.back() != '}') return -1;
    int n = 0;
    for (const std::string& r : split_operands(s.substr(1, s.size() - 2))) {
        const size_t dash = r.find('-');
        if (dash == std::string::npos) {
            ++n;
            continue;
        }
        const std::string a = r.substr(0, dash), b = r.substr(dash + 1);  // "r4-r7"
        if (a.size() < 2 || b.size() < 2 || a[0] != 'r' || b[0] != 'r') return -1;
        const int lo = std::atoi(a.c_str() + 1), hi = std::atoi(b.c_str() + 1);
        if (hi < lo) return -1;
        n += hi - lo + 1;
    }
    return n;
}

}  // namespace detail

bool parse_objdump(std::istream& in, Program& p, std::string& why) {
    p = Program{};
    Parser ps{p, {}, {}};
    enum Section { none, symbols, contents, disassembly } section = none;
    bool skip_contents = false, have_format = false;
    struct Sym { uint32_t addr, size; std::string name; bool func; };
    std::vector<Sym> syms;
    std::string line;
    size_t line_no = 0;
    auto fail = [&](const std::string& what) {
        why = "line " + std::to_string(line_no) + ": " + what;
        return false;
    };
    auto build_functions = [&]() {
        std::sort(syms.begin(), syms.end(), [](const Sym& a, const Sym& b) { return a.addr < b.addr; });
        for (const Sym& s : syms) {
            if (!s.func) {
                p.objects.push_back({s.addr, s.size, s.name});
                continue;
            }
            if (!p.funcs.empty() && p.funcs.back().start == s.addr) {  // an alias
                p.funcs.back().names.push_back(s.name);
                p.funcs.back().size = std::max(p.funcs.back().size, s.size);
                continue;
            }
            Function f;
            f.names.push_back(s.name);
            f.start = s.addr;
            f.size = s.size;
            p.funcs.push_back(f);
        }
        for (size_t i = 0; i < p.funcs.size(); ++i) {
            if (p.funcs[i].size != 0) continue;
            uint32_t end = i + 1 < p.funcs.size() ? p.funcs[i + 1].start : uint32_t{0xFFFFFFFFu};
            for (const Program::Range& r : p.objects)
                if (r.start > p.funcs[i].start) end = std::min(end, r.start);
            p.funcs[i].size = end - p.funcs[i].start;
        }
        p.address_taken_by_code.assign(p.funcs.size(), false);
        ps.code.assign(p.funcs.size(), {});
    };
    uint32_t contents_addr = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find("file format elf32-littlearm") != std::string::npos) {
            p.isa = Isa::arm;
            have_format = true;
            continue;
        }
        if (line.find("file format elf32-littleriscv") != std::string::npos) {
            p.isa = Isa::riscv;
            have_format = true;
            continue;
        }
        if (line == "SYMBOL TABLE:") {
            section = symbols;
            continue;
        }
        if (starts_with(line, "Contents of section ")) {
            if (section == symbols) build_functions();
            section = contents;
            const std::string name = line.substr(20, line.size() - 21);
            skip_contents = starts_with(name, ".debug") || starts_with(name, ".comment") || name.find("attributes") != std::string::npos ||
                            starts_with(name, ".note");
            continue;
        }
        if (starts_with(line, "Disassembly of section ")) {
            if (section == symbols) build_functions();
            section = disassembly;
            continue;
        }
        if (section == symbols) {
            // "000001d8 l     F .text\t0000000c name"
            if (line.size() < 18 || !is_hex(line.substr(0, 8))) continue;
            const size_t tab = line.find('\t', 17);
            if (tab == std::string::npos || tab + 10 > line.size()) continue;
            const char type = line[15];
            std::string name = line.substr(tab + 10);
            for (const char* prefix : {".hidden ", ".protected ", ".internal "})
                if (starts_with(name, prefix)) name = name.substr(std::string(prefix).size());
            const uint32_t size = hex_value(line.substr(tab + 1, 8));
            if (type == 'F' || (type == 'O' && size != 0)) {  // a function of size 0 (libgcc assembly) ends at the next symbol
                uint32_t addr = hex_value(line.substr(0, 8));
                if (type == 'F' && p.isa == Isa::arm) addr &= ~1u;
                syms.push_back({addr, size, name, type == 'F'});
            }
        } else if (section == contents && !skip_contents) {
            // " 0000 e83f0020 c1000000 d9010000 d9010000  .?. ............"
            const std::string t = trim(line);
            const size_t sp = t.find(' ');
            if (sp == std::string::npos || !is_hex(t.substr(0, sp))) continue;
            contents_addr = hex_value(t.substr(0, sp));
            const size_t ascii = line.find("  ", line.find(t.substr(0, sp)) + sp);
            std::istringstream groups(line.substr(0, ascii).substr(line.find(t.substr(0, sp)) + sp));
            std::string g;
            uint32_t a = contents_addr;
            while (groups >> g) {
                if (!is_hex(g) || g.size() % 2 != 0) break;
                if (g.size() == 8 && a % 4 == 0) {
                    uint32_t v = 0;
                    for (int b = 3; b >= 0; --b) v = (v << 8) | hex_value(g.substr(static_cast<size_t>(b) * 2, 2));
                    ps.words[a] = v;
                }
                a += static_cast<uint32_t>(g.size() / 2);
            }
        } else if (section == disassembly) {
            // "     15c:\tblx\tr3" ; comments after '@', ';' (arm) or '#' (riscv)
            const size_t colon = line.find(':');
            if (colon == std::string::npos || line.size() <= colon + 1 || line[colon + 1] != '\t') continue;
            const std::string a = trim(line.substr(0, colon));
            if (!is_hex(a)) continue;
            const uint32_t addr = hex_value(a);
            std::string rest = line.substr(colon + 2);
            std::string comment;
            const size_t c = p.isa == Isa::arm ? rest.find("\t@") : rest.find(" # ");
            if (c != std::string::npos) {
                comment = rest.substr(c + 2);
                rest = rest.substr(0, c);
            } else if (p.isa == Isa::arm && rest.find("; (") != std::string::npos) {
                comment = rest.substr(rest.find("; (") + 2);
                rest = rest.substr(0, rest.find("; ("));
            }
            const size_t tab = rest.find('\t');
            std::string mn = trim(tab == std::string::npos ? rest : rest.substr(0, tab));
            const std::string ops = tab == std::string::npos ? std::string() : trim(rest.substr(tab + 1));
            if (mn.empty() || mn[0] == '.') continue;  // .word, .short: data
            for (char& ch : mn) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            const long fi = ps.containing(addr);
            if (fi >= 0) ps.code[static_cast<size_t>(fi)].push_back({addr, mn, ops, comment});
        }
    }
    if (!have_format) return fail("no \"file format elf32-littlearm\" or \"elf32-littleriscv\" line (objdump -t -s -d output?)");
    if (p.funcs.empty()) return fail("no function symbols (objdump -t missing, or a stripped ELF)");
    for (size_t i = 0; i < p.funcs.size(); ++i) {
        if (p.isa == Isa::arm) classify_arm(ps, i);
        else classify_riscv(ps, i);
    }
    // Code addresses held in data or literal pools: function pointers (a Thumb address has bit 0 set).
    for (const auto& [addr, v] : ps.words) {
        const bool thumb = p.isa == Isa::arm;
        if (thumb && (v & 1u) == 0) continue;
        const long t = ps.starting_at(thumb ? v & ~1u : v);
        if (t >= 0) p.pointer_sites.push_back({addr, static_cast<size_t>(t)});
    }
    return true;
}

Bound bound(const Program& p, const Options& opt) {
    Bound b;
    auto find = [&p](const std::string& name) -> long {
        for (size_t i = 0; i < p.funcs.size(); ++i)
            for (const std::string& n : p.funcs[i].names)
                if (n == name) return static_cast<long>(i);
        return -1;
    };
    const long entry = find(opt.entry);
    if (entry < 0) {
        b.why = "no function named " + opt.entry;
        return b;
    }
    // Indirect targets: address-taken functions. Every aligned word equal to a code address counts,
    // but in the data objects opt.not_pointers names (a vector table, a mesh whose integers equal code
    // addresses where flash starts at 0). `why_taken` remembers one word per function for messages.
    std::vector<bool> taken(p.funcs.size(), false);
    std::vector<std::string> why_taken(p.funcs.size());
    for (size_t i = 0; i < p.funcs.size(); ++i)
        if (p.address_taken_by_code[i]) {
            taken[i] = true;
            why_taken[i] = "its address is formed by an instruction";
        }
    for (const Program::PointerSite& s : p.pointer_sites) {
        const Program::Range* in = nullptr;
        for (const Program::Range& r : p.objects)
            if (s.addr >= r.start && s.addr < r.start + r.size) in = &r;
        if (in != nullptr && std::any_of(opt.not_pointers.begin(), opt.not_pointers.end(),
                                         [&](const std::string& pattern) { return detail::glob_match(pattern, in->name); }))
            continue;
        if (!taken[s.func]) {
            std::ostringstream w;
            w << "its address is the word at " << std::hex << s.addr << std::dec;
            if (in != nullptr) w << ", in " << in->name;
            why_taken[s.func] = w.str();
        }
        taken[s.func] = true;
    }
    for (const std::string& h : opt.handlers) {
        const long i = find(h);
        if (i < 0) {
            b.why = "no handler named " + h;
            return b;
        }
        taken[static_cast<size_t>(i)] = false;
    }
    for (size_t i = 0; i < p.funcs.size(); ++i)
        if (taken[i]) b.indirect_targets.push_back(p.funcs[i].names.front());

    enum State : uint8_t { unvisited, active, done };
    std::vector<State> state(p.funcs.size(), unvisited);
    std::vector<uint32_t> total(p.funcs.size(), 0);
    std::vector<long> via(p.funcs.size(), -1);
    std::string error;
    // Depth-first with an explicit stack of (function, next callee index); the callees of an indirect
    // site are every taken function after the direct ones.
    struct Frame { size_t f; size_t next; };
    std::vector<Frame> work;
    auto callees_of = [&](size_t f) {
        std::vector<size_t> c = p.funcs[f].callees;
        if (p.funcs[f].indirect_sites != 0)
            for (size_t i = 0; i < p.funcs.size(); ++i)
                if (taken[i] && std::find(c.begin(), c.end(), i) == c.end()) c.push_back(i);
        return c;
    };
    auto enter = [&](size_t f) -> bool {
        const Function& fn = p.funcs[f];
        if (!fn.problems.empty()) {
            error = fn.names.front() + ": " + fn.problems.front();
            return false;
        }
        if (fn.sets_sp && static_cast<long>(f) != entry) {
            error = fn.names.front() + ": loads sp with a new value";
            return false;
        }
        state[f] = active;
        work.push_back({f, 0});
        return true;
    };
    if (!enter(static_cast<size_t>(entry))) {
        b.why = error;
        return b;
    }
    while (!work.empty()) {
        Frame& fr = work.back();
        const std::vector<size_t> cs = callees_of(fr.f);
        if (fr.next < cs.size()) {
            const size_t c = cs[fr.next++];
            if (state[c] == active) {
                std::string cycle;
                for (const Frame& w : work) cycle += p.funcs[w.f].names.front() + " -> ";
                b.why = "recursion: " + cycle + p.funcs[c].names.front();
                if (std::find(p.funcs[fr.f].callees.begin(), p.funcs[fr.f].callees.end(), c) == p.funcs[fr.f].callees.end())
                    b.why += " (an indirect call: " + why_taken[c] + ")";
                return b;
            }
            if (state[c] == unvisited && !enter(c)) {
                b.why = error + " (reached from " + p.funcs[fr.f].names.front() + ")";
                return b;
            }
            continue;
        }
        uint32_t best = 0;
        for (size_t c : cs)
            if (via[fr.f] < 0 || total[c] > best) {
                best = total[c];
                via[fr.f] = static_cast<long>(c);
            }
        total[fr.f] = p.funcs[fr.f].frame + best;
        state[fr.f] = done;
        work.pop_back();
    }
    b.ok = true;
    b.bytes = total[static_cast<size_t>(entry)];
    for (long f = entry; f >= 0; f = via[static_cast<size_t>(f)]) b.path.push_back({p.funcs[static_cast<size_t>(f)].names.front(), p.funcs[static_cast<size_t>(f)].frame});
    return b;
}

}  // namespace stackbound

// hider-stack's analysis: objdump's symbol table, section contents and disassembly into functions with
// frames and callees (Thumb and RV32 rules below), then the deepest chain from the entry.
#include "stack_bound.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <istream>
#include <map>
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
    errno = 0;
    v = std::strtol(s.c_str(), &end, 0);
    // No instruction moves sp by 16 MB: a larger value is a damaged dump (a 32-bit wrap once gave a frame of 0).
    return end != nullptr && *end == '\0' && errno == 0 && v > -(1L << 24) && v < (1L << 24);
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

/// The mnemonic without Thumb-2's width suffix (".n", ".w").
std::string without_width(const std::string& mn) {
    if (mn.size() > 2 && (mn.compare(mn.size() - 2, 2, ".n") == 0 || mn.compare(mn.size() - 2, 2, ".w") == 0))
        return mn.substr(0, mn.size() - 2);
    return mn;
}

/// True when the register list ("{r4, r5, lr}", "{r4-r7}") names reg; a range of other names counts.
bool list_names(const std::string& list, const std::string& reg) {
    const std::string s = trim(list);
    if (s.size() < 2 || s.front() != '{' || s.back() != '}') return false;
    for (const std::string& r : split_operands(s.substr(1, s.size() - 2))) {
        if (r == reg) return true;
        const size_t dash = r.find('-');
        if (dash == std::string::npos) continue;
        const std::string a = r.substr(0, dash), b = r.substr(dash + 1);
        if (a.size() < 2 || b.size() < 2 || reg.size() < 2 || a[0] != reg[0] || b[0] != reg[0]) return true;
        const int n = std::atoi(reg.c_str() + 1);
        if (n >= std::atoi(a.c_str() + 1) && n <= std::atoi(b.c_str() + 1)) return true;
    }
    return false;
}

struct Insn {
    uint32_t addr;
    std::string mn, ops, comment;
};

struct Parser {
    Program& p;
    std::map<uint32_t, uint32_t> words;  ///< aligned words of allocated sections, by address
    std::vector<std::vector<Insn>> code;  ///< per function

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

void add_callee(Function& f, size_t callee) {
    if (std::find(f.callees.begin(), f.callees.end(), callee) == f.callees.end()) f.callees.push_back(callee);
}

std::string where(uint32_t addr, const std::string& what) {
    std::ostringstream s;
    s << std::hex << addr << ": " << what;
    return s.str();
}

/// A call or jump from function fi to `target`: a callee, a branch inside fi, or a problem (a call
/// to fi's own start is recursion; nothing may go outside every function).
void transfer(Parser& ps, size_t fi, uint32_t addr, uint32_t target, bool call) {
    Function& f = ps.p.funcs[fi];
    const long t = ps.containing(target);
    if (t < 0) {
        f.problems.push_back(where(addr, std::string(call ? "call" : "jump") + " to an address outside every function"));
    } else if (t != static_cast<long>(fi)) {
        add_callee(f, static_cast<size_t>(t));
    } else if (call && target == f.start) {
        f.problems.push_back(where(addr, "calls itself (recursion)"));
    }  // else a branch or a local subroutine inside the function
}

/// The constant register `reg` holds before instruction k, when the few instructions before it built
/// it: a literal load, a move, adr, shifts, negation, adds (Thumb-1 changes sp by a register for frames
/// above 508 bytes: "ldr r4, [pc, #8]; add sp, r4", "movs r3, #193; lsls r3, r3, #2; add sp, r3").
/// False at anything else that may write it: a call, a load-multiple, a second destination.
bool literal_value(const Parser& ps, const std::vector<Insn>& ins, size_t k, const std::string& reg, long& v, int depth = 0) {
    for (size_t j = k; j-- > 0 && j + 6 > k;) {
        const std::string mn = without_width(ins[j].mn);
        const std::vector<std::string> ops = split_operands(ins[j].ops);
        if (arm_is(mn, "bl") || arm_is(mn, "blx")) return false;  // r0-r3, r12 and lr are the callee's
        for (size_t o = 0; o < ops.size(); ++o)
            if (list_names(ops[o], reg) || (o == 1 && ops[o] == reg && (starts_with(mn, "ldrd") || starts_with(mn, "umull") ||
                                                                         starts_with(mn, "smull") || starts_with(mn, "umlal") ||
                                                                         starts_with(mn, "smlal"))))
                return false;
        if (ops.empty() || ops[0] != reg) continue;
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
        if (mn == "lsls" || mn == "lsl") {
            if (!immediate(ops.back(), s) || s < 0 || s > 31 || !literal_value(ps, ins, j, src, a, depth + 1)) return false;
            v = static_cast<long>(static_cast<int32_t>(static_cast<uint32_t>(a) << s));
            return true;
        }
        if (mn == "negs" || mn == "rsbs" || mn == "neg") {
            if (!literal_value(ps, ins, j, ops.size() >= 2 ? ops[1] : reg, a, depth + 1)) return false;
            v = -a;
            return true;
        }
        if (mn == "adds" || mn == "subs" || mn == "add" || mn == "sub") {
            if (!immediate(ops.back(), s) || !literal_value(ps, ins, j, src, a, depth + 1)) return false;
            v = starts_with(mn, "add") ? a + s : a - s;
            return true;
        }
        return false;
    }
    return false;
}

/// Bytes a Thumb instruction takes from the stack (0 for none or a release); problems for sp changes it
/// cannot size.
uint32_t arm_allocation(Parser& ps, size_t fi, size_t k) {
    Function& f = ps.p.funcs[fi];
    const Insn& in = ps.code[fi][k];
    const std::string mn = without_width(in.mn);
    const std::vector<std::string> ops = split_operands(in.ops);
    const std::string first = ops.empty() ? std::string() : ops[0];
    auto list_bytes = [&](const std::string& list, uint32_t each) -> uint32_t {
        const int n = detail::register_count(list);
        if (n < 0) f.problems.push_back(where(in.addr, "unreadable register list: " + in.mn + " " + in.ops));
        return n < 0 ? 0 : each * static_cast<uint32_t>(n);
    };
    if (arm_is(mn, "push")) return list_bytes(first, 4);
    if (arm_is(mn, "vpush")) return list_bytes(first, first.find('d') != std::string::npos ? 8 : 4);
    if ((starts_with(mn, "stmdb") || starts_with(mn, "stmfd") || starts_with(mn, "vstmdb")) && first == "sp!")
        return ops.size() > 1 ? list_bytes(ops[1], starts_with(mn, "v") && ops[1].find('d') != std::string::npos ? 8 : 4) : 0;
    // A load or store that moves sp: "[sp, #-8]!" (pre-index) or "[sp], #-8" (post-index).
    for (size_t o = 1; o < ops.size(); ++o) {
        long v = 0;
        if (starts_with(ops[o], "[sp, #") && ops[o].back() == '!') {
            if (!immediate(ops[o].substr(5, ops[o].size() - 7), v)) f.problems.push_back(where(in.addr, "unreadable sp write-back"));
            return v < 0 ? static_cast<uint32_t>(-v) : 0;
        }
        if (ops[o] == "[sp]" && o + 1 < ops.size()) {
            if (!immediate(ops[o + 1], v)) f.problems.push_back(where(in.addr, "unreadable sp write-back"));
            return v < 0 ? static_cast<uint32_t>(-v) : 0;
        }
    }
    if (first != "sp" || !(arm_is(mn, "sub") || mn == "subw" || arm_is(mn, "add") || mn == "addw")) return 0;
    long v = 0;
    const bool from_sp = ops.size() == 2 || (ops.size() == 3 && ops[1] == "sp");
    if (!from_sp || !(immediate(ops.back(), v) || literal_value(ps, ps.code[fi], k, ops.back(), v))) {
        f.problems.push_back(where(in.addr, "sp changed by a register: " + in.mn + " " + in.ops));
        return 0;
    }
    const long alloc = starts_with(mn, "sub") ? v : -v;
    return alloc > 0 ? static_cast<uint32_t>(alloc) : 0;
}

/// Stack offsets where function fi saves its link register ("str lr, [sp, #N]", or Thumb-1's
/// "mov r3, lr; str r3, [sp, #N]"): a "ldr rX, [sp, #N]; bx rX" through one of them is a return.
std::set<std::string> arm_link_slots(const std::vector<Insn>& ins) {
    std::set<std::string> slots;
    for (size_t k = 0; k < ins.size(); ++k) {
        const std::vector<std::string> ops = split_operands(ins[k].ops);
        if (!starts_with(ins[k].mn, "str") || ops.size() != 2 || !starts_with(ops[1], "[sp")) continue;
        bool from_lr = ops[0] == "lr";
        if (k > 0) {
            const std::vector<std::string> prev = split_operands(ins[k - 1].ops);
            from_lr = from_lr || (without_width(ins[k - 1].mn) == "mov" && prev.size() == 2 && prev[0] == ops[0] && prev[1] == "lr");
        }
        if (from_lr) slots.insert(ops[1]);
    }
    return slots;
}

/// A "bx rX" (rX not lr) at instruction k: a return, a jump inside, a tail call, or an indirect jump.
void arm_bx(Parser& ps, size_t fi, size_t k, const std::set<std::string>& link_slots) {
    Function& f = ps.p.funcs[fi];
    const std::vector<Insn>& ins = ps.code[fi];
    const std::string reg = trim(ins[k].ops);
    long v = 0;
    if (literal_value(ps, ins, k, reg, v)) {  // a jump to a known address
        transfer(ps, fi, ins[k].addr, static_cast<uint32_t>(v) & ~1u, false);
        return;
    }
    // A return through the register the instructions just before loaded: Thumb-1's "pop {r3}; add sp,
    // #8; bx r3", or a saved link ("ldr r3, [sp, #172]; bx r3").
    for (size_t j = k; j-- > 0 && j + 3 > k;) {
        const std::vector<std::string> ops = split_operands(ins[j].ops);
        if (ops.empty()) continue;
        if (arm_is(ins[j].mn, "pop") && list_names(ops[0], reg)) return;
        if (ops[0] == reg) {
            if (starts_with(ins[j].mn, "ldr") && ops.size() == 2 && link_slots.count(ops[1]) != 0) return;
            break;
        }
    }
    ++f.indirect_sites;
}

void classify_arm(Parser& ps, size_t fi) {
    Function& f = ps.p.funcs[fi];
    const std::vector<Insn>& ins = ps.code[fi];
    const std::set<std::string> link_slots = arm_link_slots(ins);
    for (size_t k = 0; k < ins.size(); ++k) {
        const Insn& in = ins[k];
        const std::string mn = without_width(in.mn);
        const std::vector<std::string> ops = split_operands(in.ops);
        const std::string first = ops.empty() ? std::string() : ops[0];
        uint32_t target = 0;
        f.frame += arm_allocation(ps, fi, k);
        if (arm_is(mn, "bl") || (arm_is(mn, "blx") && branch_target(in.ops, target))) {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, true);
            else f.problems.push_back(where(in.addr, "unreadable call"));
        } else if (arm_is(mn, "blx")) {
            ++f.indirect_sites;
        } else if (arm_is(mn, "bx")) {
            if (first != "lr") arm_bx(ps, fi, k, link_slots);
        } else if (mn == "b" || (mn.size() == 3 && mn[0] == 'b' && arm_condition(mn.substr(1))) || mn == "cbz" || mn == "cbnz") {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, false);
            else f.problems.push_back(where(in.addr, "unreadable branch"));
        } else if (first == "pc") {
            long v = 0;
            const bool pops_pc = starts_with(mn, "ldr") && ops.size() > 1 && starts_with(ops[1], "[sp]");
            if (pops_pc) continue;
            if (arm_is(mn, "mov") && ops.size() == 2 && literal_value(ps, ins, k, ops[1], v))
                transfer(ps, fi, in.addr, static_cast<uint32_t>(v) & ~1u, false);
            else ++f.indirect_sites;  // mov pc / ldr pc to an unknown place
        } else if (arm_is(mn, "msr") && (first == "MSP" || first == "PSP" || first == "msp" || first == "psp")) {
            f.sets_sp = true;
        } else if (first == "sp" && !arm_is(mn, "sub") && mn != "subw" && !arm_is(mn, "add") && mn != "addw") {  // those: arm_allocation
            static const char* const kReads[] = {"cmp", "cmn", "tst", "teq", "stm", "stmia", "stmea", "ldm", "ldmia", "ldmfd"};
            const bool reads = starts_with(mn, "str") ||
                               std::any_of(std::begin(kReads), std::end(kReads), [&](const char* w) { return arm_is(mn, w); });
            if (reads) continue;
            if (arm_is(mn, "mov") || starts_with(mn, "ldr")) f.sets_sp = true;
            else f.problems.push_back(where(in.addr, "sp written by " + in.mn + " " + in.ops));
        }
        if (mn == "adr" && branch_target(in.ops, target) && ps.starting_at(target & ~1u) >= 0)
            ps.p.address_taken_by_code[static_cast<size_t>(ps.starting_at(target & ~1u))] = true;
    }
}

void classify_riscv(Parser& ps, size_t fi) {
    Function& f = ps.p.funcs[fi];
    std::set<std::string> local_links;  // registers a local subroutine call links through (jal t2, label)
    for (const Insn& in : ps.code[fi]) {
        const std::vector<std::string> ops = split_operands(in.ops);
        uint32_t target = 0;
        if (in.mn == "jal" && ops.size() == 2 && branch_target(in.ops, target) && ps.containing(target) == static_cast<long>(fi))
            local_links.insert(ops[0]);
    }
    bool sp_formed = false;  // the previous instruction was auipc or lui sp: an addi completes the address
    bool built = false;      // an allocation or a call came before: sp may not be loaded afresh after it
    for (const Insn& in : ps.code[fi]) {
        const std::string& mn = in.mn;
        const std::vector<std::string> ops = split_operands(in.ops);
        const std::string first = ops.empty() ? std::string() : ops[0];
        uint32_t target = 0;
        const bool annotated = branch_target(in.comment, target);
        const bool completes_sp = sp_formed;
        sp_formed = first == "sp" && (mn == "auipc" || mn == "lui");
        if (mn == "jal" || mn == "call") {
            const bool link_ra = ops.size() == 1 || first == "ra";
            if (!branch_target(in.ops, target)) f.problems.push_back(where(in.addr, "unreadable call"));
            else transfer(ps, fi, in.addr, target, link_ra || ps.containing(target) != static_cast<long>(fi));
            built = true;
        } else if (mn == "j" || mn == "tail" || (mn[0] == 'b' && mn != "bset" && mn != "bclr" && mn != "binv" && mn != "bext")) {
            if (branch_target(in.ops, target)) transfer(ps, fi, in.addr, target, false);
            else f.problems.push_back(where(in.addr, "unreadable branch"));
        } else if (mn == "jalr" || mn == "jr") {
            // An annotated target is an unrelaxed call or tail call (auipc + jalr/jr); else a return
            // (jr ra, or the link of a local subroutine) or an indirect call or jump.
            if (annotated) transfer(ps, fi, in.addr, target, mn == "jalr");
            else if (mn == "jr" && (first == "ra" || local_links.count(first) != 0)) {
            } else ++f.indirect_sites;
            built = built || mn == "jalr";
        } else if (mn == "ret") {
        } else if (first == "sp") {
            long v = 0;
            static const char* const kNoDest[] = {"sw", "sh", "sb", "csrw", "csrs", "csrc", "csrwi", "csrsi", "csrci"};
            const bool reads = std::any_of(std::begin(kNoDest), std::end(kNoDest), [&](const char* w) { return mn == w; });
            const bool adds_sp = (mn == "addi" || mn == "add" || mn == "c.addi16sp" || mn == "c.addi") &&
                                 ((ops.size() == 3 && ops[1] == "sp" && immediate(ops[2], v)) || (ops.size() == 2 && immediate(ops[1], v)));
            if (reads) {
            } else if (completes_sp || sp_formed || (!adds_sp && (mn == "mv" || mn == "li" || mn == "lw" || mn == "addi" || mn == "add"))) {
                // la sp (auipc/lui + addi, or gp-relative), mv, li, lw: a new stack, allowed in the entry
                // before anything was built on the old one.
                if (built) f.problems.push_back(where(in.addr, "sp loaded afresh after the frame was built: " + mn + " " + in.ops));
                f.sets_sp = true;
                f.frame = 0;
            } else if (adds_sp) {
                if (v < 0) {
                    f.frame += static_cast<uint32_t>(-v);
                    built = true;
                }
            } else {
                f.problems.push_back(where(in.addr, "sp written by " + mn + " " + in.ops));
            }
        }
        static const char* const kForms[] = {"addi", "add", "c.addi", "auipc", "lui", "li", "mv"};  // address formation, not loads
        if (annotated && std::any_of(std::begin(kForms), std::end(kForms), [&](const char* w) { return mn == w; })) {
            const long t = ps.starting_at(target);
            if (t >= 0) ps.p.address_taken_by_code[static_cast<size_t>(t)] = true;  // la / lui+addi of a function
        }
    }
}

/// One disassembly line ("     15c:\tblx\tr3", comments after '@', "; (" or " # ", raw bytes
/// optional) into code[function]; false for a line that is not an instruction.
bool read_instruction(Parser& ps, const std::string& line, bool& orphan, Insn& out) {
    const size_t colon = line.find(':');
    if (colon == std::string::npos || line.size() <= colon + 1 || line[colon + 1] != '\t') return false;
    const std::string a = trim(line.substr(0, colon));
    if (!is_hex(a)) return false;
    std::string rest = line.substr(colon + 2);
    std::string comment;
    const size_t c = ps.p.isa == Isa::arm ? rest.find("\t@") : rest.find(" # ");
    if (c != std::string::npos) {
        comment = rest.substr(c + 2);
        rest = rest.substr(0, c);
    } else if (ps.p.isa == Isa::arm && rest.find("; (") != std::string::npos) {
        comment = rest.substr(rest.find("; (") + 2);
        rest = rest.substr(0, rest.find("; ("));
    }
    std::vector<std::string> fields;
    for (size_t start = 0;;) {
        const size_t tab = rest.find('\t', start);
        fields.push_back(trim(rest.substr(start, tab == std::string::npos ? std::string::npos : tab - start)));
        if (tab == std::string::npos) break;
        start = tab + 1;
    }
    // Raw bytes (objdump without --no-show-raw-insn): "4798", "f7ff fffe", "0007a783" before the mnemonic.
    auto raw = [](const std::string& s) {
        std::istringstream words(s);
        std::string w;
        bool any = false;
        while (words >> w)
            if (!is_hex(w) || (w.size() != 4 && w.size() != 8)) return false;
            else any = true;
        return any;
    };
    if (fields.size() >= 2 && raw(fields[0]) && !fields[1].empty()) fields.erase(fields.begin());
    std::string mn = fields[0];
    if (mn.empty() || mn[0] == '.' || mn == "...") return false;  // .word, .short: data
    for (char& ch : mn) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    out = {hex_value(a), mn, fields.size() > 1 ? fields[1] : std::string(), comment};
    orphan = ps.containing(out.addr) < 0;
    return true;
}

/// An instruction rather than objdump's text view of data ("5c40:\t... .......") or padding: a
/// mnemonic of letters and digits (one width suffix) with operands.
bool looks_like_code(const Insn& in) {
    if (in.ops.empty() || in.mn == "nop" || !std::isalpha(static_cast<unsigned char>(in.mn[0]))) return false;
    const std::string base = without_width(in.mn);
    return std::all_of(base.begin(), base.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; });
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
        const std::string a = r.substr(0, dash), b = r.substr(dash + 1);  // "r4-r7", "d8-d15"
        if (a.size() < 2 || b.size() < 2 || a[0] != b[0] || !std::isalpha(static_cast<unsigned char>(a[0]))) return -1;
        const int lo = std::atoi(a.c_str() + 1), hi = std::atoi(b.c_str() + 1);
        if (hi < lo) return -1;
        n += hi - lo + 1;
    }
    return n;
}
}  // namespace detail

namespace {

struct Sym {
    uint32_t addr, size;
    std::string name;
    bool func;
};

/// A run of section bytes in memory order from `base`.
struct Bytes {
    uint32_t base;
    std::vector<uint8_t> data;
};

/// One symbol table line ("000001d8 l     F .text\t0000000c name"): functions (Thumb bit cleared) and
/// sized data objects; false for anything else.
bool read_symbol(const std::string& line, Isa isa, Sym& out) {
    if (line.size() < 18 || !is_hex(line.substr(0, 8))) return false;
    const size_t tab = line.find('\t', 17);
    if (tab == std::string::npos || tab + 10 > line.size()) return false;
    const char type = line[15];
    std::string name = line.substr(tab + 10);
    for (const char* prefix : {".hidden ", ".protected ", ".internal "})
        if (starts_with(name, prefix)) name = name.substr(std::string(prefix).size());
    const uint32_t size = hex_value(line.substr(tab + 1, 8));
    if (type != 'F' && (type != 'O' || size == 0)) return false;
    uint32_t addr = hex_value(line.substr(0, 8));
    if (type == 'F' && isa == Isa::arm) addr &= ~1u;
    out = {addr, size, name, type == 'F'};
    return true;
}

/// Functions (aliases merged; a function of size 0, libgcc assembly, ends at the next symbol) and objects.
void build_functions(std::vector<Sym>& syms, Parser& ps) {
    Program& p = ps.p;
    // By address, then name: which alias comes first does not depend on the sort.
    std::sort(syms.begin(), syms.end(), [](const Sym& a, const Sym& b) { return a.addr != b.addr ? a.addr < b.addr : a.name < b.name; });
    for (const Sym& s : syms) {
        if (!s.func) {
            p.objects.push_back({s.addr, s.size, s.name});
        } else if (!p.funcs.empty() && p.funcs.back().start == s.addr) {
            p.funcs.back().names.push_back(s.name);
            p.funcs.back().size = std::max(p.funcs.back().size, s.size);
        } else {
            Function f;
            f.names.push_back(s.name);
            f.start = s.addr;
            f.size = s.size;
            p.funcs.push_back(f);
        }
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
}

/// One line of a section's contents (" 0000 e83f0020 c1000000  .?.."), appended to the last run (a
/// new run after a gap).
void read_contents(const std::string& line, std::vector<Bytes>& runs) {
    const std::string t = trim(line);
    const size_t sp = t.find(' ');
    if (sp == std::string::npos || !is_hex(t.substr(0, sp)) || runs.empty()) return;
    const size_t at = line.find(t.substr(0, sp)) + sp;
    std::istringstream groups(line.substr(at, line.find("  ", at) - at));
    const uint32_t addr = hex_value(t.substr(0, sp));
    if (runs.back().data.empty()) runs.back().base = addr;
    if (addr != runs.back().base + runs.back().data.size()) runs.push_back({addr, {}});
    std::string g;
    while (groups >> g) {
        if (!is_hex(g) || g.size() % 2 != 0) break;
        for (size_t i = 0; i < g.size(); i += 2) runs.back().data.push_back(static_cast<uint8_t>(hex_value(g.substr(i, 2))));
    }
}

/// The aligned words of the runs, and those that hold a function's address (a Thumb one with bit 0 set).
void find_pointers(const std::vector<Bytes>& runs, Parser& ps) {
    for (const Bytes& b : runs)
        for (size_t i = (4 - b.base % 4) % 4; i + 4 <= b.data.size(); i += 4)
            ps.words[b.base + static_cast<uint32_t>(i)] = static_cast<uint32_t>(b.data[i]) | static_cast<uint32_t>(b.data[i + 1]) << 8 |
                                                          static_cast<uint32_t>(b.data[i + 2]) << 16 | static_cast<uint32_t>(b.data[i + 3]) << 24;
    const bool thumb = ps.p.isa == Isa::arm;
    for (const auto& [addr, v] : ps.words) {
        if (thumb && (v & 1u) == 0) continue;
        const long t = ps.starting_at(thumb ? v & ~1u : v);
        if (t >= 0) ps.p.pointer_sites.push_back({addr, static_cast<size_t>(t)});
    }
}

}  // namespace

bool parse_objdump(std::istream& in, Program& p, std::string& why) {
    p = Program{};
    Parser ps{p, {}, {}};
    enum Section { none, symbols, contents, disassembly } section = none;
    bool skip_contents = false, have_format = false;
    std::vector<Sym> syms;
    std::vector<Bytes> runs;
    std::string line;
    size_t line_no = 0, instructions = 0;
    why.clear();
    while (std::getline(in, line)) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        Sym sym;
        if (line.find("file format elf32-littlearm") != std::string::npos || line.find("file format elf32-littleriscv") != std::string::npos) {
            p.isa = line.find("riscv") != std::string::npos ? Isa::riscv : Isa::arm;
            have_format = true;
        } else if (line == "SYMBOL TABLE:") {
            section = symbols;
        } else if (starts_with(line, "Contents of section ") || starts_with(line, "Disassembly of section ")) {
            if (section == symbols) build_functions(syms, ps);
            const bool dump = starts_with(line, "Contents");
            section = dump ? contents : disassembly;
            const std::string name = dump && line.size() > 21 ? line.substr(20, line.size() - 21) : std::string();
            skip_contents = starts_with(name, ".debug") || starts_with(name, ".comment") || name.find("attributes") != std::string::npos ||
                            starts_with(name, ".note");
            if (dump && !skip_contents) runs.push_back({0, {}});
        } else if (section == symbols) {
            if (read_symbol(line, p.isa, sym)) syms.push_back(sym);
        } else if (section == contents && !skip_contents) {
            read_contents(line, runs);
        } else if (section == disassembly) {
            Insn insn;
            bool orphan = false;
            if (!read_instruction(ps, line, orphan, insn)) continue;
            if (!orphan) {
                ps.code[static_cast<size_t>(ps.containing(insn.addr))].push_back(insn);
                ++instructions;
            } else if (p.isa == Isa::arm && why.empty() && looks_like_code(insn) &&
                       std::none_of(p.objects.begin(), p.objects.end(),
                                    [&](const Program::Range& r) { return insn.addr >= r.start && insn.addr < r.start + r.size; })) {
                // Thumb data shows as .word (mapping symbols): an orphan here is code no symbol covers. On RV32
                // data decodes as instructions, so code without a function symbol is not seen (README).
                std::ostringstream s;
                s << "line " << line_no << ": code outside every function symbol at " << std::hex << insn.addr << ": " << insn.mn << " " << insn.ops;
                why = s.str();
            }
        }
    }
    if (!have_format) why = "no \"file format elf32-littlearm\" or \"elf32-littleriscv\" line (objdump -t -s -d output?)";
    else if (p.funcs.empty()) why = "no function symbols (objdump -t missing, or a stripped ELF)";
    else if (instructions == 0) why = "no instructions inside the function symbols (objdump -d missing?)";
    if (!why.empty()) return false;
    find_pointers(runs, ps);
    for (size_t i = 0; i < p.funcs.size(); ++i) {
        if (p.isa == Isa::arm) classify_arm(ps, i);
        else classify_riscv(ps, i);
        // A symbol with bytes but no instruction (a cut-off dump, code in a section -d does not show) would
        // count as a frame of 0: refused if the bound reaches it.
        if (p.funcs[i].size != 0 && ps.code[i].empty())
            p.funcs[i].problems.push_back("no instructions in the dump for its " + std::to_string(p.funcs[i].size) +
                                          " bytes (objdump -d output cut off, or code in a section -d does not show)");
    }
    return true;
}

namespace {

/// Functions an indirect call may reach: formed by an instruction, or held in a word outside the data
/// objects opt.not_pointers names (a vector table, a mesh whose integers equal code addresses where
/// flash starts at 0); not the handlers. why[f] says what made f a target, for messages.
std::vector<bool> indirect_targets(const Program& p, const Options& opt, std::vector<std::string>& why) {
    std::vector<bool> taken(p.funcs.size(), false);
    why.assign(p.funcs.size(), std::string());
    for (size_t i = 0; i < p.funcs.size(); ++i)
        if (p.address_taken_by_code[i]) {
            taken[i] = true;
            why[i] = "its address is formed by an instruction";
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
            why[s.func] = w.str();
        }
        taken[s.func] = true;
    }
    for (size_t i = 0; i < p.funcs.size(); ++i)
        for (const std::string& n : p.funcs[i].names)
            if (std::find(opt.handlers.begin(), opt.handlers.end(), n) != opt.handlers.end()) taken[i] = false;
    return taken;
}

long find_function(const Program& p, const std::string& name) {
    for (size_t i = 0; i < p.funcs.size(); ++i)
        for (const std::string& n : p.funcs[i].names)
            if (n == name) return static_cast<long>(i);
    return -1;
}

}  // namespace

Bound bound(const Program& p, const Options& opt) {
    Bound b;
    const long entry = find_function(p, opt.entry);
    if (entry < 0) {
        b.why = "no function named " + opt.entry;
        return b;
    }
    for (const std::string& h : opt.handlers)
        if (find_function(p, h) < 0) {
            b.why = "no handler named " + h;
            return b;
        }
    for (const std::string& pattern : opt.not_pointers)
        if (std::none_of(p.objects.begin(), p.objects.end(), [&](const Program::Range& r) { return detail::glob_match(pattern, r.name); })) {
            b.why = "--not-pointers " + pattern + " matches no data object";
            return b;
        }
    std::vector<std::string> why_taken;
    const std::vector<bool> taken = indirect_targets(p, opt, why_taken);
    for (size_t i = 0; i < p.funcs.size(); ++i)
        if (taken[i]) b.indirect_targets.push_back(p.funcs[i].names.front());
    // Callees: the direct ones, then every taken function for a function with an indirect site.
    std::vector<std::vector<size_t>> callees(p.funcs.size());
    for (size_t f = 0; f < p.funcs.size(); ++f) {
        callees[f] = p.funcs[f].callees;
        if (p.funcs[f].indirect_sites != 0)
            for (size_t i = 0; i < p.funcs.size(); ++i)
                if (taken[i] && std::find(callees[f].begin(), callees[f].end(), i) == callees[f].end()) callees[f].push_back(i);
    }
    auto refuse = [&p, entry](size_t f) -> std::string {
        const Function& fn = p.funcs[f];
        if (!fn.problems.empty()) return fn.names.front() + ": " + fn.problems.front();
        if (fn.sets_sp && static_cast<long>(f) != entry) return fn.names.front() + ": loads sp with a new value";
        return std::string();
    };
    // Depth first with an explicit stack of (function, next callee); a function on the stack reached
    // again is recursion.
    enum State : uint8_t { unvisited, active, done };
    std::vector<State> state(p.funcs.size(), unvisited);
    std::vector<uint32_t> total(p.funcs.size(), 0);
    std::vector<long> via(p.funcs.size(), -1);
    struct Step { size_t f, next; };
    std::vector<Step> work;
    if (!(b.why = refuse(static_cast<size_t>(entry))).empty()) return b;
    state[static_cast<size_t>(entry)] = active;
    work.push_back({static_cast<size_t>(entry), 0});
    while (!work.empty()) {
        const size_t f = work.back().f;
        if (work.back().next < callees[f].size()) {
            const size_t c = callees[f][work.back().next++];
            if (state[c] == active) {
                b.why = "recursion: ";
                for (const Step& w : work) b.why += p.funcs[w.f].names.front() + " -> ";
                b.why += p.funcs[c].names.front();
                if (std::find(p.funcs[f].callees.begin(), p.funcs[f].callees.end(), c) == p.funcs[f].callees.end())
                    b.why += " (an indirect call: " + why_taken[c] + ")";
                return b;
            }
            if (state[c] == unvisited) {
                if (!(b.why = refuse(c)).empty()) {
                    b.why += " (reached from " + p.funcs[f].names.front() + ")";
                    return b;
                }
                state[c] = active;
                work.push_back({c, 0});
            }
            continue;
        }
        for (size_t c : callees[f])
            if (via[f] < 0 || total[c] > total[static_cast<size_t>(via[f])]) via[f] = static_cast<long>(c);
        total[f] = p.funcs[f].frame + (via[f] < 0 ? 0 : total[static_cast<size_t>(via[f])]);
        state[f] = done;
        work.pop_back();
    }
    b.ok = true;
    b.bytes = total[static_cast<size_t>(entry)];
    for (long f = entry; f >= 0; f = via[static_cast<size_t>(f)])
        b.path.push_back({p.funcs[static_cast<size_t>(f)].names.front(), p.funcs[static_cast<size_t>(f)].frame});
    return b;
}

}  // namespace stackbound

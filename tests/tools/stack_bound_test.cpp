// hider-stack's analysis (tools/hider-stack) on small hand-written objdump listings: frames from every
// way a function takes stack (push, store-multiple, sp decrements, Thumb-1's constant in a register),
// returns that are not calls, tail calls, indirect calls through address-taken functions, and the cases
// that must refuse to give a bound. The firmware ctests (<name>.stack_bound) run it on every real ELF
// and hold it against the high-water mark each run measures.
#include <fstream>
#include <sstream>
#include <string>

#include <doctest/doctest.h>

#include "hider-stack/stack_bound.hpp"

namespace {

stackbound::Program parse(const std::string& text) {
    std::istringstream in(text);
    stackbound::Program p;
    std::string why;
    const bool ok = stackbound::parse_objdump(in, p, why);
    REQUIRE_MESSAGE(ok, why);
    return p;
}

stackbound::Bound bound_of(const std::string& text, const std::string& entry, std::vector<std::string> not_pointers = {},
                           std::vector<std::string> handlers = {}) {
    const stackbound::Program p = parse(text);
    stackbound::Options opt;
    opt.entry = entry;
    opt.not_pointers = std::move(not_pointers);
    opt.handlers = std::move(handlers);
    return stackbound::bound(p, opt);
}

std::string path_of(const stackbound::Bound& b) {
    std::string s;
    for (const auto& [name, frame] : b.path) s += name + ":" + std::to_string(frame) + " ";
    return s;
}

// tests/data/stack/chain.dump (also hider-stack's command-line tests): Thumb, reset -> main -> {leaf,
// big}; big takes its frame the Thumb-1 way (a constant from a literal added to sp) and returns through
// a popped register; `spin` loops on itself (a local branch).
std::string chain_dump() {
    std::ifstream in(std::string(HIDER_TEST_DATA) + "/stack/chain.dump");
    std::stringstream text;
    text << in.rdbuf();
    REQUIRE_MESSAGE(!text.str().empty(), "tests/data/stack/chain.dump");
    return text.str();
}

}  // namespace

TEST_CASE("hider-stack: Thumb frames add up along the deepest call chain") {
    const stackbound::Bound b = bound_of(chain_dump(), "reset");
    REQUIRE_MESSAGE(b.ok, b.why);
    // reset 8 + 16; main 20 + 1024; big 8 + 600 (the literal -600 added to sp) + leaf 4
    CHECK(b.bytes == 24 + 1044 + 608 + 4);
    CHECK(path_of(b) == "reset:24 main:1044 big:608 leaf:4 ");
    CHECK(b.indirect_targets.empty());  // the literal is a frame size, not a code address
    const stackbound::Bound leaf = bound_of(chain_dump(), "leaf");
    CHECK(leaf.bytes == 4);
    CHECK(!bound_of(chain_dump(), "nowhere").ok);
}

TEST_CASE("hider-stack: an indirect call reaches every address-taken function, less named data") {
    const std::string text = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	0000000c caller
00000110 g     F .text	00000004 small
00000120 g     F .text	00000004 deep
00000130 g     F .text	00000004 handler
00000140 g     F .text	0000000a hop
00000200 l     O .text	00000008 kMesh

Contents of section .text:
 0108 11010000 00000000 00000000 00000000  ................
 0200 21010000 31010000                    ........

Disassembly of section .text:

00000100 <caller>:
 100:	push	{r4, lr}
 102:	ldr	r3, [pc, #4]	@ (108 <caller+0x8>)
 104:	blx	r3
 106:	pop	{r4, pc}
 108:	.word	0x00000111

00000110 <small>:
 110:	push	{lr}
 112:	pop	{pc}

00000120 <deep>:
 120:	sub	sp, #400	@ 0x190
 122:	bx	lr

00000130 <handler>:
 130:	sub	sp, #800	@ 0x320
 132:	bx	lr

00000140 <hop>:
 140:	push	{lr}
 142:	add	r0, pc, #4	@ (adr r0, 148 <hop+0x8>)
 144:	adds	r0, #1
 146:	bx	r0
 148:	pop	{pc}
)";
    // Pointers: small in caller's literal pool; deep and handler in the data object kMesh.
    const stackbound::Bound all = bound_of(text, "caller");
    REQUIRE_MESSAGE(all.ok, all.why);
    CHECK(all.bytes == 8 + 800);
    CHECK(all.indirect_targets.size() == 3);
    const stackbound::Bound no_handler = bound_of(text, "caller", {}, {"handler"});
    CHECK(no_handler.bytes == 8 + 400);
    const stackbound::Bound no_mesh = bound_of(text, "caller", {"kMe*"});
    CHECK(no_mesh.bytes == 8 + 4);
    CHECK(path_of(no_mesh) == "caller:8 small:4 ");
    const stackbound::Bound hop = bound_of(text, "hop");  // a jump through a register to its own label
    CHECK(hop.bytes == 4);
}

TEST_CASE("hider-stack: recursion and sp set from an unknown register give no bound") {
    const std::string recursion = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	00000008 a
00000110 g     F .text	00000008 b

Disassembly of section .text:

00000100 <a>:
 100:	push	{lr}
 102:	bl	110 <b>
 106:	pop	{pc}

00000110 <b>:
 110:	push	{lr}
 112:	bl	100 <a>
 116:	pop	{pc}
)";
    const stackbound::Bound r = bound_of(recursion, "a");
    CHECK(!r.ok);
    CHECK(r.why.find("recursion: a -> b -> a") != std::string::npos);

    const std::string dynamic = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	00000008 vla

Disassembly of section .text:

00000100 <vla>:
 100:	push	{r7, lr}
 102:	sub	sp, r0
 104:	mov	sp, r7
 106:	pop	{r7, pc}
)";
    const stackbound::Bound d = bound_of(dynamic, "vla");
    CHECK(!d.ok);
    CHECK(d.why.find("sp changed by a register") != std::string::npos);

    // A constant loaded before a call is not the register's value after it.
    const std::string clobbered = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	0000000c g
00000110 g     F .text	00000002 leaf

Contents of section .text:
 0108 a8fdffff                             ....

Disassembly of section .text:

00000100 <g>:
 100:	ldr	r3, [pc, #4]	@ (108 <g+0x8>)
 102:	bl	110 <leaf>
 106:	add	sp, r3
 108:	.word	0xfffffda8

00000110 <leaf>:
 110:	bx	lr
)";
    const stackbound::Bound c = bound_of(clobbered, "g");
    CHECK(!c.ok);
    CHECK(c.why.find("sp changed by a register") != std::string::npos);
}

TEST_CASE("hider-stack: RV32 start-up, local subroutines and an address formed by la") {
    const std::string text = R"(
/build/fw.elf:     file format elf32-littleriscv

SYMBOL TABLE:
20400000 g     F .text	00000010 _start
20400010 g     F .text	00000010 hider_reset
20400020 g     F .text	00000020 main
20400040 g     F .text	00000008 callback
20400050 g     F .text	00000004 trap

Disassembly of section .text:

20400000 <_start>:
20400000:	auipc	sp,0x5fc03
20400004:	add	sp,sp,-1848 # 800028d0 <__stack_top__>
20400008:	auipc	t0,0x0
2040000c:	add	t0,t0,72 # 20400050 <trap>

20400010 <hider_reset>:
20400010:	add	sp,sp,-32
20400014:	sw	ra,28(sp)
20400018:	jal	20400020 <main>
2040001c:	j	2040001c <hider_reset+0xc>

20400020 <main>:
20400020:	add	sp,sp,-64
20400024:	jal	t2,20400034 <main+0x14>
20400028:	lui	a5,0x20400
2040002c:	add	a5,a5,64 # 20400040 <callback>
20400030:	jalr	a5
20400034:	jr	t2

20400040 <callback>:
20400040:	add	sp,sp,-208
20400044:	ret

20400050 <trap>:
20400050:	add	sp,sp,-1000
)";
    // _start sets sp (its own allocation restarts there) and falls into hider_reset: no edge, so the
    // entry for this listing is hider_reset; the trap handler's address is formed too.
    const stackbound::Bound with_trap = bound_of(text, "hider_reset");
    REQUIRE_MESSAGE(with_trap.ok, with_trap.why);
    CHECK(with_trap.bytes == 32 + 64 + 1000);
    const stackbound::Bound b = bound_of(text, "hider_reset", {}, {"trap"});
    CHECK(b.bytes == 32 + 64 + 208);
    CHECK(path_of(b) == "hider_reset:32 main:64 callback:208 ");
    const stackbound::Bound start = bound_of(text, "_start", {}, {"trap"});
    REQUIRE_MESSAGE(start.ok, start.why);
    CHECK(start.bytes == 0);
}

TEST_CASE("hider-stack: a return through a local subroutine's link is no indirect jump") {
    // kernel_setup_rv32 style: a walker subroutine called with jal t2 and left with jr t2; cb is
    // address-taken, so an indirect jump would reach it.
    const std::string text = R"(
/build/fw.elf:     file format elf32-littleriscv

SYMBOL TABLE:
20400000 g     F .text	00000010 setup
20400010 g     F .text	00000008 cb
20400020 g     F .text	00000008 take

Disassembly of section .text:

20400000 <setup>:
20400000:	add	sp,sp,-48
20400004:	jal	t2,2040000c <setup+0xc>
20400008:	ret
2040000c:	jr	t2

20400010 <cb>:
20400010:	add	sp,sp,-512
20400014:	ret

20400020 <take>:
20400020:	lui	a0,0x20400
20400024:	add	a0,a0,16 # 20400010 <cb>
)";
    const stackbound::Bound b = bound_of(text, "setup");
    REQUIRE_MESSAGE(b.ok, b.why);
    CHECK(b.bytes == 48);
    CHECK(b.indirect_targets.size() == 1);  // cb, which setup does not reach
}

TEST_CASE("hider-stack: pre-indexed stores, wide sp arithmetic and objdump's raw bytes") {
    // The same function twice: without and with objdump's raw instruction bytes.
    const std::string plain = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	00000010 f

Disassembly of section .text:

00000100 <f>:
 100:	str.w	lr, [sp, #-4]!
 104:	subw	sp, sp, #2052	@ 0x804
 108:	vpush	{d8-d9}
 10c:	add.w	sp, sp, #2052	@ 0x804
)";
    const std::string raw = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	00000010 f

Disassembly of section .text:

00000100 <f>:
 100:	f84d ed04 	str.w	lr, [sp, #-4]!
 104:	f6ad 0d04 	subw	sp, sp, #2052	@ 0x804
 108:	ed2d 8b04 	vpush	{d8-d9}
 10c:	f60d 0d04 	addw	sp, sp, #2052	@ 0x804
)";
    CHECK(bound_of(plain, "f").bytes == 4 + 2052 + 16);
    CHECK(bound_of(raw, "f").bytes == 4 + 2052 + 16);
}

TEST_CASE("hider-stack: a function calling itself, a jump into nothing and code without a symbol give no bound") {
    const std::string self = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	00000008 fact

Disassembly of section .text:

00000100 <fact>:
 100:	push	{r4, lr}
 102:	bl	100 <fact>
 106:	pop	{r4, pc}
)";
    const stackbound::Bound s = bound_of(self, "fact");
    CHECK(!s.ok);
    CHECK(s.why.find("calls itself") != std::string::npos);

    const std::string nowhere = R"(
/build/fw.elf:     file format elf32-littleriscv

SYMBOL TABLE:
20400000 g     F .text	00000008 f

Disassembly of section .text:

20400000 <f>:
20400000:	add	sp,sp,-16
20400004:	j	20400100 <f+0x100>
)";
    const stackbound::Bound n = bound_of(nowhere, "f");
    CHECK(!n.ok);
    CHECK(n.why.find("jump to an address outside every function") != std::string::npos);

    const std::string orphan = R"(
/build/fw.elf:     file format elf32-littlearm

SYMBOL TABLE:
00000100 g     F .text	00000004 f

Disassembly of section .text:

00000100 <f>:
 100:	push	{lr}
 102:	pop	{pc}
 104:	nop
 106:	bl	100 <f>
)";
    std::istringstream in(orphan);
    stackbound::Program p;
    std::string why;
    CHECK(!stackbound::parse_objdump(in, p, why));
    CHECK(why.find("code outside every function symbol at 106") != std::string::npos);
}

TEST_CASE("hider-stack: register lists and name patterns") {
    using stackbound::detail::glob_match;
    using stackbound::detail::register_count;
    CHECK(register_count("{r4, r5, r6, lr}") == 4);
    CHECK(register_count("{r4-r7, lr}") == 5);
    CHECK(register_count("{r4, r5, r6, r7, r8, r9, sl, fp, lr}") == 9);
    CHECK(register_count("r4") == -1);
    CHECK(register_count("{d8-d15}") == 8);
    CHECK(glob_match("*bsp_data*", "_ZN5hider8bsp_data17bsp_torus_160x1285kBlobE"));
    CHECK(glob_match("hider_vectors", "hider_vectors"));
    CHECK(!glob_match("hider_vectors", "hider_vectors2"));
    CHECK(glob_match("k*E", "kMeshE"));
    CHECK(!glob_match("k*E", "kMesh"));
}

TEST_CASE("hider-stack: a function without its code, an sp step past 16 MB and a --not-pointers name of nothing give no bound") {
    // A red-team pass: each of these gave a bound too low, with exit 0.
    const std::string dump = chain_dump();
    // big's symbol stays, its disassembly goes (a cut-off dump): it counted as a frame of 0 (1,072 for 1,680).
    const size_t from = dump.find("00000130 <big>:"), to = dump.find("00000150 <spin>:");
    REQUIRE(from != std::string::npos);
    REQUIRE(to != std::string::npos);
    const stackbound::Bound cut = bound_of(dump.substr(0, from) + dump.substr(to), "reset");
    CHECK(!cut.ok);
    CHECK(cut.why.find("big: no instructions in the dump for its") != std::string::npos);
    // reset's "sub sp, #16" as a 32-bit wrap of -8: the frame became 0.
    std::string wrap = dump;
    const size_t sub = wrap.find("sub\tsp, #16");
    REQUIRE(sub != std::string::npos);
    wrap.replace(sub, 11, "sub\tsp, #4294967288");
    const stackbound::Bound w = bound_of(wrap, "reset");
    CHECK(!w.ok);
    CHECK(w.why.find("4294967288") != std::string::npos);
    // A data object name that matches nothing was ignored: a typo would let pointers through unnoticed.
    const stackbound::Bound typo = bound_of(dump, "reset", {"nope"});
    CHECK(!typo.ok);
    CHECK(typo.why == "--not-pointers nope matches no data object");
}

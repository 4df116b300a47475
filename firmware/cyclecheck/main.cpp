// cyclecheck firmware (ARM targets): hand-written instruction sequences whose cycle counts the processor's
// Technical Reference Manual gives, each called once between bench_begin() and bench_end(), so the
// insncount plugin's cycle model (tools/qemu-insncount/arm_cycles.h) reports one region pair per
// sequence. expected_<model>.txt holds each sequence's cycles worked out from the manual, and
// check_cycles.sh compares them with the plugin's pairs (each less pair 0, the empty sequence, so the
// call around it cancels). Sequences keep r4-r11 and sp as they found them.
#include <stdint.h>

#include "common/bench.hpp"

namespace {

using Sequence = void (*)();

#define HIDER_SEQUENCE(name, body) \
    __attribute__((naked, noinline)) void name() { __asm__ volatile(".syntax unified\n\t" body ::: "memory"); }

#if defined(__ARM_ARCH_6M__)
// Cortex-M0+ (ARM DDI 0484C table 3.1); the cycles of each are in expected_m0plus.txt.
HIDER_SEQUENCE(empty, "bx lr\n")
HIDER_SEQUENCE(alu, "adds r0, r0, #1\n\tsubs r1, r1, r2\n\tlsls r2, r2, #3\n\teors r3, r3, r0\n\tbx lr\n")
HIDER_SEQUENCE(multiply, "movs r0, #3\n\tmovs r1, #5\n\tmuls r0, r1, r0\n\tbx lr\n")
HIDER_SEQUENCE(load_store, "sub sp, sp, #8\n\tmov r1, sp\n\tstr r0, [r1]\n\tstr r0, [r1, #4]\n\tldr r2, [r1]\n\t"
                           "ldrh r3, [r1, #2]\n\tmovs r0, #1\n\tldrb r3, [r1, r0]\n\tadd sp, sp, #8\n\tbx lr\n")
HIDER_SEQUENCE(multiple, "sub sp, sp, #16\n\tmov r1, sp\n\tstm r1!, {r0, r2, r3}\n\tmov r1, sp\n\t"
                         "ldm r1!, {r0, r2, r3}\n\tadd sp, sp, #16\n\tbx lr\n")
HIDER_SEQUENCE(push_pop, "push {r4-r7}\n\tpop {r4-r7}\n\tbx lr\n")
HIDER_SEQUENCE(call_return, "push {r4, lr}\n\tbl 1f\n\tpop {r4, pc}\n1:\n\tpush {lr}\n\tpop {pc}\n")
HIDER_SEQUENCE(branch_not_taken, "movs r0, #0\n\tcmp r0, #1\n\tbeq 1f\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(branch_taken, "movs r0, #0\n\tcmp r0, #0\n\tbeq 1f\n\tnop\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(loop, "movs r0, #5\n1:\n\tsubs r0, r0, #1\n\tbne 1b\n\tbx lr\n")
HIDER_SEQUENCE(branch, "b 1f\n\tnop\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(branch_register, "adr r0, 1f\n\tadds r0, r0, #1\n\tbx r0\n\t.balign 4\n1:\n\tbx lr\n")
HIDER_SEQUENCE(move_to_pc, "adr r0, 1f\n\tmov pc, r0\n\t.balign 4\n1:\n\tbx lr\n")
HIDER_SEQUENCE(system, "mrs r0, msp\n\tdsb\n\tbx lr\n")
// 16-bit instructions on the last halfwords of a 1 KB page (QEMU's translation page): QEMU 7.2 reports
// the one before the page's last halfword as 4 bytes, and the plugin must still cost it as the 16-bit
// ADDS it is.
HIDER_SEQUENCE(page_end, "b 1f\n\t.balign 1024\n\t.space 1020\n1:\n\tadds r0, r0, #1\n\tadds r0, r0, #1\n\t"
                         "adds r0, r0, #1\n\tbx lr\n")
// Encodings the firmware uses that the sequences above leave out. ADD PC and BLX to a register have no
// sequence: hider-stack takes a function jumping by one as able to reach every listed sequence (itself
// too), a false recursion that fails cyclecheck.stack_bound.
HIDER_SEQUENCE(load_literal, "ldr r0, 1f\n\tbx lr\n\t.balign 4\n1:\n\t.word 0x12345678\n")
HIDER_SEQUENCE(signed_loads, "sub sp, sp, #8\n\tmov r1, sp\n\tmovs r2, #0\n\tstr r2, [r1]\n\tldrsh r3, [r1, r2]\n\t"
                             "ldrsb r3, [r1, r2]\n\tadd sp, sp, #8\n\tbx lr\n")
HIDER_SEQUENCE(barriers, "cpsid i\n\tcpsie i\n\tdmb\n\tisb\n\tbx lr\n")
const Sequence kSequences[] = {empty, alu, multiply, load_store, multiple, push_pop, call_return, branch_not_taken,
                               branch_taken, loop, branch, branch_register, move_to_pc, system, page_end,
                               load_literal, signed_loads, barriers};
#elif defined(__ARM_ARCH_7M__)
// Cortex-M3 (ARM DDI 0337I table 3-1 and 3.3.1 "Load/store timings"); cycles in expected_m3.txt.
HIDER_SEQUENCE(empty, "bx lr\n")
HIDER_SEQUENCE(alu, "adds r0, r0, #1\n\tadd.w r1, r1, r2, lsl #2\n\teor r3, r3, r0\n\tbx lr\n")
HIDER_SEQUENCE(multiply, "mul r0, r1, r0\n\tmla r0, r1, r2, r0\n\tbx lr\n")
HIDER_SEQUENCE(load_pair, "sub sp, #16\n\tmov r1, sp\n\tmov r2, sp\n\tnop\n\tldr r0, [r1]\n\tldr r1, [r2]\n\t"
                          "add sp, #16\n\tbx lr\n")
HIDER_SEQUENCE(load_triple, "sub sp, #16\n\tmov r1, sp\n\tmov r2, sp\n\tmov r3, sp\n\tmovs r0, #0\n\tmov r12, r0\n\tnop\n\t"
                            "ldr r0, [r1, r12]\n\tldr r1, [r2]\n\tldr r2, [r3, #4]\n\tadd sp, #16\n\tbx lr\n")
HIDER_SEQUENCE(stores, "sub sp, #16\n\tmov r1, sp\n\tnop\n\tstr r0, [r1, #4]\n\tmovs r2, #8\n\tnop\n\t"
                       "str r0, [r1, r2]\n\tadd sp, #16\n\tbx lr\n")
HIDER_SEQUENCE(address_stall, "sub sp, #8\n\tadd r1, sp, #4\n\tldr r0, [r1]\n\tadd sp, #8\n\tbx lr\n")
HIDER_SEQUENCE(load_use, "sub sp, #8\n\tmov r1, sp\n\tstr r1, [r1]\n\tldr r2, [r1]\n\tldr r3, [r2]\n\tadd sp, #8\n\tbx lr\n")
HIDER_SEQUENCE(branch_not_taken, "movs r0, #0\n\tcmp r0, #1\n\tbeq 1f\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(branch_taken, "movs r0, #0\n\tcmp r0, #0\n\tbeq 1f\n\tnop\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(loop, "movs r0, #5\n1:\n\tsubs r0, r0, #1\n\tbne 1b\n\tbx lr\n")
HIDER_SEQUENCE(divide, "movs r0, #100\n\tmovs r1, #7\n\tudiv r2, r0, r1\n\tbx lr\n")
HIDER_SEQUENCE(long_multiply, "umull r2, r3, r0, r1\n\tumlal r2, r3, r0, r1\n\tbx lr\n")
HIDER_SEQUENCE(multiple, "sub sp, #16\n\tmov r1, sp\n\tstm r1, {r0, r2, r3}\n\tldm r1, {r0, r2, r3}\n\tadd sp, #16\n\tbx lr\n")
HIDER_SEQUENCE(push_pop_return, "push {r4-r7, lr}\n\tpop {r4-r7, pc}\n")
HIDER_SEQUENCE(if_then, "movs r0, #0\n\tcmp r0, #0\n\tit eq\n\tmoveq r1, r0\n\tbx lr\n")
HIDER_SEQUENCE(call_return, "push {r4, lr}\n\tbl 1f\n\tpop {r4, pc}\n1:\n\tbx lr\n")
HIDER_SEQUENCE(dual, "sub sp, #8\n\tstrd r0, r1, [sp]\n\tldrd r2, r3, [sp]\n\tadd sp, #8\n\tbx lr\n")
// Across a 1 KB page (QEMU's translation page, where it ends a block): the NOP before the page's last
// halfword, reported by QEMU 7.2 as 4 bytes, an LDR on that halfword and the LDR after it on the next
// page, which pairs with it.
HIDER_SEQUENCE(page_end, "sub sp, #16\n\tmov r1, sp\n\tmov r2, sp\n\tb 1f\n\t.balign 1024\n\t.space 1020\n1:\n\tnop\n\t"
                         "ldr r0, [r1]\n\tldr r1, [r2]\n\tadd sp, #16\n\tbx lr\n")
// Table branches and a load to PC: blocking loads (3.3.1: TBB/TBH "at least six cycles", LDR PC "at least
// five"), which stall like any load whose address the preceding data-processing instruction wrote.
HIDER_SEQUENCE(table_branch, "movs r0, #1\n\tnop\n\ttbb [pc, r0]\n1:\n\t.byte 0, (2f - 1b) / 2\n\t.balign 2\n\tnop\n2:\n\t"
                             "bx lr\n")
HIDER_SEQUENCE(table_branch_stall, "movs r0, #1\n\ttbb [pc, r0]\n1:\n\t.byte 0, (2f - 1b) / 2\n\t.balign 2\n\tnop\n2:\n\t"
                                   "bx lr\n")
HIDER_SEQUENCE(load_pc_stall, "adr r0, 1f\n\tadds r0, r0, #1\n\tpush {r0}\n\tsub sp, #8\n\tadd sp, #8\n\tldr pc, [sp], #4\n\t"
                              ".balign 4\n1:\n\tbx lr\n")
// Encodings the firmware uses that the sequences above leave out.
HIDER_SEQUENCE(load_literal, "ldr r0, 1f\n\tbx lr\n\t.balign 4\n1:\n\t.word 0x12345678\n")
HIDER_SEQUENCE(compare_branch, "movs r0, #0\n\tcbz r0, 1f\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(compare_branch_not_taken, "movs r0, #0\n\tcbnz r0, 1f\n\tnop\n1:\n\tbx lr\n")
HIDER_SEQUENCE(post_indexed, "sub sp, #8\n\tmov r1, sp\n\tnop\n\tldr r0, [r1], #4\n\tldr r2, [r1]\n\tadd sp, #8\n\tbx lr\n")
HIDER_SEQUENCE(divide_long, "movs r0, #100\n\tmovs r1, #7\n\tsdiv r2, r0, r1\n\tmls r3, r2, r1, r0\n\tsmull r2, r3, r0, r1\n\t"
                            "smlal r2, r3, r0, r1\n\tbx lr\n")
HIDER_SEQUENCE(pop_wide, "push {r4, r8, lr}\n\tpop {r4, r8, pc}\n")
HIDER_SEQUENCE(loads_wide, "sub sp, #8\n\tmov r1, sp\n\tmovs r2, #0\n\tstr r2, [r1, #4]\n\tnop\n\tldrsh.w r3, [r1, r2]\n\t"
                           "ldrb.w r0, [r1, r2, lsl #1]\n\tadd sp, #8\n\tbx lr\n")
// An IT after a 32-bit instruction: nothing 16-bit to fold onto, so it takes its cycle.
HIDER_SEQUENCE(if_then_wide, "movs r0, #0\n\tcmp.w r0, #0\n\tit eq\n\tmoveq r1, r0\n\tbx lr\n")
const Sequence kSequences[] = {empty,        alu,      multiply,         load_pair,    load_triple, stores,
                               address_stall, load_use, branch_not_taken, branch_taken, loop,        divide,
                               long_multiply, multiple, push_pop_return,  if_then,      call_return, dual,
                               page_end,      table_branch, table_branch_stall, load_pc_stall, if_then_wide,
                               load_literal,  compare_branch, compare_branch_not_taken, post_indexed, divide_long,
                               pop_wide,      loads_wide};
#else
const Sequence kSequences[] = {nullptr};  // no cycle model for this target: the firmware is not built
#endif

}  // namespace

int main() {
    for (const Sequence s : kSequences) {
        bench_begin();
        s();
        bench_end();
    }
    return 0;
}

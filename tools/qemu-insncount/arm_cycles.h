/* Cycle models of the Cortex-M0+ and Cortex-M3 for insncount.c, from the processors' Technical Reference
 * Manuals (zero wait-state memory, no interrupts). Each Thumb instruction gets a cost range [lo, hi] when it
 * falls through and extra cycles when it is a branch that is taken (decided at run time by the plugin).
 *
 * Cortex-M0+ (ARM DDI 0484C, table 3.1 "Cortex-M0+ instruction summary"): data processing and MULS 1
 * (the single-cycle multiplier), loads and stores 2, LDM/STM/PUSH/POP 1+N, POP with PC 3+N (N: the other
 * registers), B<cc> 1 not taken / 2 taken, B 2, BL 3, BX/BLX 2, MOV/ADD to PC 2, MRS/MSR/DMB/DSB/ISB 3,
 * WFE/WFI 2. Every cost is exact: lo == hi.
 *
 * Cortex-M3 (ARM DDI 0337I, table 3-1 and section 3.3.1 "Load/store timings"): P, the pipeline refill of
 * a taken branch, is 1..3 cycles "depending on the alignment and width of the target instruction", so
 * branches are ranges; so are the divides (2..12, early termination on the operands), the long multiplies
 * (3..5, accumulating 4..7), an IT (0 when folded onto the preceding 16-bit instruction, else 1: 0..1 after
 * a 16-bit instruction that falls through to it, 1 after a 32-bit one) and a
 * PC-relative load (2, "might add a cycle"). Exact rules applied within a translated block: LDR/STR 2,
 * STR Rt,[Rn,#imm] 1 (write buffer); a single load or store right after a single LDR (no base update, not
 * to PC) whose destination does not form its address costs one cycle less; a load or store (multiples
 * too) whose address register the preceding data-processing instruction wrote stalls one cycle; LDRD/STRD 3;
 * LDM/STM 1+N (+P with PC); LDR PC 5 and TBB/TBH 6 (3.3.1: "at least five" / "at least six cycles": load 2,
 * (add 1,) reload 3; blocking, so classed with the multiples and stalled like them; where table 3-1's
 * summary row differs, the model follows 3.3.1's breakdown). Left out: wait states and bus contention, the base-update
 * load's one-cycle case, IT-skipped instructions (charged as executed), interrupts and exceptions. */
#ifndef HIDER_ARM_CYCLES_H
#define HIDER_ARM_CYCLES_H

#include <stdint.h>

enum CycleModel { MODEL_NONE, MODEL_M0PLUS, MODEL_M3 };

/* Classes that matter for the Cortex-M3's pairing rules. */
enum InsnClass {
    CLS_OTHER,      /* anything else (no pairing effect) */
    CLS_DP,         /* data processing with destination registers (dest) */
    CLS_LDR,        /* single load, no base update, not to PC: can pipeline the next load/store */
    CLS_LOADSTORE,  /* other single load or store: may gain from a preceding LDR, stalls on a DP address */
    CLS_MULTI,      /* LDM, STM, PUSH, POP, LDRD, STRD, LDR PC, TBB/TBH: never pipelined, stall on a DP address */
    CLS_IT,         /* IT: folds (0 cycles) only onto a preceding 16-bit instruction, else 1 */
};

typedef struct {
    uint8_t lo, hi;              /* cycles when it falls through (a conditional branch: not taken) */
    uint8_t taken_lo, taken_hi;  /* extra cycles when it is a conditional branch that is taken */
    uint8_t cls;                 /* InsnClass */
    uint8_t store_imm;           /* CLS_LOADSTORE: STR Rt,[Rn,#imm] (already 1 cycle) */
    uint8_t wide;                /* a 32-bit encoding (an IT after it cannot fold) */
    uint16_t dest;               /* registers written (CLS_DP, CLS_LDR) */
    uint16_t addr;               /* registers forming the address (loads and stores) */
} InsnCost;

static int popcount16(uint32_t v) {
    int n = 0;
    for (v &= 0xFFFFu; v != 0; v &= v - 1) ++n;
    return n;
}

static InsnCost cost_const(int lo, int hi) {
    InsnCost c = {(uint8_t)lo, (uint8_t)hi, 0, 0, CLS_OTHER, 0, 0, 0, 0};
    return c;
}

/* A multiple (or dual) load or store with base register rn. */
static InsnCost cost_multi(int lo, int hi, int rn) {
    InsnCost c = cost_const(lo, hi);
    c.cls = CLS_MULTI;
    c.addr = (uint16_t)(1u << rn);
    return c;
}

/* Cortex-M0+: ARMv6-M Thumb (16-bit, plus BL, MSR, MRS and the barriers). */
static InsnCost cost_m0plus(uint32_t hw, uint32_t hw2, int size) {
    if (size == 4) {
        if ((hw & 0xF800u) == 0xF000u && (hw2 & 0xD000u) == 0xD000u) return cost_const(3, 3); /* BL */
        return cost_const(3, 3);  /* MSR, MRS, DSB, DMB, ISB */
    }
    if ((hw & 0xFFC0u) == 0x4340u) return cost_const(1, 1);                      /* MULS */
    if ((hw & 0xFF00u) == 0x4700u) return cost_const(2, 2);                      /* BX, BLX */
    if ((hw & 0xFD00u) == 0x4400u && (((hw >> 4) & 8u) | (hw & 7u)) == 15u) return cost_const(2, 2); /* ADD/MOV PC */
    if ((hw & 0xF800u) == 0x4800u) return cost_const(2, 2);                      /* LDR literal */
    if ((hw & 0xF000u) == 0x5000u || (hw & 0xE000u) == 0x6000u || (hw & 0xF000u) == 0x8000u ||
        (hw & 0xF000u) == 0x9000u)
        return cost_const(2, 2);                                                 /* single loads, stores */
    if ((hw & 0xFE00u) == 0xB400u) return cost_const(1 + popcount16(hw & 0x1FFu), 1 + popcount16(hw & 0x1FFu)); /* PUSH */
    if ((hw & 0xFE00u) == 0xBC00u) {                                             /* POP */
        const int n = popcount16(hw & 0xFFu);
        return (hw & 0x100u) != 0 ? cost_const(3 + n, 3 + n) : cost_const(1 + n, 1 + n);
    }
    if ((hw & 0xFF0Fu) == 0xBF00u && ((hw >> 4) & 0xFu) >= 2u && ((hw >> 4) & 0xFu) <= 3u) return cost_const(2, 2); /* WFE, WFI */
    if ((hw & 0xF000u) == 0xC000u) return cost_const(1 + popcount16(hw & 0xFFu), 1 + popcount16(hw & 0xFFu)); /* LDM, STM */
    if ((hw & 0xF000u) == 0xD000u && (hw & 0x0E00u) != 0x0E00u) {                /* B<cc> */
        InsnCost c = cost_const(1, 1);
        c.taken_lo = c.taken_hi = 1;
        return c;
    }
    if ((hw & 0xF800u) == 0xE000u) return cost_const(2, 2);                      /* B */
    return cost_const(1, 1);
}

enum { P_LO = 1, P_HI = 3 };  /* Cortex-M3 pipeline refill after a taken branch */

static InsnCost cost_branch_m3(int base) { return cost_const(base + P_LO, base + P_HI); }

static InsnCost cost_dp(uint16_t dest) {
    InsnCost c = cost_const(1, 1);
    if (dest != 0) c.cls = CLS_DP;
    c.dest = dest;
    return c;
}

/* A single load or store: cls, addressing registers, destination (loads). */
static InsnCost cost_single(int load, int writeback, int rt, int rn, int rm, int store_imm) {
    InsnCost c;
    const uint16_t addr = (uint16_t)((1u << rn) | (rm >= 0 ? 1u << rm : 0u));
    if (load && rt == 15) {                                         /* LDR PC: "at least five cycles", blocking */
        c = cost_multi(5, 5, rn);
        c.addr = addr;
        return c;
    }
    if (load && rn == 15) {                                         /* literal: "might add a cycle" */
        c = cost_const(2, 3);
        c.cls = CLS_LOADSTORE;
        c.addr = addr;
        return c;
    }
    c = cost_const(store_imm ? 1 : 2, store_imm ? 1 : 2);
    c.cls = load && !writeback ? CLS_LDR : CLS_LOADSTORE;
    c.store_imm = (uint8_t)store_imm;
    c.dest = load ? (uint16_t)(1u << rt) : 0;
    c.addr = addr;
    return c;
}

static InsnCost cost_m3_16(uint32_t hw) {
    if ((hw & 0xE000u) == 0x0000u && (hw & 0x1800u) != 0x1800u) return cost_dp((uint16_t)(1u << (hw & 7u))); /* shifts */
    if ((hw & 0xF800u) == 0x1800u) return cost_dp((uint16_t)(1u << (hw & 7u)));   /* ADDS/SUBS reg, imm3 */
    if ((hw & 0xE000u) == 0x2000u)                                                /* MOVS/CMP/ADDS/SUBS imm8 */
        return cost_dp((hw & 0x1800u) == 0x0800u ? 0 : (uint16_t)(1u << ((hw >> 8) & 7u)));
    if ((hw & 0xFC00u) == 0x4000u) {                                              /* data processing */
        const uint32_t op = (hw >> 6) & 0xFu;
        return cost_dp(op == 8u || op == 10u || op == 11u ? 0 : (uint16_t)(1u << (hw & 7u)));
    }
    if ((hw & 0xFF00u) == 0x4700u) return cost_branch_m3(1);                      /* BX, BLX */
    if ((hw & 0xFC00u) == 0x4400u) {                                              /* ADD/CMP/MOV high */
        const uint32_t rd = ((hw >> 4) & 8u) | (hw & 7u);
        if ((hw & 0x0300u) == 0x0100u) return cost_dp(0);                         /* CMP */
        return rd == 15u ? cost_branch_m3(1) : cost_dp((uint16_t)(1u << rd));
    }
    if ((hw & 0xF800u) == 0x4800u) return cost_single(1, 0, (hw >> 8) & 7, 15, -1, 0);  /* LDR literal */
    if ((hw & 0xF000u) == 0x5000u) {                                              /* register offset */
        const int load = ((hw >> 9) & 7u) >= 3u;
        return cost_single(load, 0, hw & 7, (hw >> 3) & 7, (hw >> 6) & 7, 0);
    }
    if ((hw & 0xE000u) == 0x6000u || (hw & 0xF000u) == 0x8000u) {                 /* immediate offset */
        const int load = (hw & 0x0800u) != 0;
        return cost_single(load, 0, hw & 7, (hw >> 3) & 7, -1, !load);
    }
    if ((hw & 0xF000u) == 0x9000u) {                                              /* SP-relative */
        const int load = (hw & 0x0800u) != 0;
        return cost_single(load, 0, (hw >> 8) & 7, 13, -1, !load);
    }
    if ((hw & 0xF000u) == 0xA000u) return cost_dp((uint16_t)(1u << ((hw >> 8) & 7u)));  /* ADR, ADD Rd, SP */
    if ((hw & 0xFF00u) == 0xB000u) return cost_dp(1u << 13);                      /* ADD/SUB SP */
    if ((hw & 0xF500u) == 0xB100u) {                                              /* CBZ, CBNZ */
        InsnCost c = cost_const(1, 1);
        c.taken_lo = P_LO;
        c.taken_hi = P_HI;
        return c;
    }
    if ((hw & 0xFF00u) == 0xB200u || (hw & 0xFF00u) == 0xBA00u) return cost_dp((uint16_t)(1u << (hw & 7u))); /* extend, REV */
    if ((hw & 0xFE00u) == 0xB400u) { const int n = 1 + popcount16(hw & 0x1FFu); return cost_multi(n, n, 13); }  /* PUSH */
    if ((hw & 0xFE00u) == 0xBC00u) {                                              /* POP */
        const int n = 1 + popcount16(hw & 0x1FFu);
        return (hw & 0x100u) != 0 ? cost_multi(n + P_LO, n + P_HI, 13) : cost_multi(n, n, 13);
    }
    if ((hw & 0xFF00u) == 0xBF00u && (hw & 0xFu) != 0) {                         /* IT (folded or not) */
        InsnCost c = cost_const(0, 1);
        c.cls = CLS_IT;
        return c;
    }
    if ((hw & 0xF000u) == 0xC000u) {                                              /* LDM, STM */
        const int n = 1 + popcount16(hw & 0xFFu);
        return cost_multi(n, n, (hw >> 8) & 7);
    }
    if ((hw & 0xF000u) == 0xD000u && (hw & 0x0E00u) != 0x0E00u) {                 /* B<cc> */
        InsnCost c = cost_const(1, 1);
        c.taken_lo = P_LO;
        c.taken_hi = P_HI;
        return c;
    }
    if ((hw & 0xF800u) == 0xE000u) return cost_branch_m3(1);                      /* B */
    return cost_const(1, 1);
}

static InsnCost cost_m3_32(uint32_t hw, uint32_t hw2) {
    const uint32_t rn = hw & 0xFu, rt = (hw2 >> 12) & 0xFu, rd = (hw2 >> 8) & 0xFu;
    if ((hw & 0xFE40u) == 0xE800u) {                                              /* LDM, STM, PUSH.W, POP.W */
        const int n = 1 + popcount16(hw2);
        if ((hw & 0x0010u) != 0 && (hw2 & 0x8000u) != 0) return cost_multi(n + P_LO, n + P_HI, (int)rn);
        return cost_multi(n, n, (int)rn);
    }
    if ((hw & 0xFE40u) == 0xE840u) {                                              /* dual, exclusive, table branch */
        if ((hw & 0xFFF0u) == 0xE8D0u && (hw2 & 0x00E0u) == 0x0000u) {          /* TBB, TBH: "at least six cycles" */
            InsnCost c = cost_multi(6, 6, (int)rn);
            c.addr |= (uint16_t)(1u << (hw2 & 0xFu));                            /* the index forms the address too */
            return c;
        }
        if ((hw & 0x0120u) != 0) return cost_multi(3, 3, (int)rn);                /* LDRD, STRD */
        return cost_single((hw & 0x0010u) != 0, 0, (int)rt, (int)rn, -1, 0);      /* LDREX, STREX */
    }
    if ((hw & 0xFE00u) == 0xEA00u)                                                /* data processing, shifted register */
        return cost_dp((hw & 0x0010u) != 0 && rd == 15u ? 0 : (uint16_t)(1u << rd));
    if ((hw & 0xF800u) == 0xF000u && (hw2 & 0x8000u) == 0) {                       /* data processing, immediate */
        const int compare = (hw & 0x0010u) != 0 && rd == 15u && (hw & 0x0200u) == 0;
        return cost_dp(compare ? 0 : (uint16_t)(1u << rd));
    }
    if ((hw & 0xF800u) == 0xF000u) {                                              /* branches, misc control */
        if ((hw2 & 0x5000u) == 0x0000u) {
            if ((hw & 0x0380u) != 0x0380u) {                                      /* B<cc>.W */
                InsnCost c = cost_const(1, 1);
                c.taken_lo = P_LO;
                c.taken_hi = P_HI;
                return c;
            }
            if ((hw & 0xFFF0u) == 0xF3B0u) return cost_const(1, 1 + P_HI);        /* barriers: 1 + B */
            return cost_const(1, 2);                                              /* MSR, MRS, hints */
        }
        return cost_branch_m3(1);                                                 /* B.W, BL */
    }
    if ((hw & 0xFE00u) == 0xF800u) {                                              /* single loads and stores */
        const int load = (hw & 0x0010u) != 0;
        if (load && rt == 15u && (hw & 0x0060u) != 0x0040u) return cost_const(1, 1);  /* PLD, PLI hints */
        if (rn == 15u) return cost_single(load, 0, (int)rt, 15, -1, 0);
        if ((hw & 0x0080u) != 0) return cost_single(load, 0, (int)rt, (int)rn, -1, !load);  /* imm12 */
        if ((hw2 & 0x0FC0u) == 0) return cost_single(load, 0, (int)rt, (int)rn, (int)(hw2 & 0xFu), 0);  /* register */
        if ((hw2 & 0x0800u) != 0) {                                               /* imm8: P U W */
            const int writeback = (hw2 & 0x0100u) != 0 || (hw2 & 0x0400u) == 0;
            return cost_single(load, writeback, (int)rt, (int)rn, -1, !load && !writeback);
        }
        return cost_single(load, 0, (int)rt, (int)rn, -1, 0);                     /* unprivileged */
    }
    if ((hw & 0xFF00u) == 0xFA00u) return cost_dp((uint16_t)(1u << rd));          /* data processing, register */
    if ((hw & 0xFF80u) == 0xFB00u) {                                              /* MUL, MLA, MLS */
        const int accumulate = (hw & 0x0070u) != 0 || (hw2 & 0x00F0u) != 0 || rt != 15u;
        InsnCost c = cost_dp((uint16_t)(1u << rd));
        c.lo = c.hi = (uint8_t)(accumulate ? 2 : 1);
        return c;
    }
    if ((hw & 0xFF80u) == 0xFB80u) {                                              /* long multiply, divide */
        const uint32_t op = (hw >> 4) & 7u;
        InsnCost c;
        if (op == 1u || op == 3u) {                                               /* SDIV, UDIV */
            c = cost_dp((uint16_t)(1u << rd));
            c.lo = 2;
            c.hi = 12;
        } else {
            c = cost_dp((uint16_t)((1u << rd) | (1u << rt)));
            c.lo = (uint8_t)(op >= 4u ? 4 : 3);
            c.hi = (uint8_t)(op >= 4u ? 7 : 5);
        }
        return c;
    }
    return cost_const(1, 1);
}

/* Size of the Thumb instruction whose first halfword is in `data`: 4 for the 32-bit encodings (first
 * five bits 0b11101, 0b11110 or 0b11111), else 2. QEMU 7.2 reports the 16-bit instruction before a page's
 * last halfword as 4 bytes (it reads that halfword while translating it, to see whether the next
 * instruction crosses the page), so the plugin takes the size from the encoding (firmware/cyclecheck's
 * page_end). */
static int thumb_insn_size(const uint8_t *data) {
    const uint32_t hw = (uint32_t)data[0] | ((uint32_t)data[1] << 8);
    return (hw >> 11) >= 0x1Du ? 4 : 2;
}

/* Cost of one instruction (its bytes in `data`, 2 or 4 of them) under `model`. */
static InsnCost insn_cost(int model, const uint8_t *data, int size) {
    const uint32_t hw = (uint32_t)data[0] | ((uint32_t)data[1] << 8);
    const uint32_t hw2 = size == 4 ? (uint32_t)data[2] | ((uint32_t)data[3] << 8) : 0;
    if (model == MODEL_M0PLUS) return cost_m0plus(hw, hw2, size);
    InsnCost c = size == 4 ? cost_m3_32(hw, hw2) : cost_m3_16(hw);
    c.wide = (uint8_t)(size == 4);
    return c;
}

/* The Cortex-M3's pairing rules between an instruction and the one before it in the same block. */
static void pair_m3(const InsnCost *prev, InsnCost *cur) {
    if (cur->cls == CLS_IT && prev->wide) cur->lo = 1;  /* nothing 16-bit to fold onto */
    if (cur->cls != CLS_LDR && cur->cls != CLS_LOADSTORE && cur->cls != CLS_MULTI) return;
    if (prev->cls == CLS_LDR && cur->cls != CLS_MULTI && (prev->dest & cur->addr) == 0) {
        if (!cur->store_imm && cur->lo > 1) { cur->lo--; cur->hi--; }
    } else if (prev->cls == CLS_DP && (prev->dest & cur->addr) != 0) {
        cur->lo++;
        cur->hi++;
    }
}

#endif

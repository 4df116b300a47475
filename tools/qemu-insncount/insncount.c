/* QEMU TCG plugin: exact guest instruction counts and, with model=, estimated
 * cycles of a Cortex-M0+ or Cortex-M3 (arm_cycles.h). Counts the whole run and the region from the first
 * instruction at start= up to the first instruction at end=, summed over all pairs. Options:
 *   start=0x.. end=0x..   region bounds (Thumb bit ignored)
 *   out=<file>            also write the report there
 *   model=m0plus|m3       cycle model (ARM targets only)
 *   pairs=1               one more line per region pair: "pair <i> insns=<n> cycles=<lo> cycles_max=<hi>"
 *   profile=<file>        region executions per instruction address: "<pc hex> <count> <cycles lo>"
 *   profile_pair=<n>      profile only the n-th region pair (from 0)
 *                         (cycles 0 without model=)
 * First line of the report (cycle fields only with model=):
 *   insncount total=<n> region=<n> pairs=<n> cycles=<lo> cycles_max=<hi> region_cycles=<lo> region_cycles_max=<hi>
 * Build with the host compiler: cc -O2 -shared -fPIC -o libinsncount.so insncount.c
 * The few plugin API v1 declarations used are written out below (as in QEMU 7.2 qemu-plugin.h). */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arm_cycles.h"

#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))
typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
typedef struct qemu_info_t {
    const char *target_name;
    struct { int min; int cur; } version;
    bool system_emulation;
    union { struct { int smp_vcpus; int max_vcpus; } system; };
} qemu_info_t;
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb *tb, qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn, qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
const void *qemu_plugin_insn_data(const struct qemu_plugin_insn *insn);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

/* One translated block under a cycle model: its cost when it runs to the end, and what its last
 * instruction adds when it is a branch that is taken (the next block does not start at fallthrough). */
typedef struct Block {
    uint64_t lo, hi;
    uint64_t fallthrough;
    uint32_t taken_lo, taken_hi;
    InsnCost first, last;   /* M3: the pairing rules across a fall-through from one block into the next */
    uint32_t n;
    uint64_t region_execs;  /* profile: executions that started inside the region */
    uint64_t *pcs;          /* profile: address of each instruction */
    uint32_t *costs;        /* profile: lo cycles of each instruction */
    struct Block *next;     /* every block, for the profile */
} Block;

/* Where a region marker sits: instructions and cycles from it to the end of its block, inclusive, and
 * whether it is the block's first instruction (which carries the block's entry adjustment). */
typedef struct {
    uint64_t insns, lo, hi;
    bool first;
} Tail;

static uint64_t total;          /* every executed instruction: whole blocks, added inline */
static uint64_t cyc_lo, cyc_hi; /* cycle totals (whole blocks added on entry, taken branches when seen) */
static uint64_t adj_lo, adj_hi; /* the current block's first instruction: its pairing with the block before */
static uint64_t region, region_lo, region_hi;
static uint64_t pair_max;  /* largest single start..end count */
static uint64_t from_insns, from_lo, from_hi;  /* running counts at the last start */
static uint64_t pairs;
static bool in_region;
static bool have_start, have_end, printed, list_pairs;
static uint64_t start_addr, end_addr;
static int model = MODEL_NONE;
static long profile_pair = -1;
static const Block *last_block;
static Block *blocks;
static char out_path[4096], profile_path[4096];

enum { kMaxPairs = 256 };
static uint64_t pair_insns[kMaxPairs], pair_lo[kMaxPairs], pair_hi[kMaxPairs];

/* Block entry: settle the previous block's branch (taken unless we continue at its fallthrough), then
 * charge this block as if it runs to its end. */
static void on_block(unsigned int vcpu, void *userdata) {
    (void)vcpu;
    Block *b = (Block *)userdata;
    const Block *prev = last_block;
    if (prev != NULL && prev->taken_hi != 0 && prev->fallthrough != b->pcs[0]) {
        cyc_lo += prev->taken_lo;
        cyc_hi += prev->taken_hi;
    }
    adj_lo = adj_hi = 0;
    if (model == MODEL_M3 && prev != NULL && prev->fallthrough == b->pcs[0]) {
        /* QEMU ends blocks at page boundaries too: the pair across one costs what it would inside a block. */
        InsnCost paired = b->first;
        pair_m3(&prev->last, &paired);
        adj_lo = (uint64_t)((int64_t)paired.lo - (int64_t)b->first.lo);
        adj_hi = (uint64_t)((int64_t)paired.hi - (int64_t)b->first.hi);
        cyc_lo += adj_lo;
        cyc_hi += adj_hi;
    }
    cyc_lo += b->lo;
    cyc_hi += b->hi;
    last_block = b;
    if (in_region && (profile_pair < 0 || (uint64_t)profile_pair == pairs)) b->region_execs++;
}

static void on_start(unsigned int vcpu, void *userdata) {
    (void)vcpu;
    const Tail *t = (const Tail *)userdata;
    if (in_region) return;
    in_region = true;
    from_insns = total - t->insns;
    from_lo = cyc_lo - t->lo - (t->first ? adj_lo : 0);  /* the marker's own adjustment is inside the region */
    from_hi = cyc_hi - t->hi - (t->first ? adj_hi : 0);
}

static void on_end(unsigned int vcpu, void *userdata) {
    (void)vcpu;
    const Tail *t = (const Tail *)userdata;
    if (!in_region) return;
    in_region = false;
    const uint64_t n = total - t->insns - from_insns;
    const uint64_t lo = cyc_lo - t->lo - (t->first ? adj_lo : 0) - from_lo, hi = cyc_hi - t->hi - (t->first ? adj_hi : 0) - from_hi;
    region += n;
    if (n > pair_max) pair_max = n;
    region_lo += lo;
    region_hi += hi;
    if (pairs < kMaxPairs) {
        pair_insns[pairs] = n;
        pair_lo[pairs] = lo;
        pair_hi[pairs] = hi;
    }
    ++pairs;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb) {
    (void)id;
    const size_t n = qemu_plugin_tb_n_insns(tb);
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &total, n);
    Block *b = NULL;
    InsnCost *cost = NULL;
    if ((model != MODEL_NONE || profile_path[0] != '\0') && n > 0) {
        b = calloc(1, sizeof *b);
        cost = calloc(n, sizeof *cost);
        b->pcs = calloc(n, sizeof *b->pcs);
        b->costs = calloc(n, sizeof *b->costs);
        if (b == NULL || cost == NULL || b->pcs == NULL || b->costs == NULL) {
            fputs("insncount: out of memory\n", stderr);
            exit(1);
        }
        b->n = (uint32_t)n;
        for (size_t i = 0; i < n; ++i) {
            struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
            const uint8_t *data = (const uint8_t *)qemu_plugin_insn_data(insn);
            const int size = model != MODEL_NONE ? thumb_insn_size(data) : (int)qemu_plugin_insn_size(insn);
            if (model != MODEL_NONE) cost[i] = insn_cost(model, data, size);
            if (model == MODEL_M3 && i > 0) pair_m3(&cost[i - 1], &cost[i]);
            b->pcs[i] = qemu_plugin_insn_vaddr(insn) & ~(uint64_t)1;
            b->costs[i] = cost[i].lo;
            b->lo += cost[i].lo;
            b->hi += cost[i].hi;
            if (i == 0) b->first = cost[0];  /* before pairing inside the block: it has no predecessor here */
            if (i + 1 == n) {
                b->last = cost[i];
                b->fallthrough = b->pcs[i] + (uint64_t)size;
                b->taken_lo = cost[i].taken_lo;
                b->taken_hi = cost[i].taken_hi;
            }
        }
        b->next = blocks;
        blocks = b;
        qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS, b);
    }
    /* Markers: the tail from the marker to the block's end was charged on entry but has not run yet. */
    Tail tail = {0, 0, 0, false};
    for (size_t i = n; i-- > 0;) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t pc = qemu_plugin_insn_vaddr(insn) & ~(uint64_t)1;
        tail.insns++;
        if (cost != NULL) {
            tail.lo += cost[i].lo;
            tail.hi += cost[i].hi;
        }
        const bool is_start = have_start && pc == start_addr, is_end = have_end && pc == end_addr;
        if (!is_start && !is_end) continue;
        Tail *t = malloc(sizeof *t);
        if (t == NULL) exit(1);
        *t = tail;
        t->first = i == 0;
        if (is_start) qemu_plugin_register_vcpu_insn_exec_cb(insn, on_start, QEMU_PLUGIN_CB_NO_REGS, t);
        if (is_end) qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, t);
    }
    free(cost);
}

typedef struct {
    uint64_t pc, count, cycles;
} ProfileRow;

static int by_pc(const void *a, const void *b) {
    const uint64_t x = ((const ProfileRow *)a)->pc, y = ((const ProfileRow *)b)->pc;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* Region executions per instruction address, merged over every translation of each block. */
static void write_profile(void) {
    size_t rows = 0;
    for (const Block *b = blocks; b != NULL; b = b->next) rows += b->region_execs != 0 ? b->n : 0;
    ProfileRow *r = calloc(rows + 1, sizeof *r);
    FILE *f = fopen(profile_path, "w");
    if (r == NULL || f == NULL) {
        fprintf(stderr, "insncount: cannot write %s\n", profile_path);
        free(r);
        if (f != NULL) fclose(f);
        return;
    }
    size_t k = 0;
    for (const Block *b = blocks; b != NULL; b = b->next)
        for (uint32_t i = 0; b->region_execs != 0 && i < b->n; ++i) r[k++] = (ProfileRow){b->pcs[i], b->region_execs, b->costs[i]};
    qsort(r, rows, sizeof *r, by_pc);
    for (size_t i = 0; i < rows;) {
        ProfileRow m = r[i];
        size_t j = i + 1;
        for (; j < rows && r[j].pc == m.pc; ++j) m.count += r[j].count;
        fprintf(f, "%08" PRIx64 " %" PRIu64 " %" PRIu64 "\n", m.pc, m.count, m.cycles);
        i = j;
    }
    fclose(f);
    free(r);
}

static void report(void) {
    if (printed) return;
    printed = true;
    char line[512];
    int len = snprintf(line, sizeof line, "insncount total=%" PRIu64 " region=%" PRIu64 " pairs=%" PRIu64 " max=%" PRIu64, total,
                       region, pairs, pair_max);
    if (model != MODEL_NONE)
        len += snprintf(line + len, sizeof line - (size_t)len,
                        " cycles=%" PRIu64 " cycles_max=%" PRIu64 " region_cycles=%" PRIu64 " region_cycles_max=%" PRIu64,
                        cyc_lo, cyc_hi, region_lo, region_hi);
    snprintf(line + len, sizeof line - (size_t)len, "\n");
    FILE *f = NULL;
    if (out_path[0] != '\0' && (f = fopen(out_path, "w")) == NULL) fprintf(stderr, "insncount: cannot write %s\n", out_path);
    fputs(line, stderr);
    if (f != NULL) fputs(line, f);
    for (uint64_t i = 0; list_pairs && i < pairs && i < kMaxPairs; ++i) {
        snprintf(line, sizeof line, "pair %" PRIu64 " insns=%" PRIu64 " cycles=%" PRIu64 " cycles_max=%" PRIu64 "\n", i,
                 pair_insns[i], pair_lo[i], pair_hi[i]);
        fputs(line, stderr);
        if (f != NULL) fputs(line, f);
    }
    if (f != NULL) fclose(f);
    if (profile_path[0] != '\0') write_profile();
}

static void on_exit_cb(qemu_plugin_id_t id, void *userdata) {
    (void)id;
    (void)userdata;
    report();
}

/* A semihosting exit calls exit() directly; the destructor still prints the counts once. */
__attribute__((destructor)) static void on_unload(void) { report(); }

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv) {
    for (int i = 0; i < argc; ++i) {
        const char *arg = argv[i];
        if (strncmp(arg, "start=", 6) == 0) {
            start_addr = strtoull(arg + 6, NULL, 0) & ~(uint64_t)1;
            have_start = true;
        } else if (strncmp(arg, "end=", 4) == 0) {
            end_addr = strtoull(arg + 4, NULL, 0) & ~(uint64_t)1;
            have_end = true;
        } else if (strncmp(arg, "out=", 4) == 0) {
            snprintf(out_path, sizeof out_path, "%s", arg + 4);
        } else if (strcmp(arg, "model=m0plus") == 0) {
            model = MODEL_M0PLUS;
        } else if (strcmp(arg, "model=m3") == 0) {
            model = MODEL_M3;
        } else if (strcmp(arg, "pairs=1") == 0) {
            list_pairs = true;
        } else if (strncmp(arg, "profile_pair=", 13) == 0) {
            profile_pair = strtol(arg + 13, NULL, 0);
        } else if (strncmp(arg, "profile=", 8) == 0) {
            snprintf(profile_path, sizeof profile_path, "%s", arg + 8);
        } else {
            fprintf(stderr, "insncount: unknown option '%s' (start=, end=, out=, model=m0plus|m3, pairs=1, profile=, profile_pair=)\n", arg);
            return -1;
        }
    }
    if (model != MODEL_NONE && (info == NULL || info->target_name == NULL || strcmp(info->target_name, "arm") != 0)) {
        fprintf(stderr, "insncount: model= needs an ARM target (this is %s)\n", info && info->target_name ? info->target_name : "?");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit_cb, NULL);
    return 0;
}

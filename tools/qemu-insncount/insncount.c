/* QEMU TCG plugin: exact guest instruction counts (docs/targets.md s.6). Counts the whole run and
 * the region from the first instruction at start= up to the first instruction at end=, summed over
 * all pairs. Options: start=0x.., end=0x.. (Thumb bit ignored), out=<file>. Prints one line once:
 *   insncount total=<n> region=<n> pairs=<n> max=<n>   (max: the largest single pair)
 * Build with the host compiler: cc -O2 -shared -fPIC -o libinsncount.so insncount.c
 * The few plugin API v1 declarations used are written out below (as in QEMU 7.2 qemu-plugin.h). */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn, qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

static uint64_t total;          /* every executed instruction: whole blocks, added inline */
static uint64_t region;         /* instructions between start and end, over all pairs */
static uint64_t region_from;    /* value of the running count at the last start */
static uint64_t pairs;
static uint64_t pair_max;       /* largest single start..end count */
static bool in_region;
static bool have_start, have_end, printed;
static uint64_t start_addr, end_addr;
static char out_path[4096];

/* The inline add counted the whole block on entry; `left` = this instruction and the ones after
 * it in the block, so total - left is the count just before this instruction executes. */
static void on_start(unsigned int vcpu, void *left) {
    (void)vcpu;
    if (in_region) return;
    in_region = true;
    region_from = total - (uint64_t)(uintptr_t)left;
}

static void on_end(unsigned int vcpu, void *left) {
    (void)vcpu;
    if (!in_region) return;
    in_region = false;
    const uint64_t n = total - (uint64_t)(uintptr_t)left - region_from;
    region += n;
    if (n > pair_max) pair_max = n;
    ++pairs;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb) {
    (void)id;
    const size_t n = qemu_plugin_tb_n_insns(tb);
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &total, n);
    for (size_t i = 0; i < n; ++i) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t pc = qemu_plugin_insn_vaddr(insn) & ~(uint64_t)1;
        void *left = (void *)(uintptr_t)(n - i);
        if (have_start && pc == start_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_start, QEMU_PLUGIN_CB_NO_REGS, left);
        if (have_end && pc == end_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, left);
    }
}

static void report(void) {
    if (printed) return;
    printed = true;
    char line[160];
    snprintf(line, sizeof line, "insncount total=%" PRIu64 " region=%" PRIu64 " pairs=%" PRIu64 " max=%" PRIu64 "\n",
             total, region, pairs, pair_max);
    fputs(line, stderr);
    if (out_path[0] != '\0') {
        FILE *f = fopen(out_path, "w");
        if (f != NULL) {
            fputs(line, f);
            fclose(f);
        } else {
            fprintf(stderr, "insncount: cannot write %s\n", out_path);
        }
    }
}

static void on_exit_cb(qemu_plugin_id_t id, void *userdata) {
    (void)id;
    (void)userdata;
    report();
}

/* A semihosting exit calls exit() directly; the destructor still prints the counts once. */
__attribute__((destructor)) static void on_unload(void) { report(); }

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv) {
    (void)info;
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
        } else {
            fprintf(stderr, "insncount: unknown option '%s' (start=, end=, out=)\n", arg);
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit_cb, NULL);
    return 0;
}

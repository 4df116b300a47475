/* QEMU TCG plugin: instruction profile by translated block. Counts how often each block runs and writes
 * one line per block, "<start address, decimal> <instructions in the block> <executions>", to out=<file>
 * at exit; tools/qemu-insncount/profile.sh maps the blocks to function symbols. Same plugin API v1
 * declarations as insncount.c. Build: cc -O2 -shared -fPIC -o libtbprofile.so tbprofile.c */
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
typedef struct qemu_info_t {
    const char *target_name;
    struct { int min; int cur; } version;
    bool system_emulation;
    union { struct { int smp_vcpus; int max_vcpus; } system; };
} qemu_info_t;
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

/* One record per translation (a block translated twice gets two records; the script adds them). The
 * records are never moved: the inline counters point into them. */
struct block {
    uint64_t pc, insns, runs;
    struct block *next;
};
static struct block *blocks;
static char out_path[4096];
static bool written;

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb) {
    (void)id;
    struct block *b = calloc(1, sizeof *b);
    if (b == NULL) return;
    b->pc = qemu_plugin_tb_vaddr(tb) & ~(uint64_t)1;
    b->insns = qemu_plugin_tb_n_insns(tb);
    b->next = blocks;
    blocks = b;
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &b->runs, 1);
}

static void write_profile(void) {
    if (written || out_path[0] == '\0') return;
    written = true;
    FILE *f = fopen(out_path, "w");
    if (f == NULL) {
        fprintf(stderr, "tbprofile: cannot write %s\n", out_path);
        return;
    }
    for (const struct block *b = blocks; b != NULL; b = b->next)
        if (b->runs != 0) fprintf(f, "%" PRIu64 " %" PRIu64 " %" PRIu64 "\n", b->pc, b->insns, b->runs);
    fclose(f);
}

static void on_exit_cb(qemu_plugin_id_t id, void *userdata) {
    (void)id;
    (void)userdata;
    write_profile();
}

/* A semihosting exit calls exit() directly; the destructor still writes the profile once. */
__attribute__((destructor)) static void on_unload(void) { write_profile(); }

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv) {
    (void)info;
    for (int i = 0; i < argc; ++i) {
        if (strncmp(argv[i], "out=", 4) == 0) {
            snprintf(out_path, sizeof out_path, "%s", argv[i] + 4);
        } else {
            fprintf(stderr, "tbprofile: unknown option '%s' (out=)\n", argv[i]);
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit_cb, NULL);
    return 0;
}

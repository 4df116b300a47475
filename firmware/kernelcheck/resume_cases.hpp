// Random runs of carried set-ups for the band renderer's resumes (raster/band_resume.hpp), shared by the
// kernelcheck firmware and its host twin. Each case is up to kResumeSlots kernel states (cases.hpp's
// make_case(), over one pair of depth and colour rows), a run of them in mesh order from a random subset
// of the slots (the others free), a band end row anywhere around their rows (so some have no row to draw
// and some end in the band) and a limit that stops the run before a record, after it or never.
// run_resume_cases() runs every case through `run` (on the M0+ and RV32 the assembly run) and `twin`
// (resume_carried()) and digests the buffers, the slot lists, the pending triangle and the states a
// later band reads: every field of a record sent onward, the row of one sent back to the free slots (the
// assembly stores no edges for those: they are never read again).
#pragma once
#include <hider/raster/band_resume.hpp>

#include "kernelcheck/cases.hpp"

namespace kernelcheck {

constexpr int kResumeCases = 300;
constexpr uint32_t kResumeSeed = 0x6C8E9CF5u;
constexpr uint8_t kResumeSlots = 6;

/// One case: the slot pool, the slot lists (this band's run at 0, the next band's at kResumeSlots, the
/// free stack at 2 kResumeSlots, as KernelBands lays them out), the run's state and where it draws.
struct ResumeCase {
    hider::KernelTriangle pool[kResumeSlots];
    uint8_t slots[3 * kResumeSlots];
    hider::detail::CarriedSlots cs;
    hider::detail::KernelBandTarget bt;
    uint32_t limit;
    const uint8_t* free_start;  ///< the free stack's top before the run
};

/// The next case of the sequence into c, over buffers b.
inline void make_resume_case(Rng& rng, Buffers& b, ResumeCase& c) {
    const uint32_t used = rng.next() % (kResumeSlots + 1);
    uint16_t tri = static_cast<uint16_t>(rng.range(0, 20));
    for (uint8_t k = 0; k < kResumeSlots; ++k) {
        const Case one = make_case(rng, b);  // the last one's buffers and target are the run's
        c.pool[k] = one.t;
        c.bt.target = one.target;
        c.bt.zrow = one.zrow;
    }
    uint8_t order[kResumeSlots];
    for (uint8_t k = 0; k < kResumeSlots; ++k) order[k] = k;
    for (uint8_t k = kResumeSlots - 1; k > 0; --k) {  // a random order of the slots
        const uint8_t j = static_cast<uint8_t>(rng.next() % (k + 1u));
        const uint8_t s = order[k];
        order[k] = order[j];
        order[j] = s;
    }
    for (uint8_t k = 0; k < 3 * kResumeSlots; ++k) c.slots[k] = 0xEE;
    for (uint32_t k = 0; k < used; ++k) {  // the run, its triangles ascending
        c.slots[k] = order[k];
        c.pool[order[k]].tri = tri;
        tri = static_cast<uint16_t>(tri + rng.range(1, 4));
    }
    uint8_t* const free_base = c.slots + 2 * kResumeSlots;
    for (uint32_t k = used; k < kResumeSlots; ++k) free_base[k - used] = order[k];
    // Records' rows lie in [-5, 5] and end within 8 rows (make_case()): the band ends anywhere from above
    // them to below, so a record may have no row here, end here or continue.
    c.bt.row_end = rng.range(-6, 12);
    const uint32_t pick = rng.next() % 3;
    c.limit = pick == 0 || used == 0 ? 0xFFFFu : pick == 1 ? c.pool[order[rng.next() % used]].tri : rng.next() % 40u;
    c.cs = {c.pool, c.slots, c.slots + used, c.slots + kResumeSlots, free_base + (kResumeSlots - used)};
    c.free_start = c.cs.free_top;
}

/// FNV-1a over the buffers, the pending triangle, the lists and the states the next band reads.
inline uint32_t resume_digest(const Buffers& b, const ResumeCase& c, uint32_t pending) {
    Fnv fnv;
    for (int32_t i = 0; i < kMaxRows * kWidth; ++i) fnv.add(uint32_t{b.depth[i]} | (uint32_t{b.color[i]} << 16));
    fnv.add(pending);
    fnv.add(static_cast<uint32_t>(c.cs.cur - c.slots) | static_cast<uint32_t>(c.cs.nxt - c.slots) << 8 |
            static_cast<uint32_t>(c.cs.free_top - c.slots) << 16);
    for (uint8_t k = 0; k < 3 * kResumeSlots; ++k) fnv.add(c.slots[k]);
    for (const uint8_t* s = c.slots + kResumeSlots; s != c.cs.nxt; ++s) {  // onward: every field
        const hider::KernelTriangle& t = c.pool[*s];
        const hider::RowKernel& k = t.k;
        const uint32_t fields[] = {static_cast<uint32_t>(k.lx), static_cast<uint32_t>(k.lg), k.lz,
                                   static_cast<uint32_t>(k.rx), static_cast<uint32_t>(k.rg), static_cast<uint32_t>(k.la),
                                   static_cast<uint32_t>(k.lm), static_cast<uint32_t>(k.lstep), k.ldz,
                                   static_cast<uint32_t>(k.ra), static_cast<uint32_t>(k.rm), static_cast<uint32_t>(k.rstep),
                                   k.dzdx, k.color, static_cast<uint32_t>(t.row)};
        for (uint32_t f : fields) fnv.add(f);
    }
    for (const uint8_t* s = c.free_start; s != c.cs.free_top; ++s) fnv.add(static_cast<uint32_t>(c.pool[*s].row));
    return fnv.h;
}

/// Digests of every case through `run` and `twin` (functions of (CarriedSlots&, limit, KernelBandTarget&)
/// returning the pending triangle), `run`'s folded into *out (one word: kernelcheck_small's 16 KB);
/// returns the first case whose digests differ, or -1. The case lives on the stack, which the band cases
/// before it need deeper.
template <class Run, class Twin>
int run_resume_cases(Run&& run, Twin&& twin, Buffers& b, uint32_t* out) {
    Rng rng{kResumeSeed};
    int first_difference = -1;
    ResumeCase c;
    Fnv all;
    for (int i = 0; i < kResumeCases; ++i) {
        const Rng at = rng;
        uint32_t digests[2];
        for (int pass = 0; pass < 2; ++pass) {
            rng = at;
            make_resume_case(rng, b, c);
            const uint32_t pending = pass == 0 ? run(c.cs, c.limit, c.bt) : twin(c.cs, c.limit, c.bt);
            digests[pass] = resume_digest(b, c, pending);
        }
        all.add(digests[0]);
        if (digests[0] != digests[1] && first_difference < 0) first_difference = i;
    }
    *out = all.h;
    return first_difference;
}

}  // namespace kernelcheck

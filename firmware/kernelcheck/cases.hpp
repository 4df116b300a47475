// Random row-kernel cases shared by the kernelcheck firmware and its host twin: each case is a
// KernelTriangle state (edges that stay inside a 64-pixel row for its rows, random steps, corrections,
// depths, a middle row anywhere and the lower edge on either side) over depth and colour rows filled with
// random values, drawn in two calls. run_cases() runs every case through `run` and folds the buffers and
// the final states into one 32-bit digest per case. fill_digest()
// covers the frame clear (detail::fill, store-multiples on Cortex-M) the same way.
#pragma once
#include <hider/frame.hpp>
#include <hider/raster/row_kernel.hpp>

namespace kernelcheck {

constexpr int kCases = 600;
constexpr int32_t kWidth = 64;
constexpr int32_t kMaxRows = 9;
constexpr uint32_t kSeed = 0x9E3779B9u;

/// xorshift32: the same sequence on every target.
struct Rng {
    uint32_t s;
    uint32_t next() {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        return s;
    }
    int32_t range(int32_t lo, int32_t hi) { return lo + static_cast<int32_t>(next() % static_cast<uint32_t>(hi - lo + 1)); }
};

/// FNV-1a over 32-bit words, a byte at a time from the least significant: every kernelcheck digest.
struct Fnv {
    uint32_t h = 2166136261u;
    void add(uint32_t v) {
        for (int i = 0; i < 4; ++i) { h ^= (v >> (8 * i)) & 0xFFu; h *= 16777619u; }
    }
};

/// Buffers of one case: depth and colour rows share the stride, colour sits `offset` bytes after depth.
struct Buffers {
    uint16_t depth[kMaxRows * kWidth];
    uint16_t color[kMaxRows * kWidth];
};

/// One kernel case: a triangle's state, its depth row and two calls (rows up to stop1, then up to stop2).
struct Case {
    hider::KernelTriangle t;
    uint16_t* zrow;
    int32_t stop1, stop2;
    hider::KernelTarget target;
};

/// Random edge fields in kernel form: error term biased to [-a, 0) and the per-row step 2 q + stride.
inline void make_edge(Rng& rng, int32_t x_lo, int32_t x_hi, int32_t stride, int32_t& x, int32_t& g, int32_t& a,
                      int32_t& m, int32_t& step) {
    a = rng.range(1, 1 << 19);
    m = static_cast<int32_t>(rng.next() % static_cast<uint32_t>(a));
    g = static_cast<int32_t>(rng.next() % static_cast<uint32_t>(a)) - a;
    if ((rng.next() & 1u) != 0) {  // the boundary the kernels decide with a sign flag: g + m lands on 0
        if ((rng.next() & 1u) != 0) a = rng.range(1, 4);
        g = -rng.range(1, a);
        m = g > -a ? -g : static_cast<int32_t>(rng.next() % static_cast<uint32_t>(a));
    }
    x = 2 * rng.range(x_lo, x_hi);  // kernel bytes: 2 px
    step = 2 * rng.range(-2, 2) + stride;
}

/// The next case of the sequence: fills `b` and returns the case (zrow = the depth array).
inline Case make_case(Rng& rng, Buffers& b) {
    Case cs{};
    hider::KernelTriangle& t = cs.t;
    hider::RowKernel& k = t.k;
    k.lz = rng.next();
    // Half the cases hold depths near the span's own (z >> 16 +- 3): ties, which must keep the stored pixel.
    const bool near = (rng.next() & 1u) != 0;
    for (int32_t i = 0; i < kMaxRows * kWidth; ++i) {
        b.depth[i] = near ? static_cast<uint16_t>((k.lz >> 16) + static_cast<uint32_t>(rng.range(-3, 3)))
                          : static_cast<uint16_t>(rng.next());
        b.color[i] = static_cast<uint16_t>(rng.next());
    }
    cs.target.stride_bytes = kWidth * 2;
    // |q| <= 2 and one correction a row: x moves by -3 .. +2 pixels a row, so over at most 7 steps a left
    // edge from [21, 38] stays >= 0 and a right edge from [20, 50] <= 64: every pixel touched is in the row.
    make_edge(rng, 21, 38, cs.target.stride_bytes, k.lx, k.lg, k.la, k.lm, k.lstep);
    make_edge(rng, 20, 50, cs.target.stride_bytes, k.rx, k.rg, k.ra, k.rm, k.rstep);
    k.dzdx = rng.next() >> rng.range(8, 31);
    k.ldz = near ? rng.next() >> rng.range(12, 31) : rng.next();
    k.color = rng.next() & 0xFFFFu;
    // Rows: the middle row before, inside or after them; the lower short edge on either side. Two calls
    // stop anywhere, the first perhaps on the middle row (the second then starts there).
    t.row = static_cast<int16_t>(rng.range(-5, 5));
    t.end = static_cast<int16_t>(t.row + rng.range(1, kMaxRows - 1));
    t.mid = static_cast<int16_t>(rng.range(t.row - 2, t.end + 2));
    t.next_left = (rng.next() & 1u) != 0;
    make_edge(rng, t.next_left ? 21 : 20, t.next_left ? 38 : 50, cs.target.stride_bytes, t.next_x, t.next_g, t.next_a,
              t.next_m, t.next_step);
    cs.stop1 = rng.range(t.row - 1, t.end + 1);
    if ((rng.next() & 3u) == 0 && t.row < t.mid && t.mid < t.end) cs.stop1 = t.mid;
    cs.stop2 = rng.range(cs.stop1, t.end + 2);
    // Every other case swaps the two arrays' roles, so the colour sits before the depth (negative offset).
    const bool swapped = (rng.next() & 1u) != 0;
    uint16_t* const depth = swapped ? b.color : b.depth;
    uint16_t* const color = swapped ? b.depth : b.color;
    if (near && swapped) {  // the tie-heavy depths belong in whichever array is the depth buffer
        for (int32_t i = 0; i < kMaxRows * kWidth; ++i) {
            const uint16_t v = depth[i];
            depth[i] = color[i];
            color[i] = v;
        }
    }
    cs.zrow = depth;
    cs.target.color_offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(color) - reinterpret_cast<uintptr_t>(depth));
    return cs;
}

/// FNV-1a over the buffers, the final state and the depth rows each call returned (as row counts from
/// the first, so the digest is address-free).
inline uint32_t digest(const Buffers& b, const Case& cs, const uint16_t* first_row, const uint16_t* after1,
                       const uint16_t* after2) {
    Fnv fnv;
    for (int32_t i = 0; i < kMaxRows * kWidth; ++i) fnv.add(uint32_t{b.depth[i]} | (uint32_t{b.color[i]} << 16));
    const hider::RowKernel& k = cs.t.k;
    const uint32_t fields[] = {static_cast<uint32_t>(k.lx), static_cast<uint32_t>(k.lg), k.lz,
                               static_cast<uint32_t>(k.rx), static_cast<uint32_t>(k.rg), static_cast<uint32_t>(k.la),
                               static_cast<uint32_t>(k.lm), static_cast<uint32_t>(k.lstep), k.ldz,
                               static_cast<uint32_t>(k.ra), static_cast<uint32_t>(k.rm), static_cast<uint32_t>(k.rstep),
                               static_cast<uint32_t>(cs.t.row)};
    for (uint32_t f : fields) fnv.add(f);
    const intptr_t stride = cs.target.stride_bytes;
    fnv.add(static_cast<uint32_t>((reinterpret_cast<intptr_t>(after1) - reinterpret_cast<intptr_t>(first_row)) / stride));
    fnv.add(static_cast<uint32_t>((reinterpret_cast<intptr_t>(after2) - reinterpret_cast<intptr_t>(first_row)) / stride));
    return fnv.h;
}

/// Digest of every case run through `run` (a function of (KernelTriangle&, zrow, row_stop, KernelTarget)
/// returning the depth row of the row it stopped on), into out[kCases]. With `twin`, each case is made
/// again and run through the twin too; returns the first case whose digests differ, or -1.
template <class Run, class Twin>
int run_cases(Run&& run, Twin&& twin, Buffers& b, uint32_t* out) {
    Rng rng{kSeed};
    int first_difference = -1;
    for (int c = 0; c < kCases; ++c) {
        const Rng at = rng;
        uint32_t digests[2];
        for (int pass = 0; pass < 2; ++pass) {
            rng = at;
            Case cs = make_case(rng, b);
            uint16_t* after1 = nullptr;
            uint16_t* after2 = nullptr;
            if (pass == 0) {
                after1 = run(cs.t, cs.zrow, cs.stop1, cs.target);
                after2 = run(cs.t, after1, cs.stop2, cs.target);
            } else {
                after1 = twin(cs.t, cs.zrow, cs.stop1, cs.target);
                after2 = twin(cs.t, after1, cs.stop2, cs.target);
            }
            digests[pass] = digest(b, cs, cs.zrow, after1, after2);
        }
        out[c] = digests[0];
        if (digests[0] != digests[1] && first_difference < 0) first_difference = c;
    }
    return first_difference;
}

/// Longest fill tried: two of the ARMv7-M clear's 96-word blocks, four of the ARMv6-M clear's 56-word
/// blocks and of RV32's 64-word ones, with remainders, so every loop and every remainder runs.
constexpr uint32_t kFillMax = 520;

/// One digest of `fill` over every length 0..kFillMax from an odd and an even 16-bit element, each
/// with guard elements on both sides (an overrun or a missed element changes it).
template <class Fill>
uint32_t fill_digest(Fill&& fill, Buffers& b) {
    static_assert(kFillMax + 6 <= kMaxRows * kWidth, "fill cases fit the buffer");
    uint32_t h = 2166136261u;
    // A 4-byte-aligned base, so the two starts are one word-aligned and one not on every target.
    uint16_t* const base = b.depth + ((reinterpret_cast<uintptr_t>(b.depth) & 2u) != 0 ? 1 : 0);
    for (uint32_t start = 1; start <= 2; ++start)
        for (uint32_t n = 0; n <= kFillMax; ++n) {
            for (uint32_t i = 0; i < n + 4; ++i) base[i] = static_cast<uint16_t>(0xA5A5u ^ (i * 257u));
            fill(base + start, n, static_cast<uint16_t>(0x1234u + n));
            for (uint32_t i = 0; i < n + 4; ++i) {
                h ^= base[i];
                h *= 16777619u;
            }
        }
    return h;
}

/// The plain loop the clear must equal.
inline void fill_plain(uint16_t* p, uint32_t n, uint16_t v) {
    for (uint32_t i = 0; i < n; ++i) p[i] = v;
}

}  // namespace kernelcheck

// Random row-kernel cases shared by the kernelcheck firmware and its host twin: each case is a
// RowKernel state (edges that stay inside a 64-pixel row for its rows, random steps, corrections and
// depths) over depth and colour rows filled with random values. run_cases() runs every case through
// `run` and folds the buffers and the final states into one 32-bit digest per case. fill_digest()
// covers the frame clear (detail::fill, store-multiples on Cortex-M) the same way.
#pragma once
#include <hider/frame.hpp>
#include <hider/raster/row_kernel.hpp>

namespace kernelcheck {

constexpr int kCases = 400;
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

/// Buffers of one case: depth and colour rows share the stride, colour sits `offset` bytes after depth.
struct Buffers {
    uint16_t depth[kMaxRows * kWidth];
    uint16_t color[kMaxRows * kWidth];
};

/// One kernel call: the state and the call's arguments.
struct Case {
    hider::RowKernel k;
    uint16_t* zrow;
    int32_t rows;
    intptr_t color_offset;
};

/// The next case of the sequence: fills `b` and returns the call (zrow = the depth array).
inline Case make_case(Rng& rng, Buffers& b) {
    Case cs{};
    hider::RowKernel& k = cs.k;
    k.lz = rng.next();
    // Half the cases hold depths near the span's own (z >> 16 +- 3): ties, which must keep the stored pixel.
    const bool near = (rng.next() & 1u) != 0;
    for (int32_t i = 0; i < kMaxRows * kWidth; ++i) {
        b.depth[i] = near ? static_cast<uint16_t>((k.lz >> 16) + static_cast<uint32_t>(rng.range(-3, 3)))
                          : static_cast<uint16_t>(rng.next());
        b.color[i] = static_cast<uint16_t>(rng.next());
    }
    cs.rows = rng.range(1, kMaxRows - 1);
    // |q| <= 2 and one correction a row: px moves by -3 .. +2 a row, so over at most 7 steps a left edge
    // from [21, 38] stays >= 0 and a right edge from [20, 50] <= 64: every pixel touched is in the row.
    k.la = rng.range(1, 1 << 19);
    k.lm = static_cast<int32_t>(rng.next() % static_cast<uint32_t>(k.la));
    k.lg = static_cast<int32_t>(rng.next() % static_cast<uint32_t>(k.la)) - k.la;  // biased: [-a, 0)
    const int32_t lq = rng.range(-2, 2);
    k.lx = 2 * rng.range(21, 38);  // kernel bytes: 2 px
    k.ra = rng.range(1, 1 << 19);
    k.rm = static_cast<int32_t>(rng.next() % static_cast<uint32_t>(k.ra));
    k.rg = static_cast<int32_t>(rng.next() % static_cast<uint32_t>(k.ra)) - k.ra;
    // Every other case puts both edges on the boundary the kernels decide with a sign flag: small a
    // (g + m often lands on exactly 0, which must take the extra step) or m = -g for the first row.
    if ((rng.next() & 1u) != 0) {
        const bool tiny = (rng.next() & 1u) != 0;
        int32_t* const fields[2][3] = {{&k.la, &k.lm, &k.lg}, {&k.ra, &k.rm, &k.rg}};
        for (auto& f : fields) {
            int32_t& a = *f[0];
            int32_t& m = *f[1];
            int32_t& g = *f[2];
            if (tiny) a = rng.range(1, 4);
            g = -rng.range(1, a);                                         // [-a, -1]
            m = g > -a ? -g : static_cast<int32_t>(rng.next() % static_cast<uint32_t>(a));  // in [0, a)
        }
    }
    const int32_t rq = rng.range(-2, 2);
    k.rx = 2 * rng.range(20, 50);  // empty, one-pixel and long spans
    k.dzdx = rng.next() >> rng.range(8, 31);
    k.ldz = near ? rng.next() >> rng.range(12, 31) : rng.next();
    k.stride_bytes = kWidth * 2;
    k.lstep = 2 * lq + k.stride_bytes;  // kernel bytes: 2 q + stride
    k.rstep = 2 * rq + k.stride_bytes;
    // Every other case swaps the two arrays' roles, so the colour sits before the depth (negative offset).
    const bool swapped = (rng.next() & 1u) != 0;
    uint16_t* const depth = swapped ? b.color : b.depth;
    uint16_t* const color = swapped ? b.depth : b.color;
    if (near && swapped) {  // the tie-heavy depths belong in whichever array is the depth buffer
        for (int32_t i = 0; i < kMaxRows * kWidth; ++i) {
            const uint16_t t = depth[i];
            depth[i] = color[i];
            color[i] = t;
        }
    }
    cs.zrow = depth;
    cs.color_offset = static_cast<intptr_t>(reinterpret_cast<uintptr_t>(color) - reinterpret_cast<uintptr_t>(depth));
    k.color = rng.next() & 0xFFFFu;
    return cs;
}

/// FNV-1a over the buffers and the final edge state (the returned zrow as a row count, so the digest is
/// address-free).
inline uint32_t digest(const Buffers& b, const hider::RowKernel& k, const uint16_t* zrow) {
    uint32_t h = 2166136261u;
    auto add = [&h](uint32_t v) {
        for (int i = 0; i < 4; ++i) { h ^= (v >> (8 * i)) & 0xFFu; h *= 16777619u; }
    };
    for (int32_t i = 0; i < kMaxRows * kWidth; ++i) add(uint32_t{b.depth[i]} | (uint32_t{b.color[i]} << 16));
    const uintptr_t base = reinterpret_cast<uintptr_t>(zrow) >= reinterpret_cast<uintptr_t>(b.color) &&
                                   reinterpret_cast<uintptr_t>(zrow) <= reinterpret_cast<uintptr_t>(b.color + kMaxRows * kWidth)
                               ? reinterpret_cast<uintptr_t>(b.color)
                               : reinterpret_cast<uintptr_t>(b.depth);
    const uint32_t rows_done = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(zrow) - base) /
                               static_cast<uint32_t>(k.stride_bytes);
    const uint32_t fields[] = {static_cast<uint32_t>(k.lx), static_cast<uint32_t>(k.lg), k.lz,
                               static_cast<uint32_t>(k.rx), static_cast<uint32_t>(k.rg), rows_done};
    for (uint32_t f : fields) add(f);
    return h;
}

/// Digest of every case run through `run` (a function of RowKernel&, zrow, rows, colour offset that
/// returns the next zrow), into out[kCases].
template <class Run>
void run_cases(Run&& run, Buffers& b, uint32_t* out) {
    Rng rng{kSeed};
    for (int c = 0; c < kCases; ++c) {
        Case cs = make_case(rng, b);
        const uint16_t* const next = run(cs.k, cs.zrow, cs.rows, cs.color_offset);
        out[c] = digest(b, cs.k, next);
    }
}

/// Longest fill tried: more than three of the ARMv7-M clear's 20-word blocks and five of the ARMv6-M
/// clear's 12-word blocks, so every loop and every remainder runs.
constexpr uint32_t kFillMax = 130;

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

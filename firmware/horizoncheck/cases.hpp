// Random cases for the floating horizon's hot loops, shared by the horizoncheck firmware and its host
// twin: rows for the two row passes and the level pass (heights, bases, steps and knots inside the
// ranges project.hpp guarantees), and curves with horizons for the walk kernel (dense points, steps it
// hands back, visible and hidden columns, points outside the frame). Each case folds its outputs (points,
// queued columns, final state, results) into one 32-bit digest, so the Thumb-1 loops (ARMv6-M) can be
// compared with their portable twins on the device and every target with the host.
#pragma once
#include <hider/horizon/horizon.hpp>
#include <hider/horizon/level_pass.hpp>
#include <hider/horizon/row_pass.hpp>
#include <hider/horizon/walk_kernel.hpp>

namespace horizoncheck {

constexpr int kCases = 300;   ///< of each kind
constexpr int kPoints = 64;   ///< at most, per case
constexpr int kWidth = 96;    ///< walk cases: columns with horizons

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

/// FNV-1a over 32-bit words.
struct Digest {
    uint32_t h = 2166136261u;
    void add(uint32_t v) {
        for (int i = 0; i < 4; ++i) h = (h ^ ((v >> (8 * i)) & 255u)) * 16777619u;
    }
};

struct Buffers {
    uint8_t values[kPoints];
    hider::horizon::PlotPoint points[kPoints];
    hider::horizon::LevelKnot knots[hider::horizon::kLevelKnots];
    int16_t upper[kWidth], lower[kWidth];
    int32_t runs[3 * 8];  // a short queue, so it fills
};

/// Row-pass case: W' in [2^27, 2^30) over the row (up to 2 normalisation steps), |U|, |V| < 2^28.
inline hider::horizon::RowPass row_case(Rng& rng, Buffers& b) {
    const int n = rng.range(1, kPoints);
    for (int i = 0; i < n; ++i) b.values[i] = static_cast<uint8_t>(rng.next());
    hider::horizon::RowPass p{};
    p.values = b.values;
    p.out = b.points;
    p.out_end = b.points + n;
    p.w = rng.range(1 << 27, (1 << 29) + (1 << 28));
    p.dw = rng.range(-(1 << 14), 1 << 14);
    p.hw = rng.range(-(1 << 15), 1 << 15);
    p.s0 = rng.range(3, 28);
    p.table = reinterpret_cast<uintptr_t>(hider::horizon::detail::kRecip.v) - 1024;
    p.u = rng.range(-(1 << 27), 1 << 27);
    p.du = rng.range(-(1 << 17), 1 << 17);
    p.hu = rng.range(-(1 << 17), 1 << 17);
    p.v = rng.range(-(1 << 27), 1 << 27);
    p.dv = rng.range(-(1 << 17), 1 << 17);
    p.hv = rng.range(-(1 << 17), 1 << 17);
    p.dvu = rng.range(-2, 2);
    return p;
}

/// Level-pass case: knots from r in [2^15, 2^16] and |Y| < 2^14, as project.hpp builds them.
inline hider::horizon::LevelPass level_case(Rng& rng, Buffers& b) {
    using namespace hider::horizon;
    const int n = rng.range(1, kPoints);
    for (int i = 0; i < n; ++i) b.values[i] = static_cast<uint8_t>(rng.next());
    int32_t r[kLevelKnots], y[kLevelKnots];
    for (int j = 0; j < kLevelKnots; ++j) {
        r[j] = rng.range(1 << 15, 1 << 16);
        y[j] = rng.range(-(1 << 14), 1 << 14);
    }
    for (int j = 0; j < kLevelKnots; ++j) {
        const int32_t dr = j + 1 < kLevelKnots ? r[j + 1] - r[j] : 0, dy = j + 1 < kLevelKnots ? y[j + 1] - y[j] : 0;
        b.knots[j] = {(r[j] - j * dr) << kLevelKnotBits, dr, (y[j] - j * dy) << kLevelKnotBits, dy};
    }
    LevelPass p{};
    p.values = b.values;
    p.out = b.points;
    p.out_end = b.points + n;
    p.knots = b.knots;
    p.u = rng.range(-(1 << 27), 1 << 27);
    p.du = rng.range(-(1 << 17), 1 << 17);
    p.hu = rng.range(-(1 << 17), 1 << 17);
    p.s = rng.range(7, 31);
    return p;
}

/// Walk case: horizons with gaps, and a curve of mostly short steps (some long, some back, some outside
/// the columns), |y| < 2^15.
inline hider::horizon::WalkKernel walk_case(Rng& rng, Buffers& b) {
    for (int c = 0; c < kWidth; ++c) {
        const int16_t a = static_cast<int16_t>(rng.range(-1, 40)), d = static_cast<int16_t>(rng.range(-1, 40));
        b.upper[c] = rng.range(0, 9) == 0 ? INT16_MAX : (a < d ? a : d);
        b.lower[c] = b.upper[c] == INT16_MAX ? INT16_MIN : (a < d ? d : a);
    }
    const int n = rng.range(2, kPoints);
    int32_t x = rng.range(-40, kWidth * 16 + 40), y = rng.range(-40, 40 * 16);
    for (int i = 0; i < n; ++i) {
        b.points[i] = {x, y};
        const int k = rng.range(0, 15);
        x += k == 0 ? rng.range(-300, 300) : (k == 1 ? 0 : rng.range(1, 20));
        y += k == 1 ? rng.range(-400, 400) : rng.range(-40, 40);
        y = y < -30000 ? -30000 : (y > 30000 ? 30000 : y);
    }
    hider::horizon::WalkKernel k{};
    k.p = b.points + 1;
    k.end = b.points + n;
    k.col = b.points[0].x >> 4;
    k.ymin = k.ymax = b.points[0].y;
    k.upper = b.upper;
    k.lower = b.lower;
    k.width = kWidth;
    k.slope = hider::horizon::detail::kSlope.v;
    k.runs = b.runs;
    k.runs_end = b.runs + 3 * 8;
    return k;
}

/// The digests of kCases cases of each kind: row passes, level pass, walk. `rows(p)` runs both row
/// passes, `level(p)` the level pass, `walk(k)` the walk kernel once (returns its WalkResult).
template <class Rows, class Level, class Walk>
void run_cases(Rows rows, Level level, Walk walk, Buffers& b, uint32_t* digests) {
    Rng rng{0x6A09E667u};
    for (int c = 0; c < kCases; ++c) {
        const hider::horizon::RowPass p = row_case(rng, b);
        rows(p);
        Digest d;
        for (const hider::horizon::PlotPoint* o = p.out; o != p.out_end; ++o) {
            d.add(static_cast<uint32_t>(o->x));
            d.add(static_cast<uint32_t>(o->y));
        }
        digests[c] = d.h;
    }
    for (int c = 0; c < kCases; ++c) {
        const hider::horizon::LevelPass p = level_case(rng, b);
        level(p);
        Digest d;
        for (const hider::horizon::PlotPoint* o = p.out; o != p.out_end; ++o) {
            d.add(static_cast<uint32_t>(o->x));
            d.add(static_cast<uint32_t>(o->y));
        }
        digests[kCases + c] = d.h;
    }
    for (int c = 0; c < kCases; ++c) {
        hider::horizon::WalkKernel k = walk_case(rng, b);
        Digest d;
        for (;;) {  // queued runs, results and states; a step handed back is taken as a restart there
            const int r = walk(k);
            for (const int32_t* q = b.runs; q != k.runs; ++q) d.add(static_cast<uint32_t>(*q));
            k.runs = b.runs;
            d.add(static_cast<uint32_t>(r));
            d.add(static_cast<uint32_t>(k.col));
            d.add(static_cast<uint32_t>(k.ymin));
            d.add(static_cast<uint32_t>(k.ymax));
            d.add(static_cast<uint32_t>(k.p - b.points));
            if (r == hider::horizon::kWalkDone) break;
            if (r == hider::horizon::kWalkCross) {
                k.col = k.p->x >> 4;
                k.ymin = k.ymax = k.p->y;
                ++k.p;
            }
        }
        digests[2 * kCases + c] = d.h;
    }
}

}  // namespace horizoncheck

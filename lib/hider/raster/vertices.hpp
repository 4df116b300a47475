// Per-frame vertex projection of a mesh: each position to view space, its clip code, and the projected
// ScreenVertex (or the planes it lies outside of), into a caller array indexed like the positions.
#pragma once
#include <hider/raster/clip.hpp>
#include <hider/raster/vertices_v6m.hpp>
#include <hider/raster/vertices_v7m.hpp>

namespace hider {

namespace detail {
/// clz32(v) for v != 0 without a CLZ instruction or a library call: the bits below the top one set,
/// then a de Bruijn multiply and a 32-entry table (Bit Twiddling Hacks).
inline constexpr uint8_t kTopBitDeBruijn[32] = {0,  9,  1,  10, 13, 21, 2,  29, 11, 14, 16, 18, 22, 25, 3, 30,
                                                8,  12, 20, 28, 15, 17, 24, 7,  19, 27, 23, 6,  26, 5,  4, 31};
constexpr int leading_zeros_smeared(uint32_t v) {
    v |= v >> 1;
    v |= v >> 2;
    v |= v >> 4;
    v |= v >> 8;
    v |= v >> 16;
    return 31 - kTopBitDeBruijn[(v * 0x07C4ACDDu) >> 27];
}

/// clz32(v) for v != 0: on RISC-V without Zbb leading_zeros_smeared() (libgcc's __clzsi2 and the spills
/// around the call cost more), else the instruction.
__attribute__((always_inline)) inline int leading_zeros(uint32_t v) {
#if defined(__riscv) && !defined(__riscv_zbb)
    return leading_zeros_smeared(v);
#else
    return clz32(v);
#endif
}

/// floor(n 2^31 / w) for 0 < n < w, given s = clz32(w): udiv64_32() for this numerator (normalised
/// divisor, two 16-bit quotient digits, each one 32-bit division and at most two corrections), without
/// the call.
__attribute__((always_inline)) constexpr uint32_t ratio_q31(uint32_t n, uint32_t w, int s) {
    const uint32_t v = w << s, vn1 = v >> 16, vn0 = v & 0xFFFFu;
    const uint32_t nn = n << s;  // below v
    const uint32_t un32 = nn >> 1, un1 = (nn & 1u) << 15;  // nn 2^31 = un32 2^32 + un1 2^16
    uint32_t q1 = un32 / vn1, rhat = un32 - q1 * vn1;
    while (q1 > 0xFFFFu || q1 * vn0 > ((rhat << 16) | un1)) {
        --q1;
        rhat += vn1;
        if (rhat > 0xFFFFu) break;
    }
    const uint32_t un21 = (un32 << 16) + un1 - q1 * v;
    uint32_t q0 = un21 / vn1;
    rhat = un21 - q0 * vn1;
    while (q0 > 0xFFFFu || q0 * vn0 > (rhat << 16)) {
        --q0;
        rhat += vn1;
        if (rhat > 0xFFFFu) break;
    }
    return (q1 << 16) | q0;
}

/// project() of a view point inside the view volume (outcode() == 0) with w < 2^30, for targets that
/// divide 32 bits in one instruction. Inside the guard band a screen quotient is at most kGuardBand
/// (no clamp) and below 2^15, so div_small_quotient()'s method applies without its test, both
/// coordinates sharing w's top 16 bits as divisor; u = n / w is ratio_q31(). Writes the vertex and
/// returns true; false (out untouched) for any other point.
__attribute__((always_inline)) inline bool project_common(const View& v, const ViewPoint& p, ScreenVertex& out) {
    const int32_t w = p.w;
    if (w < v.near_raw || w > v.far_raw || w >= (int32_t{1} << 30)) return false;
    const int64_t xk = mul_wide(p.x, v.k_q8), yk = mul_wide(p.y, v.k_q8);
    const uint64_t ax = xk < 0 ? 0 - static_cast<uint64_t>(xk) : static_cast<uint64_t>(xk);
    const uint64_t ay = yk < 0 ? 0 - static_cast<uint64_t>(yk) : static_cast<uint64_t>(yk);
    const uint32_t uw = static_cast<uint32_t>(w);
    const uint64_t guard = mul_wide_u(uw, kGuardBand * 256);
    if (ax > guard || ay > guard) return false;
    // m = floor((|n| + 128 w) / 256) < w 2^15; m >> s over W = ceil(w / 2^s) (w's top 16 bits, rounded
    // up, at least 2^15 when s > 0) is the quotient q or one less: it is at least q - (q + 1) / (W + 1)
    // - 1 and q <= kGuardBand < 2^14. The remainder m - e w < 2 w fits the low words.
    const int leading = leading_zeros(uw);
    const int s = leading > 16 ? 0 : 16 - leading;
    const uint32_t wd = ((uw - 1) >> s) + 1;
    const int t = s + 8;  // m >> s = sum >> t, 8 <= t <= 22: two words
    auto quotient = [&](uint64_t a) __attribute__((always_inline)) {
        const uint64_t sum = a + (uint64_t{uw} << 7);
        const uint32_t lo = static_cast<uint32_t>(sum), hi = static_cast<uint32_t>(sum >> 32);
        uint32_t e = ((lo >> t) | (hi << (32 - t))) / wd;
        const uint32_t r = ((lo >> 8) | (hi << 24)) - e * uw;
        if (r >= uw) ++e;
        return static_cast<int32_t>(e);
    };
    const int32_t qx = quotient(ax), qy = quotient(ay);
    uint32_t u = uint32_t{1} << 31;
    if (w > v.near_raw) u = ratio_q31(static_cast<uint32_t>(v.near_raw), uw, leading);  // at least n / f: w <= f
    const uint32_t z = kDepthNear + static_cast<uint32_t>(
        (mul_u32_u64((uint32_t{1} << 31) - u, v.depth_scale_q31) + (uint64_t{1} << 30)) >> 31);
    out.x = static_cast<int16_t>(xk < 0 ? -qx : qx);
    out.y = static_cast<int16_t>(yk < 0 ? qy : -qy);  // project() divides -y k
    out.z = z;  // at most kDepthFar: the scale is rounded down and 2^31 - u <= 2^31 - n / f
    return true;
}


/// One position the general way: its clip codes, then project() or the planes it lies outside of.
inline void project_one(const View& view, const ViewPoint& p, ScreenVertex& o) {
    const ScaledXY xy = scaled_xy(view, p);
    const uint8_t code = outcode(view, p, xy);
    if (code != 0) {
        o.mark_outside(code);
        return;
    }
    const ScreenVertex s = project(view, p, xy);
    o.x = s.x;  // field by field: a whole-struct copy became a 9-byte memcpy call on ARMv6-M
    o.y = s.y;
    o.z = s.z;
}
}  // namespace detail

namespace detail {
/// The assembly vertex loops' driver: `loop` projects positions until one it refuses (outside its
/// volume), which goes the general way through `to_view` (the View or a PreparedTransform of it).
template <class Prep, class Loop, class ToView>
__attribute__((always_inline)) inline void project_by_loop(const View& view, const Prep& prep, Loop loop, const ToView& to_view,
                                                           Span<const Vec3q16> positions, ScreenVertex* out) {
    const Vec3q16* const first = positions.data();
    const Vec3q16* const end = first + positions.size();
    for (const Vec3q16* p = first; p != end; ++p) {
        p = loop(&prep, p, out + (p - first), end);
        if (p == end) break;
        project_one(view, to_view_point(to_view, *p), out[p - first]);
    }
}

#if defined(HIDER_ARMV6M) || defined(HIDER_ARMV7M)
/// project_vertices() through the chip's assembly loop. Out of line: the loop's constants stay off the
/// caller's frame, which a band renderer keeps through the frame.
__attribute__((noinline)) inline void project_all(const View& view, Span<const Vec3q16> positions, ScreenVertex* out) {
#if defined(HIDER_ARMV6M)
    project_by_loop(view, vertex_prep(view), project_common_v6m, PreparedTransform(view.to_view), positions, out);
#else
    project_by_loop(view, vertex_prep_v7m(view), project_common_v7m, view, positions, out);
#endif
}
#endif
}  // namespace detail

namespace detail {
/// check_view_range() for project_vertices(); where it fails, every vertex is marked outside the near
/// plane and the depth range left empty. Out of line, so that the callers' frames (a band renderer's
/// lives through the frame) and their inlining stay as they were.
__attribute__((noinline)) inline Status check_placement(const View& view, Span<const Vec3q16> positions,
                                                       Span<ScreenVertex> out, DepthRange* range) {
    const Status s = check_view_range(view.to_view, positions);
    if (s != Status::ok) {
        for (size_t i = 0; i < positions.size(); ++i) out[i].mark_outside(kClipNear);
        if (range != nullptr) *range = DepthRange{};
    }
    return s;
}
}  // namespace detail

/// Transforms and projects every position into `out` (same index); vertices outside a clip plane are
/// marked (ScreenVertex::outside()) and clipped per triangle later. Returns invalid_argument if out is
/// too small, and check_view_range()'s errors (view.hpp: a model transform, with_model(), that puts a
/// position where its view coordinates wrap), with every vertex then marked outside the near plane, so
/// that nothing of the mesh draws. Precondition: validate(mesh) == ok. Cost per vertex: the transform
/// (nine 32x32->64 products, or 36 32-bit multiplies on ARMv6-M), clip codes, and three quotients by w
/// (one reciprocal on ARMv6-M; where the CPU divides, project_common(): one 32-bit division for each
/// screen coordinate and two for n / w).
inline Status project_vertices(const View& view, Span<const Vec3q16> positions, Span<ScreenVertex> out,
                               DepthRange* range = nullptr) {
    if (out.size() < positions.size()) return Status::invalid_argument;
#if defined(HIDER_ARMV6M) || defined(HIDER_ARMV7M)
    // Checked first on ARM: ARMv6-M's 32-bit transform must not meet a coordinate that overflows.
    const Status placed = detail::check_placement(view, positions, out, range);
    if (placed != Status::ok) return placed;
    detail::project_all(view, positions, out.data());
#else
    const PreparedTransform to_view(view.to_view);
    for (size_t i = 0; i < positions.size(); ++i) {
        if constexpr (kSlow64BitDivide && kHardwareDivide32) {  // the transform inline, then the common case
            const Vec3q16 q = apply_inline(view.to_view, positions[i]);
            const ViewPoint p{q.x.raw(), q.y.raw(), negate_wrapping(q.z.raw())};
            if (!detail::project_common(view, p, out[i])) detail::project_one(view, p, out[i]);
        } else {
            detail::project_one(view, to_view_point(to_view, positions[i]), out[i]);
        }
    }
#endif
    if (range != nullptr) {  // a second pass, so frames without depth shading do not pay for it
        DepthRange r;
        for (size_t i = 0; i < positions.size(); ++i) {
            const uint32_t z = out[i].z;
            if (z == 0) continue;  // outside a clip plane
            r.min = min(r.min, z);
            r.max = max(r.max, z);
        }
        *range = r;
    }
#if defined(HIDER_ARMV6M) || defined(HIDER_ARMV7M)
    return Status::ok;  // checked before the loop
#else
    // Checked last elsewhere: apply() wraps here without overflow (64-bit sums, unsigned adds, z negated
    // modulo 2^32), and the loop above keeps the registers it had without the call before it.
    return detail::check_placement(view, positions, out, range);
#endif
}

/// project_vertices() for one position, with the view transform prepared once by the caller: the same
/// ScreenVertex (or outside mark) for the same view. For walks that project only what they draw.
inline void project_vertex(const View& view, const PreparedTransform& to_view, const Vec3q16& position, ScreenVertex& out) {
    const ViewPoint p = to_view_point(to_view, position);
    if constexpr (kSlow64BitDivide && kHardwareDivide32) {  // the common case as project_vertices() takes it
        if (detail::project_common(view, p, out)) return;
    }
    detail::project_one(view, p, out);
}

/// project_vertex() for one view and many single positions, prepared once: on ARMv7-M each position goes
/// through the assembly vertex loop (project_vertices()'s, one position a call), the rare ones it refuses
/// the general way. For walks that project only what they draw (draw_bsp()); same vertices as
/// project_vertex().
class VertexProjector {
public:
    explicit VertexProjector(const View& view)
        : view_(view), to_view_(view.to_view)
#if defined(HIDER_ARMV7M)
          , prep_(detail::vertex_prep_v7m(view))
#endif
    {
    }
    /// Out of line: a walk's loop keeps its registers around the call.
    __attribute__((noinline)) void operator()(const Vec3q16& position, ScreenVertex& out) const {
#if defined(HIDER_ARMV7M)
        if (project_common_v7m(&prep_, &position, &out, &position + 1) != &position + 1)
            detail::project_one(view_, to_view_point(to_view_, position), out);
#else
        project_vertex(view_, to_view_, position, out);
#endif
    }

private:
    const View& view_;
    PreparedTransform to_view_;
#if defined(HIDER_ARMV7M)
    detail::VertexPrepV7m prep_;
#endif
};

/// Marks every vertex as not projected yet (x = z = 0, which project_vertex() never gives: a drawable
/// vertex has z != 0, an outside one x != 0), for a walk that projects on first use (draw_bsp()): once
/// per frame, before the first band. All of each vertex goes to zero, two words at a time (fill_words()).
inline void mark_unprojected(Span<ScreenVertex> verts) {
    static_assert(sizeof(ScreenVertex) == 8 && alignof(ScreenVertex) == 4, "two whole words per vertex");
    fill_words(verts.data(), 2 * verts.size(), 0);
}

/// True for a vertex mark_unprojected() left alone.
constexpr bool unprojected(const ScreenVertex& v) { return v.z == 0 && v.x == 0; }

}  // namespace hider

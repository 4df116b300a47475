// Triangle setup and exact row traversal. Screen coordinates are integers in 1/16 pixel, relative to
// the frame centre (see CONVENTIONS.md); pixels are sampled at their centres with the top-left rule.
// Coverage uses Pineda edge functions evaluated exactly in int32; each row's span ends are found by
// stepping the two active edges as exact DDAs (no division per row). Depth is the plane through the three vertices,
// stepped by dz/dx per pixel and dz/dy per row (Giesen, "Triangle rasterization in practice").
#pragma once
#include <hider/raster/edge.hpp>
#include <hider/raster/plane.hpp>
#include <hider/raster/screen.hpp>

namespace hider {

namespace detail {
/// Row functor of TriangleRaster::spans() and PieceRaster::spans() (piece.hpp): hands non-empty spans
/// to fn(y, x0, x1, z); counts fragments.
template <class T> struct NoRef { using type = T; };
template <class T> struct NoRef<T&> { using type = T; };
template <class Fn>
struct SpanAdapter {
    static constexpr bool kCountFragments = true;
    static constexpr bool kRowKernel = false;
    typename NoRef<Fn>::type* f;  // spans() takes Fn&&: Fn is a reference type for an lvalue functor
    int32_t y;
    void begin(int32_t first) { y = first; }
    void operator()(int32_t x0, int32_t x1, uint32_t z) {
        if (x0 < x1) (*f)(y, x0, x1, z);
        ++y;
    }
};
}  // namespace detail

/// One triangle set up for traversal. setup() once; then spans(y_begin, y_end, fn) any number of
/// times for any row ranges (bands) with identical results per row.
class TriangleRaster {
public:
    /// Twice the signed area in subpixels^2 of (a, b, c); < 0 means counter-clockwise on the image.
    __attribute__((always_inline)) static constexpr int32_t signed_area(const ScreenVertex& a, const ScreenVertex& b,
                                                                        const ScreenVertex& c) {
        return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    }

    /// Prepares (a, b, c) for a width x height frame. Returns false for zero area. Both windings are
    /// accepted; front() tells which one it was. Cost: two 64-bit divisions (on 32-bit targets one
    /// 64/32 division for a reciprocal of the area, then multiplies).
    bool setup(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t width, int32_t height) {
        return setup(a, b, c, signed_area(a, b, c), width, height);
    }
    /// setup() with the caller's signed_area(a, b, c).
    bool setup(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t area, int32_t width,
               int32_t height) {
        return setup_impl<false, true>(a, b, c, area, width, height, nullptr);
    }
    /// setup() for one band: also false, before the depth plane (the divisions), when no pixel centre
    /// of the band lies in the triangle's bounding box (misses_band); nothing is drawn then.
    __attribute__((always_inline)) bool setup(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                              int32_t area, int32_t width, int32_t height,
                                              const BandBounds& band) {
        return setup_impl<true, true>(a, b, c, area, width, height, &band);
    }
    /// setup() for one band without the depth plane: dzdx() and every span's z are 0, so both divisions
    /// are skipped. The same rows and spans as setup(); for shaders that ignore depth (flat colour).
    __attribute__((always_inline)) bool setup_flat(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                                   int32_t area, int32_t width, int32_t height, const BandBounds& band) {
        return setup_impl<true, false>(a, b, c, area, width, height, &band);
    }

    bool front() const { return front_; }
    int32_t first_row() const { return row_top_; }
    int32_t end_row() const { return row_bottom_; }
    uint32_t dzdx() const { return dzdx_; }

    /// Visits every row y in [y_begin, y_end) the triangle touches, in order: rows.begin(y0) once,
    /// then rows(x0, x1, z) per row with the covered pixels [x0, x1) clipped to [0, width) (possibly
    /// empty: x0 >= x1) and z the depth at (x0, y). Returns the number of pixels covered when
    /// RowFn::kCountFragments, else 0. A row functor keeps its own row pointers and steps them by a
    /// stride (no multiply), and triangles that cannot reach left of pixel 0 take a loop without the
    /// depth-at-column-0 bookkeeping. (The z-buffer's flat RGB565 path does not come here: it sets its
    /// triangles up for the row kernel directly, kernel_triangle.hpp; RowFn::kRowKernel is not read.)
    template <class RowFn>
    uint32_t scan(int32_t y_begin, int32_t y_end, RowFn& rows_fn) const {
        const int32_t y0 = max(row_top_, y_begin), y1 = min(row_bottom_, y_end);
        if (y0 >= y1) return 0;
        const bool left = clip_left_, right = clip_right_;
        if (left) return right ? scan_rows<true, true>(y0, y1, rows_fn) : scan_rows<true, false>(y0, y1, rows_fn);
        if (right) return scan_rows<false, true>(y0, y1, rows_fn);
        return scan_rows<false, false>(y0, y1, rows_fn);
    }

    /// Convenience form of scan(): fn(y, x0, x1, z) for each row with a non-empty span.
    template <class Fn>
    uint32_t spans(int32_t y_begin, int32_t y_end, Fn&& fn) const {
        detail::SpanAdapter<Fn> adapter{&fn, 0};
        return scan(y_begin, y_end, adapter);
    }

private:
    template <bool kBandTest, bool kDepth>
    __attribute__((always_inline)) bool setup_impl(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                                   int32_t area, int32_t width, int32_t height,
                                                   const BandBounds* band) {
        row_top_ = row_mid_ = row_bottom_ = 0;  // an empty row range if we return early
        front_ = false;
        if (area == 0) {
            dzdx_ = 0;
            long_left_ = false;
            return false;
        }
        front_ = area < 0;
        const ScreenVertex& v1 = area < 0 ? c : b;  // traverse clockwise on the image
        const ScreenVertex& v2 = area < 0 ? b : c;
        if (area < 0) area = -area;
        width_ = width;
        x_origin_ = pixel_centre_origin(width);
        y_origin_ = pixel_centre_origin(height);
        // Rows: the vertices sorted by y (top, mid, bottom), counting swaps. The long edge (top to
        // bottom) is the left one when the clockwise order runs bottom -> top, i.e. when (top, mid,
        // bottom) is an even permutation of (a, v1, v2).
        int32_t xt = a.x, yt = a.y, xm = v1.x, ym = v1.y, xb = v2.x, yb = v2.y;
        bool even = true;
        if (ym < yt) { swap_values(xm, xt); swap_values(ym, yt); even = !even; }
        if (yb < ym) { swap_values(xb, xm); swap_values(yb, ym); even = !even; }
        if (ym < yt) { swap_values(xm, xt); swap_values(ym, yt); even = !even; }
        const int32_t x_min = min(xt, min(xm, xb)), x_max = max(xt, max(xm, xb));
        if (kBandTest && misses_band({x_min, x_max, yt, yb}, *band)) return false;
        long_left_ = even;
        clip_left_ = x_min < x_origin_;
        clip_right_ = x_max > x_origin_ + (width - 1) * kSubpixel;
        xs_[0] = xt; ys_[0] = yt;
        xs_[1] = xm; ys_[1] = ym;
        xs_[2] = xb; ys_[2] = yb;
        row_top_ = first_row_at_or_below(yt);
        row_mid_ = first_row_at_or_below(ym);
        row_bottom_ = first_row_at_or_below(yb);
        if (kDepth) {
            setup_depth(a, v1, v2, area);
        } else {  // depth_at() is then 0 everywhere
            z_ref_ = dzdx_ = dzdy_ = 0;
            ref_px_ = ref_py_ = 0;
        }
        return true;
    }

    int32_t first_row_at_or_below(int32_t y_sub) const {
        return (y_sub - y_origin_ + kSubpixel - 1) >> kSubpixelBits;  // ceil((y - origin) / 16)
    }

    /// The depth plane of (v0, v1, v2), clockwise on the image, with area = their signed area (> 0).
    void setup_depth(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int32_t area) {
        const DepthPlane p = depth_plane(v0, v1, v2, area, x_origin_, y_origin_);
        dzdx_ = p.dzdx;
        dzdy_ = p.dzdy;
        z_ref_ = p.z_ref;
        ref_px_ = p.ref_px;
        ref_py_ = p.ref_py;
    }

    /// Depth at pixel (px, py): exact modulo 2^32, equal to what stepping produces.
    __attribute__((always_inline)) uint32_t depth_at(int32_t px, int32_t py) const {
        return z_ref_ + dzdx_ * static_cast<uint32_t>(px - ref_px_) + dzdy_ * static_cast<uint32_t>(py - ref_py_);
    }

    /// The row loop of scan(). kClipLeft: spans may start left of pixel 0, so the depth at column 0 is
    /// stepped along (z_col0) for them. kClipRight: spans may end past the last column.
    template <bool kClipLeft, bool kClipRight, class RowFn>
    uint32_t scan_rows(int32_t y0, int32_t y1, RowFn& rows_fn) const {
        RowFn fn = rows_fn;  // a copy whose address never escapes: its fields can stay in registers
        fn.begin(y0);
        const int32_t y_mid = clamp(row_mid_, y0, y1);
        // The long edge (top to bottom) and the short edge of the half holding y0; both short edges
        // lie on the same side, so left and right never swap, only the short walker is replaced at y_mid.
        const Walker lw = walker(0, 2, y0);
        const Walker sw = y0 < y_mid ? walker(0, 1, y0) : walker(1, 2, y0);
        const bool long_left = long_left_;
        const Walker& l = long_left ? lw : sw;
        const Walker& r = long_left ? sw : lw;
        int32_t lpx = l.px, lg = l.g, la = l.a, lm = l.m, lq = l.q;
        int32_t rpx = r.px, rg = r.g, ra = r.a, rm = r.m, rq = r.q;
        uint32_t lz = depth_at(lpx, y0), ldz = dzdy_ + dzdx_ * static_cast<uint32_t>(lq);
        const uint32_t dzdx = dzdx_;
        const int32_t width = width_;
        uint32_t z_col0 = kClipLeft ? depth_at(0, y0) : 0;  // depth at pixel 0, for spans that start off-screen
        uint32_t covered = 0;
        for (int32_t y = y0;;) {
            const int32_t x0 = kClipLeft && lpx < 0 ? 0 : lpx;
            const int32_t x1 = kClipRight && rpx > width ? width : rpx;
            fn(x0, x1, kClipLeft && lpx < 0 ? z_col0 : lz);
            if constexpr (RowFn::kCountFragments) {
                if (x0 < x1) covered += static_cast<uint32_t>(x1 - x0);
            }
            if (++y == y1) break;
            lg += lm;  // both edges step as DDAs with an exact error term
            lpx += lq;
            lz += ldz;
            if (lg >= la) { lg -= la; --lpx; lz -= dzdx; }
            rg += rm;
            rpx += rq;
            if (rg >= ra) { rg -= ra; --rpx; }
            if constexpr (kClipLeft) z_col0 += dzdy_;
            if (y == y_mid) {  // once per triangle: the short side continues along the other short edge
                const Walker w = walker(1, 2, y);
                if (long_left) { rpx = w.px; rg = w.g; ra = w.a; rm = w.m; rq = w.q; }
                else {
                    lpx = w.px; lg = w.g; la = w.a; lm = w.m; lq = w.q;
                    lz = depth_at(lpx, y);
                    ldz = dzdy_ + dzdx_ * static_cast<uint32_t>(lq);
                }
            }
        }
        rows_fn = fn;
        return covered;
    }

    using Walker = EdgeWalker;

    /// Walker on row py for the edge from sorted vertex u down to sorted vertex l (u < l, ys_[u] <
    /// ys_[l]). Both sides share one form: a left edge (run upwards clockwise, top-left rule
    /// inclusive) and a right edge (run downwards, exclusive, its edge function negated and biased by
    /// one) give the same g = dy (x - xu) - dx (y - yu) at pixel centres (edge.hpp).
    Walker walker(int u, int l, int32_t py) const {
        return edge_walker(xs_[u], ys_[u], xs_[l], ys_[l], py, x_origin_, y_origin_);
    }

    // No default initialisers: setup() writes every member, and a per-triangle memset costs real time.
    int32_t xs_[3], ys_[3];  ///< vertices sorted by y: top, mid, bottom
    int32_t width_, x_origin_, y_origin_;
    int32_t row_top_, row_mid_, row_bottom_;
    int32_t ref_px_, ref_py_;
    uint32_t z_ref_, dzdx_, dzdy_;
    bool front_;
    bool long_left_;               ///< the edge top -> bottom bounds the triangle on the left
    bool clip_left_, clip_right_;  ///< spans may start left of pixel 0 / end past the last column
};

}  // namespace hider

// plot(): a function source draws what the same heights in a grid draw; a ring of rows (first_row)
// what the rotated copy draws; shading by palette, height and id; unusable arguments draw nothing and
// say invalid_argument; clamped heights say out_of_range; every target format (RGB565, RGB888, grey,
// 1-bit) gives the same picture, whole and in bands; views with the eye's plane inside the surface.
#include <hider/horizon/plot.hpp>

#include <cmath>
#include <set>
#include <vector>

#include <doctest/doctest.h>

using namespace hider;
using namespace hider::horizon;

namespace {

Q16 q(double v) { return Q16::from_raw(static_cast<int32_t>(std::lround(v * 65536))); }

Camera camera(double ex, double ey, double ez, double tx = 0, double ty = 0, double tz = 0, bool up_z = false) {
    Camera c;
    c.eye = {q(ex), q(ey), q(ez)};
    c.target = {q(tx), q(ty), q(tz)};
    c.up = up_z ? Vec3q16{q(0), q(0), q(-1)} : Vec3q16{q(0), q(1), q(0)};
    c.fovy = Angle::from_degrees(Q16::from_int(45));
    c.near = q(0.05);
    c.far = q(50);
    return c;
}

constexpr int kSamples = 60, kCurves = 24;

Surface surface(int32_t vmin, int32_t vmax, int32_t unit) {
    Surface s;
    s.samples = kSamples;
    s.curves = kCurves;
    s.dx = Q16::from_ratio(2, kSamples - 1);
    s.x0 = Q16::from_int(-1);
    s.dz = Q16::from_ratio(2, kCurves - 1);
    s.z0 = Q16::from_int(-1);
    s.value_min = vmin;
    s.value_max = vmax;
    s.y_unit_raw = unit;
    return s;
}

/// A bumpy Q16 height field in [-0.35, 0.35] (the same numbers the grid tests use).
Q16 bumps(Q16 x, Q16 z) {
    const double fx = x.raw() / 65536.0, fz = z.raw() / 65536.0;
    return q(0.2 * std::sin(4 * fx + 1) * std::cos(3 * fz) + 0.15 * std::exp(-4 * (fx * fx + fz * fz)));
}

/// The heights of bumps() on the grid of `s`, row-major.
std::vector<int32_t> grid_of(const Surface& s) {
    std::vector<int32_t> g;
    for (int k = 0; k < s.curves; ++k)
        for (int i = 0; i < s.samples; ++i)
            g.push_back(bumps(Q16::from_raw(s.x0.raw() + i * s.dx.raw()), Q16::from_raw(s.z0.raw() + k * s.dz.raw())).raw());
    return g;
}

/// Scratch for any view of these surfaces.
struct Scratch {
    std::vector<PlotPoint> cur, prev;
    std::vector<int32_t> vcur, vprev;
    std::vector<int16_t> upper, lower, pu, pl;
    Horizon hz;
    PlotBuffers b;
    Scratch(int w, int h)
        : cur(kSamples), prev(kSamples), vcur(kSamples), vprev(kSamples), upper(w), lower(w), pu(w), pl(w) {
        REQUIRE(make_horizon({upper.data(), upper.size()}, {lower.data(), lower.size()}, w, h, hz) == Status::ok);
        b = {{cur.data(), cur.size()}, {prev.data(), prev.size()}, {vcur.data(), vcur.size()},
             {vprev.data(), vprev.size()}, {pu.data(), pu.size()}, {pl.data(), pl.size()}};
    }
};

const Rgb kPalette[] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};

/// Plots into a whole RGB888 frame; returns its bytes.
template <class Source>
std::vector<Rgb888> render(const SurfaceProjection& p, const Source& src, const PlotStyle& st, PlotStats* stats = nullptr) {
    const int w = p.width(), h = p.height();
    std::vector<Rgb888> px(static_cast<size_t>(w) * h, Rgb888{0, 0, 0});
    Scratch sc(w, h);
    const PlotStats s = plot(p, src, sc.hz, sc.b, FrameTarget<Rgb888Format>(frame_view<Rgb888Format, uint16_t>(px.data(), nullptr, w, h)), st);
    CHECK(s.status == Status::ok);
    if (stats != nullptr) *stats = s;
    return px;
}

bool same(const std::vector<Rgb888>& a, const std::vector<Rgb888>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].r != b[i].r || a[i].g != b[i].g || a[i].b != b[i].b) return false;
    return true;
}

long lit(const std::vector<Rgb888>& a) {
    long n = 0;
    for (const Rgb888& c : a) n += (c.r | c.g | c.b) != 0;
    return n;
}

PlotStyle palette_style(bool mesh = false) {
    PlotStyle st;
    st.colours = kPalette;
    st.mesh = mesh;
    st.mesh_step = 4;
    return st;
}

struct Fn {
    Q16 operator()(Q16 x, Q16 z) const { return bumps(x, z); }
};

}  // namespace

TEST_CASE("A mesh step past the last sample draws the first and last lines, up to INT32_MAX") {
    // The sums of the step with the sample index must not overflow (UBSan in the host-asan build).
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    for (const Camera& cam : {camera(0.4, 1.6, 2.6), camera(3.0, 1.2, 0.3)}) {
        SurfaceProjection p;
        REQUIRE(p.prepare(cam, 160, 120, s) == Status::ok);
        PlotStyle st = palette_style(true);
        st.mesh_step = kSamples - 1;
        const std::vector<Rgb888> ref = render(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, st);
        for (int32_t step : {kSamples, 1000, INT32_MAX - 30, INT32_MAX}) {
            CAPTURE(step);
            st.mesh_step = step;
            CHECK(same(render(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, st), ref));
        }
        st.mesh_step = kSamples - 2;  // a line more: the check can tell them apart
        CHECK_FALSE(same(render(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, st), ref));
    }
}

TEST_CASE("A function source draws exactly what the same heights in a grid draw") {
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    for (const Camera& cam : {camera(0.4, 1.6, 2.6), camera(3.0, 1.2, 0.3), camera(0.2, 2.5, 0.05, 0, 0, 0, true)}) {
        SurfaceProjection p;
        REQUIRE(p.prepare(cam, 160, 120, s) == Status::ok);
        for (bool mesh : {false, true}) {
            CAPTURE(mesh);
            const std::vector<Rgb888> a = render(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, palette_style(mesh));
            const std::vector<Rgb888> b = render(p, FunctionSource<Fn>{Fn{}}, palette_style(mesh));
            CHECK(same(a, b));
            CHECK(lit(a) > 500);
        }
    }
}

TEST_CASE("A ring of rows (first_row) draws what the rotated copy draws") {
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    SurfaceProjection p;
    REQUIRE(p.prepare(camera(0.4, 1.6, 2.6), 160, 120, s) == Status::ok);
    const std::vector<Rgb888> direct = render(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, palette_style());
    for (int first : {1, 7, kCurves - 1}) {
        CAPTURE(first);
        std::vector<int32_t> ring(g.size());
        for (int k = 0; k < kCurves; ++k)  // curve k stored in row (first + k) mod curves
            std::copy(g.begin() + k * kSamples, g.begin() + (k + 1) * kSamples, ring.begin() + ((first + k) % kCurves) * kSamples);
        CHECK(same(render(p, GridSource<int32_t>{ring.data(), kSamples, kCurves, first}, palette_style()), direct));
    }
}

TEST_CASE("Shading: a palette per curve, ids per curve and constant-x line, a ramp by height") {
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    const GridSource<int32_t> src{g.data(), kSamples, kCurves, 0};
    SurfaceProjection p;
    REQUIRE(p.prepare(camera(0.4, 1.6, 2.6), 200, 150, s) == Status::ok);
    SUBCASE("palette: every colour used, nothing else") {
        std::set<uint32_t> colours;
        for (const Rgb888& c : render(p, src, palette_style())) colours.insert(uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b);
        CHECK(colours == std::set<uint32_t>{0, 0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF});  // white: the side edges
    }
    SUBCASE("id: curves 1..24, side edges 25 and 25 + 15 (mesh step 4), the mesh's lines in between") {
        PlotStyle st = palette_style();
        st.shading = Shading::id;
        std::set<uint32_t> ids;
        for (const Rgb888& c : render(p, src, st)) ids.insert(uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b);
        CHECK(ids.count(1) == 1);
        CHECK(ids.count(kCurves) == 1);
        CHECK(ids.count(kCurves + 1) == 1);
        CHECK(ids.count(kCurves + 1 + 15) == 1);
        CHECK(ids.count(kCurves + 2) == 0);
        CHECK(*ids.rbegin() == kCurves + 1 + 15);
        st.mesh = true;
        ids.clear();
        for (const Rgb888& c : render(p, src, st)) ids.insert(uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b);
        for (uint32_t id = kCurves + 1; id <= kCurves + 1 + 15; ++id) CHECK(ids.count(id) == 1);
    }
    SUBCASE("height: the ramp's low end on low columns, its high end on the highest") {
        const Rgb ramp[] = {{0, 0, 255}, {0, 255, 0}, {255, 0, 0}};
        PlotStyle st = palette_style();
        st.shading = Shading::height;
        st.colours = ramp;
        std::set<uint32_t> colours;
        for (const Rgb888& c : render(p, src, st)) colours.insert(uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b);
        CHECK(colours == std::set<uint32_t>{0, 0x0000FF, 0x00FF00, 0xFF0000});
    }
}

TEST_CASE("Unusable arguments draw nothing and say invalid_argument") {
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    const GridSource<int32_t> src{g.data(), kSamples, kCurves, 0};
    SurfaceProjection p;
    REQUIRE(p.prepare(camera(0.4, 1.6, 2.6), 64, 48, s) == Status::ok);
    std::vector<Rgb888> px(64 * 48, Rgb888{9, 9, 9});
    const FrameTarget<Rgb888Format> t(frame_view<Rgb888Format, uint16_t>(px.data(), nullptr, 64, 48));
    Scratch sc(64, 48);
    PlotStyle st = palette_style();
    auto check_refused = [&](const PlotBuffers& b, const PlotStyle& style, const Horizon& hz) {
        const PlotStats r = plot(p, src, hz, b, t, style);
        CHECK(r.status == Status::invalid_argument);
        CHECK(r.pixels == 0);
        for (const Rgb888& c : px) CHECK((c.r == 9 && c.g == 9 && c.b == 9));
    };
    PlotBuffers short_points = sc.b;
    short_points.current = {sc.cur.data(), kSamples - 1};
    check_refused(short_points, st, sc.hz);
    PlotBuffers no_previous = sc.b;
    no_previous.previous = {};
    PlotStyle mesh = st;
    mesh.mesh = true;
    check_refused(no_previous, mesh, sc.hz);
    PlotStyle no_colours = st;
    no_colours.colours = {};
    check_refused(sc.b, no_colours, sc.hz);
    PlotStyle bad_step = st;
    bad_step.mesh_step = 0;
    check_refused(sc.b, bad_step, sc.hz);
    Scratch other(65, 48);  // horizons of another width
    check_refused(sc.b, st, other.hz);
    CHECK(plot(p, GridSource<int32_t>{g.data(), kSamples, kCurves - 1, 0}, sc.hz, sc.b, t, st).status == Status::invalid_argument);
    // A function source needs the value buffers; a side view needs buffers of the curves.
    PlotBuffers no_values = sc.b;
    no_values.values_current = {};
    CHECK(plot(p, FunctionSource<Fn>{Fn{}}, sc.hz, no_values, t, st).status == Status::invalid_argument);
    SurfaceProjection side;
    REQUIRE(side.prepare(camera(3.0, 1.2, 0.3), 64, 48, s) == Status::ok);
    REQUIRE(side.sweep() == Sweep::x_lines);
    PlotBuffers no_pending = sc.b;
    no_pending.pending_upper = {};
    CHECK(plot(side, src, sc.hz, no_pending, t, st).status == Status::invalid_argument);
    CHECK(plot(side, src, sc.hz, sc.b, t, st).status == Status::ok);
}

TEST_CASE("A MonoFrame band of more pages than its frame has is refused, however many (no page1 * 8 overflow)") {
    // valid() computed page1 * 8 in int32: from 2^28 pages it wrapped below the height, so a 48-row frame
    // claiming 2^29 pages was valid and plot() said ok and drew nothing.
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    const GridSource<int32_t> src{g.data(), kSamples, kCurves, 0};
    SurfaceProjection p;
    REQUIRE(p.prepare(camera(0.4, 1.6, 2.6), 64, 48, s) == Status::ok);
    Scratch sc(64, 48);
    std::vector<uint8_t> pages(64 * 6, 0);
    for (int32_t page1 : {1, 6}) CHECK(MonoFrame{pages.data(), 64, 48, 0, page1}.valid());
    for (int32_t page1 : {7, 0x0FFFFFFF, 0x10000000, 0x1FFFFFFF, 0x20000000, 0x40000000, INT32_MAX}) {
        const MonoFrame f{pages.data(), 64, 48, 0, page1};
        CHECK_FALSE(f.valid());
        const PlotStats r = plot(p, src, sc.hz, sc.b, MonoTarget(f), palette_style());
        CHECK(r.status == Status::invalid_argument);
    }
    CHECK(MonoFrame{pages.data(), 64, 47, 0, 6}.valid());   // 47 rows: 6 pages, the last one partly
    CHECK_FALSE(MonoFrame{pages.data(), 64, 40, 0, 6}.valid());
    const PlotStats ok = plot(p, src, sc.hz, sc.b, MonoTarget(MonoFrame{pages.data(), 64, 48, 0, 6}), palette_style());
    CHECK(ok.status == Status::ok);
    CHECK(ok.pixels > 0);
}

TEST_CASE("Heights outside the declared range are drawn at its limits and reported as out_of_range") {
    Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    std::vector<int32_t> g = grid_of(s);
    s.value_max = q(0.1).raw();  // declared too small: the hills are cut
    SurfaceProjection p;
    REQUIRE(p.prepare(camera(0.4, 1.6, 2.6), 160, 120, s) == Status::ok);
    std::vector<Rgb888> px(160 * 120);
    Scratch sc(160, 120);
    const PlotStats r = plot(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, sc.hz, sc.b,
                             FrameTarget<Rgb888Format>(frame_view<Rgb888Format, uint16_t>(px.data(), nullptr, 160, 120)), palette_style());
    CHECK(r.status == Status::out_of_range);
    long over = 0;
    for (int32_t v : g) over += v > s.value_max;
    CHECK(r.values_clamped == static_cast<uint32_t>(over));
    CHECK(r.pixels > 500);
    // Heights at the ends of int32 alternating, coloured by height: the ramp's interpolation between
    // them overflowed int32 (undefined behaviour, caught by UBSan in the sanitizer build; a red-team
    // pass). Still out_of_range, every value counted.
    std::vector<int32_t> wild(g.size());
    for (size_t i = 0; i < wild.size(); ++i) wild[i] = (i & 1) != 0 ? INT32_MAX : INT32_MIN;
    PlotStyle ramp = palette_style();
    ramp.shading = Shading::height;
    Scratch sc2(160, 120);
    const PlotStats w = plot(p, GridSource<int32_t>{wild.data(), kSamples, kCurves, 0}, sc2.hz, sc2.b,
                             FrameTarget<Rgb888Format>(frame_view<Rgb888Format, uint16_t>(px.data(), nullptr, 160, 120)), ramp);
    CHECK(w.status == Status::out_of_range);
    CHECK(w.values_clamped == static_cast<uint32_t>(wild.size()));
}

namespace {

/// The bumps, lifted to [0, 0.7] (unsigned types hold them), with a peak of `huge` in the middle, as T;
/// and the same surface with the peak at value_max as int32_t, which is what the clamp means.
template <class T>
void wide_heights_plot_as_clamped(T huge, const char* type) {
    CAPTURE(type);
    Surface s = surface(0, q(0.7).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    std::vector<T> wide(g.size());
    std::vector<int32_t> clamped(g.size());
    for (int k = 0; k < kCurves; ++k)
        for (int i = 0; i < kSamples; ++i) {
            const size_t at = static_cast<size_t>(k) * kSamples + i;
            const bool peak = k >= 10 && k < 14 && i >= 25 && i < 35;
            wide[at] = peak ? huge : static_cast<T>(g[at] + q(0.35).raw());
            clamped[at] = peak ? s.value_max : g[at] + q(0.35).raw();
        }
    // Curves and constant-x lines from outside; then eyes inside the box beside the peak, where lines
    // cross the near plane next to its samples (the crossing and the mesh pieces read the heights too).
    const Camera views[6] = {camera(0.4, 1.6, 2.6), camera(3.0, 1.2, 0.3), camera(0.1, 0.75, 0.2, -1, 0.3, -0.9),
                             camera(0.2, 0.8, 0.15, 0.2, 0.3, -1), camera(0.25, 0.8, -0.1, -1, 0.3, -0.1),
                             camera(-0.2, 0.75, 0.18, 1, 0.3, -0.9)};
    for (const Camera& cam : views)
        for (Shading shading : {Shading::palette, Shading::height}) {
            SurfaceProjection p;
            REQUIRE(p.prepare(cam, 96, 72, s) == Status::ok);
            PlotStyle st = palette_style(true);
            st.shading = shading;
            if (&cam != &views[0]) st.mesh_step = 1;
            const int view_index = static_cast<int>(&cam - views);
            CAPTURE(view_index);
            CAPTURE(static_cast<int>(shading));
            std::vector<Rgb888> a(96 * 72), b(96 * 72);
            Scratch sa(96, 72), sb(96, 72);
            const PlotStats ra = plot(p, GridSource<T>{wide.data(), kSamples, kCurves, 0}, sa.hz, sa.b,
                                      FrameTarget<Rgb888Format>(frame_view<Rgb888Format, uint16_t>(a.data(), nullptr, 96, 72)), st);
            const PlotStats rb = plot(p, GridSource<int32_t>{clamped.data(), kSamples, kCurves, 0}, sb.hz, sb.b,
                                      FrameTarget<Rgb888Format>(frame_view<Rgb888Format, uint16_t>(b.data(), nullptr, 96, 72)), st);
            CHECK(ra.status == Status::out_of_range);
            CHECK(rb.status == Status::ok);
            CHECK(same(a, b));
            CHECK(lit(a) > 300);
        }
}

}  // namespace

TEST_CASE("Heights of a type wider than int32 (or unsigned 32-bit) are clamped and counted, not wrapped") {
    // They were cast to int32_t before the range check: a uint32_t height of 2^32 - 1 was drawn as -1 (at
    // the bottom), an int64_t one of 2^32 + 50 at 50 with status ok.
    wide_heights_plot_as_clamped<uint32_t>(UINT32_MAX, "uint32_t");
    wide_heights_plot_as_clamped<int64_t>((int64_t{1} << 32) + 50, "int64_t");
    wide_heights_plot_as_clamped<int64_t>(INT64_MAX, "int64_t max");
    wide_heights_plot_as_clamped<uint64_t>((uint64_t{1} << 63) + 7, "uint64_t");
    wide_heights_plot_as_clamped<int32_t>(INT32_MAX, "int32_t");
    // A range reaching INT32_MAX (where a saturated value would pass the range check uncounted) cannot be
    // prepared: world y = value * y_unit_raw with y_unit_raw >= 1 would pass the world range.
    CHECK(SurfaceProjection().prepare(camera(0.4, 1.6, 2.6), 96, 72, surface(0, INT32_MAX, 1)) == Status::out_of_range);
    CHECK(horizon::detail::height_value<int64_t>(INT64_MIN) == INT32_MIN);
    CHECK(horizon::detail::height_value<int64_t>(-5) == -5);
    CHECK(horizon::detail::height_value<uint32_t>(0x80000000u) == INT32_MAX);
    CHECK(horizon::detail::height_value<uint16_t>(65535) == 65535);
    CHECK(horizon::detail::height_value<int8_t>(-128) == -128);
}

namespace {

template <class Format>
std::vector<uint8_t> as_grey(const std::vector<typename Format::Pixel>& px) {
    std::vector<uint8_t> g;
    for (const auto& p : px) {
        const Rgb c = Format::unpack(p);
        g.push_back((c.r | c.g | c.b) != 0 ? 1 : 0);
    }
    return g;
}

/// The surface plotted into a Format frame in bands of `rows`, as lit (1) / dark (0) pixels.
template <class Format>
std::vector<uint8_t> plot_lit(const SurfaceProjection& p, const GridSource<uint8_t>& src, int rows) {
    const int w = p.width(), h = p.height();
    std::vector<typename Format::Pixel> frame(static_cast<size_t>(w) * h), band(static_cast<size_t>(w) * rows);
    Scratch sc(w, h);
    const Rgb white[] = {{255, 255, 255}};
    PlotStyle st;
    st.colours = white;
    for (int y0 = 0; y0 < h; y0 += rows) {
        const int y1 = std::min(h, y0 + rows);
        const auto v = band_view<Format, uint16_t>(band.data(), nullptr, w, h, y0, y1);
        clear(v, Rgb{0, 0, 0});
        CHECK(plot(p, src, sc.hz, sc.b, FrameTarget<Format>(v), st).ok());
        std::copy(band.begin(), band.begin() + (y1 - y0) * w, frame.begin() + y0 * w);
    }
    return as_grey<Format>(frame);
}

}  // namespace

TEST_CASE("Every target format shows the same pixels, whole and in bands (8-bit heights, level and yawed views)") {
    const Surface s = surface(0, 255, 96);
    std::vector<uint8_t> g;
    for (int k = 0; k < kCurves; ++k)
        for (int i = 0; i < kSamples; ++i) g.push_back(static_cast<uint8_t>(128 + 100 * std::sin(i * 0.3 + k * 0.5)));
    const GridSource<uint8_t> src{g.data(), kSamples, kCurves, 0};
    for (const Camera& cam : {camera(0, 1.4, 2.5, 0, 0, -0.2), camera(1.1, 1.4, 2.2)}) {
        SurfaceProjection p;
        REQUIRE(p.prepare(cam, 96, 64, s) == Status::ok);
        const std::vector<uint8_t> ref = plot_lit<Rgb888Format>(p, src, 64);
        long n = 0;
        for (uint8_t v : ref) n += v;
        CHECK(n > 300);
        for (int rows : {1, 5, 8, 64}) {
            CAPTURE(rows);
            CHECK(plot_lit<Rgb565Format>(p, src, rows) == ref);
            CHECK(plot_lit<Grey8Format>(p, src, rows) == ref);
            CHECK(plot_lit<Rgb888Format>(p, src, rows) == ref);
        }
        // 1-bit pages, whole and in bands of one page.
        for (int pages : {8, 1}) {
            CAPTURE(pages);
            std::vector<uint8_t> all(96 * 8);
            std::vector<uint8_t> band(static_cast<size_t>(96) * pages);
            Scratch sc(96, 64);
            const Rgb white[] = {{255, 255, 255}};
            PlotStyle st;
            st.colours = white;
            for (int p0 = 0; p0 < 8; p0 += pages) {
                const MonoFrame f{band.data(), 96, 64, p0, p0 + pages};
                horizon::clear(f);
                CHECK(plot(p, src, sc.hz, sc.b, MonoTarget(f), st).ok());
                std::copy(band.begin(), band.end(), all.begin() + p0 * 96);
            }
            const MonoFrame whole{all.data(), 96, 64, 0, 8};
            std::vector<uint8_t> mono;
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 96; ++x) mono.push_back(whole.lit(x, y) ? 1 : 0);
            CHECK(mono == ref);
        }
    }
}

TEST_CASE("With the eye above the middle every curve shows; the halves around its plane are swept separately") {
    const Surface s = surface(-q(0.35).raw(), q(0.35).raw(), 1);
    const std::vector<int32_t> g = grid_of(s);
    SurfaceProjection p;
    REQUIRE(p.prepare(camera(0.1, 2.4, 0.05, 0, 0, 0, true), 200, 200, s) == Status::ok);
    REQUIRE(p.sweep() == Sweep::curves);
    PlotStyle st = palette_style();
    st.shading = Shading::id;
    PlotStats stats;
    const std::vector<Rgb888> px = render(p, GridSource<int32_t>{g.data(), kSamples, kCurves, 0}, st, &stats);
    std::set<uint32_t> ids;
    for (const Rgb888& c : px) ids.insert(uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b);
    for (uint32_t k = 1; k <= kCurves; ++k) CHECK(ids.count(k) == 1);
    CHECK(stats.curves == kCurves);
    CHECK(stats.samples == static_cast<uint32_t>(kCurves * kSamples + 2 * kSamples));  // each pass loads the other's first
}

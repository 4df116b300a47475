// The offline BSP compiler (see bsp_build.hpp). Host code: standard library, 128-bit integers, doubles
// only to round cut points and to order points along a line.
#include "common/bsp_build.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <tuple>
#include <sstream>
#include <unordered_map>

namespace hider::tool {
namespace {

using I128 = __int128;
using P = std::array<int32_t, 3>;  // a world grid point, raw Q16

struct PHash {
    size_t operator()(const P& p) const {
        uint64_t h = 1469598103934665603ull;
        for (int32_t c : p) h = (h ^ static_cast<uint32_t>(c)) * 1099511628211ull;
        return static_cast<size_t>(h);
    }
};

/// An exact plane: side(p) = n . (p - o).
struct Plane {
    int64_t n[3];
    P o;
    uint32_t origin;  ///< vertex id of o
};

/// A convex polygon piece of input triangle `tri` (whose plane is planes_[tri], in group groups_[tri]);
/// sup[i] is the line the edge v[i] -> v[i+1] lies on.
struct Poly {
    std::vector<uint32_t> v;
    std::vector<uint32_t> sup;
    uint32_t tri;
};

/// A line polygon edges lie on (an input edge, or a cut line inside a face): the points made on it.
struct Support {
    std::vector<uint32_t> points;
};

class Builder {
public:
    Builder(const BspOptions& opt, BspStats& stats) : opt_(opt), stats_(stats) {}

    bool run(const std::vector<Vec3q16>& positions, const std::vector<Tri>& tris, const std::vector<uint32_t>& ids,
             BspBuilt& out, std::string& error) {
        // Vertices merged by position, so triangles that share a corner share its id (and their edges).
        std::vector<uint32_t> remap(positions.size());
        for (size_t i = 0; i < positions.size(); ++i)
            remap[i] = vertex({positions[i].x.raw(), positions[i].y.raw(), positions[i].z.raw()});
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_support;
        std::vector<uint32_t> work;
        stats_.input_triangles = tris.size();
        for (size_t t = 0; t < tris.size(); ++t) {
            const uint32_t a = remap[tris[t].v[0]], b = remap[tris[t].v[1]], c = remap[tris[t].v[2]];
            Plane pl = plane_of(a, b, c);
            if (pl.n[0] == 0 && pl.n[1] == 0 && pl.n[2] == 0) {
                ++stats_.degenerate;
                continue;
            }
            planes_.push_back(pl);
            groups_.push_back(group_of(pl));
            faces_.push_back(ids.empty() ? static_cast<uint32_t>(t + 1) : ids[t]);
            Poly p{{a, b, c}, {}, static_cast<uint32_t>(planes_.size() - 1)};
            for (int i = 0; i < 3; ++i) {
                const uint32_t u = p.v[i], w = p.v[(i + 1) % 3];
                const auto key = std::minmax(u, w);
                auto it = edge_support.find(key);
                if (it == edge_support.end()) {
                    it = edge_support.emplace(key, new_support()).first;
                    supports_[it->second].points = {key.first, key.second};
                }
                p.sup.push_back(it->second);
            }
            polys_.push_back(std::move(p));
            work.push_back(static_cast<uint32_t>(polys_.size() - 1));
        }
        for (const Plane& pl : planes_)
            for (int64_t c : pl.n)
                if (c <= -(int64_t{1} << 62) || c >= (int64_t{1} << 62)) {
                    error = "a triangle's plane does not fit the format (normal beyond 2^62)";
                    return false;
                }
        build_tree(std::move(work));
        return finish(out, error);
    }

private:
    uint32_t vertex(const P& p) {
        auto it = index_.find(p);
        if (it != index_.end()) return it->second;
        verts_.push_back(p);
        index_.emplace(p, static_cast<uint32_t>(verts_.size() - 1));
        return static_cast<uint32_t>(verts_.size() - 1);
    }

    uint32_t new_support() {
        supports_.emplace_back();
        return static_cast<uint32_t>(supports_.size() - 1);
    }

    void add_point(uint32_t support, uint32_t v) {
        std::vector<uint32_t>& pts = supports_[support].points;
        if (std::find(pts.begin(), pts.end(), v) == pts.end()) pts.push_back(v);
    }

    Plane plane_of(uint32_t a, uint32_t b, uint32_t c) const {
        const P &pa = verts_[a], &pb = verts_[b], &pc = verts_[c];
        const int64_t e1[3] = {int64_t{pb[0]} - pa[0], int64_t{pb[1]} - pa[1], int64_t{pb[2]} - pa[2]};
        const int64_t e2[3] = {int64_t{pc[0]} - pa[0], int64_t{pc[1]} - pa[1], int64_t{pc[2]} - pa[2]};
        Plane pl;
        pl.n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        pl.n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        pl.n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        pl.o = pa;
        pl.origin = a;
        return pl;
    }

    /// The group of planes equal to pl (exactly: the same normal direction and offset), so polygons of
    /// coplanar triangles are recognised as coplanar whatever rounding their cut points had.
    uint32_t group_of(const Plane& pl) {
        int64_t g = 0;
        for (int64_t c : pl.n) g = std::gcd(g, c < 0 ? -c : c);
        int64_t n[3] = {pl.n[0] / g, pl.n[1] / g, pl.n[2] / g};
        const int flip = (n[0] < 0 || (n[0] == 0 && (n[1] < 0 || (n[1] == 0 && n[2] < 0)))) ? -1 : 1;
        for (int64_t& c : n) c *= flip;
        const I128 d = I128(n[0]) * pl.o[0] + I128(n[1]) * pl.o[1] + I128(n[2]) * pl.o[2];
        const auto key = std::make_tuple(n[0], n[1], n[2], static_cast<int64_t>(d >> 64), static_cast<uint64_t>(d));
        const auto it = group_index_.emplace(key, static_cast<uint32_t>(group_index_.size())).first;
        return it->second;
    }

    static I128 side(const Plane& pl, const P& p) {
        return I128(pl.n[0]) * (int64_t{p[0]} - pl.o[0]) + I128(pl.n[1]) * (int64_t{p[1]} - pl.o[1]) +
               I128(pl.n[2]) * (int64_t{p[2]} - pl.o[2]);
    }
    static int sign(I128 v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

    /// Side of a vertex: 0 on the plane or within half a grid step of it (a rounded cut point).
    int side_of(const Plane& pl, uint32_t v) const {
        const I128 s = side(pl, verts_[v]);
        const I128 slack = half_l1(pl);
        return s > slack ? 1 : (s < -slack ? -1 : 0);
    }
    /// Half a grid step's reach of side(): |n|_1 / 2.
    static I128 half_l1(const Plane& pl) {
        return (I128(pl.n[0] < 0 ? -pl.n[0] : pl.n[0]) + (pl.n[1] < 0 ? -pl.n[1] : pl.n[1]) + (pl.n[2] < 0 ? -pl.n[2] : pl.n[2])) / 2;
    }

    /// -1 back, +1 front, 0 coplanar, 2 straddles. Coplanar means a piece of a triangle of the plane's
    /// group, and nothing else: a node's triangles take their facing from its plane. A piece of another
    /// plane with every corner within rounding of this one (a sliver along the planes' intersection)
    /// goes to the side of its farthest corner (front when all lie exactly on it), not into the node:
    /// there the walk would cull or keep it by a plane that is not its own.
    int classify(uint32_t plane, const Poly& p) const {
        if (groups_[p.tri] == groups_[plane]) return 0;
        const Plane& pl = planes_[plane];
        const I128 slack = half_l1(pl);
        bool pos = false, neg = false;
        I128 farthest = 0;
        for (uint32_t v : p.v) {  // side_of() of each corner
            const I128 d = side(pl, verts_[v]);
            pos = pos || d > slack;
            neg = neg || d < -slack;
            if ((d < 0 ? -d : d) > (farthest < 0 ? -farthest : farthest)) farthest = d;
        }
        return pos && neg ? 2 : (pos ? 1 : (neg ? -1 : (farthest < 0 ? -1 : 1)));
    }

    /// The splitter among evenly spaced candidates of `list` (the cost is measured on at most 4096 of its
    /// polygons, evenly spaced, so large nodes stay fast). The sampled polygons' distinct corners are
    /// gathered first, so each candidate computes the side of a corner once however many polygons share
    /// it, in a contiguous array (the same decisions as classify(), except that a piece of another plane
    /// within rounding of this one counts on neither side).
    uint32_t choose(const std::vector<uint32_t>& list) {
        const size_t n = list.size(), tries = std::min<size_t>(n, static_cast<size_t>(std::max(1, opt_.candidates)));
        const size_t sample = std::min<size_t>(n, 4096);
        if (corner_stamp_.size() < verts_.size()) corner_stamp_.resize(verts_.size(), {0, 0});
        ++stamp_;
        sample_group_.clear();
        sample_end_.clear();
        sample_corner_.clear();
        sample_point_.clear();
        for (size_t j = 0; j < sample; ++j) {
            const Poly& q = polys_[list[j * n / sample]];
            sample_group_.push_back(groups_[q.tri]);
            for (uint32_t v : q.v) {
                std::array<uint32_t, 2>& st = corner_stamp_[v];
                if (st[0] != stamp_) {
                    st = {stamp_, static_cast<uint32_t>(sample_point_.size())};
                    sample_point_.push_back(verts_[v]);
                }
                sample_corner_.push_back(st[1]);
            }
            sample_end_.push_back(static_cast<uint32_t>(sample_corner_.size()));
        }
        point_side_.resize(sample_point_.size());
        uint32_t best = polys_[list[0]].tri;
        int64_t best_cost = INT64_MAX;
        std::vector<uint32_t> tried;
        for (size_t k = 0; k < tries; ++k) {
            const uint32_t plane = polys_[list[k * n / tries]].tri;
            if (std::find(tried.begin(), tried.end(), plane) != tried.end()) continue;
            tried.push_back(plane);
            const Plane& pl = planes_[plane];
            const uint32_t group = groups_[plane];
            const I128 slack = half_l1(pl);
            for (size_t i = 0; i < sample_point_.size(); ++i) {  // bit 0: beyond the slack in front, bit 1: behind
                const I128 sd = side(pl, sample_point_[i]);
                point_side_[i] = static_cast<uint8_t>((sd > slack ? 1 : 0) | (sd < -slack ? 2 : 0));
            }
            int64_t front = 0, back = 0, cut = 0;
            uint32_t begin = 0;
            for (size_t j = 0; j < sample; ++j) {
                const uint32_t end = sample_end_[j];
                if (sample_group_[j] != group) {  // else coplanar
                    unsigned sides = 0;
                    for (uint32_t c = begin; c < end; ++c) sides |= point_side_[sample_corner_[c]];
                    front += sides == 1;
                    back += sides == 2;
                    cut += sides == 3;
                }
                begin = end;
            }
            const int64_t cost = opt_.split_weight * cut + opt_.balance_weight * std::llabs(front - back);
            if (cost < best_cost) {
                best_cost = cost;
                best = plane;
            }
        }
        return best;
    }

    /// The grid point where edge (a, b) meets the plane, the same whichever polygon asks (computed from
    /// the lower vertex id).
    uint32_t cut_point(const Plane& pl, uint32_t a, uint32_t b) {
        if (a > b) std::swap(a, b);
        const I128 sa = side(pl, verts_[a]), sb = side(pl, verts_[b]);
        const long double t = static_cast<long double>(sa) / static_cast<long double>(sa - sb);
        P m;
        for (int k = 0; k < 3; ++k)
            m[k] = static_cast<int32_t>(std::llround(verts_[a][k] + t * (static_cast<long double>(verts_[b][k]) - verts_[a][k])));
        return vertex(m);
    }

    /// Cuts p by the plane into its front and back parts (Sutherland-Hodgman with two outputs).
    void split(const Plane& pl, const Poly& p, Poly& front, Poly& back) {
        const size_t n = p.v.size();
        std::vector<int> s(n);
        for (size_t i = 0; i < n; ++i) s[i] = side_of(pl, p.v[i]);
        // Three or more corners "on" the plane (within rounding) of a polygon that still straddles it: the
        // plane is nearly the polygon's own, and those corners span an area, which both parts would hold.
        // Cut at the exact sides then, so the parts do not overlap.
        if (std::count(s.begin(), s.end(), 0) >= 3)
            for (size_t i = 0; i < n; ++i) s[i] = sign(side(pl, verts_[p.v[i]]));
        const uint32_t cut_line = new_support();
        struct Out {
            uint32_t v;
            int e0, e1;  ///< input edges the point lies on (-1: none)
        };
        std::vector<Out> fo, bo;
        for (size_t i = 0; i < n; ++i) {
            const size_t j = (i + 1) % n;
            const int prev = static_cast<int>((i + n - 1) % n);
            if (s[i] >= 0) fo.push_back({p.v[i], prev, static_cast<int>(i)});
            if (s[i] <= 0) bo.push_back({p.v[i], prev, static_cast<int>(i)});
            if (s[i] == 0) add_point(cut_line, p.v[i]);
            if (s[i] * s[j] < 0) {
                const uint32_t m = cut_point(pl, p.v[i], p.v[j]);
                add_point(p.sup[i], m);
                add_point(cut_line, m);
                fo.push_back({m, static_cast<int>(i), -1});
                bo.push_back({m, static_cast<int>(i), -1});
            }
        }
        auto make = [&](const std::vector<Out>& o, Poly& out) {
            out.tri = p.tri;
            out.v.clear();
            out.sup.clear();
            for (size_t k = 0; k < o.size(); ++k) {
                const Out& a = o[k];
                const Out& b = o[(k + 1) % o.size()];
                int common = -1;
                for (int ea : {a.e0, a.e1})
                    if (ea >= 0 && (ea == b.e0 || ea == b.e1)) common = ea;
                if (a.v == b.v) continue;  // a cut point rounded onto a corner
                out.v.push_back(a.v);
                out.sup.push_back(common >= 0 ? p.sup[static_cast<size_t>(common)] : cut_line);
            }
        };
        make(fo, front);
        make(bo, back);
    }

    /// An axis plane across the polygons of `list`: perpendicular to an axis of their corners' box (the
    /// longest first), through the median corner on it (the plane's origin: that corner's vertex), the
    /// first that leaves a polygon wholly on each side. Appended to planes_ (with its group and no face), with its
    /// classification of `list` in cls; kBspNone (planes_ as it was) when no axis does. Polygons lying in
    /// the plane, if any, stay in its node as usual.
    uint32_t splitter(const std::vector<uint32_t>& list, std::vector<int>& cls) {
        std::vector<std::pair<int32_t, uint32_t>> corner[3];  // (coordinate, vertex) per axis
        for (uint32_t q : list)
            for (uint32_t v : polys_[q].v)
                for (int k = 0; k < 3; ++k) corner[k].push_back({verts_[v][static_cast<size_t>(k)], v});
        int64_t extent[3];
        for (int k = 0; k < 3; ++k) {
            const auto [lo, hi] = std::minmax_element(corner[k].begin(), corner[k].end());
            extent[k] = int64_t{hi->first} - lo->first;
        }
        int order[3] = {0, 1, 2};
        std::stable_sort(order, order + 3, [&](int a, int b) { return extent[a] > extent[b]; });
        for (int axis : order) {
            std::vector<std::pair<int32_t, uint32_t>>& c = corner[axis];
            std::nth_element(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(c.size() / 2), c.end());
            const uint32_t origin = c[c.size() / 2].second;
            Plane pl;
            pl.n[0] = pl.n[1] = pl.n[2] = 0;
            pl.n[axis] = 1;
            pl.o = verts_[origin];
            pl.origin = origin;
            planes_.push_back(pl);
            groups_.push_back(group_of(pl));
            faces_.push_back(0);
            const uint32_t index = static_cast<uint32_t>(planes_.size() - 1);
            classify_all(index, list, cls);
            if (splits_off_both(cls)) return index;
            planes_.pop_back();
            groups_.pop_back();
            faces_.pop_back();
        }
        return kBspNone;
    }

    /// Splits the polygons of each node by its plane, depth first, in preorder (children after parents).
    /// With opt_.max_chain, a node of more polygons than that whose chosen plane leaves one side empty
    /// (a link of a chain, as every plane of a convex surface does) takes a splitter() plane instead
    /// when one leaves a polygon wholly on each side.
    void build_tree(std::vector<uint32_t> all) {
        struct Item {
            std::vector<uint32_t> list;
            uint32_t parent;
            int child;
            uint32_t depth;
        };
        std::vector<Item> stack;
        std::vector<int> cls;
        if (!all.empty()) stack.push_back({std::move(all), kBspNone, 0, 1});
        while (!stack.empty()) {
            Item item = std::move(stack.back());
            stack.pop_back();
            const uint32_t id = static_cast<uint32_t>(node_plane_.size());
            uint32_t plane = choose(item.list);
            classify_all(plane, item.list, cls);
            if (opt_.max_chain > 0 && item.list.size() > static_cast<size_t>(opt_.max_chain) && one_sided(cls)) {
                std::vector<int> across_cls;
                const uint32_t across = splitter(item.list, across_cls);
                if (across != kBspNone) {
                    plane = across;
                    cls = std::move(across_cls);
                    ++stats_.splitters;
                }
            }
            node_plane_.push_back(plane);
            node_polys_.emplace_back();
            node_child_.push_back({kBspNone, kBspNone});
            node_depth_.push_back(item.depth);
            stats_.max_depth = std::max<size_t>(stats_.max_depth, item.depth);
            if (item.parent != kBspNone) node_child_[item.parent][item.child] = id;
            std::vector<uint32_t> front, back;
            const Plane pl = planes_[plane];
            for (size_t i = 0; i < item.list.size(); ++i) {
                const uint32_t q = item.list[i];
                const int c = cls[i];
                if (c == 0) node_polys_[id].push_back(q);
                else if (c == 1) front.push_back(q);
                else if (c == -1) back.push_back(q);
                else {
                    Poly f, b;
                    split(pl, polys_[q], f, b);
                    ++stats_.cuts;
                    polys_[q] = std::move(f);  // the front part keeps the slot
                    polys_.push_back(std::move(b));
                    if (polys_[q].v.size() >= 3) front.push_back(q);
                    if (polys_.back().v.size() >= 3) back.push_back(static_cast<uint32_t>(polys_.size() - 1));
                }
            }
            if (!back.empty()) stack.push_back({std::move(back), id, 1, item.depth + 1});
            if (!front.empty()) stack.push_back({std::move(front), id, 0, item.depth + 1});
        }
    }

    void classify_all(uint32_t plane, const std::vector<uint32_t>& list, std::vector<int>& cls) const {
        cls.resize(list.size());
        for (size_t i = 0; i < list.size(); ++i) cls[i] = classify(plane, polys_[list[i]]);
    }
    /// Which sides of the plane hold polygons: bit 0 front, bit 1 back (a cut one counts for both).
    static int sides(const std::vector<int>& cls) {
        int s = 0;
        for (int c : cls) s |= (c == 1 || c == 2 ? 1 : 0) | (c == -1 || c == 2 ? 2 : 0);
        return s;
    }
    /// Polygons on one side only: a chain link (none on either: all in the plane, a leaf).
    static bool one_sided(const std::vector<int>& cls) {
        const int s = sides(cls);
        return s == 1 || s == 2;
    }
    /// A polygon wholly on each side: both children then hold fewer polygons than the node, cut ones
    /// counted on both sides (with only cut polygons on one side a split may cut every polygon again
    /// and again, and the tree never ends).
    static bool splits_off_both(const std::vector<int>& cls) {
        bool front = false, back = false;
        for (int c : cls) {
            front = front || c == 1;
            back = back || c == -1;
        }
        return front && back;
    }

    /// Every point made on an edge's line between its ends joins the edge, in order along it.
    std::vector<uint32_t> closed_loop(const Poly& p) {
        std::vector<uint32_t> loop;
        for (size_t i = 0; i < p.v.size(); ++i) {
            const uint32_t a = p.v[i], b = p.v[(i + 1) % p.v.size()], s = p.sup[i];
            loop.push_back(a);
            // Order along the edge itself, exactly: (q - a) . (b - a) in (0, |b - a|^2). A direction taken from
            // two of the support's points could be two rounded cut points a few grid steps apart, pointing
            // anywhere, and misorder the points (a self-crossing loop, overlapping pieces).
            const P& pa = verts_[a];
            const P& pb = verts_[b];
            const int64_t d[3] = {int64_t{pb[0]} - pa[0], int64_t{pb[1]} - pa[1], int64_t{pb[2]} - pa[2]};
            const int64_t len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            std::vector<std::pair<int64_t, uint32_t>> inner;
            for (uint32_t q : supports_[s].points) {
                // A corner of the polygon itself is never inserted (near an edge of a thin polygon it may
                // project inside another edge): the loop visits each point once.
                if (std::find(p.v.begin(), p.v.end(), q) != p.v.end()) continue;
                const P& pq = verts_[q];
                const int64_t t = (int64_t{pq[0]} - pa[0]) * d[0] + (int64_t{pq[1]} - pa[1]) * d[1] + (int64_t{pq[2]} - pa[2]) * d[2];
                if (t > 0 && t < len2) inner.push_back({t, q});
            }
            std::sort(inner.begin(), inner.end());
            for (const auto& e : inner) loop.push_back(e.second);
            stats_.tjunction_points += inner.size();
        }
        return loop;
    }

    /// Twice the area vector of triangle (a, b, c), exact.
    static std::array<I128, 3> area(const P& pa, const P& pb, const P& pc) {
        const int64_t e1[3] = {int64_t{pb[0]} - pa[0], int64_t{pb[1]} - pa[1], int64_t{pb[2]} - pa[2]};
        const int64_t e2[3] = {int64_t{pc[0]} - pa[0], int64_t{pc[1]} - pa[1], int64_t{pc[2]} - pa[2]};
        return {I128(e1[1]) * e2[2] - I128(e1[2]) * e2[1], I128(e1[2]) * e2[0] - I128(e1[0]) * e2[2],
                I128(e1[0]) * e2[1] - I128(e1[1]) * e2[0]};
    }

    /// Triangles of a closed loop: a fan from a corner whose triangles all have area, else from a new
    /// vertex at the centroid, else (a loop made slightly concave by rounded cut points) by clipping ears.
    /// Every triangle then faces the loop's way, so the pieces cover the loop once and keep its area.
    void triangulate(const std::vector<uint32_t>& loop, const Plane& pl, std::vector<std::array<uint32_t, 3>>& out) {
        const size_t n = loop.size();
        auto facing_p = [&](const P& a, const P& b, const P& c) {
            const auto ar = area(a, b, c);
            return ar[0] * pl.n[0] + ar[1] * pl.n[1] + ar[2] * pl.n[2];
        };
        auto facing = [&](uint32_t a, uint32_t b, uint32_t c) { return facing_p(verts_[a], verts_[b], verts_[c]); };
        I128 total = 0;  // orientation of the loop along the node's normal
        for (size_t i = 1; i + 1 < n; ++i) total += facing(loop[0], loop[i], loop[i + 1]);
        const int orient = total > 0 ? 1 : -1;
        for (size_t k = 0; k < n; ++k) {
            bool good = true;
            for (size_t i = 1; i + 1 < n && good; ++i) good = sign(facing(loop[k], loop[(k + i) % n], loop[(k + i + 1) % n])) == orient;
            if (!good) continue;
            for (size_t i = 1; i + 1 < n; ++i) out.push_back({loop[k], loop[(k + i) % n], loop[(k + i + 1) % n]});
            return;
        }
        P c{};
        for (int d = 0; d < 3; ++d) {
            double sum = 0;
            for (uint32_t v : loop) sum += verts_[v][d];
            c[d] = static_cast<int32_t>(std::llround(sum / static_cast<double>(n)));
        }
        bool good = true;
        for (size_t i = 0; i < n && good; ++i) good = sign(facing_p(c, verts_[loop[i]], verts_[loop[(i + 1) % n]])) == orient;
        if (good) {  // the vertex is made only when used
            const uint32_t cv = vertex(c);
            for (size_t i = 0; i < n; ++i) out.push_back({cv, loop[i], loop[(i + 1) % n]});
            return;
        }
        clip_ears(loop, orient, facing, out);
    }

    /// Ear clipping with exact orientations (projected along the plane's normal): an ear is a corner
    /// turning the loop's way whose triangle holds no other loop point, not even on its border (a
    /// T-junction point there would leave a crack). A rest with no ear (collinear or self-touching after
    /// rounding) is fanned as it is.
    template <class Facing>
    void clip_ears(std::vector<uint32_t> rest, int orient, const Facing& facing, std::vector<std::array<uint32_t, 3>>& out) {
        auto holds = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t q) {
            return sign(facing(a, b, q)) != -orient && sign(facing(b, c, q)) != -orient && sign(facing(c, a, q)) != -orient;
        };
        while (rest.size() > 3) {
            const size_t m = rest.size();
            bool clipped = false;
            for (size_t i = 0; i < m && !clipped; ++i) {
                const uint32_t a = rest[(i + m - 1) % m], b = rest[i], c = rest[(i + 1) % m];
                if (sign(facing(a, b, c)) != orient) continue;
                bool empty = true;
                for (uint32_t q : rest)
                    if (q != a && q != b && q != c && holds(a, b, c, q)) empty = false;
                if (!empty) continue;
                out.push_back({a, b, c});
                rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
                clipped = true;
            }
            if (!clipped) break;
        }
        for (size_t i = 1; i + 1 < rest.size(); ++i) out.push_back({rest[0], rest[i], rest[i + 1]});
    }

    bool finish(BspBuilt& out, std::string& error) {
        const size_t nodes = node_plane_.size();
        out.nodes.assign(nodes, BspNode{});
        out.triangles.clear();
        std::vector<std::array<int64_t, 6>> box(nodes, {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN, INT64_MIN});
        for (size_t id = 0; id < nodes; ++id) {
            const Plane& pl = planes_[node_plane_[id]];
            BspNode& nd = out.nodes[id];
            nd.n[0] = pl.n[0];
            nd.n[1] = pl.n[1];
            nd.n[2] = pl.n[2];
            nd.origin = pl.origin;
            nd.child[0] = node_child_[id][0];
            nd.child[1] = node_child_[id][1];
            nd.first = static_cast<uint32_t>(out.triangles.size());
            Vec3q30 unit{};
            if (normalize({pl.n[0], pl.n[1], pl.n[2]}, unit)) {
                auto to14 = [](Q30 c) { return static_cast<int16_t>((c.raw() + (1 << 15)) >> 16); };
                nd.normal[0] = to14(unit.x);
                nd.normal[1] = to14(unit.y);
                nd.normal[2] = to14(unit.z);
            }
            for (uint32_t q : node_polys_[id]) {
                const Poly& p = polys_[q];
                const Plane& own = planes_[p.tri];
                const I128 dot = I128(own.n[0]) * pl.n[0] + I128(own.n[1]) * pl.n[1] + I128(own.n[2]) * pl.n[2];
                const uint32_t face = (faces_[p.tri] & kBspFaceMask) | (dot < 0 ? kBspFaceBack : 0u);
                ++stats_.polygons;
                std::vector<std::array<uint32_t, 3>> tris;
                triangulate(closed_loop(p), own, tris);
                for (const auto& t : tris) {
                    out.triangles.push_back({{t[0], t[1], t[2]}, face});
                    for (uint32_t v : t)
                        for (int k = 0; k < 3; ++k) {
                            box[id][k] = std::min<int64_t>(box[id][k], verts_[v][k]);
                            box[id][3 + k] = std::max<int64_t>(box[id][3 + k], verts_[v][k]);
                        }
                }
            }
            nd.count = static_cast<uint32_t>(out.triangles.size() - nd.first);
            stats_.largest_node = std::max<size_t>(stats_.largest_node, nd.count);
        }
        for (size_t id = nodes; id-- > 0;) {  // children come after their parents: boxes bottom-up
            for (uint32_t c : node_child_[id])
                if (c != kBspNone)
                    for (int k = 0; k < 3; ++k) {
                        box[id][k] = std::min(box[id][k], box[c][k]);
                        box[id][3 + k] = std::max(box[id][3 + k], box[c][3 + k]);
                    }
            for (int k = 0; k < 3; ++k) {
                if (box[id][k] > box[id][3 + k]) box[id][k] = box[id][3 + k] = 0;  // no triangle below (all degenerate)
                out.nodes[id].box_min[k] = static_cast<int16_t>(box[id][k] >> kBspBoxShift);  // floor
                out.nodes[id].box_max[k] = static_cast<int16_t>(-((-box[id][3 + k]) >> kBspBoxShift));  // ceil
            }
        }
        // bsp_load() takes fewer than 2^30 nodes (walks tag indices with two bits).
        if (verts_.size() >= 0x80000000u || out.triangles.size() >= 0x80000000u || nodes >= 0x40000000u) {
            error = "the tree is too large for the format";
            return false;
        }
        out.vertices.clear();
        for (const P& p : verts_) out.vertices.push_back({p[0], p[1], p[2]});
        out.max_depth = static_cast<uint32_t>(stats_.max_depth);
        stats_.nodes = nodes;
        stats_.triangles = out.triangles.size();
        stats_.vertices = verts_.size();
        return true;
    }

    const BspOptions& opt_;
    BspStats& stats_;
    std::vector<P> verts_;
    std::unordered_map<P, uint32_t, PHash> index_;
    std::vector<Plane> planes_;    ///< per input triangle kept
    std::vector<uint32_t> groups_;  ///< its group of equal planes
    std::map<std::tuple<int64_t, int64_t, int64_t, int64_t, uint64_t>, uint32_t> group_index_;
    std::vector<uint32_t> faces_;  ///< face id per input triangle kept
    std::vector<Poly> polys_;
    std::vector<Support> supports_;
    std::vector<uint32_t> node_plane_, node_depth_;
    std::vector<std::vector<uint32_t>> node_polys_;
    std::vector<std::array<uint32_t, 2>> node_child_;
    // choose()'s scratch: the sampled polygons' groups, the end of each one's corners in sample_corner_
    // (indices into sample_point_, its distinct corners), their sides; corner_stamp_ (stamp, index) per
    // vertex marks those already gathered for the current call.
    std::vector<uint32_t> sample_group_, sample_end_, sample_corner_;
    std::vector<P> sample_point_;
    std::vector<uint8_t> point_side_;
    std::vector<std::array<uint32_t, 2>> corner_stamp_;
    uint32_t stamp_ = 0;
};

BspScaled to_scaled(double v) {
    if (v == 0 || !std::isfinite(v)) return {0, 0};
    int e = 0;
    const double m = std::frexp(v, &e);  // v = m 2^e, 0.5 <= |m| < 1
    return {static_cast<int32_t>(std::llround(m * 1073741824.0)), e};
}
double from_scaled(BspScaled s) {  // any exponent a blob holds: past +-2000 the value is 0 or inf anyway
    return std::ldexp(static_cast<double>(s.mantissa_q30), std::clamp(s.exponent, -2000, 2000) - 30);
}

}  // namespace

namespace {

using V3 = std::array<int64_t, 3>;

V3 sub3(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// det[b - a, c - a, p - a]: positive when p lies on the front (normal) side of triangle a b c. Exact for
/// coordinates below 2^35.
I128 orient3(const V3& a, const V3& b, const V3& c, const V3& p) {
    const V3 u = sub3(b, a), v = sub3(c, a), w = sub3(p, a);
    return (I128(u[0]) * v[1] - I128(u[1]) * v[0]) * w[2] + (I128(u[1]) * v[2] - I128(u[2]) * v[1]) * w[0] +
           (I128(u[2]) * v[0] - I128(u[0]) * v[2]) * w[1];
}

int sgn(I128 v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

/// label_cells()'s work on one tree: the checks, the ray casts and the labels.
class CellLabeller {
public:
    CellLabeller(BspBuilt& t, BspStats& stats) : t_(t), stats_(stats) {}

    void run() {
        stats_.cells = BspCells::labelled;
        stats_.cells_labelled = 0;
        stats_.winding_low = stats_.winding_high = 0;
        stats_.cells_stray_raw = 0;
        for (BspNode& n : t_.nodes) n.cells = 0;
        if (t_.nodes.empty()) return none(BspCells::empty, "no nodes");
        if (!closed()) return none(BspCells::open, "the surface is not closed (an edge without its reverse)");
        // A binary tree of N nodes has N + 1 empty children, each cast against every triangle.
        if (static_cast<double>(t_.nodes.size() + 1) * static_cast<double>(t_.triangles.size()) > 4e9)
            return none(BspCells::too_large, "too large to label (empty children x triangles > 4e9)");
        if (!strays_within(kBspCellStrayRaw))
            return none(BspCells::straying, "a triangle strays from its cell by more than " + std::to_string(kBspCellStrayRaw) + " raw units");
        prepare_casts();
        std::vector<int> winding;
        for (const BspNode& n : t_.nodes)
            for (int c = 0; c < 2; ++c) {
                if (n.child[c] != kBspNone) continue;
                int w = 0;
                if (!winding_of(n, c, w))
                    return none(BspCells::unclear, "a cell's winding number is unclear (a surface at its start, or rays through edges)");
                winding.push_back(w);
            }
        assign(winding);
    }

private:
    enum class Cast { known, again, unknown };

    void none(BspCells why, const std::string& note) {
        stats_.cells = why;
        stats_.cells_note = note;
        stats_.cells_labelled = 0;
        for (BspNode& n : t_.nodes) n.cells = 0;
    }

    V3 pos(uint32_t v) const { return V3{t_.vertices[v].x, t_.vertices[v].y, t_.vertices[v].z}; }

    /// n . (p - origin), exact.
    I128 side(const BspNode& n, const V3& p) const {
        const V3 o = pos(n.origin);
        return I128(n.n[0]) * (p[0] - o[0]) + I128(n.n[1]) * (p[1] - o[1]) + I128(n.n[2]) * (p[2] - o[2]);
    }

    static double norm(const BspNode& n) {
        return std::sqrt(static_cast<double>(n.n[0]) * static_cast<double>(n.n[0]) + static_cast<double>(n.n[1]) * static_cast<double>(n.n[1]) +
                         static_cast<double>(n.n[2]) * static_cast<double>(n.n[2]));
    }

    /// Every directed edge used as often as its reverse: a 2-cycle, so winding numbers exist.
    bool closed() const {
        std::unordered_map<uint64_t, int> edges;
        auto key = [](uint32_t a, uint32_t b) { return (uint64_t{a} << 32) | b; };
        for (const BspTriangle& tr : t_.triangles)
            for (int i = 0; i < 3; ++i) ++edges[key(tr.v[i], tr.v[(i + 1) % 3])];
        for (const auto& [k, count] : edges) {
            const auto it = edges.find(key(static_cast<uint32_t>(k), static_cast<uint32_t>(k >> 32)));
            if (it == edges.end() || it->second != count) return false;
        }
        return true;
    }

    /// Every triangle's vertices within `limit` of its node's plane and at most `limit` past each plane
    /// above it, on the wrong side (cut points are rounded to the grid); records the largest stray.
    bool strays_within(double limit) {
        struct Visit {
            uint32_t node, depth, parent;
            int side;  // the side of the parent's plane this subtree lies on: +1 front, -1 back
        };
        std::vector<std::pair<uint32_t, int>> path;  // the ancestors of the visited node and its side of each
        std::vector<Visit> todo{{0u, 0u, 0u, 0}};
        double worst = 0;
        while (!todo.empty()) {
            const Visit at = todo.back();
            todo.pop_back();
            path.resize(at.depth);  // preorder: path[0, depth - 1) still holds this node's upper ancestors
            if (at.depth > 0) path[at.depth - 1] = {at.parent, at.side};
            const BspNode& n = t_.nodes[at.node];
            for (uint32_t k = n.first; k < n.first + n.count; ++k)
                for (uint32_t v : t_.triangles[k].v) {
                    const V3 p = pos(v);
                    worst = std::max(worst, std::fabs(static_cast<double>(side(n, p))) / norm(n));
                    for (const auto& [a, sd] : path)
                        worst = std::max(worst, -static_cast<double>(side(t_.nodes[a], p)) * sd / norm(t_.nodes[a]));
                }
            if (n.child[1] != kBspNone) todo.push_back({n.child[1], at.depth + 1, at.node, -1});
            if (n.child[0] != kBspNone) todo.push_back({n.child[0], at.depth + 1, at.node, 1});
        }
        stats_.cells_stray_raw = worst;
        return worst <= limit;
    }

    /// Triangles in x3 coordinates (centres integral), which have area, and their boxes.
    void prepare_casts() {
        const size_t n = t_.triangles.size();
        tri3_.assign(n, {});
        has_area_.assign(n, 0);
        box_.assign(n, {});
        for (size_t k = 0; k < n; ++k) {
            for (int i = 0; i < 3; ++i) {
                const V3 p = pos(t_.triangles[k].v[i]);
                tri3_[k][i] = {3 * p[0], 3 * p[1], 3 * p[2]};
            }
            const auto& u = tri3_[k];
            has_area_[k] = orient3(u[0], u[1], u[2], {u[0][0] + 1, u[0][1], u[0][2]}) != 0 ||
                           orient3(u[0], u[1], u[2], {u[0][0], u[0][1] + 1, u[0][2]}) != 0 ||
                           orient3(u[0], u[1], u[2], {u[0][0], u[0][1], u[0][2] + 1}) != 0;
            for (int i = 0; i < 3; ++i) {  // widened by one: a box miss is certain
                box_[k][i] = static_cast<double>(std::min({u[0][i], u[1][i], u[2][i]})) - 1;
                box_[k][3 + i] = static_cast<double>(std::max({u[0][i], u[1][i], u[2][i]})) + 1;
            }
        }
    }

    /// Whether segment q -> r may meet box b (slab test in doubles, with slack: a miss is certain).
    static bool may_meet(const V3& q, const V3& r, const std::array<double, 6>& b) {
        double lo = 0, hi = 1;
        for (int i = 0; i < 3; ++i) {
            const double o = static_cast<double>(q[i]), d = static_cast<double>(r[i] - q[i]);
            if (d == 0) {
                if (o < b[i] || o > b[3 + i]) return false;
                continue;
            }
            double t0 = (b[i] - o) / d, t1 = (b[3 + i] - o) / d;
            if (t0 > t1) std::swap(t0, t1);
            lo = std::max(lo, t0 - 1e-9);
            hi = std::min(hi, t1 + 1e-9);
            if (lo > hi) return false;
        }
        return true;
    }

    /// Signed crossings of the segment q -> r (r beyond every triangle) with every triangle but `from`:
    /// w(q) = those left through a front face - those entered through one.
    Cast cast(size_t from, const V3& q, const V3& r, int& w) const {
        const double dx = static_cast<double>(r[0] - q[0]), dy = static_cast<double>(r[1] - q[1]), dz = static_cast<double>(r[2] - q[2]);
        const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
        w = 0;
        for (size_t k = 0; k < tri3_.size(); ++k) {
            if (k == from || !has_area_[k] || !may_meet(q, r, box_[k])) continue;
            const auto& u = tri3_[k];
            const I128 sq = orient3(u[0], u[1], u[2], q), sr = orient3(u[0], u[1], u[2], r);
            if (sr == 0) return Cast::again;  // the far end in its plane
            if (sq != 0 && (sq > 0) == (sr > 0)) continue;
            // The line against the three edges: one sign for all when it passes through the triangle.
            const int o1 = sgn(orient3(q, r, u[0], u[1])), o2 = sgn(orient3(q, r, u[1], u[2])), o3 = sgn(orient3(q, r, u[2], u[0]));
            const bool all_pos = o1 >= 0 && o2 >= 0 && o3 >= 0, all_neg = o1 <= 0 && o2 <= 0 && o3 <= 0;
            if (!all_pos && !all_neg) continue;  // passes beside it
            if (sq == 0) return Cast::unknown;   // the start on another triangle (or its border): two surfaces meet there
            if (o1 == 0 || o2 == 0 || o3 == 0) return Cast::again;  // through an edge or a vertex
            const double along = static_cast<double>(sq) / (static_cast<double>(sq) - static_cast<double>(sr)) * length;
            if (along < 3.0 * kBspCellMarginRaw) return Cast::unknown;  // a surface within the margin: the start's side is unclear
            w += sq < 0 ? 1 : -1;  // left through a front face: the start lies one deeper
        }
        return Cast::known;
    }

    /// The winding number of node n's empty child c, by rays from the centre of its largest triangle
    /// into the child's side (tilted at random; cast again when one passes through an edge). Every
    /// triangle of the node borders the child's cell, so when another surface lies within the margin of
    /// that centre (a sliver along two faces' line), the next largest one starts the rays.
    bool winding_of(const BspNode& n, int c, int& w) {
        std::vector<std::pair<I128, uint32_t>> by_area;  // largest first: its centre lies farthest from other surfaces
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            const auto& u = tri3_[k];
            const V3 a = sub3(u[1], u[0]), b = sub3(u[2], u[0]);
            const I128 x = I128(a[1]) * b[2] - I128(a[2]) * b[1], y = I128(a[2]) * b[0] - I128(a[0]) * b[2],
                       z = I128(a[0]) * b[1] - I128(a[1]) * b[0];
            by_area.push_back({x * x + y * y + z * z, k});  // below 2^126 for x3 coordinates below 2^31
        }
        std::stable_sort(by_area.begin(), by_area.end(), [](const auto& l, const auto& r) { return l.first > r.first; });
        for (const auto& [area, start] : by_area) {
            const auto& u = tri3_[start];
            const V3 q = {u[0][0] + u[1][0] + u[2][0], u[0][1] + u[1][1] + u[2][1], u[0][2] + u[1][2] + u[2][2]};
            const V3 centre = {q[0] / 3, q[1] / 3, q[2] / 3};  // exact: the sum of three x3 coordinates
            const double len = norm(n), s = c == 0 ? 1.0 : -1.0;
            for (int attempt = 0; attempt < 16; ++attempt) {
                V3 r;  // far beyond the world (|x3 coordinates| < 2^29) on the child's side, slightly tilted
                for (int i = 0; i < 3; ++i)
                    r[i] = centre[i] + static_cast<int64_t>(std::llround(s * static_cast<double>(n.n[i]) / len * 0x1p33)) + jitter_(rng_);
                const I128 along = I128(n.n[0]) * (r[0] - centre[0]) + I128(n.n[1]) * (r[1] - centre[1]) + I128(n.n[2]) * (r[2] - centre[2]);
                if (sgn(along) != (c == 0 ? 1 : -1)) continue;  // the ray must leave into the child's side
                const Cast result = cast(start, centre, r, w);
                if (result == Cast::known) return true;
                if (result == Cast::unknown) break;  // another surface at this start: try the next triangle
            }
        }
        return false;
    }

    /// Labels the cells of the lowest and highest winding numbers (0 outside counted), in node order.
    void assign(const std::vector<int>& winding) {
        int low = 0, high = 0;
        for (int w : winding) {
            low = std::min(low, w);
            high = std::max(high, w);
        }
        if (low == high) return none(BspCells::uniform, "every cell has the same winding number");
        size_t next = 0;
        for (BspNode& n : t_.nodes)
            for (int c = 0; c < 2; ++c) {
                if (n.child[c] != kBspNone) continue;
                const int w = winding[next++];
                if (w == low) n.cells |= static_cast<uint16_t>(kBspCellLowest << c);
                else if (w == high) n.cells |= static_cast<uint16_t>(kBspCellHighest << c);
                if (w == low || w == high) ++stats_.cells_labelled;
            }
        stats_.winding_low = low;
        stats_.winding_high = high;
        stats_.cells_note.clear();
    }

    BspBuilt& t_;
    BspStats& stats_;
    std::vector<std::array<V3, 3>> tri3_;
    std::vector<char> has_area_;
    std::vector<std::array<double, 6>> box_;
    std::mt19937_64 rng_{0x5EED};
    std::uniform_int_distribution<int64_t> jitter_{-(int64_t{1} << 29), int64_t{1} << 29};
};

}  // namespace

void label_cells(BspBuilt& t, BspStats& stats) { CellLabeller(t, stats).run(); }

bool build_bsp(const std::vector<Vec3q16>& positions, const std::vector<Tri>& tris, const std::vector<uint32_t>& ids,
               const BspOptions& opt, BspBuilt& out, BspStats& stats, std::string& error) {
    stats = BspStats{};
    // The tree's node boxes must hold every vertex within the BSP world (bsp_load() refuses others with
    // out_of_range); say so here rather than build a tree no walk will load.
    const int32_t limit = kBspWorldLimitRaw - (int32_t{1} << kBspBoxShift);
    for (size_t i = 0; i < positions.size(); ++i)
        for (const Q16 c : {positions[i].x, positions[i].y, positions[i].z})
            if (c.raw() <= -limit || c.raw() >= limit) {
                error = "vertex " + std::to_string(i) + " lies " + std::to_string(std::abs(c.raw() / 65536.0)) +
                        " units from the origin, beyond the BSP world of +-" + std::to_string(limit / 65536) + " units";
                return false;
            }
    Builder b(opt, stats);
    if (!b.run(positions, tris, ids, out, error)) return false;
    label_cells(out, stats);
    return true;
}

bool bsp_model_fit(const ObjModel& model, BspFit& out, std::string& error) {
    if (model.vertices.empty()) {
        error = "empty model";
        return false;
    }
    Vec3d lo = model.vertices[0], hi = model.vertices[0];
    for (const auto& v : model.vertices)
        for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], v[i]); hi[i] = std::max(hi[i], v[i]); }
    double half = 0;
    for (int i = 0; i < 3; ++i) half = std::max(half, (hi[i] - lo[i]) / 2);
    if (!std::isfinite(half) || half <= 0 || !std::isfinite(kFitHalfExtent / half)) {
        char extent[32];  // %g: std::to_string's %f printed a model of extent 1e-310 as "0.000000"
        std::snprintf(extent, sizeof extent, "%g", half * 2);
        error = std::string("model cannot be represented in fixed point (extent ") + extent + ")";
        return false;
    }
    for (int i = 0; i < 3; ++i) out.centre[i] = from_scaled(to_scaled(lo[i] / 2 + hi[i] / 2));
    out.scale = from_scaled(to_scaled(kFitHalfExtent / half));
    return true;
}

std::vector<uint8_t> bsp_blob(const BspBuilt& tree, const BspFit& fit) {
    const BspLayout l = bsp_layout(static_cast<uint32_t>(tree.nodes.size()), static_cast<uint32_t>(tree.triangles.size()),
                                   static_cast<uint32_t>(tree.vertices.size()));
    std::vector<uint8_t> blob(l.total, 0);
    // (memcpy from an empty vector's null data() is undefined even for 0 bytes: an empty tree.)
    if (!tree.nodes.empty()) std::memcpy(blob.data() + l.nodes, tree.nodes.data(), tree.nodes.size() * sizeof(BspNode));
    if (!tree.triangles.empty())
        std::memcpy(blob.data() + l.triangles, tree.triangles.data(), tree.triangles.size() * sizeof(BspTriangle));
    if (!tree.vertices.empty())
        std::memcpy(blob.data() + l.vertices, tree.vertices.data(), tree.vertices.size() * sizeof(BspVertex));
    BspHeader h{};
    h.magic = kBspMagic;
    h.version = kBspVersion;
    h.header_size = sizeof(BspHeader);
    h.node_count = static_cast<uint32_t>(tree.nodes.size());
    h.triangle_count = static_cast<uint32_t>(tree.triangles.size());
    h.vertex_count = static_cast<uint32_t>(tree.vertices.size());
    h.max_depth = tree.max_depth;
    h.total_size = static_cast<uint32_t>(l.total);
    for (int i = 0; i < 3; ++i) h.centre[i] = to_scaled(fit.centre[i]);
    h.scale = to_scaled(fit.scale);
    std::memcpy(blob.data(), &h, sizeof h);
    h.checksum = bsp_checksum(blob.data(), blob.size());  // over the header too, so after it is in place
    std::memcpy(blob.data(), &h, sizeof h);
    return blob;
}

BspFit bsp_fit_of(const BspHeader& h) {
    BspFit f;
    for (int i = 0; i < 3; ++i) f.centre[i] = from_scaled(h.centre[i]);
    f.scale = from_scaled(h.scale);
    return f;
}

std::string bsp_header_source(const std::vector<uint8_t>& blob, const std::string& name, const std::string& source,
                              const std::string& options, const std::string& extra) {
    std::ostringstream o;
    o << "// " << name << ": a BSP tree built by hider-bsp from " << source << " in the flat format of\n"
      << "// lib/hider/bsp/format.hpp (" << blob.size() << " bytes of flash). Do not edit; rebuild it instead.\n";
    if (!options.empty()) o << "// Options: " << options << "\n";
    o << "// Load it with hider::bsp_load({kBlob, sizeof kBlob}, stack, tree).\n"
      << "#pragma once\n#include <hider/view.hpp>\n\nnamespace hider::bsp_data::" << name << " {\n\n"
      << "alignas(8) inline constexpr uint8_t kBlob[" << blob.size() << "] = {";
    for (size_t i = 0; i < blob.size(); ++i) {
        if (i % 24 == 0) o << "\n   ";
        o << ' ' << static_cast<unsigned>(blob[i]) << ',';
    }
    BspHeader h{};
    std::memcpy(&h, blob.data(), std::min(blob.size(), sizeof h));
    o << "\n};\n\n"
      << "/// The header's counts, for static storage: one ScreenVertex per vertex, bsp_stack_entries(kMaxDepth)\n"
      << "/// stack entries (bsp_load() checks both against the blob).\n"
      << "inline constexpr uint32_t kNodeCount = " << h.node_count << ";\n"
      << "inline constexpr uint32_t kTriangleCount = " << h.triangle_count << ";\n"
      << "inline constexpr uint32_t kVertexCount = " << h.vertex_count << ";\n"
      << "inline constexpr uint32_t kMaxDepth = " << h.max_depth << ";\n\n"
      << extra << "}  // namespace hider::bsp_data::" << name << "\n";
    return o.str();
}

bool bsp_from_obj(const std::string& path, const BspOptions& opt, std::vector<uint8_t>& blob, BspStats& stats,
                  std::string& error) {
    ObjModel model;
    ObjError err;
    if (!load_obj(path, model, err)) {
        error = format(err);
        return false;
    }
    const std::vector<int> badly_fanned = badly_fanned_faces(model);
    BspFit fit;
    if (!bsp_model_fit(model, fit, error)) {
        error = path + ": " + error;
        return false;
    }
    CameraArgs cam;
    cam.fit_centre = fit.centre;
    cam.fit_scale = fit.scale;
    // The camera is irrelevant here (only the world positions are kept): one inside the world, so that no
    // model the world holds fails for want of a default eye (which overflows for coordinates near 1.8e308).
    cam.width = cam.height = 1;
    cam.target = fit.centre;
    const double half = kFitHalfExtent / fit.scale;  // a half extent of the model, towards the origin
    cam.eye = Vec3d{fit.centre[0], fit.centre[1], fit.centre[2] + (fit.centre[2] > 0 ? -half : half)};
    Scene scene;
    if (!build_scene(model, cam, scene, error)) {
        error = path + ": " + error;
        return false;
    }
    const std::vector<int> collapsed = collapsed_faces(model, scene);
    // The blob keeps the centre to 30 bits: for a model far from the origin for its size, the rounding
    // times the scale moves it off the tree's world (whose node boxes must hold every vertex).
    const int32_t limit = kBspWorldLimitRaw - (int32_t{1} << kBspBoxShift);
    for (const Vec3q16& v : scene.positions)
        for (const Q16 c : {v.x, v.y, v.z})
            if (c.raw() <= -limit || c.raw() >= limit) {
                std::ostringstream o;
                o << path << ": the model lies too far from the origin for its size (centre " << fit.centre[0] << ", "
                  << fit.centre[1] << ", " << fit.centre[2] << ", extent " << 2 * half
                  << "): a tree keeps its centre to 30 bits, which puts a vertex " << std::abs(to_double(c))
                  << " world units from it, beyond the tree's world of +-" << limit / 65536
                  << "; move the model nearer the origin";
                error = o.str();
                return false;
            }
    BspBuilt tree;
    if (!build_bsp(scene.positions, scene.tris, scene.ids, opt, tree, stats, error)) {
        error = path + ": " + error;
        return false;
    }
    blob = bsp_blob(tree, fit);
    stats.bytes = blob.size();
    stats.badly_fanned = badly_fanned;  // build_bsp() starts the statistics afresh
    stats.collapsed = collapsed;
    return true;
}

bool bsp_scene(const BspTree& tree, const CameraArgs& args, Scene& out, std::string& error) {
    const BspFit fit = bsp_fit_of(*tree.header);
    if (!(fit.scale > 0) || !std::isfinite(fit.scale) || !std::isfinite(fit.centre[0]) || !std::isfinite(fit.centre[1]) ||
        !std::isfinite(fit.centre[2])) {
        error = "the tree's world transform is unusable";
        return false;
    }
    ObjModel model;  // the tree's vertices in model units: camera defaults as for the OBJ it came from
    for (const Vec3q16& v : tree.vertices)
        model.vertices.push_back({to_double(v.x) / fit.scale + fit.centre[0], to_double(v.y) / fit.scale + fit.centre[1],
                                  to_double(v.z) / fit.scale + fit.centre[2]});
    if (!model.vertices.empty()) model.faces.push_back(ObjFace{{0, 0, 0}, 1, 0});  // build_scene wants a face
    CameraArgs cam = args;
    cam.fit_centre = fit.centre;
    cam.fit_scale = fit.scale;
    // A tree's cuts may take it past a Mesh's 65,536 vertices (the bunny's: 96,703); its walk indexes them
    // in 32 bits and projects them without a Mesh.
    if (!build_scene(model, cam, out, error, tree.vertices.size())) return false;
    for (size_t i = 0; i < tree.vertices.size(); ++i)
        if (!(out.positions[i] == tree.vertices[i])) {
            error = "the tree's world transform does not reproduce its vertices";
            return false;
        }
    return true;
}

}  // namespace hider::tool

// Binned-SAH BVH builder (see bvh_build.hpp). Recursion depth is bounded by options.max_depth.
#include "common/bvh_build.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

namespace hider::tool {
namespace {

struct Box {
    std::array<int32_t, 3> lo{INT32_MAX, INT32_MAX, INT32_MAX}, hi{INT32_MIN, INT32_MIN, INT32_MIN};
    void grow(const Box& b) {
        for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], b.lo[i]); hi[i] = std::max(hi[i], b.hi[i]); }
    }
    bool empty() const { return lo[0] > hi[0]; }
    double area() const {
        if (empty()) return 0;
        const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
        return 2 * (x * y + y * z + z * x);
    }
};

struct Prim {
    Box box;
    std::array<double, 3> centre;  // twice the box centre, raw
    uint32_t tri;
};

constexpr int kBins = 16;

class Builder {
public:
    Builder(std::vector<Prim>& prims, BakedBvh& out, const BvhBuildOptions& opt) : prims_(prims), out_(out), opt_(opt) {}

    /// Emits the subtree of prims_[begin, end) at `depth` (root 1) in pre-order.
    void build(size_t begin, size_t end, uint16_t depth) {
        deepest_ = std::max(deepest_, depth);
        const uint32_t index = static_cast<uint32_t>(out_.nodes.size());
        out_.nodes.push_back({});
        Box box;
        for (size_t i = begin; i < end; ++i) box.grow(prims_[i].box);
        const size_t n = end - begin;
        size_t mid = begin;
        if (n > 1 && depth < opt_.max_depth && split(begin, end, box, mid)) {
            build(begin, mid, static_cast<uint16_t>(depth + 1));
            const uint32_t second = static_cast<uint32_t>(out_.nodes.size());
            build(mid, end, static_cast<uint16_t>(depth + 1));
            set(index, box, second, 0);
            return;
        }
        const uint32_t first = static_cast<uint32_t>(out_.triangles.size());
        for (size_t i = begin; i < end; ++i) out_.triangles.push_back(prims_[i].tri);
        set(index, box, first, static_cast<uint32_t>(n));
    }

    uint16_t deepest() const { return deepest_; }

private:
    void set(uint32_t index, const Box& b, uint32_t first, uint32_t count) {
        ray::BvhNode& node = out_.nodes[index];
        for (int i = 0; i < 3; ++i) { node.lo[i] = b.lo[i]; node.hi[i] = b.hi[i]; }
        node.first = first;
        node.count = count;
    }

    /// Chooses a split of [begin, end) and partitions it at `mid`; false: keep a leaf.
    bool split(size_t begin, size_t end, const Box& box, size_t& mid) {
        const size_t n = end - begin;
        std::array<double, 3> clo{}, chi{};
        clo.fill(std::numeric_limits<double>::max());
        chi.fill(std::numeric_limits<double>::lowest());
        for (size_t i = begin; i < end; ++i)
            for (int a = 0; a < 3; ++a) { clo[a] = std::min(clo[a], prims_[i].centre[a]); chi[a] = std::max(chi[a], prims_[i].centre[a]); }
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (chi[a] - clo[a] > chi[axis] - clo[axis]) axis = a;
        const double extent = chi[axis] - clo[axis];
        if (extent <= 0) {  // all centres coincide: halve by order so the tree still ends
            if (n <= opt_.max_leaf) return false;
            mid = begin + n / 2;
            return true;
        }
        auto bin_of = [&](const Prim& p) {
            return std::min(kBins - 1, static_cast<int>((p.centre[axis] - clo[axis]) / extent * kBins));
        };
        std::array<Box, kBins> bins;
        std::array<size_t, kBins> counts{};
        for (size_t i = begin; i < end; ++i) {
            const int b = bin_of(prims_[i]);
            bins[b].grow(prims_[i].box);
            ++counts[b];
        }
        // Sweep: cost of splitting after bin k = A(left) N(left) + A(right) N(right).
        std::array<double, kBins> left_cost{};
        Box acc;
        size_t acc_n = 0;
        for (int k = 0; k < kBins - 1; ++k) {
            acc.grow(bins[k]);
            acc_n += counts[k];
            left_cost[k] = acc.area() * double(acc_n);
        }
        double best = std::numeric_limits<double>::max();
        int best_k = -1;
        acc = Box{};
        acc_n = 0;
        for (int k = kBins - 1; k > 0; --k) {
            acc.grow(bins[k]);
            acc_n += counts[k];
            const double cost = left_cost[k - 1] + acc.area() * double(acc_n);
            if (acc_n > 0 && acc_n < n && cost < best) { best = cost; best_k = k - 1; }
        }
        // Both end bins hold a centre, so some split exists. A small node stays a leaf unless the split's
        // expected triangle tests (area-weighted counts) beat testing all n here.
        if (best_k < 0 || (n <= opt_.max_leaf && best >= box.area() * double(n))) return false;
        auto it = std::partition(prims_.begin() + static_cast<std::ptrdiff_t>(begin), prims_.begin() + static_cast<std::ptrdiff_t>(end),
                                 [&](const Prim& p) { return bin_of(p) <= best_k; });
        mid = static_cast<size_t>(it - prims_.begin());
        return mid > begin && mid < end;
    }

    std::vector<Prim>& prims_;
    BakedBvh& out_;
    const BvhBuildOptions& opt_;
    uint16_t deepest_ = 0;
};

}  // namespace

bool build_bvh(const Mesh& mesh, BakedBvh& out, std::string& error, const BvhBuildOptions& options) {
    if (mesh.tris.empty()) {
        error = "mesh has no triangles";
        return false;
    }
    if (options.max_leaf < 1 || options.max_depth < 1) {
        error = "bvh options out of range";
        return false;
    }
    std::vector<Prim> prims(mesh.tris.size());
    for (size_t t = 0; t < mesh.tris.size(); ++t) {
        Prim& p = prims[t];
        for (uint16_t v : mesh.tris[t].v) {
            const Vec3q16& q = mesh.positions[v];
            const int32_t c[3] = {q.x.raw(), q.y.raw(), q.z.raw()};
            for (int i = 0; i < 3; ++i) { p.box.lo[i] = std::min(p.box.lo[i], c[i]); p.box.hi[i] = std::max(p.box.hi[i], c[i]); }
        }
        for (int i = 0; i < 3; ++i) p.centre[i] = double(p.box.lo[i]) + double(p.box.hi[i]);
        p.tri = static_cast<uint32_t>(t);
    }
    BakedBvh b;
    b.nodes.reserve(2 * prims.size());
    b.triangles.reserve(prims.size());
    Builder builder(prims, b, options);
    builder.build(0, prims.size(), 1);
    b.header = {ray::kBvhMagic, ray::kBvhVersion, builder.deepest(), static_cast<uint32_t>(b.nodes.size()),
                static_cast<uint32_t>(b.triangles.size())};
    out = std::move(b);
    return true;
}

}  // namespace hider::tool

// Floating-horizon reference: ray casting from the eye to dense samples of each plot line against the
// surface's triangle mesh (Moller-Trumbore), triangles bucketed by their screen bounding boxes.
#include "support/horizon_reference.hpp"

#include <algorithm>
#include <cmath>

namespace hider::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTile = 8;                 // bucket side in pixels
constexpr double kSamplesPerPixel = 4;   // samples along a line per pixel of its screen length
constexpr double kSelfHit = 1e-6;        // hits at ray parameter > 1 - this are the sample's own triangles

struct V3 {
    double x, y, z;
};
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 unit(V3 a) {
    const double l = std::sqrt(dot(a, a));
    return {a.x / l, a.y / l, a.z / l};
}
V3 lerp(V3 a, V3 b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t}; }

struct Tri {
    V3 v0, e1, e2;
};

class Scene {
public:
    Scene(const HorizonSurface& s, const HorizonCamera& cam) : s_(s), cam_(cam) {
        eye_ = {cam.eye[0], cam.eye[1], cam.eye[2]};
        f_ = unit(sub({cam.target[0], cam.target[1], cam.target[2]}, eye_));
        side_ = unit(cross(f_, {cam.up[0], cam.up[1], cam.up[2]}));
        up_ = cross(side_, f_);
        ty_ = std::tan(cam.fovy_deg * kPi / 360.0);
        tx_ = ty_ * cam.width / cam.height;
        tiles_x_ = (cam.width + kTile - 1) / kTile;
        tiles_y_ = (cam.height + kTile - 1) / kTile;
        tiles_.resize(static_cast<size_t>(tiles_x_) * tiles_y_);
        for (int k = 0; k + 1 < s.rows; ++k)
            for (int i = 0; i + 1 < s.cols; ++i) {
                add({point(k, i), point(k, i + 1), point(k + 1, i + 1)});
                add({point(k, i), point(k + 1, i + 1), point(k + 1, i)});
            }
    }

    V3 point(int k, int i) const {
        return {s_.x[static_cast<size_t>(i)], s_.y[static_cast<size_t>(k) * s_.cols + i], s_.z[static_cast<size_t>(k)]};
    }
    double depth(V3 p) const { return dot(sub(p, eye_), f_); }

    /// Screen position in pixels of a point in front of the eye.
    void project(V3 p, double& sx, double& sy) const {
        const V3 q = sub(p, eye_);
        const double d = dot(q, f_);
        sx = cam_.width * 0.5 * (1.0 + dot(q, side_) / (d * tx_));
        sy = cam_.height * 0.5 * (1.0 - dot(q, up_) / (d * ty_));
    }

    /// Whether the open segment eye -> p meets the mesh before p (p at screen position sx, sy).
    bool hidden(V3 p, double sx, double sy) const {
        const V3 dir = sub(p, eye_);
        const int tx = std::clamp(static_cast<int>(sx) / kTile, 0, tiles_x_ - 1);
        const int ty = std::clamp(static_cast<int>(sy) / kTile, 0, tiles_y_ - 1);
        for (const std::vector<size_t>* list : {&tiles_[static_cast<size_t>(ty) * tiles_x_ + tx], &everywhere_})
            for (size_t t : *list)
                if (hits(tris_[t], dir)) return true;
        return false;
    }

private:
    void add(const V3 (&v)[3]) {
        const size_t index = tris_.size();
        tris_.push_back({v[0], sub(v[1], v[0]), sub(v[2], v[0])});
        double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
        for (const V3& p : v) {
            if (!(depth(p) > 1e-9)) {  // reaches behind the eye: test it everywhere
                everywhere_.push_back(index);
                return;
            }
            double sx = 0, sy = 0;
            project(p, sx, sy);
            x0 = std::min(x0, sx);
            x1 = std::max(x1, sx);
            y0 = std::min(y0, sy);
            y1 = std::max(y1, sy);
        }
        const int c0 = std::max(0, static_cast<int>(std::floor(x0 - 1)) / kTile), c1 = std::min(tiles_x_ - 1, static_cast<int>(std::floor(std::min(x1 + 1, 1e9))) / kTile);
        const int r0 = std::max(0, static_cast<int>(std::floor(y0 - 1)) / kTile), r1 = std::min(tiles_y_ - 1, static_cast<int>(std::floor(std::min(y1 + 1, 1e9))) / kTile);
        if (x1 < -1 || y1 < -1) return;
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) tiles_[static_cast<size_t>(r) * tiles_x_ + c].push_back(index);
    }

    /// Moller-Trumbore: the ray eye + s dir meets the triangle (edges included) at 0 < s < 1 - kSelfHit.
    bool hits(const Tri& t, V3 dir) const {
        const V3 pvec = cross(dir, t.e2);
        const double det = dot(t.e1, pvec);
        if (std::fabs(det) < 1e-300) return false;
        const double inv = 1.0 / det;
        const V3 tvec = sub(eye_, t.v0);
        const double u = dot(tvec, pvec) * inv;
        if (u < -1e-12 || u > 1 + 1e-12) return false;
        const V3 qvec = cross(tvec, t.e1);
        const double v = dot(dir, qvec) * inv;
        if (v < -1e-12 || u + v > 1 + 1e-12) return false;
        const double s = dot(t.e2, qvec) * inv;
        return s > 1e-9 && s < 1.0 - kSelfHit;
    }

    const HorizonSurface& s_;
    const HorizonCamera& cam_;
    V3 eye_{}, f_{}, side_{}, up_{};
    double tx_ = 0, ty_ = 0;
    int tiles_x_ = 0, tiles_y_ = 0;
    std::vector<Tri> tris_;
    std::vector<std::vector<size_t>> tiles_;
    std::vector<size_t> everywhere_;
};

}  // namespace

std::vector<HorizonLine> horizon_lines(const HorizonSurface& s, bool mesh, int step) {
    std::vector<HorizonLine> lines;
    for (int k = 0; k < s.rows; ++k) {
        HorizonLine l{static_cast<uint32_t>(k + 1), {}, {}};
        for (int i = 0; i < s.cols; ++i) {
            l.rows.push_back(k);
            l.cols.push_back(i);
        }
        lines.push_back(l);
    }
    const int last_line = (s.cols - 1 + step - 1) / step;
    for (int j = 0; j <= last_line; ++j) {
        if (!mesh && j != 0 && j != last_line) continue;
        HorizonLine l{static_cast<uint32_t>(s.rows + 1 + j), {}, {}};
        for (int k = 0; k < s.rows; ++k) {
            l.rows.push_back(k);
            l.cols.push_back(std::min(j * step, s.cols - 1));
        }
        lines.push_back(l);
    }
    return lines;
}

std::vector<std::vector<uint32_t>> visible_pixels(const HorizonSurface& s, const HorizonCamera& cam,
                                                  const std::vector<HorizonLine>& lines) {
    const Scene scene(s, cam);
    std::vector<std::vector<uint32_t>> out(lines.size());
    for (size_t n = 0; n < lines.size(); ++n) {
        const HorizonLine& l = lines[n];
        std::vector<uint32_t>& pixels = out[n];
        for (size_t m = 0; m + 1 < l.rows.size(); ++m) {
            const V3 a = scene.point(l.rows[m], l.cols[m]), b = scene.point(l.rows[m + 1], l.cols[m + 1]);
            double steps = 64;  // when an end is behind the eye: sample by a fixed count
            if (scene.depth(a) > cam.near && scene.depth(b) > cam.near) {
                double ax = 0, ay = 0, bx = 0, by = 0;
                scene.project(a, ax, ay);
                scene.project(b, bx, by);
                steps = std::clamp(std::ceil(std::hypot(bx - ax, by - ay) * kSamplesPerPixel), 1.0, 1e5);
            }
            for (int q = 0; q <= static_cast<int>(steps); ++q) {
                const V3 p = lerp(a, b, q / steps);
                if (!(scene.depth(p) >= cam.near)) continue;
                double sx = 0, sy = 0;
                scene.project(p, sx, sy);
                if (!(sx >= 0 && sy >= 0 && sx < cam.width && sy < cam.height)) continue;
                if (scene.hidden(p, sx, sy)) continue;
                pixels.push_back(static_cast<uint32_t>(static_cast<int>(sy) * cam.width + static_cast<int>(sx)));
            }
        }
        std::sort(pixels.begin(), pixels.end());
        pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
    }
    return out;
}

LineAgreement compare_lines(const std::vector<uint32_t>& ids, int width, int height, const std::vector<HorizonLine>& lines,
                            const std::vector<std::vector<uint32_t>>& visible, uint32_t first_id, uint32_t last_id) {
    LineAgreement a;
    uint32_t top = first_id;  // largest id of a line in range
    for (const HorizonLine& l : lines)
        if (l.id >= first_id && l.id <= last_id) top = std::max(top, l.id);
    std::vector<std::vector<uint32_t>> image(static_cast<size_t>(top) + 1);
    for (size_t p = 0; p < ids.size(); ++p)
        if (ids[p] >= first_id && ids[p] <= top) image[ids[p]].push_back(static_cast<uint32_t>(p));
    std::vector<uint8_t> mask(static_cast<size_t>(width) * height, 0);
    // Lines the reference sees at each pixel (any id): an id image holds one of several lines that
    // share a pixel, so a reference pixel also counts as matched when the image shows one of them there.
    std::vector<std::vector<uint32_t>> seen(mask.size());
    for (size_t n = 0; n < lines.size(); ++n)
        for (uint32_t p : visible[n]) seen[p].push_back(lines[n].id);
    auto shared = [&](uint32_t p) {
        return ids[p] != 0 && std::find(seen[p].begin(), seen[p].end(), ids[p]) != seen[p].end();
    };
    // Counts the pixels of `from` with a pixel of `to` in their 8-neighbourhood (or, for_reference, a
    // shared pixel).
    auto matched = [&](const std::vector<uint32_t>& from, const std::vector<uint32_t>& to, bool for_reference) {
        for (uint32_t p : to) mask[p] = 1;
        long m = 0;
        for (uint32_t p : from) {
            const int x = static_cast<int>(p % width), y = static_cast<int>(p / width);
            bool near = for_reference && shared(p);
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    near = nx >= 0 && ny >= 0 && nx < width && ny < height && mask[static_cast<size_t>(ny) * width + nx] != 0;
                }
            m += near;
        }
        for (uint32_t p : to) mask[p] = 0;
        return m;
    };
    for (size_t n = 0; n < lines.size(); ++n) {
        const uint32_t id = lines[n].id;
        if (id < first_id || id > last_id) continue;
        a.image_pixels += static_cast<long>(image[id].size());
        a.ref_pixels += static_cast<long>(visible[n].size());
        a.image_matched += matched(image[id], visible[n], false);
        a.ref_matched += matched(visible[n], image[id], true);
    }
    return a;
}

}  // namespace hider::ref

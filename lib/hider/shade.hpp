// Flat shading per face: headlight (brightness = N.z of the unit face normal in view space, the
// light sitting at the eye), the face id as a colour, or grey by depth (a per-pixel debug mode).
#pragma once
#include <hider/frame.hpp>
#include <hider/mesh.hpp>

namespace hider {

enum class Shade : uint8_t {
    headlight,  ///< base colour * max(N.z, 0); back faces (drawn when not culling) use -N.z
    id,         ///< pixel = (id >> 16 & 255, id >> 8 & 255, id & 255)
    depth,      ///< grey: 255 at DrawOptions::depth_range.min, 0 at .max
};

struct DrawOptions {
    bool cull = true;               ///< drop faces that run clockwise on the image
    Shade shade = Shade::headlight;
    Rgb base{255, 255, 255};        ///< surface colour for headlight shading
    DepthRange depth_range{};       ///< for Shade::depth (from project_vertices)
};

/// Per-frame constants of face shading; color() costs six 32-bit multiplies per face.
class FaceShading {
public:
    FaceShading(const View& view, const DrawOptions& opt) : opt_(opt) {
        for (int j = 0; j < 3; ++j) view_z_[j] = (view.to_view.rot.m[2][j].raw() + (1 << 15)) >> 16;
    }

    /// Colour of triangle t of `mesh`, seen from its front (true) or back side.
    Rgb color(const Mesh& mesh, size_t t, bool front) const {
        if (opt_.shade == Shade::id) return id_color(mesh.id(t));
        if (mesh.normals.empty()) return opt_.base;
        return lit(mesh.normals[t], front);
    }

    /// Colour of a face with this id and unit normal, seen from its front or back side.
    Rgb color(uint32_t id, const Normal14& normal, bool front) const {
        return opt_.shade == Shade::id ? id_color(id) : lit(normal, front);
    }

    /// The headlight's constants (for the Cortex-M draw loops, raster/draw_loop_asm.hpp): the third row of
    /// the view rotation in Q14, and the options.
    int32_t view_z(int j) const { return view_z_[j]; }
    const DrawOptions& options() const { return opt_; }

    /// Rgb565Format::pack(color(mesh, t, front)), the headlight with normals computed in place (the row
    /// kernel's draw loops call it per drawn triangle).
    __attribute__((always_inline)) uint16_t color565(const Mesh& mesh, size_t t, bool front) const {
        if (opt_.shade != Shade::headlight || mesh.normals.empty()) return Rgb565Format::pack(color(mesh, t, front));
        const Normal14& n = mesh.normals[t];
        int32_t b_q16 = (view_z_[0] * n.x + view_z_[1] * n.y + view_z_[2] * n.z) >> 12;
        if (!front) b_q16 = -b_q16;
        b_q16 = clamp<int32_t>(b_q16, 0, int32_t{1} << 16);
        const uint32_t r = static_cast<uint32_t>(opt_.base.r * b_q16 + (1 << 15)) >> 16;
        const uint32_t g = static_cast<uint32_t>(opt_.base.g * b_q16 + (1 << 15)) >> 16;
        const uint32_t b = static_cast<uint32_t>(opt_.base.b * b_q16 + (1 << 15)) >> 16;
        return static_cast<uint16_t>(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
    }

private:
    __attribute__((always_inline)) static Rgb id_color(uint32_t id) {
        return {static_cast<uint8_t>(id >> 16), static_cast<uint8_t>(id >> 8), static_cast<uint8_t>(id)};
    }
    /// Headlight: base * max(N.z, 0) in view space (back side: -N.z).
    __attribute__((always_inline)) Rgb lit(const Normal14& n, bool front) const {
        // Q14 x Q14 products: the sum stays below 2^30, and 14 bits are far more than 8-bit colour needs.
        const int32_t nz_q28 = view_z_[0] * n.x + view_z_[1] * n.y + view_z_[2] * n.z;
        int32_t b_q16 = nz_q28 >> 12;
        if (!front) b_q16 = -b_q16;
        b_q16 = clamp<int32_t>(b_q16, 0, int32_t{1} << 16);
        auto scale = [b_q16](uint8_t c) { return static_cast<uint8_t>((c * b_q16 + (1 << 15)) >> 16); };
        return {scale(opt_.base.r), scale(opt_.base.g), scale(opt_.base.b)};
    }

    DrawOptions opt_;
    int32_t view_z_[3];  // third row of the view rotation, Q14: N_view.z = row . N
};

/// Per-pixel grey from depth over the frame's depth range (a multiply per pixel; debug view only).
template <class Format>
struct DepthShader {
    explicit DepthShader(DepthRange r) : zmin(r.min) {
        const uint32_t span = r.max > r.min ? (r.max - r.min) >> 8 : 1;
        scale = (uint32_t{255} << 16) / (span == 0 ? 1 : span);
    }
    typename Format::Pixel operator()(uint32_t z) const {
        const uint32_t d = z > zmin ? (z - zmin) >> 8 : 0;
        const uint64_t g = min<uint64_t>((uint64_t{d} * scale) >> 16, 255);
        const uint8_t grey = static_cast<uint8_t>(255 - g);
        return Format::pack({grey, grey, grey});
    }
    uint32_t zmin = 0, scale = 0;
};

}  // namespace hider

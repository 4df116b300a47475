// The spin program, for firmware and host alike: renders `frames` frames of a scene into caller-owned
// full-frame buffers, each bracketed by bench_begin()/bench_end() (the host defines them empty), and
// streams each as <prefix>_NNN.ppm through PpmSink. Io: bool open(path), bool write(data, size),
// bool close(), void print(text), void print_u32(v).
#pragma once
#include "common/bench.hpp"
#include "spin/ppm_sink.hpp"
#include "spin/render.hpp"

namespace spin {

/// Frames spin renders at 160x128 (spin320 renders one at 320x240).
constexpr uint32_t kSpinFrames = 4;

/// Buffers of a full-frame renderer, declared by the application (statics on a device).
struct FrameBuffers {
    hider::Span<hider::ScreenVertex> verts;  ///< one per mesh vertex
    uint16_t* color;                         ///< width * height RGB565
    uint16_t* depth;                         ///< width * height
    hider::Span<uint8_t> ppm_row;            ///< width * 3 bytes
};

/// "<prefix>_NNN.ppm" into `out` (room for prefix + 9 characters); frame < 1000.
inline void frame_file_name(char* out, const char* prefix, uint32_t frame) {
    while (*prefix != '\0') *out++ = *prefix++;
    const char digits[3] = {static_cast<char>('0' + frame / 100 % 10), static_cast<char>('0' + frame / 10 % 10),
                            static_cast<char>('0' + frame % 10)};
    const char tail[] = "_000.ppm";
    for (int i = 0; i < 9; ++i) out[i] = tail[i];
    for (int i = 0; i < 3; ++i) out[1 + i] = digits[i];
}

/// Streams a whole RGB565 frame as a PPM file `path` through PpmSink; false on any refusal.
template <class Io>
bool write_frame_ppm(Io& io, const char* path, const uint16_t* rgb565, int32_t width, int32_t height,
                     hider::Span<uint8_t> row) {
    if (!io.open(path)) return false;
    PpmSink<Io> ppm(io, row);
    const bool sent = hider::port::send_frame_in_bands(ppm.sink(), rgb565, static_cast<uint16_t>(width),
                                                       static_cast<uint16_t>(height), static_cast<uint32_t>(width),
                                                       static_cast<uint16_t>(height));
    return io.close() && sent;
}

/// Renders and writes frames 0 .. frames-1; returns the exit status (0 ok, 1 failure, with a message).
template <class Io>
int run(Io& io, const Scene& s, const FrameBuffers& buf, uint32_t frames, const char* prefix) {
    const Frame frame = hider::frame_view<hider::Rgb565Format, uint16_t>(buf.color, buf.depth, s.width, s.height);
    for (uint32_t n = 0; n < frames; ++n) {
        bench_begin();
        const hider::FrameStats st = render_frame(s, n, buf.verts, frame);
        bench_end();
        if (!st.ok()) {
            io.print("spin: render failed: ");
            io.print(hider::status_name(st.status));
            io.print("\n");
            return 1;
        }
        char path[64];
        frame_file_name(path, prefix, n);
        if (!write_frame_ppm(io, path, buf.color, s.width, s.height, buf.ppm_row)) {
            io.print("spin: cannot write ");
            io.print(path);
            io.print("\n");
            return 1;
        }
        io.print(path);
        io.print(": triangles drawn ");
        io.print_u32(st.triangles_drawn);
        io.print("\n");
    }
    return 0;
}

/// One frame (frame 0) of `s` in three bench pairs: view set-up and projection, clear, draw; written as
/// "<prefix>_000.ppm". Returns the exit status as run() does.
template <class Io>
int run_split(Io& io, const Scene& s, const FrameBuffers& buf, const char* prefix, hider::Span<hider::Tri> turned = {}) {
    const Frame frame = hider::frame_view<hider::Rgb565Format, uint16_t>(buf.color, buf.depth, s.width, s.height);
    hider::View view;
    bench_begin();
    hider::Status status = frame_view(s, 0, view);
    if (status == hider::Status::ok) status = hider::project_vertices(view, s.mesh.positions, buf.verts);
    bench_end();
    bench_begin();
    hider::clear(frame, kBackground);
    bench_end();
    hider::FrameStats st;
    bench_begin();
    if (status == hider::Status::ok) st = hider::draw_zbuffer<false>(view, s.mesh, buf.verts, frame, draw_options());
    bench_end();
    if (status != hider::Status::ok || !st.ok()) {
        io.print("spin: render failed\n");
        return 1;
    }
    char path[64];
    frame_file_name(path, prefix, 0);
    if (!write_frame_ppm(io, path, buf.color, s.width, s.height, buf.ppm_row)) {
        io.print("spin: cannot write ");
        io.print(path);
        io.print("\n");
        return 1;
    }
    io.print(path);
    io.print(": triangles drawn ");
    io.print_u32(st.triangles_drawn);
    io.print(", culled ");
    io.print_u32(st.triangles_culled);
    io.print("\n");
    if (turned.size() >= s.mesh.tris.size()) {
        // A fourth pair: the same draw with every face turned away (each front face's winding reversed),
        // so every triangle costs what a culled one does.
        for (size_t t = 0; t < s.mesh.tris.size(); ++t) {
            hider::Tri tri = s.mesh.tris[t];
            const hider::ScreenVertex& a = buf.verts[tri.v[0]];
            const hider::ScreenVertex& b = buf.verts[tri.v[1]];
            const hider::ScreenVertex& c = buf.verts[tri.v[2]];
            if (hider::TriangleRaster::signed_area(a, b, c) < 0) {
                const uint16_t v = tri.v[1];
                tri.v[1] = tri.v[2];
                tri.v[2] = v;
            }
            turned[t] = tri;
        }
        hider::Mesh away = s.mesh;
        away.tris = {turned.data(), s.mesh.tris.size()};
        hider::clear(frame, kBackground);
        bench_begin();
        st = hider::draw_zbuffer<false>(view, away, buf.verts, frame, draw_options());
        bench_end();
        io.print("every face turned away: triangles drawn ");
        io.print_u32(st.triangles_drawn);
        io.print(", culled ");
        io.print_u32(st.triangles_culled);
        io.print("\n");
    }
    return 0;
}

}  // namespace spin

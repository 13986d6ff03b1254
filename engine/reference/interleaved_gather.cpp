#include "engine/reference/interleaved_gather.h"

#include <cmath>
#include <cstdlib>
#include <optional>

#include "engine/core/parallel.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"
#include "engine/trace/shading_point.h"
#include "shaders/shared/interleave.h"

namespace mvpl::reference {

namespace {

// What the filter reads of a pixel's first hit: GBufferLayer's position, winding normal and
// material, and the pixel's interleaved share.
struct Texel {
    bool covered = false;
    Vec3 p{0.0f};
    Vec3 ng{0.0f};
    int material = -1;
    Vec3 base{0.0f};    // the closure's base colour (the G-buffer's)
    Vec3 albedo{0.0f};  // base, floored at kInterleaveMinAlbedo
    DVec3 shaded{0.0};
};

// interleave_filter.comp's test, in the same order and precision.
bool same_surface(const Texel& a, const Texel& b) {
    if (!b.covered || b.material != a.material) return false;
    if (glm::dot(a.ng, b.ng) < shared::kInterleaveMinCos) return false;
    const Vec3 d = b.p - a.p;
    if (std::abs(glm::dot(a.ng, d)) > shared::kInterleavePlaneSlope * glm::length(d)) return false;
    const Vec3 diff = glm::abs(b.base - a.base);
    const Vec3 allowed =
        shared::kInterleaveAlbedo * glm::max(a.base, b.base) + Vec3(shared::kInterleaveMinAlbedo);
    return diff.x <= allowed.x && diff.y <= allowed.y && diff.z <= allowed.z;
}

// The filtered value of pixel (x, y) (interleave.h's window, clamped into the image).
DVec3 filtered(const std::vector<Texel>& texels, int width, int height, int k, int x, int y) {
    const Texel& t = texels[size_t(y) * size_t(width) + size_t(x)];
    const int r = k / 2;
    const bool even = k % 2 == 0;
    const int cx = std::max(std::min(x, width - 1 - r), r);
    const int cy = std::max(std::min(y, height - 1 - r), r);
    DVec3 sum(0.0);
    double weights = 0.0;
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            const int qx = cx + dx;
            const int qy = cy + dy;
            if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
            const Texel& q = texels[size_t(qy) * size_t(width) + size_t(qx)];
            if ((qx != x || qy != y) && !same_surface(t, q)) continue;
            const double w =
                (even && std::abs(dx) == r ? 0.5 : 1.0) * (even && std::abs(dy) == r ? 0.5 : 1.0);
            sum += w * q.shaded / DVec3(q.albedo);
            weights += w;
        }
    }
    return DVec3(t.albedo) * (sum / weights);
}

}  // namespace

Image interleaved_vpl_sum(const scene::Scene& scene, const trace::Accel& accel,
                          const std::vector<light::PreparedVpl>& vpls, const GatherOptions& options,
                          float d_min2) {
    const int width = options.width;
    const int height = options.height;
    const int k = options.interleave;
    const uint64_t classes = uint64_t(k) * uint64_t(k);
    const SubpixelSchedule& schedule = options.subpixel;
    const uint64_t first = options.first_vpl;
    const float vsl_radius = options.vsl_radius * scene.bounds().diagonal();
    const float vsl_r2 = vsl_radius * vsl_radius;
    std::vector<DVec3> sum(size_t(width) * size_t(height), DVec3(0.0));
    std::vector<Texel> texels(sum.size());
    for (size_t i = 0; i < vpls.size();) {
        const uint64_t position = schedule.position_of(first + i);
        size_t end = i;
        while (end < vpls.size() && schedule.position_of(first + end) == position)
            ++end;
        const Vec2 offset = schedule.position(position);
        parallel_for(height, 1, [&](int64_t y0, int64_t y1) {
            for (int64_t y = y0; y < y1; ++y) {
                for (int x = 0; x < width; ++x) {
                    Texel& t = texels[size_t(y) * size_t(width) + size_t(x)];
                    t = Texel{};
                    const scene::CameraRay cr =
                        scene::generate_camera_ray(scene.camera, width, height,
                                                   Vec2(float(x) + offset.x, float(y) + offset.y));
                    const trace::Ray ray{cr.origin, cr.direction};
                    const std::optional<trace::Hit> hit = accel.intersect_camera(ray);
                    if (!hit) continue;
                    const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, ray);
                    t.covered = true;
                    t.p = si.p;
                    t.ng = si.ng;
                    t.material = si.material;
                    t.base =
                        trace::make_shading_point(accel.materials(), si).bsdf.params().base_color;
                    t.albedo = glm::max(t.base, Vec3(shared::kInterleaveMinAlbedo));
                    const std::optional<light::Receiver> receiver =
                        light::make_receiver(scene, accel, ray);
                    if (!receiver) continue;
                    const uint64_t c = uint64_t(x % k) + uint64_t(k) * uint64_t(y % k);
                    // The first VPL of the position whose index since begin() is c mod K².
                    size_t v = i + size_t((c + classes - (first + i) % classes) % classes);
                    for (; v < end; v += classes) {
                        t.shaded += DVec3(
                            light::vpl_contribution(accel, *receiver, vpls[v], d_min2, vsl_r2));
                    }
                    t.shaded *= double(classes);
                }
            }
        });
        parallel_for(height, 1, [&](int64_t y0, int64_t y1) {
            for (int64_t y = y0; y < y1; ++y) {
                for (int x = 0; x < width; ++x) {
                    if (!texels[size_t(y) * size_t(width) + size_t(x)].covered) continue;
                    sum[size_t(y) * size_t(width) + size_t(x)] +=
                        filtered(texels, width, height, k, x, int(y));
                }
            }
        });
        i = end;
    }
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x)
            image.at(x, y) = Rgb(sum[size_t(y) * size_t(width) + size_t(x)]);
    }
    return image;
}

}  // namespace mvpl::reference

#include "engine/reference/interleaved_gather.h"

#include <cmath>
#include <cstdlib>
#include <optional>

#include "engine/core/parallel.h"
#include "engine/light/specular_chain.h"
#include "engine/material/closure.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"
#include "engine/trace/shading_point.h"
#include "shaders/shared/chain_record.h"
#include "shaders/shared/interleave.h"

namespace mvpl::reference {

namespace {

// What the filter reads of a pixel's first hit: GBufferLayer's position, winding normal and
// material, and the pixel's interleaved share; for a chained pixel (state kChainReceiver) the
// chain record's rough end instead (render/chain_layer.cpp, to_record).
struct Texel {
    bool covered = false;
    uint32_t state = shared::kChainNone;
    Vec3 p{0.0f};
    Vec3 ng{0.0f};
    int material = -1;
    Vec3 base{0.0f};    // the closure's base colour (the G-buffer's)
    Vec3 albedo{0.0f};  // base, floored at kInterleaveMinAlbedo
    DVec3 shaded{0.0};  // unweighted by the chain's throughput
    // Chained pixels only.
    Vec3 wo{0.0f};
    Rgb throughput{1.0f};
    uint32_t closure_type = 0;
    uint32_t max_vpl_length = 0;
    Vec3 specular_color{0.0f};
    float metallic = 0.0f;
    float roughness = 0.0f;
    float specular = 0.0f;
    float ior = 0.0f;
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

// interleave_filter.comp's close_to.
bool close_to(float a, float b) {
    return std::abs(a - b) <=
           shared::kInterleaveAlbedo * std::max(a, b) + shared::kInterleaveMinAlbedo;
}
bool close_to(const Vec3& a, const Vec3& b) {
    return close_to(a.x, b.x) && close_to(a.y, b.y) && close_to(a.z, b.z);
}

// interleave_filter.comp's compatible_chain, in the same order and precision: a and b both
// kChainReceiver.
bool compatible_chains(const Texel& a, const Texel& b) {
    if (a.max_vpl_length != b.max_vpl_length || a.closure_type != b.closure_type) return false;
    if (glm::dot(a.ng, b.ng) < shared::kInterleaveMinCos) return false;
    const Vec3 d = b.p - a.p;
    if (std::abs(glm::dot(a.ng, d)) > shared::kInterleavePlaneSlope * glm::length(d)) return false;
    if (!close_to(a.base, b.base)) return false;
    if (a.closure_type == uint32_t(material::ClosureType::Lambertian)) return true;
    if (glm::dot(a.wo, b.wo) < shared::kInterleaveMinCos) return false;
    return close_to(a.specular_color, b.specular_color) && close_to(a.metallic, b.metallic) &&
           close_to(a.roughness, b.roughness) && close_to(a.specular, b.specular) &&
           close_to(a.ior, b.ior);
}

// Whether the filter of pixel t takes neighbour q (not t itself): a chained pixel only
// compatible chained ones, an unchained pixel only unchained ones on its surface.
bool accepts(const Texel& t, const Texel& q) {
    if (t.state == shared::kChainReceiver)
        return q.state == shared::kChainReceiver && compatible_chains(t, q);
    return q.state == shared::kChainNone && same_surface(t, q);
}

// A chained pixel's texel at its chain's rough end (render/chain_layer.cpp, to_record).
void set_chain_end(Texel& t, const light::ChainedReceiver& chained) {
    if (!chained.receiver) {
        t.state = shared::kChainBlack;
        return;
    }
    const trace::ShadingPoint& sp = chained.receiver->sp;
    const material::ClosureParams& c = sp.bsdf.params();
    t.state = shared::kChainReceiver;
    t.p = sp.p;
    t.ng = sp.ng;
    t.base = c.base_color;
    t.albedo = glm::max(t.base, Vec3(shared::kInterleaveMinAlbedo));
    t.wo = sp.frame.to_world(chained.receiver->wo);
    t.throughput = chained.throughput;
    t.closure_type = uint32_t(material::closure_type(c));
    t.max_vpl_length = chained.max_vpl_length;
    t.specular_color = c.specular_color;
    t.metallic = c.metallic;
    t.roughness = c.roughness;
    t.specular = c.specular;
    t.ior = c.ior;
}

// The filtered value of pixel (x, y) (interleave.h's window, clamped into the image).
DVec3 filtered(const std::vector<Texel>& texels, int width, int height, int k, int x, int y) {
    const Texel& t = texels[size_t(y) * size_t(width) + size_t(x)];
    if (t.state == shared::kChainBlack) return DVec3(0.0);
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
            if ((qx != x || qy != y) && !accepts(t, q)) continue;
            const double w =
                (even && std::abs(dx) == r ? 0.5 : 1.0) * (even && std::abs(dy) == r ? 0.5 : 1.0);
            sum += w * q.shaded / DVec3(q.albedo);
            weights += w;
        }
    }
    const DVec3 mean = DVec3(t.albedo) * (sum / weights);
    // The pixel's own chain weight, outside the mean (interleave.h, "Chains").
    return t.state == shared::kChainReceiver ? mean * DVec3(t.throughput) : mean;
}

// What every pixel's shading reads, fixed over the run.
struct GatherInputs {
    const scene::Scene& scene;
    const trace::Accel& accel;
    const std::vector<light::PreparedVpl>& vpls;
    const GatherOptions& options;
    float d_min2;
    float vsl_r2;
    const light::LightSampler* lights;
};

// The VPLs [begin, end) of one sub-pixel position (`offset` in the pixel).
struct PositionRun {
    uint64_t position;
    Vec2 offset;
    size_t begin;
    size_t end;
};

// Texel (x, y) for the run: its first hit and its interleaved share of the run's VPLs.
void shade_texel(const GatherInputs& in, const PositionRun& run, int x, int64_t y, Texel& t) {
    const int width = in.options.width;
    const int k = in.options.interleave;
    const uint64_t classes = uint64_t(k) * uint64_t(k);
    const uint64_t first = in.options.first_vpl;
    t = Texel{};
    const scene::CameraRay cr =
        scene::generate_camera_ray(in.scene.camera, width, in.options.height,
                                   Vec2(float(x) + run.offset.x, float(y) + run.offset.y));
    const trace::Ray ray{cr.origin, cr.direction};
    const std::optional<trace::Hit> hit = in.accel.intersect_camera(ray);
    if (!hit) return;
    const trace::SurfaceInteraction si = trace::make_interaction(in.scene, *hit, ray);
    t.covered = true;
    t.p = si.p;
    t.ng = si.ng;
    t.material = si.material;
    t.base = trace::make_shading_point(in.accel.materials(), si).bsdf.params().base_color;
    t.albedo = glm::max(t.base, Vec3(shared::kInterleaveMinAlbedo));
    // As gather_vpls's shade_pixel: the chain's receiver and path-length limit.
    std::optional<light::Receiver> receiver;
    uint32_t max_vpl_length = UINT32_MAX;
    if (in.lights) {
        Rng rng = light::chain_rng(in.options.chain_seed,
                                   uint64_t(y) * uint64_t(width) + uint64_t(x), run.position);
        const light::ChainedReceiver chained = light::make_chained_receiver(
            in.scene, in.accel, ray, rng, in.options.chains, nullptr, in.lights);
        receiver = chained.receiver;
        max_vpl_length = chained.max_vpl_length;
        if (chained.continued) set_chain_end(t, chained);
    } else {
        receiver = light::make_receiver(in.scene, in.accel, ray);
    }
    if (!receiver) return;
    const uint64_t c = uint64_t(x % k) + uint64_t(k) * uint64_t(y % k);
    const size_t i = run.begin;
    // The first VPL of the position whose index since begin() is c mod K².
    size_t v = i + size_t((c + classes - (first + i) % classes) % classes);
    for (; v < run.end; v += classes) {
        if (in.vpls[v].vpl->path_length > max_vpl_length) continue;
        t.shaded +=
            DVec3(light::vpl_contribution(in.accel, *receiver, in.vpls[v], in.d_min2, in.vsl_r2));
    }
    t.shaded *= double(classes);
}

}  // namespace

Image interleaved_vpl_sum(const scene::Scene& scene, const trace::Accel& accel,
                          const std::vector<light::PreparedVpl>& vpls, const GatherOptions& options,
                          float d_min2, const light::LightSampler* lights) {
    const int width = options.width;
    const int height = options.height;
    const int k = options.interleave;
    const SubpixelSchedule& schedule = options.subpixel;
    const uint64_t first = options.first_vpl;
    const float vsl_radius = options.vsl_radius * scene.bounds().diagonal();
    const GatherInputs in{scene, accel, vpls, options, d_min2, vsl_radius * vsl_radius, lights};
    std::vector<DVec3> sum(size_t(width) * size_t(height), DVec3(0.0));
    std::vector<Texel> texels(sum.size());
    for (size_t i = 0; i < vpls.size();) {
        const uint64_t position = schedule.position_of(first + i);
        size_t end = i;
        while (end < vpls.size() && schedule.position_of(first + end) == position)
            ++end;
        const PositionRun run{position, schedule.position(position), i, end};
        parallel_for(height, 1, [&](int64_t y0, int64_t y1) {
            for (int64_t y = y0; y < y1; ++y) {
                for (int x = 0; x < width; ++x)
                    shade_texel(in, run, x, y, texels[size_t(y) * size_t(width) + size_t(x)]);
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

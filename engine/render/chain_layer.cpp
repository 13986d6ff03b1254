#include "engine/render/chain_layer.h"

#include <cstring>
#include <vector>

#include "engine/core/parallel.h"
#include "engine/light/light_sampler.h"
#include "engine/light/specular_chain.h"
#include "engine/material/closure.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "shaders/shared/chain_record.h"

namespace mvpl::render {
namespace {

using shared::ChainRecord;

void put(float (&out)[3], const Vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

ChainRecord to_record(const light::ChainedReceiver& c) {
    if (!c.receiver) {
        ChainRecord r{};
        put(r.emitted, c.chain_emitted);
        r.state = shared::kChainBlack;
        return r;
    }
    ChainRecord r = receiver_record(*c.receiver, c.throughput, c.max_vpl_length);
    put(r.emitted, c.chain_emitted);
    return r;
}

}  // namespace

ChainRecord receiver_record(const light::Receiver& receiver, const Rgb& throughput,
                            uint32_t max_vpl_length) {
    ChainRecord r{};
    const trace::ShadingPoint& sp = receiver.sp;
    const material::ClosureParams& p = sp.bsdf.params();
    r.state = shared::kChainReceiver;
    put(r.position, sp.p);
    put(r.shading_normal, sp.frame.n);
    put(r.geometric_normal, sp.ng);
    put(r.wo, sp.frame.to_world(receiver.wo));
    put(r.throughput, throughput);
    put(r.base_color, p.base_color);
    put(r.specular_color, p.specular_color);
    r.metallic = p.metallic;
    r.roughness = p.roughness;
    r.specular = p.specular;
    r.ior = p.ior;
    r.max_vpl_length = max_vpl_length;
    r.closure_type = uint32_t(material::closure_type(p));
    return r;
}

ChainLayer::ChainLayer(gpu::Context& context, const scene::Scene& scene, const trace::Accel& accel,
                       uint32_t width, uint32_t height)
    : m_scene(scene),
      m_accel(accel),
      m_lights(std::make_unique<light::LightSampler>(scene)),
      m_width(width),
      m_height(height),
      m_records(context, uint64_t(width) * height * sizeof(ChainRecord), gpu::BufferUsage::storage,
                gpu::MemoryLocation::upload, "chain records") {}

ChainLayer::~ChainLayer() = default;

void ChainLayer::trace(const scene::Camera& camera, Vec2 offset, uint64_t position,
                       const light::ChainOptions& options, uint64_t seed) {
    auto* records = reinterpret_cast<ChainRecord*>(m_records.mapped());
    const uint64_t rays_before = m_accel.ray_count();
    update_centres(camera, options);
    const auto centre_continues = [&](uint64_t pixel) {
        return !m_centres.empty() && m_centres[pixel] != 0;
    };
    parallel_for(int64_t(m_height), 1, [&](int64_t begin, int64_t end) {
        for (int64_t y = begin; y < end; ++y) {
            for (uint32_t x = 0; x < m_width; ++x) {
                const uint64_t pixel = uint64_t(y) * m_width + x;
                const Vec2 film(float(x) + offset.x, float(y) + offset.y);
                const scene::CameraRay cr =
                    scene::generate_camera_ray(camera, int(m_width), int(m_height), film);
                Rng rng = light::chain_rng(seed, pixel, position);
                const light::ChainedReceiver c = light::make_chained_receiver(
                    m_scene, m_accel, trace::Ray{cr.origin, cr.direction}, rng, options, nullptr,
                    m_lights.get());
                // A pixel whose first vertex is rough keeps the G-buffer's receiver.
                ChainRecord r = c.continued ? to_record(c) : ChainRecord{};
                put(r.emitted, light::pixel_chain_emission(m_scene, m_accel, camera, int(m_width),
                                                           int(m_height), int(x), int(y),
                                                           centre_continues(pixel), c, rng, options,
                                                           m_lights.get()));
                std::memcpy(&records[pixel], &r, sizeof(r));
            }
        }
    });
    m_rays += m_accel.ray_count() - rays_before;
}

void ChainLayer::update_centres(const scene::Camera& camera, const light::ChainOptions& options) {
    if (options.emission_samples <= 1) {
        m_centres.clear();
        return;
    }
    const bool same = !m_centres.empty() && m_centres_roughness == options.max_roughness &&
                      m_centres_camera.camera_to_world == camera.camera_to_world &&
                      m_centres_camera.yfov == camera.yfov &&
                      m_centres_camera.znear == camera.znear;
    if (same) return;
    m_centres.assign(size_t(m_width) * m_height, 0);
    parallel_for(int64_t(m_height), 1, [&](int64_t begin, int64_t end) {
        for (int64_t y = begin; y < end; ++y) {
            for (uint32_t x = 0; x < m_width; ++x)
                m_centres[size_t(y) * m_width + x] = light::pixel_centre_continues(
                    m_scene, m_accel, camera, int(m_width), int(m_height), int(x), int(y), options);
        }
    });
    m_centres_camera = camera;
    m_centres_roughness = options.max_roughness;
}

}  // namespace mvpl::render

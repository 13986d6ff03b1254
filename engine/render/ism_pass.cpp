#include "engine/render/ism_pass.h"

#include <algorithm>
#include <cstring>

#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/image.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/render/host_vec3.h"
#include "engine/render/shadow_pass.h"

namespace mvpl::render {
namespace {

using shared::IsmPush;
using shared::IsmVpl;

constexpr uint32_t kSplatGroup = 64;  // ism_splat.comp's local size

uint32_t no_occluder_bits() {
    uint32_t bits = 0;
    std::memcpy(&bits, &kShadowNoOccluder, sizeof(bits));
    return bits;
}

}  // namespace

IsmPass::IsmPass(gpu::Context& context, std::vector<IsmPoint> points, uint32_t resolution,
                 uint32_t max_batch)
    : m_resolution(resolution),
      m_max_batch(max_batch),
      m_point_count(points.size()),
      m_points(context, std::max<uint64_t>(points.size(), 1) * sizeof(IsmPoint),
               gpu::BufferUsage::storage, gpu::MemoryLocation::device, "ism points"),
      m_depths(context, uint64_t(max_batch) * 6 * resolution * resolution * sizeof(uint32_t),
               gpu::BufferUsage::storage, gpu::MemoryLocation::device, "ism depths"),
      m_vpls(context, uint64_t(std::max(max_batch, 1u)) * sizeof(IsmVpl), gpu::BufferUsage::storage,
             gpu::MemoryLocation::upload, "ism vpls"),
      m_splat(std::make_unique<gpu::ComputePipeline>(
          context, gpu::compile_embedded_shader("render/ism_splat.comp"),
          gpu::ComputeLayout{{gpu::BindingType::storage_buffer, gpu::BindingType::storage_buffer,
                              gpu::BindingType::storage_buffer},
                             sizeof(IsmPush)},
          "ism splat")),
      m_resolve(std::make_unique<gpu::ComputePipeline>(
          context, gpu::compile_embedded_shader("render/ism_resolve.comp"),
          gpu::ComputeLayout{{gpu::BindingType::storage_buffer, gpu::BindingType::storage_buffer,
                              gpu::BindingType::storage_image},
                             sizeof(IsmPush)},
          "ism resolve")) {
    if (resolution < 2 || resolution > shared::kMaxIsmResolution ||
        (resolution & (resolution - 1)) != 0) {
        throw gpu::GpuError("imperfect shadow maps: the face side must be a power of two in 2.." +
                            std::to_string(shared::kMaxIsmResolution));
    }
    if (!points.empty()) m_points.upload(points);
    m_depths.upload(std::vector<uint32_t>(m_depths.size() / sizeof(uint32_t), no_occluder_bits()));
}

IsmPass::~IsmPass() = default;

void IsmPass::record(gpu::CommandList& cmd, std::span<const light::Vpl> vpls,
                     std::span<const uint32_t> slots, float near, const gpu::Image& cubes) {
    if (vpls.empty()) return;
    if (vpls.size() > m_max_batch || slots.size() != vpls.size())
        throw gpu::GpuError("imperfect shadow maps: more VPLs than cubes, or one slot per VPL");
    auto* out = reinterpret_cast<IsmVpl*>(m_vpls.mapped());
    for (size_t i = 0; i < vpls.size(); ++i) {
        const light::Vpl& v = vpls[i];
        IsmVpl g{};
        store(g.position, v.position);
        g.near_distance = near;
        store(g.normal, v.normal);
        g.hemisphere =
            v.type == light::VplType::Area || v.type == light::VplType::Surface ? 1u : 0u;
        g.slot[0] = slots[i];
        std::memcpy(out + i, &g, sizeof(g));
    }
    const IsmPush push{uint32_t(m_point_count), uint32_t(vpls.size()), m_resolution, kFillLevels};
    if (m_point_count > 0) {
        cmd.dispatch(*m_splat, {&m_points, &m_vpls, &m_depths}, gpu::push_bytes(push),
                     uint32_t((m_point_count + kSplatGroup - 1) / kSplatGroup));
        cmd.barrier();
    }
    cmd.dispatch(*m_resolve, {&m_depths, &m_vpls, &cubes}, gpu::push_bytes(push), 6,
                 uint32_t(vpls.size()));
}

}  // namespace mvpl::render

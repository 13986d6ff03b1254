#include "engine/render/interleave_filter.h"

#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_compiler.h"
#include "shaders/shared/chain_record.h"
#include "shaders/shared/interleave.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::render {
namespace {

constexpr uint32_t kInterleaveGroupSize = 8;  // interleave_filter.comp's local size

}  // namespace

InterleaveFilter::InterleaveFilter(gpu::Context& context, uint32_t width, uint32_t height,
                                   uint32_t k)
    : m_shaded(context,
               {width, height, 1, gpu::Format::rgba32_float, gpu::ImageUsage::storage, false},
               "interleaved batch"),
      m_no_chains(context, sizeof(shared::ChainRecord), gpu::BufferUsage::storage,
                  gpu::MemoryLocation::device, "no chain records"),
      m_pipeline(std::make_unique<gpu::ComputePipeline>(
          context, gpu::compile_embedded_shader("render/interleave_filter.comp"),
          gpu::ComputeLayout{{gpu::BindingType::storage_image, gpu::BindingType::storage_image,
                              gpu::BindingType::storage_image, gpu::BindingType::storage_buffer},
                             sizeof(shared::InterleavePush)},
          "interleave filter")),
      m_k(k) {
    if (k < 2 || k > shared::kMaxInterleave)
        throw gpu::GpuError("interleave filter: K must be in 2..8");
}

InterleaveFilter::~InterleaveFilter() = default;

void InterleaveFilter::record(gpu::CommandList& cmd, const gpu::Image& g_buffer,
                              const gpu::Image& accumulation, const gpu::Buffer* chains) {
    const uint32_t width = m_shaded.width();
    const uint32_t height = m_shaded.height();
    if (g_buffer.width() != width || g_buffer.height() != height || accumulation.width() != width ||
        accumulation.height() != height) {
        throw gpu::GpuError("interleave filter: images of different sizes");
    }
    if (chains && chains->size() < uint64_t(width) * height * sizeof(shared::ChainRecord))
        throw gpu::GpuError("interleave filter: fewer chain records than pixels");
    const shared::InterleavePush push{{width, height}, m_k, chains ? 1u : 0u};
    cmd.dispatch(*m_pipeline, {&g_buffer, &m_shaded, &accumulation, chains ? chains : &m_no_chains},
                 gpu::push_bytes(push), (width + kInterleaveGroupSize - 1) / kInterleaveGroupSize,
                 (height + kInterleaveGroupSize - 1) / kInterleaveGroupSize);
    cmd.barrier();
    record_clear(cmd);
}

void InterleaveFilter::record_clear(gpu::CommandList& cmd) {
    cmd.clear_color(m_shaded, {0.0f, 0.0f, 0.0f, 0.0f});
}

}  // namespace mvpl::render

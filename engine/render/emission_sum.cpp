#include "engine/render/emission_sum.h"

#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/render/g_buffer_pass.h"
#include "shaders/shared/chain_record.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::render {
namespace {

constexpr uint32_t kEmissionSumGroupSize = 8;  // emission_sum.comp's local size

}  // namespace

EmissionSum::EmissionSum(gpu::Context& context, uint32_t width, uint32_t height)
    : m_context(context),
      m_sum(context, {width, height, 1, gpu::Format::rgba32_float, gpu::ImageUsage::storage, false},
            "emission sum"),
      m_background(context, {1, 1, 1, gpu::Format::rgba32_float, gpu::ImageUsage::storage, false},
                   "background"),
      m_no_chains(context, sizeof(shared::ChainRecord), gpu::BufferUsage::storage,
                  gpu::MemoryLocation::upload, "no chain records"),
      m_pipeline(std::make_unique<gpu::ComputePipeline>(
          context, gpu::compile_embedded_shader("render/emission_sum.comp"),
          gpu::ComputeLayout{{gpu::BindingType::storage_image, gpu::BindingType::storage_image,
                              gpu::BindingType::storage_image, gpu::BindingType::storage_buffer},
                             sizeof(shared::EmissionPush)},
          "emission sum")) {
    m_background.upload(std::vector<float>(4, 0.0f));
}

void EmissionSum::set_background(const std::vector<float>& rgba) {
    const uint32_t width = m_sum.width();
    const uint32_t height = m_sum.height();
    if (rgba.size() != size_t(width) * size_t(height) * 4)
        throw gpu::GpuError("emission sum: the background differs from the image in size");
    if (m_background.width() != width || m_background.height() != height) {
        m_background = gpu::Image(
            m_context,
            {width, height, 1, gpu::Format::rgba32_float, gpu::ImageUsage::storage, false},
            "background");
    }
    m_background.upload(rgba);
    m_has_background = true;
}

EmissionSum::~EmissionSum() = default;

void EmissionSum::record_clear(gpu::CommandList& cmd) {
    cmd.clear_color(m_sum, {0.0f, 0.0f, 0.0f, 0.0f});
}

void EmissionSum::record_add(gpu::CommandList& cmd, const gpu::Image& g_buffer,
                             const gpu::Buffer* chain_records) {
    const uint32_t width = m_sum.width();
    const uint32_t height = m_sum.height();
    if (g_buffer.width() != width || g_buffer.height() != height) {
        throw gpu::GpuError("emission sum: the G-buffer and the sum differ in size");
    }
    if (chain_records &&
        chain_records->size() < uint64_t(width) * height * sizeof(shared::ChainRecord)) {
        throw gpu::GpuError("emission sum: fewer chain records than pixels");
    }
    const uint32_t flags = (m_has_background ? shared::kEmissionBackground : 0u) |
                           (chain_records ? shared::kEmissionChains : 0u);
    const shared::EmissionPush push{{width, height}, kGBufferEmission, flags};
    cmd.dispatch(*m_pipeline,
                 {&g_buffer, &m_sum, &m_background, chain_records ? chain_records : &m_no_chains},
                 gpu::push_bytes(push), (width + kEmissionSumGroupSize - 1) / kEmissionSumGroupSize,
                 (height + kEmissionSumGroupSize - 1) / kEmissionSumGroupSize);
}

}  // namespace mvpl::render

#include "engine/gpu/gpu_timer.h"

#include <vulkan/vulkan.h>

#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {

GpuTimer::GpuTimer(Context& context, uint32_t max_scopes)
    : m_context(&context), m_capacity(max_scopes) {
    const DeviceInfo& info = context.device_info();
    const uint32_t bits = info.timestamp_valid_bits;
    m_valid_mask = bits >= 64 ? ~uint64_t(0) : (bits == 0 ? 0 : (uint64_t(1) << bits) - 1);
    m_ns_per_tick = double(info.limits.timestamp_period);
    if (!supported()) return;
    VkQueryPoolCreateInfo create{};
    create.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    create.queryType = VK_QUERY_TYPE_TIMESTAMP;
    create.queryCount = 2 * max_scopes;
    vk_check(vkCreateQueryPool(context.device(), &create, nullptr, &m_pool), "vkCreateQueryPool");
    reset();
}

GpuTimer::~GpuTimer() {
    if (m_pool) vkDestroyQueryPool(m_context->device(), m_pool, nullptr);
}

void GpuTimer::reset() {
    // Queries must be reset before their first write; hostQueryReset (Vulkan 1.2 core, enabled by
    // Context) does it without a command buffer.
    if (m_pool) vkResetQueryPool(m_context->device(), m_pool, 0, 2 * m_capacity);
    m_labels.clear();
    m_ended.clear();
}

uint32_t GpuTimer::begin(CommandList& cmd, std::string_view label) {
    if (m_labels.size() >= m_capacity) {
        throw GpuError("GpuTimer: more than " + std::to_string(m_capacity) +
                       " scopes since the last reset");
    }
    const uint32_t scope = uint32_t(m_labels.size());
    m_labels.emplace_back(label);
    m_ended.push_back(false);
    // ALL_COMMANDS: the timestamp waits for earlier work, so the scope times only its own pass.
    if (m_pool) {
        vkCmdWriteTimestamp2(cmd.handle(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, m_pool, 2 * scope);
    }
    return scope;
}

void GpuTimer::end(CommandList& cmd, uint32_t scope) {
    if (scope >= m_labels.size() || m_ended[scope]) {
        throw GpuError("GpuTimer: end() of scope " + std::to_string(scope) + " that is not open");
    }
    m_ended[scope] = true;
    if (m_pool) {
        vkCmdWriteTimestamp2(cmd.handle(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, m_pool,
                             2 * scope + 1);
    }
}

std::vector<PassTime> GpuTimer::results() const {
    std::vector<PassTime> times;
    const uint32_t scopes = uint32_t(m_labels.size());
    std::vector<uint64_t> ticks(2 * size_t(scopes));
    if (m_pool && scopes > 0) {
        // Only whole begin/end pairs that were ended are read; an open scope would block forever.
        for (uint32_t s = 0; s < scopes; ++s) {
            if (!m_ended[s]) continue;
            vk_check(vkGetQueryPoolResults(m_context->device(), m_pool, 2 * s, 2,
                                           2 * sizeof(uint64_t), &ticks[2 * s], sizeof(uint64_t),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                     "vkGetQueryPoolResults");
        }
    }
    for (uint32_t s = 0; s < scopes; ++s) {
        if (!m_ended[s]) continue;
        // Masked to the valid bits, then modular subtraction copes with one wrap-around.
        const uint64_t delta = (ticks[2 * s + 1] - ticks[2 * s]) & m_valid_mask;
        times.push_back({m_labels[s], double(delta) * m_ns_per_tick * 1e-6});
    }
    return times;
}

double GpuTimer::milliseconds(std::string_view label) const {
    double total = 0.0;
    for (const PassTime& t : results()) {
        if (t.label == label) total += t.milliseconds;
    }
    return total;
}

}  // namespace mvpl::gpu

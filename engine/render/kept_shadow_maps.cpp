#include "engine/render/kept_shadow_maps.h"

#include <algorithm>
#include <bit>
#include <map>
#include <string>

#include "engine/gpu/command_list.h"

namespace mvpl::render {

namespace {

using LayerCopies = std::map<uint32_t, std::vector<gpu::CommandList::LayerCopy>>;

uint32_t capacity_of(uint64_t budget_bytes, bool directional, uint32_t resolution) {
    const uint64_t maps = budget_bytes / KeptShadowMaps::map_bytes(directional, resolution);
    return uint32_t(std::min<uint64_t>(maps, UINT32_MAX));
}

}  // namespace

KeptShadowMaps::KeptShadowMaps(gpu::Context& context, bool directional, uint32_t resolution,
                               uint32_t maps_per_pool, uint64_t budget_bytes)
    : m_context(&context),
      m_directional(directional),
      m_layers(directional ? 1 : 6),
      m_resolution(resolution),
      m_maps_per_pool(std::max(maps_per_pool, 1u)),
      m_capacity(capacity_of(budget_bytes, directional, resolution)),
      m_budget_bytes(budget_bytes) {}

size_t KeptShadowMaps::KeyHash::operator()(const Key& key) const {
    // FNV-1a over the key's words.
    uint64_t h = 1469598103934665603ull;
    for (uint32_t word : key.bits)
        h = (h ^ word) * 1099511628211ull;
    return size_t(h);
}

KeptShadowMaps::Key KeptShadowMaps::key_of(const light::Vpl& vpl) {
    return {{uint32_t(vpl.type), std::bit_cast<uint32_t>(vpl.position.x),
             std::bit_cast<uint32_t>(vpl.position.y), std::bit_cast<uint32_t>(vpl.position.z),
             std::bit_cast<uint32_t>(vpl.normal.x), std::bit_cast<uint32_t>(vpl.normal.y),
             std::bit_cast<uint32_t>(vpl.normal.z), vpl.path_length}};
}

void KeptShadowMaps::reserve(std::span<const light::Vpl> batch) {
    const auto maps = std::count_if(batch.begin(), batch.end(),
                                    [&](const light::Vpl& vpl) { return holds(vpl); });
    const uint64_t wanted = std::min<uint64_t>(m_index.size() + uint64_t(maps), m_capacity);
    while (m_slots.size() < wanted) {
        // A pool holds m_maps_per_pool places (the last one fewer, within the budget).
        const uint32_t places =
            std::min<uint32_t>(m_maps_per_pool, m_capacity - uint32_t(m_slots.size()));
        const gpu::ImageDesc desc{m_resolution,
                                  m_resolution,
                                  m_layers * m_maps_per_pool,
                                  kShadowTexelFormat,
                                  gpu::ImageUsage::storage,
                                  false};
        m_pools.emplace_back(
            *m_context, desc,
            std::string(m_directional ? "kept orthographic maps " : "kept shadow cubes ") +
                std::to_string(m_pools.size()));
        m_slots.resize(m_slots.size() + places);
    }
}

int64_t KeptShadowMaps::place() {
    for (uint32_t s = 0; s < m_slots.size(); ++s) {
        if (!m_slots[s].full) return s;
    }
    int64_t oldest = -1;
    for (uint32_t s = 0; s < m_slots.size(); ++s) {
        if (m_slots[s].last_used < m_estimate &&
            (oldest < 0 || m_slots[s].last_used < m_slots[size_t(oldest)].last_used))
            oldest = s;
    }
    if (oldest >= 0) {
        m_index.erase(m_slots[size_t(oldest)].key);
        m_slots[size_t(oldest)].full = false;
    }
    return oldest;
}

std::vector<bool> KeptShadowMaps::restore(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                                          const std::vector<bool>& skip, gpu::Image& maps) {
    std::vector<bool> restored(batch.size(), false);
    LayerCopies copies;  // per pool
    for (uint32_t i = 0; i < batch.size(); ++i) {
        if ((!skip.empty() && skip[i]) || !holds(batch[i])) continue;
        const auto found = m_index.find(key_of(batch[i]));
        if (found == m_index.end()) continue;
        const uint32_t slot = found->second;
        m_slots[slot].last_used = m_estimate;
        copies[slot / m_maps_per_pool].push_back(
            {m_layers * (slot % m_maps_per_pool), m_layers * i, m_layers});
        restored[i] = true;
        ++m_restored;
    }
    for (const auto& [pool, regions] : copies)
        cmd.copy_image_layers(m_pools[pool], maps, regions);
    return restored;
}

void KeptShadowMaps::keep(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                          const std::vector<bool>& drawn, const gpu::Image& maps) {
    LayerCopies copies;  // per pool
    for (uint32_t i = 0; i < batch.size(); ++i) {
        if (!drawn[i] || !holds(batch[i])) continue;
        const Key key = key_of(batch[i]);
        if (m_index.count(key)) continue;  // the same VPL twice in a batch
        const int64_t slot = place();
        if (slot < 0) break;  // every place holds a cube of this estimate
        Slot& s = m_slots[size_t(slot)];
        s = {key, m_estimate, true};
        m_index[key] = uint32_t(slot);
        copies[uint32_t(slot) / m_maps_per_pool].push_back(
            {m_layers * i, m_layers * (uint32_t(slot) % m_maps_per_pool), m_layers});
    }
    for (const auto& [pool, regions] : copies)
        cmd.copy_image_layers(maps, m_pools[pool], regions);
}

}  // namespace mvpl::render

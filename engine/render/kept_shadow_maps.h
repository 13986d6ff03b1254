#pragma once
// Shadow cubes kept beyond their batch. A VPL's cube holds the distance from the VPL to the
// nearest surface in every direction: it depends on the VPL and the scene, never on the camera.
// So when the same VPL is shaded again against another G-buffer (the preview after a camera
// move replays its VPLs: tools/preview/vpl_history.h), its cube is copied back from here instead
// of being drawn again. Copies are exact, so an image shaded with kept cubes equals the one
// shaded with freshly drawn cubes.
//
// A VPL is recognised by what its cube depends on (shadow_pass.h): its type, position, normal
// (faces behind it are skipped, hemicube.h) and path length (shadow proxies), bit for bit.
// Directional VPLs' orthographic maps are not kept (a sun is one VPL, cheap to draw again).
//
// Memory: at most `budget_bytes` of R32F cubes, in pools of `cubes_per_pool` cubes allocated as
// they fill. Eviction: a new cube takes a free place, or else the place of the cube used least
// recently before the current estimate (new_estimate()); a cube used in the current estimate is
// never evicted, so replaying the same VPLs from the start keeps the first that fit and draws the
// others each time, and the cubes of VPLs no longer shaded (a dropped Metropolis chain) give way
// to new ones. Vulkan-free to include.
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "engine/gpu/image.h"
#include "engine/light/vpl.h"

namespace mvpl::gpu {
class CommandList;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

// The preview's budget (--kept-maps): 1 GiB holds 682 cubes of 256² (the default shadow
// resolution), about what the Cornell box at 512² shades in 3 s of rest on two lavapipe cores.
constexpr uint64_t kDefaultKeptBytes = 1ull << 30;

class KeptShadowMaps {
public:
    KeptShadowMaps(gpu::Context& context, uint32_t resolution, uint32_t cubes_per_pool,
                   uint64_t budget_bytes);

    static uint64_t cube_bytes(uint32_t resolution) {
        return 6ull * resolution * resolution * sizeof(float);
    }
    // How many cubes the budget holds.
    uint32_t capacity() const { return m_capacity; }
    uint32_t size() const { return uint32_t(m_index.size()); }
    // Cubes copied back by restore() since construction.
    uint64_t restored() const { return m_restored; }

    // Starts a new estimate (VplRenderer::begin): cubes used before it may be evicted.
    void new_estimate() { ++m_estimate; }
    // Allocates the pools that `cubes` more cubes need, within the budget: before the recording
    // of the batch that keeps them (images are created outside command recording).
    void reserve(uint32_t cubes);
    // Copies the kept cubes of batch's VPLs (those without skip[i]) into cube i of `cubes`
    // (layers 6i … 6i + 5); returns which were copied.
    std::vector<bool> restore(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                              const std::vector<bool>& skip, gpu::Image& cubes);
    // Keeps cube i of `cubes` for batch[i] where drawn[i] (after the draws, behind a barrier).
    void keep(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
              const std::vector<bool>& drawn, const gpu::Image& cubes);

private:
    struct Key {
        uint32_t bits[8];
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& key) const;
    };
    struct Slot {
        Key key;
        uint64_t last_used = 0;  // the estimate that last restored or kept it
        bool full = false;
    };
    static Key key_of(const light::Vpl& vpl);
    // A place for a new cube: a free one in the reserved pools, or the least recently used one
    // that the current estimate has not used; -1 when there is none.
    int64_t place();
    gpu::Image& pool_of(uint32_t slot) { return m_pools[slot / m_cubes_per_pool]; }

    gpu::Context* m_context;
    uint32_t m_resolution;
    uint32_t m_cubes_per_pool;
    uint32_t m_capacity;
    std::vector<gpu::Image> m_pools;
    std::vector<Slot> m_slots;  // one per place in the allocated pools
    std::unordered_map<Key, uint32_t, KeyHash> m_index;
    uint64_t m_estimate = 1;
    uint64_t m_restored = 0;
};

}  // namespace mvpl::render

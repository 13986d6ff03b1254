#pragma once
// Shadow maps kept beyond their batch. A VPL's cube (or a directional VPL's orthographic map)
// holds the distance from the VPL to the nearest surface: it depends on the VPL and the scene,
// never on the camera. So when the same VPL is shaded again against another G-buffer (the
// preview after a camera move replays its VPLs: tools/preview/vpl_history.h), its map is copied
// back from here instead of being drawn again. Copies are exact, so an image shaded with kept
// maps equals the one shaded with freshly drawn maps.
//
// A VPL is recognised by what its map depends on (shadow_pass.h): its type, position, normal
// (faces behind it are skipped, hemicube.h; a directional map's frame) and path length (shadow
// proxies), bit for bit. One KeptShadowMaps holds one kind: the cubes (6 layers a map) of
// point-like VPLs, or the orthographic maps (1 layer) of directional ones.
//
// Memory: at most `budget_bytes` of RG32F layers (shadow_texel.h), in pools of `maps_per_pool` maps
// allocated as they fill. Eviction: a new map takes a free place, or else the place of the map used
// least recently before the current estimate (new_estimate()); a map used in the current estimate
// is never evicted, so replaying the same VPLs from the start keeps the first that fit and draws
// the others each time, and the maps of VPLs no longer shaded (a dropped Metropolis chain) give way
// to new ones. Vulkan-free to include.
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "engine/gpu/image.h"
#include "engine/light/vpl.h"
#include "engine/render/shadow_texel.h"

namespace mvpl::gpu {
class CommandList;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

// The preview's budget (--kept-maps), shared by the cubes and the orthographic maps in
// proportion to their layers (ShadowPass): 2 GiB holds 585 cubes and 585 orthographic maps of
// 256² (the default shadow resolution; 8-byte texels, shadow_texel.h), more than the Cornell box
// at 512² shades in 3 s of rest on two lavapipe cores.
constexpr uint64_t kDefaultKeptBytes = 2ull << 30;

// What the kept maps of a renderer hold (VplRenderer::kept_maps()), both kinds together.
struct KeptMapStats {
    uint32_t maps = 0;      // held now
    uint32_t capacity = 0;  // the budget's (0: none kept)
    uint64_t budget_bytes = 0;
    uint64_t restored = 0;  // copied back instead of drawn, since the renderer was built
};

class KeptShadowMaps {
public:
    // directional: the orthographic maps of directional VPLs; else the cubes of the others.
    KeptShadowMaps(gpu::Context& context, bool directional, uint32_t resolution,
                   uint32_t maps_per_pool, uint64_t budget_bytes);

    static uint64_t map_bytes(bool directional, uint32_t resolution) {
        return (directional ? 1ull : 6ull) * resolution * resolution * kShadowTexelBytes;
    }
    // How many maps the budget holds.
    uint32_t capacity() const { return m_capacity; }
    uint64_t budget_bytes() const { return m_budget_bytes; }
    uint32_t size() const { return uint32_t(m_index.size()); }
    // Maps copied back by restore() since construction.
    uint64_t restored() const { return m_restored; }

    // Starts a new estimate (VplRenderer::begin): cubes used before it may be evicted.
    void new_estimate() { ++m_estimate; }
    // Allocates the pools that batch's VPLs of this kind may need, within the budget: before the
    // recording of the batch that keeps them (images are created outside command recording).
    void reserve(std::span<const light::Vpl> batch);
    // Copies the kept maps of batch's VPLs of this kind (those without skip[i]) into map i of
    // `maps` (layers L·i … L·i + L − 1, L layers a map); returns which were copied.
    std::vector<bool> restore(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                              const std::vector<bool>& skip, gpu::Image& maps);
    // Keeps map i of `maps` for batch[i] of this kind where drawn[i] (after the draws, behind a
    // barrier).
    void keep(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
              const std::vector<bool>& drawn, const gpu::Image& maps);

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
    bool holds(const light::Vpl& vpl) const {
        return (vpl.type == light::VplType::Directional) == m_directional;
    }

    gpu::Context* m_context;
    bool m_directional;
    uint32_t m_layers;  // a map's
    uint32_t m_resolution;
    uint32_t m_maps_per_pool;
    uint32_t m_capacity;
    uint64_t m_budget_bytes;
    std::vector<gpu::Image> m_pools;
    std::vector<Slot> m_slots;  // one per place in the allocated pools
    std::unordered_map<Key, uint32_t, KeyHash> m_index;
    uint64_t m_estimate = 1;
    uint64_t m_restored = 0;
};

}  // namespace mvpl::render

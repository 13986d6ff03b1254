#pragma once
// VplRenderer's state on one device (vpl_renderer.h's pimpl): its passes, its progressive state
// and, on device 0 of a renderer on several, the other devices. vpl_renderer_impl.cpp drives one
// device's passes; vpl_renderer.cpp is the public interface and shares the VPLs out among the
// devices (device_split.h). Private to engine/render.
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/gpu/context.h"
#include "engine/gpu/image.h"
#include "engine/render/chain_layer.h"
#include "engine/render/device_split.h"
#include "engine/render/emission_sum.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/interleave_filter.h"
#include "engine/render/matrix_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shading_pass.h"
#include "engine/render/shadow_clusters.h"
#include "engine/render/shadow_pass.h"
#include "engine/render/vpl_culling.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::gpu {
class CommandList;
class GpuTimer;
class Image;
}  // namespace mvpl::gpu

namespace mvpl::render {

double milliseconds_since(std::chrono::steady_clock::time_point start);

// The shadow pass's share of the renderer's options (the pass is rebuilt when it changes).
ShadowPassOptions shadow_pass_options(const RenderOptions& options);

struct VplRenderer::Impl {
    // Without `build_clusters` the caller hands the clusters over before the first begin()
    // (the devices of one renderer share device 0's: they are read only).
    Impl(gpu::Context& c, const scene::Scene& s, const trace::Accel* a, bool build_clusters = true)
        : context(&c),
          scene(&s),
          accel(a),
          camera(s.camera),
          geometry(c, s),
          clusters(build_clusters ? std::make_shared<const ShadowClusters>(s) : nullptr),
          culling(s) {}

    gpu::Context* context;
    const scene::Scene* scene;
    const trace::Accel* accel;  // null: no specular chains
    scene::Camera camera;
    SceneGeometry geometry;
    std::shared_ptr<const ShadowClusters> clusters;  // with the large meshes' levels of detail
    VplCulling culling;
    // Passes are kept between renders with the same sizes (pipelines compile in ~100 ms).
    std::unique_ptr<GBufferPass> g_buffer;
    std::unique_ptr<EmissionSum> emission;
    std::unique_ptr<ShadowPass> shadow;
    std::unique_ptr<ShadingPass> shading;
    std::unique_ptr<ChainLayer> chains;  // null unless the options and the scene ask for chains
    std::unique_ptr<InterleaveFilter> interleave;  // null without interleaved sampling
    // Row-column sampling's reduced matrix (VplRenderer::reduced_matrix), built at its first
    // use and again when the options of its rows' cubes or the program's types change.
    std::unique_ptr<MatrixPass> matrix;
    ShadowPassOptions matrix_shadow;
    ShaderFeatures matrix_features;
    // The passes above whose images have the image's size, parked for the sizes used before:
    // the preview switches between its motion and full resolutions, and building them again
    // costs about 0.5 s on DamagedHelmet under lavapipe (pipelines). Cleared whenever the
    // passes are rebuilt for another reason (they would be stale).
    struct SizedPasses {
        uint32_t width = 0, height = 0;
        std::unique_ptr<GBufferPass> g_buffer;
        std::unique_ptr<EmissionSum> emission;
        std::unique_ptr<ShadingPass> shading;
        std::unique_ptr<ChainLayer> chains;
        std::unique_ptr<InterleaveFilter> interleave;
    };
    static constexpr size_t kParkedSizes = 4;  // full, and the preview's divisors 2, 3 and 4
    std::vector<SizedPasses> parked;
    RenderOptions built_for = unbuilt();
    // The progressive state: what begin() set up.
    RenderOptions options;
    scene::Camera view_camera;
    RenderTimings timings;
    bool begun = false;
    uint64_t shaded = 0;      // VPLs accumulated since begin()
    uint64_t position = 0;    // the sub-pixel position of the G-buffer drawn last
    std::vector<bool> drawn;  // the positions whose emission this device added
    // Devices 1 … n − 1 of a renderer on several (device_split.h); their begin() draws no
    // G-buffer (position 0 is device 0's).
    struct Partner {
        std::unique_ptr<gpu::Context> context;
        std::unique_ptr<Impl> impl;  // destroyed before its context
    };
    std::vector<Partner> partners;
    bool draws_first_position = true;
    uint64_t group_shaded = 0;  // VPLs accumulated by all devices since begin()
    double group_wall_ms = 0.0;
    RenderTimings group_timings;

    uint32_t devices() const { return uint32_t(partners.size()) + 1; }
    Impl& device(uint32_t d) { return d == 0 ? *this : *partners[d - 1].impl; }
    const Impl& device(uint32_t d) const { return d == 0 ? *this : *partners[d - 1].impl; }
    // Throws GpuError naming `what` unless every device has begun.
    void require_begun(const char* what) const;
    // The RGBA32F image that `image` picks on each device, downloaded and summed over them.
    std::vector<float> summed(const gpu::Image& (*image)(const Impl&)) const;
    // Device 0's images of the sums that VplRenderer::presented() returns on several devices,
    // made again when `like` (device 0's own) changes size; summed again only when the group
    // began or accumulated since (`changes` counts those calls).
    gpu::Image presented_accumulation, presented_emission;
    uint64_t changes = 0, presented_changes = UINT64_MAX;
    // Uploads summed(image) into `target`, made like `like` where it is not.
    void present_sum(gpu::Image& target, const gpu::Image& like,
                     const gpu::Image& (*image)(const Impl&));
    void refresh_group_timings() {
        group_timings = timings;
        for (const Partner& p : partners)
            add_timings(group_timings, p.impl->timings);
        group_timings.wall_ms = group_wall_ms;
    }
    void start(const scene::Camera& camera, const RenderOptions& options);
    void accumulate(std::span<const light::Vpl> vpls, std::span<const uint64_t> index);
    // What every batch of accumulate() shades with: the view, the clamp, the maps, the chains.
    ShadingBatch shading_batch() const;
    // The VPLs of `slice` to shade. With options.vpl_culling (and no chains): those that may
    // light the view, copied into kept; interleaved, all of them, with skip[i] set for the others
    // (they draw no shadow cube). skip is empty otherwise.
    std::span<const light::Vpl> cull(std::span<const light::Vpl> slice,
                                     std::vector<light::Vpl>& kept, std::vector<bool>& skip);

    // Draws the G-buffer at sub-pixel `index` and, with add_emission, adds its emission to the
    // sum (and marks the position drawn).
    void record_g_buffer(gpu::CommandList& cmd, gpu::GpuTimer& timer, uint64_t index,
                         bool add_emission = true);

    void add_timing(std::chrono::steady_clock::time_point start, double shadow_ms,
                    double shading_ms);

    static RenderOptions unbuilt() {
        RenderOptions o;
        o.width = o.height = o.shadow_resolution = o.batch = 0;
        return o;
    }

    // Builds the passes these options need, keeping those that still fit.
    void prepare(const RenderOptions& o);
    // Parks the sized passes of built_for's size and takes those of width × height, parked or
    // new (the G-buffer and the emission sum; prepare() builds the others that are missing).
    void switch_size(uint32_t width, uint32_t height, const gpu::SpirvCacheOptions& cache);
};

}  // namespace mvpl::render

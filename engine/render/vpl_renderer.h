#pragma once
// The GPU VPL renderer: G-buffer once per view, then per batch of VPLs the shadow cubes and the
// shading, accumulated into one linear radiance image (docs/design.md, "GPU passes"). VPL powers
// are not divided by the number of light paths (vpl.h): render() takes a VplSet and applies its
// scale in the resolve; the progressive interface (begin/accumulate/resolve) takes the scale at the
// end (engine/sampler/vpl_stream.h), for time budgets and the interactive preview. Anti-aliasing:
// each batch is shaded against a G-buffer drawn at its own sub-pixel position
// (engine/core/subpixel.h), and the emitted radiance seen directly is averaged over the
// G-buffers drawn, so the image converges to the box-filtered pixel.
// Tonemapping happens when a PNG is written. Vulkan-free to include (pimpl).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/image_size.h"
#include "engine/core/subpixel.h"
#include "engine/light/chain_options.h"
#include "engine/light/virtual_sphere.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"
#include "shaders/shared/chain_record.h"

namespace mvpl::gpu {
class Context;
class Image;
}  // namespace mvpl::gpu
namespace mvpl::trace {
class Accel;
}

namespace mvpl::render {

struct KeptMapStats;

struct RenderOptions {
    uint32_t width = kDefaultImageWidth;
    uint32_t height = kDefaultImageHeight;
    uint32_t shadow_resolution = 256;  // side of a shadow cube face in texels
    uint32_t batch = 32;               // VPLs per shadow/shading batch
    // d_min = clamp · scene diagonal, the distance below which the geometric term stops growing.
    float clamp = light::kDefaultClamp;
    // Radius of the virtual spherical lights that area and surface VPLs become, as a fraction of
    // the scene diagonal (light/virtual_sphere.h); 0: point VPLs (--no-vsl).
    float vsl_radius = light::kDefaultVslRadius;
    bool shadows = true;  // false: every VPL unshadowed (tests, debugging)
    // Each cube face draws only the triangle clusters it can see (shadow_clusters.h); false: every
    // triangle into every face (the A/B of mvpl bench --sweep).
    bool shadow_culling = true;
    // Surface VPLs draw the simplified levels of the scene's large meshes where shadow_lod allows
    // them (shadow_clusters.h); false: surface VPLs draw the full geometry.
    bool shadow_proxy = true;
    // Each VPL draws each large mesh at the coarsest level of detail whose error stays below a
    // shadow texel's footprint at the mesh's distance (shadow_clusters.h); false:
    // full meshes.
    bool shadow_lod = true;
    // Large meshes that bound a solid draw only their faces towards a VPL outside their box
    // (ShadowPassOptions::front_faces), and towards the camera outside it into the G-buffer (as
    // one-sided materials always do); the same image. false: both faces of solids.
    bool backface_culling = true;
    // Area and Surface VPLs draw only the part of each cube face that their lit hemisphere can
    // reach (hemicube.h); false: whole faces (the A/B of mvpl bench --sweep).
    bool hemicube = true;
    // Device memory for shadow maps kept from one begin() to the next and copied back when the
    // same VPL is shaded again (kept_shadow_maps.h: the preview after a camera move); 0: none.
    // On several devices, the budget (capped by render_memory.h) is shared equally among them.
    uint64_t kept_shadow_bytes = 0;
    // Area and Surface VPLs whose lit half-space holds no point of the view are neither drawn
    // nor shaded (vpl_culling.h; the image is the same to the bit); false: every VPL.
    bool vpl_culling = true;
    // Sub-pixel positions: VPL i since begin() is shaded at position i / (batch ·
    // batches_per_position) of the sequence, its G-buffer drawn when that position comes up, so
    // that the image does not depend on how the VPLs were split into accumulate() calls. false:
    // one G-buffer at the pixel centres for the whole image (no anti-aliasing).
    bool jitter = true;
    uint32_t batches_per_position = 1;
    // The lattice rotation of the sequence (subpixel.h): subpixel_rotation(seed) for renders
    // whose error is compared across seeds; 0 (the plain sequence) by default.
    Vec2 subpixel_rotation{0.0f};
    // Specular chains (light/specular_chain.h): glossy pixels shaded at the rough end of their
    // camera paths, traced on the CPU per sub-pixel position with chain_seed's random numbers,
    // as the oracle traces them (reference::GatherOptions::chains). Only for a renderer given
    // the scene's BVH, and a scene with a material they may continue; off by default.
    light::ChainOptions chains;
    uint64_t chain_seed = 0;
    // Interleaved sampling (Keller & Heidrich 2001; shaders/shared/interleave.h): K in 1 … 8,
    // 1 for none. Each pixel shades 1/K² of every batch, then a geometry-aware filter over the
    // K×K neighbourhood on the batch's G-buffer restores the sum where the surface is smooth.
    // With specular chains, a chained pixel is filtered with the chained neighbours whose rough
    // ends are compatible only (interleave.h, "Chains").
    uint32_t interleave = 1;
    // Shader chain (shader_program.h): whether surface VPLs can occur (max depth ≥ 3), where to
    // write the generated GLSL of every stage (empty: nowhere), and the SPIR-V disk cache.
    bool surface_vpls = true;
    std::string dump_shaders;
    bool shader_cache = true;
    // Called after each batch with the number of VPLs it shaded (progress bars).
    std::function<void(size_t)> on_batch;
};

// Which VPLs share a sub-pixel position under these options (the CPU oracle's GatherOptions take
// the same schedule).
SubpixelSchedule subpixel_schedule(const RenderOptions& options);

// GPU milliseconds per pass (GpuTimer), summed over batches (and over devices, which run at once:
// then more than the wall time).
struct RenderTimings {
    double g_buffer_ms = 0.0;  // the G-buffers and the emission sum
    double shadow_ms = 0.0;
    double shading_ms = 0.0;
    double total_ms = 0.0;  // the three above
    double wall_ms = 0.0;   // host time of render(), uploads and read-back included
    uint32_t batches = 0;
    uint64_t shadow_triangles = 0;  // triangles drawn into cube faces and orthographic maps
    uint64_t shadow_front_only_triangles = 0;  // of those, solids' with their back faces culled
    // G-buffer triangles drawn with their back faces culled (one-sided materials and solids).
    uint64_t g_buffer_front_only_triangles = 0;
    uint64_t shadow_texels = 0;  // cube-face texels cleared and drawn
    uint64_t culled_vpls = 0;    // VPLs that could not reach the view (vpl_culling.h)
    // G-buffers drawn: one per sub-pixel position (and device that shades it)
    uint32_t g_buffers = 0;
    // Host time tracing specular chains (in wall_ms on one device; summed over several).
    double chain_ms = 0.0;
    uint64_t chain_rays = 0;
    uint64_t kept_maps = 0;  // shadow maps copied back instead of drawn (kept_shadow_bytes)
};

class VplRenderer {
public:
    // Uploads the scene's geometry once. The context must outlive the renderer; with `accel`
    // (the scene's BVH: specular chains), so must the scene and the BVH.
    VplRenderer(gpu::Context& context, const scene::Scene& scene,
                const trace::Accel* accel = nullptr);
    // The same on `devices` logical devices (1 … kMaxRenderDevices, device_split.h): device 0 is
    // `context`, the others are contexts made from its options, each with a renderer of its own.
    // accumulate() cuts each call's batches into one run per device (with kept shadow maps, deals
    // them out by index instead: device_split.h) and runs the devices at once; contributions(),
    // resolve(), presented() and timings() are their sums, and the image is the one device's (to
    // rounding). Why: llvmpipe rasterises a context's triangles only after it has shaded and
    // binned all of them on one thread, and waits for it, so on lavapipe one device's shadow
    // geometry runs beside the other's rasterisation and shading (docs/results.md, "Two
    // devices"); on several GPUs it is one device each. accumulation(), emission() and
    // g_buffer() below are device 0's alone.
    VplRenderer(gpu::Context& context, const scene::Scene& scene, const trace::Accel* accel,
                uint32_t devices);
    ~VplRenderer();
    VplRenderer(const VplRenderer&) = delete;
    VplRenderer& operator=(const VplRenderer&) = delete;

    // Linear radiance seen by the scene camera, row 0 at the top: vpls.scale · Σ contributions
    // plus the emitted radiance of surfaces seen directly (averaged over the G-buffers, unscaled).
    Image render(const light::VplSet& vpls, const RenderOptions& options,
                 RenderTimings* timings = nullptr);

    // Progressive rendering. begin() renders the first G-buffer seen by `camera` and clears the
    // accumulation; accumulate() shades VPLs into it, at most options.batch per shadow/shading
    // batch and a new G-buffer per sub-pixel position (any number of calls, any number of VPLs
    // each: with jitter, batches are cut at the positions' boundaries, so the image is that of
    // one call); resolve(scale) reads back scale · Σ contributions + the mean emitted radiance of
    // surfaces seen directly over the G-buffers drawn (not scaled).
    // Throws GpuError if accumulate() or resolve() come before begin(), and NonFiniteError
    // (engine/core/finite_check.h) naming the first pixel if the image holds a NaN or an
    // infinity: it is never returned silently.
    void begin(const scene::Camera& camera, const RenderOptions& options);
    void accumulate(std::span<const light::Vpl> vpls);
    Image resolve(double scale);

    // A share of a render split over ranks (engine/cluster): `index[i]` is VPL i's index since
    // begin() in the order one process would have shaded the whole set (increasing), which
    // decides its sub-pixel position, so that the ranks' images sum to the one-process image.
    void accumulate(std::span<const light::Vpl> vpls, std::span<const uint64_t> index);
    // Σ contributions so far (unscaled, no emission): what ranks sum.
    Image contributions() const;
    // scale · `sum` + the mean emitted radiance over the sub-pixel positions of `vpls` VPLs
    // (positions_after), drawing the G-buffers of the positions this renderer has not drawn.
    // resolve(scale) is resolve(scale, contributions(), VPLs accumulated).
    Image resolve(double scale, const Image& sum, uint64_t vpls);
    // Since the last begin(); batches counts shading dispatches.
    const RenderTimings& timings() const;

    // For presenting on the GPU (mvpl preview), valid after begin(): the RGBA32F accumulation of
    // Σ VPL contributions (no emission, unscaled), the RGBA32F emission sum (rgb Σ emitted
    // radiance over the G-buffers drawn, a their count: show rgb / a) and the G-buffer array
    // (GBufferLayer) of the latest sub-pixel position.
    const gpu::Image& accumulation() const;
    const gpu::Image& emission() const;
    const gpu::Image& g_buffer() const;
    // accumulation() and emission() summed over the devices, for presenting on device 0: on one
    // device its own images; on several, every device's read back, summed on the host and
    // uploaded into images of device 0 at each call (16 MB of copies at 512²).
    struct Presented {
        const gpu::Image* accumulation = nullptr;
        const gpu::Image* emission = nullptr;
    };
    Presented presented();
    // The reduced matrix of row-column sampling on device 0 after begin() (matrix_pass.h): the
    // rows' cubes at `resolution`, the clamp, spheres and shadows of begin()'s options; `out` as
    // MatrixPass::evaluate's.
    void reduced_matrix(std::span<const shared::ChainRecord> rows, std::span<const light::Vpl> vpls,
                        std::span<const uint32_t> hash, uint32_t dims, uint32_t resolution,
                        std::vector<float>& out);
    gpu::Context& context() const;
    uint32_t devices() const;
    // The kept shadow maps (RenderOptions::kept_shadow_bytes; zero without them), summed over
    // the devices.
    KeptMapStats kept_maps() const;
    // The most device memory allocated at once, summed over the devices (MemoryAllocator).
    uint64_t peak_device_bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace mvpl::render

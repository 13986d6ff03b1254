#include "engine/render/vpl_renderer.h"

#include <algorithm>
#include <chrono>
#include <span>

#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shading_pass.h"
#include "engine/render/shadow_pass.h"

namespace mvpl::render {

struct VplRenderer::Impl {
    Impl(gpu::Context& c, const scene::Scene& s) : context(&c), camera(s.camera), geometry(c, s) {}

    gpu::Context* context;
    scene::Camera camera;
    SceneGeometry geometry;
    // Passes are kept between renders with the same sizes (pipelines compile in ~100 ms).
    std::unique_ptr<GBufferPass> g_buffer;
    std::unique_ptr<ShadowPass> shadow;
    std::unique_ptr<ShadingPass> shading;
    RenderOptions built_for = unbuilt();

    static RenderOptions unbuilt() {
        RenderOptions o;
        o.width = o.height = o.shadow_resolution = o.batch = 0;
        return o;
    }

    void prepare(const RenderOptions& o) {
        if (!g_buffer || o.width != built_for.width || o.height != built_for.height) {
            g_buffer = std::make_unique<GBufferPass>(*context, geometry, o.width, o.height);
            shading.reset();
        }
        if (!shadow || o.shadow_resolution != built_for.shadow_resolution ||
            o.batch != built_for.batch) {
            shadow = std::make_unique<ShadowPass>(*context, geometry, o.shadow_resolution, o.batch);
            shading.reset();
        }
        if (!shading) shading = std::make_unique<ShadingPass>(*context, o.width, o.height, o.batch);
        built_for = o;
    }
};

VplRenderer::VplRenderer(gpu::Context& context, const scene::Scene& scene)
    : m_impl(std::make_unique<Impl>(context, scene)) {}

VplRenderer::~VplRenderer() = default;

Image VplRenderer::render(const std::vector<light::Vpl>& vpls, const RenderOptions& options,
                          RenderTimings* timings) {
    if (options.width == 0 || options.height == 0 || options.batch == 0 ||
        options.shadow_resolution == 0) {
        throw gpu::GpuError("VplRenderer::render: zero width, height, batch or shadow resolution");
    }
    const auto start = std::chrono::steady_clock::now();
    Impl& m = *m_impl;
    m.prepare(options);
    const uint32_t batches = uint32_t((vpls.size() + options.batch - 1) / options.batch);
    gpu::GpuTimer timer(*m.context, 1 + 2 * std::max(batches, 1u));
    m.context->submit_and_wait([&](gpu::CommandList& cmd) {
        const uint32_t scope = timer.begin(cmd, "g-buffer");
        m.g_buffer->record(cmd, m.camera);
        m.shading->record_clear(cmd);
        timer.end(cmd, scope);
        cmd.barrier();
    });

    ShadingBatch batch;
    batch.camera_position = m.camera.position();
    batch.d_min = options.clamp * m.geometry.bounds().diagonal();
    batch.shadows = options.shadows ? &m.shadow->cubes() : nullptr;
    batch.ortho_shadows = options.shadows ? &m.shadow->ortho_maps() : nullptr;
    // At least one shading dispatch, so that the emitted radiance is added without VPLs too.
    for (uint32_t b = 0; b < std::max(batches, 1u); ++b) {
        const size_t first = size_t(b) * options.batch;
        const size_t count =
            std::min<size_t>(options.batch, vpls.size() - std::min(first, vpls.size()));
        const std::span<const light::Vpl> slice(vpls.data() + std::min(first, vpls.size()), count);
        m.shading->upload(slice, m.geometry.bounds());
        batch.add_emission = b == 0;
        m.context->submit_and_wait([&](gpu::CommandList& cmd) {
            if (options.shadows) {
                const uint32_t scope = timer.begin(cmd, "shadow");
                m.shadow->record(cmd, slice);
                timer.end(cmd, scope);
                cmd.barrier();
            }
            const uint32_t scope = timer.begin(cmd, "shading");
            m.shading->record(cmd, m.g_buffer->image(), batch);
            timer.end(cmd, scope);
        });
        if (options.on_batch) options.on_batch(count);
    }

    const std::vector<float> rgba = m.shading->accumulation().download_as<float>();
    Image image(int(options.width), int(options.height));
    for (size_t i = 0; i < image.pixels().size(); ++i)
        image.pixels()[i] = Rgb(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);

    if (timings) {
        timings->g_buffer_ms = timer.milliseconds("g-buffer");
        timings->shadow_ms = timer.milliseconds("shadow");
        timings->shading_ms = timer.milliseconds("shading");
        timings->total_ms = timings->g_buffer_ms + timings->shadow_ms + timings->shading_ms;
        timings->wall_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        timings->batches = batches;
    }
    return image;
}

}  // namespace mvpl::render

#include "engine/render/vpl_renderer_impl.h"

#include <algorithm>
#include <limits>

#include "engine/core/error.h"
#include "engine/core/host_memory.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/image.h"
#include "engine/light/specular_chain.h"
#include "engine/render/batch_plan.h"
#include "engine/render/render_memory.h"
#include "engine/scene/camera.h"

namespace mvpl::render {

namespace {

// The environment seen through each pixel's centre, RGBA32F rows from the top, what the
// G-buffer's uncovered pixels show (EmissionSum::set_background). Pixel centres, not the
// sub-pixel positions: an environment varies little within a pixel, and where a silhouette cuts
// the pixel, the G-buffers' coverage over the positions still weighs the two.
std::vector<float> background_image(const scene::Environment& environment,
                                    const scene::Camera& camera, uint32_t width, uint32_t height) {
    std::vector<float> rgba(size_t(width) * size_t(height) * 4, 0.0f);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const scene::CameraRay r = scene::generate_camera_ray(
                camera, int(width), int(height), Vec2(float(x) + 0.5f, float(y) + 0.5f));
            const Rgb l = environment.lookup(glm::normalize(r.direction));
            float* out = &rgba[(size_t(y) * width + x) * 4];
            out[0] = l.r;
            out[1] = l.g;
            out[2] = l.b;
        }
    }
    return rgba;
}

}  // namespace

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

void VplRenderer::Impl::record_g_buffer(gpu::CommandList& cmd, gpu::GpuTimer& timer, uint64_t index,
                                        bool add_emission) {
    const uint32_t scope = timer.begin(cmd, "g-buffer");
    const Vec2 offset = subpixel_schedule(options).position(index);
    const uint64_t front_only = g_buffer->front_only_triangles();
    g_buffer->record(cmd, view_camera, offset, options.backface_culling);
    timings.g_buffer_front_only_triangles += g_buffer->front_only_triangles() - front_only;
    if (chains) {
        // The GPU is idle: each batch is submitted and waited for (accumulate()).
        const auto start = std::chrono::steady_clock::now();
        const uint64_t rays = chains->rays();
        chains->trace(view_camera, offset, index, options.chains, options.chain_seed);
        timings.chain_ms += milliseconds_since(start);
        timings.chain_rays += chains->rays() - rays;
    }
    cmd.barrier();
    if (add_emission) {
        emission->record_add(cmd, g_buffer->image(), chains ? &chains->records() : nullptr);
        cmd.barrier();
        if (drawn.size() <= index) drawn.resize(size_t(index) + 1, false);
        drawn[size_t(index)] = true;
    }
    timer.end(cmd, scope);
    position = index;
    ++timings.g_buffers;
}

void VplRenderer::Impl::require_begun(const char* what) const {
    for (uint32_t d = 0; d < devices(); ++d) {
        if (!device(d).begun) throw gpu::GpuError(std::string(what) + " before begin");
    }
}

std::vector<float> VplRenderer::Impl::summed(const gpu::Image& (*image)(const Impl&)) const {
    std::vector<float> sum = image(*this).download_as<float>();
    for (const Partner& p : partners) {
        const std::vector<float> more = image(*p.impl).download_as<float>();
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += more[i];
    }
    return sum;
}

void VplRenderer::Impl::present_sum(gpu::Image& target, const gpu::Image& like,
                                    const gpu::Image& (*image)(const Impl&)) {
    if (!target.valid() || target.width() != like.width() || target.height() != like.height())
        target = gpu::Image(*context, like.desc(), "presented " + like.name());
    target.upload(summed(image));
}

void VplRenderer::Impl::add_timing(std::chrono::steady_clock::time_point start, double shadow_ms,
                                   double shading_ms) {
    timings.shadow_ms += shadow_ms;
    timings.shading_ms += shading_ms;
    timings.total_ms = timings.g_buffer_ms + timings.shadow_ms + timings.shading_ms;
    timings.wall_ms += milliseconds_since(start);
}

ShadowPassOptions shadow_pass_options(const RenderOptions& o) {
    ShadowPassOptions so;
    so.resolution = o.shadow_resolution;
    so.max_batch = o.batch;
    so.culling = o.shadow_culling;
    so.proxy = o.shadow_proxy;
    so.lod = o.shadow_lod;
    so.front_faces = o.backface_culling;
    so.hemicube = o.hemicube;
    so.kept_bytes = o.kept_shadow_bytes;
    return so;
}

void VplRenderer::Impl::prepare(const RenderOptions& o) {
    // The program is generated for this scene (shader_program.h); SPIR-V from the disk cache.
    const gpu::SpirvCacheOptions cache{o.shader_cache, {}};
    const std::string shortfall =
        memory_shortfall(o, context->device_info(), host_memory_bytes(), devices());
    if (!shortfall.empty()) throw UsageError(shortfall);
    if (!g_buffer || o.width != built_for.width || o.height != built_for.height)
        switch_size(o.width, o.height, cache);
    ShadowPassOptions so = shadow_pass_options(o);
    so.kept_bytes = kept_maps_budget(so.kept_bytes, context->device_info(), host_memory_bytes());
    if (!shadow || shadow->options() != so) {
        shadow = std::make_unique<ShadowPass>(*context, geometry, *clusters, so);
        shading.reset();
        parked.clear();
    }
    if (o.surface_vpls != built_for.surface_vpls) {
        shading.reset();
        parked.clear();
    }
    const bool chained = accel && light::scene_may_chain(*scene, o.chains);
    if (!chained) {
        chains.reset();
    } else if (!chains || chains->width() != o.width || chains->height() != o.height) {
        chains = std::make_unique<ChainLayer>(*context, *scene, *accel, o.width, o.height);
    }
    if (shading && shading->features().specular_chains != chained) {
        shading.reset();
        parked.clear();
    }
    if (!shading) {
        ShaderFeatures features = geometry.features(o.surface_vpls);
        features.specular_chains = chained;
        shading = std::make_unique<ShadingPass>(*context, o.width, o.height, o.batch, features,
                                                nullptr, cache);
    }
    if (o.interleave <= 1) {
        interleave.reset();
    } else if (!interleave || interleave->k() != o.interleave) {  // switch_size: the size
        interleave = std::make_unique<InterleaveFilter>(*context, o.width, o.height, o.interleave);
    }
    if (!o.dump_shaders.empty()) dump_scene_shaders(o.dump_shaders, geometry, o.surface_vpls);
    built_for = o;
}

void VplRenderer::Impl::switch_size(uint32_t width, uint32_t height,
                                    const gpu::SpirvCacheOptions& cache) {
    if (g_buffer) {
        parked.push_back({built_for.width, built_for.height, std::move(g_buffer),
                          std::move(emission), std::move(shading), std::move(chains),
                          std::move(interleave)});
        if (parked.size() > kParkedSizes) parked.erase(parked.begin());
    }
    const auto same = std::find_if(parked.begin(), parked.end(), [&](const SizedPasses& p) {
        return p.width == width && p.height == height;
    });
    if (same != parked.end()) {
        g_buffer = std::move(same->g_buffer);
        emission = std::move(same->emission);
        shading = std::move(same->shading);
        chains = std::move(same->chains);
        interleave = std::move(same->interleave);
        parked.erase(same);
        return;
    }
    g_buffer =
        std::make_unique<GBufferPass>(*context, geometry, width, height, nullptr, nullptr, cache);
    emission = std::make_unique<EmissionSum>(*context, width, height);
}

void VplRenderer::Impl::start(const scene::Camera& camera, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    Impl& m = *this;
    m.prepare(options);
    m.options = options;
    m.view_camera = camera;
    if (options.vpl_culling) m.culling.set_view(camera, options.width, options.height);
    if (m.geometry.environment().active()) {
        m.emission->set_background(
            background_image(m.geometry.environment(), camera, options.width, options.height));
    }
    m.timings = RenderTimings{};
    m.shadow->new_estimate();
    m.shaded = 0;
    m.drawn.clear();
    gpu::GpuTimer timer(*m.context, 1);
    m.context->submit_and_wait([&](gpu::CommandList& cmd) {
        m.shading->record_clear(cmd);
        if (m.interleave) m.interleave->record_clear(cmd);
        m.emission->record_clear(cmd);
        if (m.draws_first_position) m.record_g_buffer(cmd, timer, 0);
    });
    if (!m.draws_first_position) m.position = std::numeric_limits<uint64_t>::max();
    m.timings.g_buffer_ms = timer.milliseconds("g-buffer");
    m.begun = true;
    m.add_timing(start, 0.0, 0.0);
}

ShadingBatch VplRenderer::Impl::shading_batch() const {
    ShadingBatch batch;
    batch.camera_position = view_camera.position();
    batch.d_min = options.clamp * geometry.bounds().diagonal();
    batch.vsl_radius = options.vsl_radius * geometry.bounds().diagonal();
    batch.shadows = options.shadows ? &shadow->cubes() : nullptr;
    batch.ortho_shadows = options.shadows ? &shadow->ortho_maps() : nullptr;
    // Emitted radiance is summed per G-buffer (EmissionSum) and added by resolve(), unscaled, so
    // the accumulation holds VPLs only.
    batch.add_emission = false;
    batch.chains = chains ? &chains->records() : nullptr;
    return batch;
}

std::span<const light::Vpl> VplRenderer::Impl::cull(std::span<const light::Vpl> slice,
                                                    std::vector<light::Vpl>& kept,
                                                    std::vector<bool>& skip) {
    skip.clear();
    // Not with chains: a VPL may light only what a mirror shows, outside the view.
    if (!options.vpl_culling || chains) return slice;
    // Without interleaving the culled VPLs leave the batch (each would add nothing); interleaved,
    // a VPL's index picks its pixels, so they stay and only lose their shadow cubes.
    kept.clear();
    skip.resize(slice.size());
    for (size_t i = 0; i < slice.size(); ++i) {
        skip[i] = !culling.may_reach_view(slice[i]);
        if (!skip[i]) kept.push_back(slice[i]);
    }
    timings.culled_vpls += slice.size() - kept.size();
    if (interleave) return slice;
    skip.clear();
    return kept;
}

void VplRenderer::Impl::accumulate(std::span<const light::Vpl> vpls,
                                   std::span<const uint64_t> index) {
    Impl& m = *this;
    if (!m.begun) throw gpu::GpuError("VplRenderer::accumulate before begin");
    if (!index.empty() && index.size() != vpls.size())
        throw gpu::GpuError("VplRenderer::accumulate: one index per VPL");
    if (vpls.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    const RenderOptions& options = m.options;
    const SubpixelSchedule schedule = subpixel_schedule(options);
    const uint64_t shaded_before = m.shaded;
    const std::vector<Slice> slices = plan_batches(vpls.size(), shaded_before, options, index);
    gpu::GpuTimer timer(*m.context, 3 * uint32_t(slices.size()));

    ShadingBatch batch = m.shading_batch();
    const uint64_t drawn_before = m.shadow->triangles_drawn();
    const uint64_t front_before = m.shadow->front_only_triangles();
    const uint64_t texels_before = m.shadow->texels_drawn();
    const uint64_t kept_before = m.shadow->kept().restored;
    std::vector<light::Vpl> kept;
    std::vector<bool> skip;
    for (size_t si = 0; si < slices.size(); ++si) {
        const Slice& s = slices[si];
        // The interleaved shares of a position are filtered once, after its last batch of the
        // call (the accumulation must hold them when the call returns).
        const bool position_ends = si + 1 == slices.size() || slices[si + 1].position != s.position;
        std::span<const light::Vpl> slice = vpls.subspan(s.first, s.count);
        slice = m.cull(slice, kept, skip);
        m.shading->upload(slice, m.geometry.bounds());
        m.shadow->reserve_kept(slice);
        if (m.interleave) {
            batch.interleave = options.interleave;
            batch.vpl_offset = index.empty() ? shaded_before + s.first : index[s.first];
            batch.interleaved = &m.interleave->shaded();
        }
        m.context->submit_and_wait([&](gpu::CommandList& cmd) {
            if (s.position != m.position) {
                // The emission of a position is added once, by whoever shades its first VPL:
                // over devices or ranks others may draw its G-buffer too (device_split.h).
                const uint64_t k = index.empty() ? shaded_before + s.first : index[s.first];
                m.record_g_buffer(cmd, timer, s.position, k == schedule.first_of(s.position));
            }
            if (options.shadows) {
                const uint32_t scope = timer.begin(cmd, "shadow");
                m.shadow->record(cmd, slice, skip);
                timer.end(cmd, scope);
                cmd.barrier();
            }
            const uint32_t scope = timer.begin(cmd, "shading");
            m.shading->record(cmd, m.g_buffer->image(), batch);
            if (m.interleave && position_ends) {
                cmd.barrier();
                m.interleave->record(cmd, m.g_buffer->image(), m.shading->accumulation(),
                                     m.chains ? &m.chains->records() : nullptr);
            }
            timer.end(cmd, scope);
        });
        m.shaded = index.empty() ? m.shaded + s.count : index[s.first + s.count - 1] + 1;
        if (options.on_batch) options.on_batch(s.count);
    }
    m.timings.batches += uint32_t(slices.size());
    m.timings.g_buffer_ms += timer.milliseconds("g-buffer");
    m.timings.shadow_triangles += m.shadow->triangles_drawn() - drawn_before;
    m.timings.shadow_front_only_triangles += m.shadow->front_only_triangles() - front_before;
    m.timings.shadow_texels += m.shadow->texels_drawn() - texels_before;
    m.timings.kept_maps += m.shadow->kept().restored - kept_before;
    m.add_timing(start, timer.milliseconds("shadow"), timer.milliseconds("shading"));
}

}  // namespace mvpl::render

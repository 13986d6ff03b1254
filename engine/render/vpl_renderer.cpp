#include "engine/render/vpl_renderer.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <span>

#include "engine/core/error.h"
#include "engine/core/finite_check.h"
#include "engine/core/host_memory.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/memory.h"
#include "engine/render/device_split.h"
#include "engine/render/render_memory.h"
#include "engine/render/vpl_renderer_impl.h"

namespace mvpl::render {

SubpixelSchedule subpixel_schedule(const RenderOptions& options) {
    return {options.jitter,
            uint64_t(options.batch) * std::max<uint64_t>(options.batches_per_position, 1),
            options.subpixel_rotation};
}

VplRenderer::VplRenderer(gpu::Context& context, const scene::Scene& scene,
                         const trace::Accel* accel)
    : m_impl(std::make_unique<Impl>(context, scene, accel)) {}

VplRenderer::VplRenderer(gpu::Context& context, const scene::Scene& scene,
                         const trace::Accel* accel, uint32_t devices) {
    if (devices == 0 || devices > kMaxRenderDevices) {
        throw gpu::GpuError("VplRenderer: " + std::to_string(devices) + " devices, not 1.." +
                            std::to_string(kMaxRenderDevices));
    }
    // Each device uploads its own geometry, all at once, while device 0 builds the shadow
    // clusters (the levels of detail: most of the start-up on a large mesh) that all share.
    std::vector<Impl::Partner> partners(devices - 1);
    run_on_devices(devices, [&](uint32_t d) {
        if (d == 0) {
            m_impl = std::make_unique<Impl>(context, scene, accel);
            return;
        }
        Impl::Partner& p = partners[d - 1];
        p.context = std::make_unique<gpu::Context>(context.options());
        p.impl = std::make_unique<Impl>(*p.context, scene, accel, false);
        p.impl->draws_first_position = false;
    });
    for (Impl::Partner& p : partners)
        p.impl->clusters = m_impl->clusters;
    m_impl->partners = std::move(partners);
}

VplRenderer::~VplRenderer() = default;

Image VplRenderer::render(const light::VplSet& vpls, const RenderOptions& options,
                          RenderTimings* timings) {
    const auto start = std::chrono::steady_clock::now();
    begin(m_impl->camera, options);
    accumulate(vpls.vpls);
    Image image = resolve(vpls.scale);
    if (timings) {
        *timings = this->timings();
        timings->wall_ms = milliseconds_since(start);
    }
    return image;
}

void VplRenderer::begin(const scene::Camera& camera, const RenderOptions& options) {
    if (options.width == 0 || options.height == 0 || options.batch == 0 ||
        options.shadow_resolution == 0 || options.batches_per_position == 0 ||
        options.interleave == 0 || options.interleave > 8) {
        throw gpu::GpuError(
            "VplRenderer::begin: zero width, height, batch, shadow resolution or batches per "
            "position, or interleave outside 1..8");
    }
    Impl& m = *m_impl;
    if (m.partners.empty()) {
        m.start(camera, options);
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    // Until every device has begun, none has: a failure below leaves the group unbegun, never
    // some devices on the old sizes and some on the new.
    for (uint32_t d = 0; d < m.devices(); ++d)
        m.device(d).begun = false;
    const std::string shortfall =
        memory_shortfall(options, m.context->device_info(), host_memory_bytes(), m.devices());
    if (!shortfall.empty()) throw UsageError(shortfall);
    RenderOptions shared = options;
    // The devices share the kept maps' budget (each keeps the maps of the VPLs dealt to it).
    shared.kept_shadow_bytes =
        kept_maps_budget(options.kept_shadow_bytes, m.context->device_info(), host_memory_bytes()) /
        m.devices();
    if (options.on_batch) {
        // The devices report from their own threads.
        auto mutex = std::make_shared<std::mutex>();
        shared.on_batch = [mutex, report = options.on_batch](size_t n) {
            std::lock_guard<std::mutex> lock(*mutex);
            report(n);
        };
    }
    RenderOptions partner = shared;
    partner.dump_shaders.clear();  // the same files: device 0 writes them
    run_on_devices(m.devices(),
                   [&](uint32_t d) { m.device(d).start(camera, d == 0 ? shared : partner); });
    m.group_shaded = 0;
    ++m.changes;
    m.group_wall_ms = milliseconds_since(start);
    m.refresh_group_timings();
}

void VplRenderer::accumulate(std::span<const light::Vpl> vpls) {
    accumulate(vpls, {});
}

void VplRenderer::accumulate(std::span<const light::Vpl> vpls, std::span<const uint64_t> index) {
    Impl& m = *m_impl;
    if (m.partners.empty()) {
        m.accumulate(vpls, index);
        return;
    }
    if (!m.begun) throw gpu::GpuError("VplRenderer::accumulate before begin");
    if (!index.empty() && index.size() != vpls.size())
        throw gpu::GpuError("VplRenderer::accumulate: one index per VPL");
    if (vpls.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    std::vector<DeviceShare> shares;
    if (m.options.kept_shadow_bytes > 0) {
        // Whole sub-pixel positions (batches without jitter) dealt out by index: a replayed VPL
        // meets its kept map, and each position's G-buffer, specular chains included, is drawn
        // on one device.
        const SubpixelSchedule schedule = subpixel_schedule(m.options);
        const uint64_t run = schedule.jitter ? schedule.vpls_per_position : m.options.batch;
        shares = deal_batches(vpls, index, m.group_shaded, run, m.devices());
    } else {
        shares = split_into_runs(vpls, index, m.group_shaded, m.options.batch, m.devices());
    }
    run_on_devices(m.devices(), [&](uint32_t d) {
        if (!shares[d].vpls.empty()) m.device(d).accumulate(shares[d].vpls, shares[d].index);
    });
    m.group_shaded = index.empty() ? m.group_shaded + vpls.size() : index.back() + 1;
    ++m.changes;
    m.group_wall_ms += milliseconds_since(start);
    m.refresh_group_timings();
}

Image VplRenderer::resolve(double scale) {
    const Impl& m = *m_impl;
    return resolve(scale, contributions(), m.partners.empty() ? m.shaded : m.group_shaded);
}

Image VplRenderer::contributions() const {
    const Impl& m = *m_impl;
    m.require_begun("VplRenderer::contributions");
    const std::vector<float> rgba =
        m.summed([](const Impl& d) -> const gpu::Image& { return d.shading->accumulation(); });
    Image image(int(m.options.width), int(m.options.height));
    for (size_t i = 0; i < image.pixels().size(); ++i)
        image.pixels()[i] = Rgb(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
    return image;
}

Image VplRenderer::resolve(double scale, const Image& sum, uint64_t vpls) {
    Impl& m = *m_impl;
    m.require_begun("VplRenderer::resolve");
    ++m.changes;  // it may draw G-buffers, adding to the emission sum
    if (sum.width() != int(m.options.width) || sum.height() != int(m.options.height))
        throw gpu::GpuError("VplRenderer::resolve: the sum is not the image's size");
    const auto start = std::chrono::steady_clock::now();
    // A rank draws the G-buffers of the positions its own VPLs fall on; the emission averages
    // over every position of the whole set, as one process would have drawn them.
    const SubpixelSchedule schedule = subpixel_schedule(m.options);
    const uint64_t positions = schedule.jitter ? schedule.positions_after(vpls) : 1;
    std::vector<uint64_t> missing;
    for (uint64_t p = 0; p < positions; ++p) {
        bool drawn = false;
        for (uint32_t d = 0; d < m.devices(); ++d) {
            const std::vector<bool>& on = m.device(d).drawn;
            drawn = drawn || (p < on.size() && on[size_t(p)]);
        }
        if (!drawn) missing.push_back(p);
    }
    // The chain records hold one position: a submission each where chains are traced.
    const size_t per_submission = m.chains ? 1 : std::max<size_t>(missing.size(), 1);
    for (size_t i = 0; i < missing.size(); i += per_submission) {
        const size_t n = std::min(per_submission, missing.size() - i);
        gpu::GpuTimer timer(*m.context, uint32_t(n));
        m.context->submit_and_wait([&](gpu::CommandList& cmd) {
            for (size_t k = i; k < i + n; ++k)
                m.record_g_buffer(cmd, timer, missing[k]);
        });
        m.timings.g_buffer_ms += timer.milliseconds("g-buffer");
    }
    // Each device summed the emission of the positions it drew, and counted them (alpha).
    const std::vector<float> emission =
        m.summed([](const Impl& d) -> const gpu::Image& { return d.emission->image(); });
    Image image(int(m.options.width), int(m.options.height));
    for (size_t i = 0; i < image.pixels().size(); ++i) {
        const Rgb a = sum.pixels()[i];
        const float* e = &emission[4 * i];
        // e[3] counts the G-buffers summed (one at least after begin()).
        const double count = std::max(double(e[3]), 1.0);
        // In double, so that a huge 1/N or a tiny one does not round the sum twice.
        image.pixels()[i] =
            Rgb(float(scale * a.r + e[0] / count), float(scale * a.g + e[1] / count),
                float(scale * a.b + e[2] / count));
    }
    m.add_timing(start, 0.0, 0.0);
    if (!m.partners.empty()) {
        m.group_wall_ms += milliseconds_since(start);
        m.refresh_group_timings();
    }
    require_finite(image, "VplRenderer::resolve");
    return image;
}

const RenderTimings& VplRenderer::timings() const {
    return m_impl->partners.empty() ? m_impl->timings : m_impl->group_timings;
}

uint32_t VplRenderer::devices() const {
    return m_impl->devices();
}

KeptMapStats VplRenderer::kept_maps() const {
    KeptMapStats sum;
    for (uint32_t d = 0; d < m_impl->devices(); ++d) {
        const Impl& device = m_impl->device(d);
        if (!device.shadow) continue;
        const KeptMapStats kept = device.shadow->kept();
        sum.maps += kept.maps;
        sum.capacity += kept.capacity;
        sum.budget_bytes += kept.budget_bytes;
        sum.restored += kept.restored;
    }
    return sum;
}

uint64_t VplRenderer::peak_device_bytes() const {
    uint64_t bytes = m_impl->context->allocator().peak_bytes();
    for (const Impl::Partner& p : m_impl->partners)
        bytes += p.context->allocator().peak_bytes();
    return bytes;
}

const gpu::Image& VplRenderer::accumulation() const {
    if (!m_impl->shading) throw gpu::GpuError("VplRenderer::accumulation before begin");
    return m_impl->shading->accumulation();
}

const gpu::Image& VplRenderer::emission() const {
    if (!m_impl->emission) throw gpu::GpuError("VplRenderer::emission before begin");
    return m_impl->emission->image();
}

VplRenderer::Presented VplRenderer::presented() {
    Impl& m = *m_impl;
    if (m.partners.empty()) return {&accumulation(), &emission()};
    m.require_begun("VplRenderer::presented");
    if (m.presented_changes == m.changes) return {&m.presented_accumulation, &m.presented_emission};
    m.presented_changes = m.changes;
    m.present_sum(m.presented_accumulation, accumulation(),
                  [](const Impl& d) -> const gpu::Image& { return d.shading->accumulation(); });
    m.present_sum(m.presented_emission, emission(),
                  [](const Impl& d) -> const gpu::Image& { return d.emission->image(); });
    return {&m.presented_accumulation, &m.presented_emission};
}

const gpu::Image& VplRenderer::g_buffer() const {
    if (!m_impl->g_buffer) throw gpu::GpuError("VplRenderer::g_buffer before begin");
    return m_impl->g_buffer->image();
}

gpu::Context& VplRenderer::context() const {
    return *m_impl->context;
}

void VplRenderer::reduced_matrix(std::span<const shared::ChainRecord> rows,
                                 std::span<const light::Vpl> vpls, std::span<const uint32_t> hash,
                                 uint32_t dims, uint32_t resolution, std::vector<float>& out) {
    Impl& m = *m_impl;
    m.require_begun("VplRenderer::reduced_matrix");
    ShadowPassOptions shadow = shadow_pass_options(m.options);
    shadow.resolution = resolution;
    ShaderFeatures features = m.shading->features();
    features.specular_chains = false;
    if (!m.matrix || !(m.matrix_shadow == shadow) ||
        m.matrix_features.vpl_types != features.vpl_types ||
        m.matrix_features.closure_types != features.closure_types) {
        m.matrix.reset();
        m.matrix =
            std::make_unique<MatrixPass>(*m.context, m.geometry, *m.clusters, features, shadow,
                                         gpu::SpirvCacheOptions{m.options.shader_cache, {}});
        m.matrix_shadow = shadow;
        m.matrix_features = features;
    }
    const ShadingBatch batch = m.shading_batch();
    const MatrixInput in{rows, vpls, hash, dims, batch.d_min, batch.vsl_radius, m.options.shadows};
    m.matrix->evaluate(in, m.geometry.bounds(), out);
}

}  // namespace mvpl::render

#include "engine/integrator/vpl_integrator.h"

#include <utility>

#include "engine/core/error.h"
#include "engine/core/interrupt.h"
#include "engine/core/timer.h"
#include "engine/sampler/metropolis_stream.h"

namespace mvpl::integrator {

namespace {

// Adds `part` into `sum`, pixel by pixel.
void add_image(Image& sum, const Image& part, float scale = 1.0f) {
    for (size_t i = 0; i < sum.pixels().size(); ++i)
        sum.pixels()[i] += part.pixels()[i] * scale;
}

}  // namespace

VplIntegrator::VplIntegrator(const SceneView& view, gpu::Context* context, uint32_t devices,
                             cluster::Cluster* ranks)
    : m_ranks(ranks ? *ranks : cluster::single_process()), m_view(view) {
    if (shared() && !context)
        throw UsageError("render: --oracle runs on one process, not under mpirun");
    cluster::together(m_ranks, [&] {
        if (context)
            m_renderer =
                std::make_unique<render::VplRenderer>(*context, *view.scene, view.accel, devices);
    });
}

void VplIntegrator::begin(const SceneView& view, const Estimate& estimate, Pacing pacing,
                          std::unique_ptr<sampler::VplStream> stream) {
    // Every rank has the same estimate, so every rank refuses it alike.
    if (shared() && estimate.many_lights.enabled())
        throw UsageError("render: --pool runs on one process, not under mpirun");
    m_view = view;
    m_estimate = estimate;
    m_pacing = pacing;
    m_stats = {};
    m_cpu.reset();  // its threads hold the old view
    cluster::together(m_ranks, [&] {
        if (m_renderer) m_renderer->begin(*view.camera, m_estimate.render);
        m_cpu = std::make_unique<CpuEstimators>(view, m_estimate, m_ranks.rank(), m_ranks.size());
    });
    Timer setup;
    if (stream) {
        m_stream = std::move(stream);
    } else {
        sampler::SamplerSettings settings = sampler_settings(m_estimate);
        // The caustic tracer carries the light of the chains' class: no VPL there.
        if (m_cpu->caustics()) settings.tracer.specular = m_estimate.render.chains;
        if (shared()) settings.cluster = &m_ranks;
        m_stream.reset();
        // The Metropolis bootstrap meets the other ranks inside (its own agreement points).
        cluster::together(m_ranks, [&] {
            m_stream = sampler::make_vpl_stream(m_estimate.sampler, *view.scene, *view.accel,
                                                *view.lights, *view.camera, settings);
        });
    }
    m_stats.sampling_seconds += setup.seconds();
    m_gather = gather_options(m_estimate);
    m_gather.max_depth = 0;  // VPL light only: the emitted radiance is added at the end
    m_gather.quiet = true;
    m_sum = m_renderer ? Image() : Image(m_gather.width, m_gather.height);
    m_many_lights.reset();
    if (m_estimate.many_lights.enabled()) {
        manylights::RowColumnContext c = row_column_context(m_estimate);
        c.scene = view.scene;
        c.accel = view.accel;
        c.camera = view.camera;
        m_many_lights = std::make_unique<manylights::RowColumnSampler>(c, m_estimate.many_lights);
    }
}

VplIntegrator::~VplIntegrator() = default;

bool VplIntegrator::unlit() const {
    const auto* metropolis = dynamic_cast<const sampler::MetropolisStream*>(m_stream.get());
    return metropolis && metropolis->no_visible_light();
}

void VplIntegrator::advance(uint64_t work) {
    m_chunk.clear();
    Timer sampling;
    m_stream->next(work, m_chunk);  // over ranks: an agreement point inside
    if (m_many_lights) {  // each pool's weighted cluster representatives instead of the pool
        m_many_lights->reduce(m_chunk);
        m_stats.many_lights = m_many_lights->stats();
    }
    m_stats.sampling_seconds += sampling.seconds();
    Timer shading;
    cluster::together(m_ranks, [&] {
        if (m_renderer) {
            m_renderer->accumulate(m_chunk, m_stream->last_index());
        } else if (!m_chunk.empty()) {
            // Shaded at the sub-pixel positions the GPU gives them: their indices since the start.
            m_gather.first_vpl = m_stats.shaded;
            add_image(m_sum,
                      reference::gather_vpls(*m_view.scene, *m_view.accel, {m_chunk}, m_gather));
        }
    });
    m_stats.shading_seconds += shading.seconds();
    m_stats.vpls = m_stream->vpls_total();
    m_stats.shaded += m_chunk.size();
    m_stats.units = m_stream->work_done();
    m_cpu->pace(paced_vpls(), m_pacing);
}

// One process, VPL light: scale · Σ contributions + emission (the GPU's resolve, or the oracle's
// emission averaged over the positions of every VPL).
Image VplIntegrator::vpl_image() {
    if (m_renderer) return m_renderer->resolve(m_stream->scale());
    reference::GatherOptions emission = gather_options(m_estimate);
    emission.quiet = true;
    emission.first_vpl = m_stats.shaded;
    Image image = reference::gather_vpls(*m_view.scene, *m_view.accel, {}, emission);
    add_image(image, m_sum, float(m_stream->scale()));
    return image;
}

Image VplIntegrator::image() {
    Timer shading;
    Image image;
    if (shared()) {
        image = shared_image(false);
    } else {
        image = vpl_image();
        add_image(image, cpu_image());
    }
    m_stats.shading_seconds += shading.seconds();
    return image;
}

Image VplIntegrator::finish() {
    m_stats.units = m_stream->work_done();
    Timer shading;
    Image image;
    if (shared()) {
        image = shared_image(true);
    } else {
        image = vpl_image();
        add_cpu_finished(image, m_pacing);
    }
    m_stats.shading_seconds += shading.seconds();
    return image;
}

Image VplIntegrator::cpu_image() const {
    return m_cpu->snapshot(int(m_estimate.render.width), int(m_estimate.render.height));
}

Image VplIntegrator::finish_cpu(Pacing pacing) {
    Image sum(int(m_estimate.render.width), int(m_estimate.render.height));
    add_cpu_finished(sum, pacing);
    return sum;
}

// Each estimator's image added on its own, in this order: the same sums, to the bit, whoever asks.
void VplIntegrator::add_cpu_finished(Image& sum, Pacing pacing) {
    m_cpu->pace(paced_vpls(), pacing);
    // Interrupted (interrupt.h): the passes done, not those allowed.
    const bool wait = pacing == Pacing::Fixed && !interrupted();
    if (CpuEstimatorThread* t = m_cpu->compensation_thread()) {
        add_image(sum, t->finish(wait));
        m_stats.compensation_passes = t->passes();
    }
    if (CpuEstimatorThread* t = m_cpu->caustic_thread()) {
        add_image(sum, t->finish(wait));
        m_stats.caustic_passes = t->passes();
    }
}

// Over ranks: the contributions and the CPU images' pass sums summed to rank 0, which resolves.
// finishing: the CPU estimators finish (a fixed size: the passes allowed, of which rank 0's
// share is never empty; open-ended: those done, at least one on rank 0); otherwise their
// passes so far.
Image VplIntegrator::shared_image(bool finishing) {
    CpuEstimatorThread* const threads[2] = {m_cpu->compensation_thread(), m_cpu->caustic_thread()};
    Image sum, parts[2];
    std::vector<double> passes(2, 0.0);
    cluster::together(m_ranks, [&] {
        sum = m_renderer->contributions();
        for (int t = 0; t < 2; ++t) {
            if (!threads[t]) continue;
            CpuEstimatorThread& thread = *threads[t];
            uint32_t n = 0;
            if (finishing) {
                parts[t] =
                    thread.finish(m_pacing == Pacing::Fixed && !interrupted(), m_ranks.root());
                n = thread.passes();
            } else {
                parts[t] = thread.snapshot(&n);
            }
            passes[size_t(t)] = double(n);
            for (Rgb& c : parts[t].pixels())
                c *= float(n);
        }
    });
    // Met first, so that the time is the reduction's, not the wait for the slowest rank.
    std::vector<double> met(1, 0.0);
    m_ranks.sum_all(met);
    Timer reduce;
    m_ranks.sum_to_root(sum.channels());
    m_stats.reduce_bytes = sum.channels().size_bytes();
    for (int t = 0; t < 2; ++t) {
        if (!threads[t]) continue;
        m_ranks.sum_to_root(parts[t].channels());
        m_stats.reduce_bytes += parts[t].channels().size_bytes();
    }
    if (threads[0] || threads[1]) m_ranks.sum_all(passes);
    m_stats.reduce_seconds = reduce.seconds();
    Image image;
    cluster::together(m_ranks, [&] {
        if (!m_ranks.root()) return;
        image = m_renderer->resolve(m_stream->scale(), sum, m_stats.vpls);
        for (int t = 0; t < 2; ++t) {
            if (threads[t] && passes[size_t(t)] > 0.0)
                add_image(image, parts[t], float(1.0 / passes[size_t(t)]));
        }
    });
    if (finishing) {
        m_stats.compensation_passes = uint32_t(passes[0]);
        m_stats.caustic_passes = uint32_t(passes[1]);
    }
    return image;
}

}  // namespace mvpl::integrator

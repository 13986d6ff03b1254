#include "engine/integrator/vpl_integrator.h"

#include <utility>

#include "engine/core/error.h"
#include "engine/core/interrupt.h"
#include "engine/core/timer.h"
#include "engine/sampler/metropolis_stream.h"

namespace mvpl::integrator {

namespace {

// Over ranks that each made counts[r] items, numbered in rank order from `total` (the items
// before, which it becomes): this rank's first.
uint64_t first_of_rank(uint64_t& total, const std::vector<uint64_t>& counts, int rank) {
    uint64_t first = total;
    for (int r = 0; r < rank; ++r)
        first += counts[size_t(r)];
    for (const uint64_t c : counts)
        total += c;
    return first;
}

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
    m_view = view;
    m_estimate = estimate;
    m_pacing = pacing;
    m_stats = {};
    m_pools = 0;
    m_representatives = 0;
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
        m_gpu_columns.reset();
        if (m_renderer && gpu_matrix(m_estimate.many_lights, m_renderer->context().device_info())) {
            m_gpu_columns =
                std::make_unique<GpuColumns>(*m_renderer, m_estimate.many_lights.row_resolution);
            c.columns = m_gpu_columns.get();
        }
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
    // Each VPL's index in the one-process order (empty: they follow those shaded before).
    std::span<const uint64_t> index = m_stream->last_index();
    if (m_many_lights) {
        // Each pool's weighted cluster representatives instead of the pool. Over ranks, each rank
        // cuts its own share of the chunk into pools: a pool's representatives estimate that
        // pool without bias whatever VPLs it holds, so the ranks' sum estimates the stream's
        // image, and the reduced matrix, the costly part on the CPU, is split among the ranks
        // instead of being built whole by each of them (or each rank building every pool's to
        // shade a part of the representatives).
        const uint64_t first_pool = number_pools();
        cluster::together(m_ranks, [&] { m_many_lights->reduce(m_chunk, first_pool); });
        m_stats.many_lights = m_many_lights->stats();
        m_stats.gpu_matrix = m_gpu_columns != nullptr;
        index = index_representatives();
    }
    m_stats.sampling_seconds += sampling.seconds();
    Timer shading;
    cluster::together(m_ranks, [&] {
        if (m_renderer) {
            m_renderer->accumulate(m_chunk, index);
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
    m_cpu->pace(shaded_by_all(), m_pacing);
}

// The number of this rank's first pool in the chunk just sampled: the pools of every rank are
// numbered in the order one process would cut them, lower ranks' first, so that no two pools
// draw the same rows and representatives, and where each rank's share is a whole number of pools
// (as with --vpl-per-path one) the ranks reduce the very pools of one process.
uint64_t VplIntegrator::number_pools() {
    const uint64_t mine = m_many_lights->pools_of(m_chunk.size());
    if (!shared()) {
        m_pools += mine;
        return m_pools - mine;
    }
    std::vector<uint64_t> counts(size_t(m_ranks.size()), 0);
    cluster::together(m_ranks, [&] { counts[size_t(m_ranks.rank())] = mine; });
    m_ranks.sum_all(counts);
    return first_of_rank(m_pools, counts, m_ranks.rank());
}

// The representatives just reduced: counted, and over ranks numbered as one process would shade
// every rank's, rank 0's first (as MonteCarloStream numbers its VPLs), so that the sub-pixel
// positions are those of [0, representatives) and each rank's indices increase.
std::span<const uint64_t> VplIntegrator::index_representatives() {
    if (!shared()) {
        m_representatives += m_chunk.size();
        return {};
    }
    std::vector<uint64_t> counts(size_t(m_ranks.size()), 0);
    counts[size_t(m_ranks.rank())] = m_chunk.size();
    m_ranks.sum_all(counts);  // after reduce()'s agreement point
    const uint64_t first = first_of_rank(m_representatives, counts, m_ranks.rank());
    m_index.resize(m_chunk.size());
    for (size_t i = 0; i < m_index.size(); ++i)
        m_index[i] = first + i;
    return m_index;
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
    m_cpu->pace(shaded_by_all(), pacing);
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
        image = m_renderer->resolve(m_stream->scale(), sum, shaded_by_all());
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

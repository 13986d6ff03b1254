#include "tools/cli/render_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "sampler/metropolis_stream.h"
#include "tools/cli/compensation_thread.h"

namespace mvpl::cli {

namespace {

// Seconds of sampling + shading aimed at per progressive chunk under --time-budget: long enough
// that a Metropolis chain merges its repeats over several steps, short enough that the last
// chunk overshoots the budget by little.
constexpr double kChunkSeconds = 0.5;

// Light paths or chain steps per chunk of a fixed-size render: a multiple of the Monte Carlo
// tracer's block of 256 paths, big enough to keep both cores busy, small enough that a chunk's
// VPLs (≈ max depth per path, 112 bytes each) stay a few megabytes.
constexpr uint64_t kStreamChunkUnits = uint64_t(1) << 14;

// Warns when the Metropolis bootstrap found no light on anything the camera sees; returns
// whether it did not (then sampling longer cannot change the black image).
bool warn_if_unlit(const sampler::VplStream& stream, const session::SceneSession& session,
                   int width, int height) {
    const auto* metropolis = dynamic_cast<const sampler::MetropolisStream*>(&stream);
    if (metropolis && metropolis->no_visible_light()) {
        // A camera that sees nothing because its near plane clips everything is told so.
        if (!session.warn_if_clipped(width, height))
            session.warn("no light reaches anything the camera sees; the image is black");
        return true;
    }
    return false;
}

// The next chunk of work units: about kChunkSeconds at the rate measured so far, never past the
// remaining budget's worth, at least one unit.
uint64_t next_chunk(uint64_t done, double elapsed, double remaining, uint64_t first,
                    double chunk_seconds) {
    if (done == 0 || !(elapsed > 0.0)) return first;
    const double per_unit = elapsed / double(done);
    const double seconds = std::min(chunk_seconds, remaining);
    // At most 2^20 units a chunk, however cheap they were so far.
    return std::clamp<uint64_t>(uint64_t(std::min(seconds / per_unit, 1e9)), 1, uint64_t(1) << 20);
}

// Adds `part` into `sum`, pixel by pixel.
void add_image(Image& sum, const Image& part, float scale = 1.0f) {
    for (size_t i = 0; i < sum.pixels().size(); ++i)
        sum.pixels()[i] += part.pixels()[i] * scale;
}

// The loop both renders share: a sampler stream whose chunks of VPLs are shaded as they come,
// on the GPU (begin/accumulate/resolve) or by the CPU oracle, each chunk gathered at once (VPL
// light only, unscaled) at the sub-pixel positions that the GPU gives the chunk's VPLs (their
// indices since the start: GatherOptions::first_vpl) and the emitted radiance added at the end,
// averaged over the positions drawn.
class ChunkedRender {
public:
    // open_ended: a time budget, whose compensation stops with it rather than finishing the
    // passes it was allowed.
    ChunkedRender(const RenderJob& job, RenderOutcome& result, bool open_ended)
        : m_job(job),
          m_session(*job.session),
          m_result(result),
          m_open_ended(open_ended),
          m_ranks(job.cluster ? *job.cluster : cluster::single_process()) {
        if (shared() && !job.renderer)
            throw UsageError("render: --oracle runs on one process, not under mpirun");
        cluster::together(m_ranks, [&] {
            if (job.renderer) job.renderer->begin(m_session.camera(), job.render);
            if (job.compensate) {
                reference::CompensationOptions options = job.compensation;
                options.first_pass = uint32_t(m_ranks.rank());
                options.pass_stride = uint32_t(m_ranks.size());
                auto compensation = std::make_unique<reference::ClampCompensation>(
                    m_session.scene(), m_session.accel(), m_session.lights(), options);
                if (compensation->active())
                    m_compensation = std::make_unique<CompensationThread>(std::move(compensation));
                if (m_compensation && job.compensation_passes > 0)
                    m_compensation->allow(my_passes(job.compensation_passes));
            }
            if (job.caustics) {
                reference::CausticOptions options = job.caustic;
                options.first_pass = uint32_t(m_ranks.rank());
                options.pass_stride = uint32_t(m_ranks.size());
                auto caustics = std::make_unique<reference::CausticTracer>(
                    m_session.scene(), m_session.accel(), m_session.lights(), options);
                if (caustics->active())
                    m_caustics = std::make_unique<CompensationThread>(std::move(caustics));
                if (m_caustics && job.compensation_passes > 0)
                    m_caustics->allow(my_passes(job.compensation_passes));
            }
        });
        Timer setup;
        sampler::SamplerSettings settings = job.settings;
        // The caustic tracer carries the light of the chains' class: no VPL there.
        if (m_caustics) settings.tracer.specular = job.caustic.specular;
        if (shared()) settings.cluster = &m_ranks;
        const session::SceneSession& s = m_session;
        // The Metropolis bootstrap meets the other ranks inside (its own agreement points).
        cluster::together(m_ranks, [&] {
            m_stream = sampler::make_vpl_stream(job.sampler, s.scene(), s.accel(), s.lights(),
                                                s.camera(), settings);
        });
        m_result.sampling_seconds += setup.seconds();
        m_unlit = warn_if_unlit(*m_stream, m_session, job.gather.width, job.gather.height);
        m_gather = job.gather;
        m_gather.max_depth = 0;
        m_gather.quiet = true;
        if (!job.renderer) m_sum = Image(job.gather.width, job.gather.height);
    }

    const sampler::VplStream& stream() const { return *m_stream; }
    // Whether the stream knows already that the image stays black however long it runs.
    bool unlit() const { return m_unlit; }

    // Samples `work` more units and shades their VPLs.
    void add(uint64_t work) {
        m_chunk.clear();
        Timer sampling;
        m_stream->next(work, m_chunk);  // over ranks: an agreement point inside
        m_result.sampling_seconds += sampling.seconds();
        Timer shading;
        cluster::together(m_ranks, [&] {
            if (m_job.renderer) {
                m_job.renderer->accumulate(m_chunk, m_stream->last_index());
            } else if (!m_chunk.empty()) {
                m_gather.first_vpl = m_result.vpls;
                add_image(m_sum, reference::gather_vpls(m_session.scene(), m_session.accel(),
                                                        {m_chunk}, m_gather));
            }
        });
        m_result.shading_seconds += shading.seconds();
        m_result.vpls = m_stream->vpls_total();
        if (m_job.compensation_passes == 0) {
            const uint32_t paced = my_passes(paced_compensation_passes(
                m_result.vpls, m_open_ended ? uint32_t(1) << 20 : kFixedRenderPasses));
            if (m_compensation) m_compensation->allow(paced);
            if (m_caustics) m_caustics->allow(paced);
        }
    }

    // The image: scale · Σ contributions + the emitted radiance seen directly.
    void finish() {
        m_result.units = m_stream->work_done();
        m_result.statistics = m_stream->statistics();
        if (shared()) {
            finish_shared();
            return;
        }
        Timer shading;
        if (m_job.renderer) {
            m_result.image = m_job.renderer->resolve(m_stream->scale());
            m_result.timings = m_job.renderer->timings();
        } else {
            reference::GatherOptions emission = m_job.gather;
            emission.first_vpl = m_result.vpls;  // averaged over the positions of every VPL
            m_result.image =
                reference::gather_vpls(m_session.scene(), m_session.accel(), {}, emission);
            add_image(m_result.image, m_sum, float(m_stream->scale()));
        }
        if (m_compensation) {
            add_image(m_result.image, m_compensation->finish(!m_open_ended));
            m_result.compensation_passes = m_compensation->passes();
        }
        if (m_caustics) {
            add_image(m_result.image, m_caustics->finish(!m_open_ended));
            m_result.caustic_passes = m_caustics->passes();
        }
        m_result.shading_seconds += shading.seconds();
    }

private:
    bool shared() const { return m_ranks.size() > 1; }

    // Of the job's first `passes` compensation passes, those this rank runs.
    uint32_t my_passes(uint32_t passes) const {
        return rank_passes(passes, m_ranks.rank(), m_ranks.size());
    }

    // Over ranks: the contributions and the CPU images' passes (compensation, caustics) summed
    // to rank 0, which resolves.
    void finish_shared() {
        Timer shading;
        Image sum, compensation, caustics;
        std::vector<double> passes(2, 0.0);
        // Fixed size: the job's passes, of which rank 0's share is never empty; a time budget:
        // those done, at least one on rank 0. The image is the sum over this rank's passes.
        auto finish_thread = [&](CompensationThread& thread, Image& image, double& count) {
            image = thread.finish(!m_open_ended, m_ranks.root());
            count = double(thread.passes());
            for (Rgb& c : image.pixels())
                c *= float(count);
        };
        cluster::together(m_ranks, [&] {
            sum = m_job.renderer->contributions();
            if (m_compensation) finish_thread(*m_compensation, compensation, passes[0]);
            if (m_caustics) finish_thread(*m_caustics, caustics, passes[1]);
        });
        // Met first, so that the time is the reduction's, not the wait for the slowest rank.
        std::vector<double> met(1, 0.0);
        m_ranks.sum_all(met);
        Timer reduce;
        m_ranks.sum_to_root(sum.channels());
        m_result.reduce_bytes = sum.channels().size_bytes();
        if (m_compensation) {
            m_ranks.sum_to_root(compensation.channels());
            m_result.reduce_bytes += compensation.channels().size_bytes();
        }
        if (m_caustics) {
            m_ranks.sum_to_root(caustics.channels());
            m_result.reduce_bytes += caustics.channels().size_bytes();
        }
        if (m_compensation || m_caustics) m_ranks.sum_all(passes);
        m_result.reduce_seconds = reduce.seconds();
        cluster::together(m_ranks, [&] {
            if (!m_ranks.root()) return;
            m_result.image = m_job.renderer->resolve(m_stream->scale(), sum, m_result.vpls);
            m_result.timings = m_job.renderer->timings();
            if (m_compensation && passes[0] > 0.0)
                add_image(m_result.image, compensation, float(1.0 / passes[0]));
            if (m_caustics && passes[1] > 0.0)
                add_image(m_result.image, caustics, float(1.0 / passes[1]));
        });
        m_result.compensation_passes = uint32_t(passes[0]);
        m_result.caustic_passes = uint32_t(passes[1]);
        m_result.shading_seconds += shading.seconds();
    }

    const RenderJob& m_job;
    const session::SceneSession& m_session;
    RenderOutcome& m_result;
    bool m_open_ended;
    cluster::Cluster& m_ranks;
    std::unique_ptr<sampler::VplStream> m_stream;
    bool m_unlit = false;
    reference::GatherOptions m_gather;
    Image m_sum;
    std::vector<light::Vpl> m_chunk;
    std::unique_ptr<CompensationThread> m_compensation;
    std::unique_ptr<CompensationThread> m_caustics;
};

}  // namespace

RenderOutcome render_once(const RenderJob& job, uint64_t units) {
    RenderOutcome result;
    ChunkedRender run(job, result, false);
    Progress progress("render", int64_t(std::min<uint64_t>(units, INT64_MAX)), job.quiet);
    // Chunk by chunk, so that memory does not grow with `units`: the same VPLs as at once (the
    // Monte Carlo stream's blocks are aligned to path indices, and a chunk is a whole number of
    // them), summed in another order.
    for (uint64_t done = 0; !run.unlit() && done < units;) {
        const uint64_t work = std::min(kStreamChunkUnits, units - done);
        run.add(work);
        done += work;
        progress.set_status(run.stream().statistics());
        progress.advance(int64_t(work));
    }
    progress.finish();
    run.finish();
    return result;
}

RenderOutcome render_for(const RenderJob& job, double seconds) {
    RenderOutcome result;
    Timer budget;
    ChunkedRender run(job, result, true);
    // Progress in tenths of the budget.
    const int64_t tenths = int64_t(std::ceil(seconds * 10.0));
    int64_t shown = 0;
    Progress progress("render", tenths, job.quiet);
    const uint64_t first = uint64_t(job.render.batch);
    // Over ranks, rank 0's clock decides for all, so that they stop together and agree on each
    // chunk's size (every rank traces its share of it).
    cluster::Cluster& ranks = job.cluster ? *job.cluster : cluster::single_process();
    // A chunk's batches are shared out among the renderer's devices (render::split_into_runs),
    // each drawing the G-buffers of the positions its run touches: a chunk per device, rank 0's.
    std::vector<double> chunk_seconds(
        1, ranks.root() ? kChunkSeconds * (job.renderer ? job.renderer->devices() : 1) : 0.0);
    ranks.sum_all(chunk_seconds);
    auto elapsed = [&] {
        std::vector<double> t(1, ranks.root() ? budget.seconds() : 0.0);
        ranks.sum_all(t);
        return t[0];
    };
    for (double t = elapsed(); !run.unlit() && t < seconds; t = elapsed()) {
        run.add(next_chunk(run.stream().work_done(), t, seconds - t, first, chunk_seconds[0]));
        progress.set_status(run.stream().statistics());
        const int64_t now = std::min(tenths, int64_t(budget.seconds() * 10.0));
        progress.advance(now - shown);
        shown = now;
    }
    progress.finish();
    run.finish();
    return result;
}

std::string summary_line(const RenderJob& job, const RenderOutcome& r, double total_seconds) {
    std::string pass_times = "CPU oracle";
    if (job.renderer) {
        char buf[160];
        // Over several devices the pass times are summed: each device's ran beside the others'.
        const uint32_t devices = job.renderer->devices();
        std::snprintf(
            buf, sizeof buf, "G-buffer %.1f ms, shadow %.1f ms, shading %.1f ms, %u batches%s",
            r.timings.g_buffer_ms, r.timings.shadow_ms, r.timings.shading_ms, r.timings.batches,
            devices > 1 ? (" on " + std::to_string(devices) + " devices").c_str() : "");
        pass_times = buf;
    }
    if (r.compensation_passes > 0)
        pass_times += "; compensation " + std::to_string(r.compensation_passes) + " spp";
    if (r.caustic_passes > 0)
        pass_times += "; caustics " + std::to_string(r.caustic_passes) + " passes";
    if (job.cluster) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "; %d ranks, images summed in %.1f ms (%.1f MB a rank)",
                      job.cluster->size(), 1e3 * r.reduce_seconds, double(r.reduce_bytes) / 1e6);
        pass_times += buf;
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "render: %zu VPLs from %llu %s, %dx%d: sampling %.2f s, shading %.2f s (%s), "
                  "total %.2f s, %.1f VPL/s%s%s\n",
                  r.vpls, static_cast<unsigned long long>(r.units),
                  job.sampler == "mc" ? "paths" : "steps", job.gather.width, job.gather.height,
                  r.sampling_seconds, r.shading_seconds, pass_times.c_str(), total_seconds,
                  double(r.vpls) / std::max(r.shading_seconds + r.sampling_seconds, 1e-9),
                  r.statistics.empty() ? "" : "; ", r.statistics.c_str());
    return line;
}

}  // namespace mvpl::cli

#include "tools/cli/render_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/interrupt.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "tools/cli/checkpoints.h"
#include "tools/cli/render_chunks.h"
#include "tools/cli/shading_status.h"

namespace mvpl::cli {

namespace {

// The job's estimate, its batches reported to `status`.
integrator::VplIntegrator& begin(const RenderJob& job, integrator::Pacing pacing,
                                 const ShadingStatus& status) {
    integrator::Estimate estimate = job.estimate;
    estimate.render.on_batch = status.on_batch();
    job.integrator->begin(job.session->view(), estimate, pacing);
    return *job.integrator;
}

// Warns when the Metropolis bootstrap found no light on anything the camera sees (then sampling
// longer cannot change the black image); a camera that sees nothing because its near plane clips
// everything is told so.
void warn_if_unlit(const RenderJob& job, const integrator::VplIntegrator& run) {
    if (!run.unlit()) return;
    const render::RenderOptions& o = job.estimate.render;
    if (!job.session->warn_if_clipped(int(o.width), int(o.height)))
        job.session->warn("no light reaches anything the camera sees; the image is black");
}

// Whether SIGINT or SIGTERM reached any rank (interrupt.h): all stop after the same chunk.
bool any_rank_interrupted(const RenderJob& job) {
    if (!job.cluster) return interrupted();
    std::vector<double> flag(1, interrupted() ? 1.0 : 0.0);
    job.cluster->sum_all(flag);
    return flag[0] > 0.0;
}

// Rank 0's answer for every rank (image() is collective: all must agree to call it).
bool root_decides(const RenderJob& job, bool answer) {
    if (!job.cluster) return answer;
    std::vector<double> v(1, job.cluster->root() && answer ? 1.0 : 0.0);
    job.cluster->sum_all(v);
    return v[0] > 0.0;
}

// --write-every (checkpoints.h): rank 0's clock decides for every rank, since image() is
// collective.
Checkpoints make_checkpoints(const RenderJob& job) {
    return Checkpoints(job.write_every, [&job](bool due) { return root_decides(job, due); });
}

// The estimate so far handed to the job's checkpoint (rank 0 writes it).
void write_checkpoint(const RenderJob& job, integrator::VplIntegrator& run) {
    const Image image = run.image();
    if (job.checkpoint && !image.pixels().empty()) job.checkpoint(image, run.stats().vpls);
}

RenderOutcome outcome_of(integrator::VplIntegrator& run) {
    RenderOutcome result;
    result.image = run.finish();
    result.stats = run.stats();
    result.statistics = run.stream().statistics();
    if (const render::VplRenderer* r = run.renderer()) result.timings = r->timings();
    return result;
}

}  // namespace

RenderOutcome render_once(const RenderJob& job, uint64_t units) {
    Progress progress("render", int64_t(std::min<uint64_t>(units, INT64_MAX)), job.quiet);
    ShadingStatus status(progress);
    integrator::VplIntegrator& run = begin(job, integrator::Pacing::Fixed, status);
    warn_if_unlit(job, run);
    Checkpoints checkpoints = make_checkpoints(job);
    // Chunk by chunk, so that memory does not grow with `units`: the same VPLs as at once (the
    // Monte Carlo stream's blocks are aligned to path indices, and a chunk is a whole number of
    // them), summed in another order.
    for (uint64_t done = 0; !run.unlit() && done < units && !any_rank_interrupted(job);) {
        // With row-column sampling, a chunk of at least a pool's units per rank (each rank cuts
        // its share into pools), so that pools are full.
        const uint64_t ranks = job.cluster ? uint64_t(job.cluster->size()) : 1;
        const uint64_t chunk =
            std::max<uint64_t>(kStreamChunkUnits, job.estimate.many_lights.pool * ranks);
        const uint64_t work = std::min(chunk, units - done);
        run.advance(work);
        done += work;
        checkpoints.after_chunk(done >= units, [&] { write_checkpoint(job, run); });
        status.set_sampler_status(run.stream().statistics());
        progress.advance(int64_t(work));
    }
    progress.finish();
    return outcome_of(run);
}

RenderOutcome render_for(const RenderJob& job, double seconds) {
    Timer budget;
    // Progress in tenths of the budget.
    const int64_t tenths = int64_t(std::ceil(seconds * 10.0));
    int64_t shown = 0;
    Progress progress("render", tenths, job.quiet);
    ShadingStatus status(progress);
    integrator::VplIntegrator& run = begin(job, integrator::Pacing::OpenEnded, status);
    warn_if_unlit(job, run);
    Checkpoints checkpoints = make_checkpoints(job);
    const uint64_t first = uint64_t(job.estimate.render.batch);
    // Over ranks, rank 0's clock decides for all, so that they stop together and agree on each
    // chunk's size (every rank traces its share of it).
    cluster::Cluster& ranks = job.cluster ? *job.cluster : cluster::single_process();
    // A chunk's batches are shared out among the renderer's devices (render::split_into_runs),
    // each drawing the G-buffers of the positions its run touches: a chunk per device, rank 0's.
    // With row-column sampling, chunks of kPoolChunkSeconds, so that they hold whole pools.
    const double target = job.estimate.many_lights.enabled() ? kPoolChunkSeconds : kChunkSeconds;
    std::vector<double> chunk_seconds(
        1, ranks.root()
               ? target * (job.integrator->renderer() ? job.integrator->renderer()->devices() : 1)
               : 0.0);
    ranks.sum_all(chunk_seconds);
    auto elapsed = [&] {
        std::vector<double> t(1, ranks.root() ? budget.seconds() : 0.0);
        ranks.sum_all(t);
        return t[0];
    };
    for (double t = elapsed(); !run.unlit() && t < seconds && !any_rank_interrupted(job);
         t = elapsed()) {
        run.advance(next_chunk(run.stream().work_done(), t, seconds - t, first, chunk_seconds[0]));
        checkpoints.after_chunk(false, [&] { write_checkpoint(job, run); });
        status.set_sampler_status(run.stream().statistics());
        const int64_t now = std::min(tenths, int64_t(budget.seconds() * 10.0));
        progress.advance(now - shown);
        shown = now;
    }
    progress.finish();
    return outcome_of(run);
}

std::string summary_line(const RenderJob& job, const RenderOutcome& r, double total_seconds) {
    std::string pass_times = "CPU oracle";
    if (const render::VplRenderer* renderer = job.integrator->renderer()) {
        char buf[160];
        // Over several devices the pass times are summed: each device's ran beside the others'.
        const uint32_t devices = renderer->devices();
        std::snprintf(
            buf, sizeof buf, "G-buffer %.1f ms, shadow %.1f ms, shading %.1f ms, %u batches%s",
            r.timings.g_buffer_ms, r.timings.shadow_ms, r.timings.shading_ms, r.timings.batches,
            devices > 1 ? (" on " + std::to_string(devices) + " devices").c_str() : "");
        pass_times = buf;
    }
    if (r.stats.compensation_passes > 0)
        pass_times += "; compensation " + std::to_string(r.stats.compensation_passes) + " spp";
    if (r.stats.caustic_passes > 0)
        pass_times += "; caustics " + std::to_string(r.stats.caustic_passes) + " passes";
    // Over ranks, rank 0's pools (each rank reduces its own share of the VPLs).
    if (const manylights::RowColumnStats& m = r.stats.many_lights; m.pools > 0) {
        char buf[220];
        std::snprintf(buf, sizeof buf,
                      "; row-column sampling%s: %llu pools, %llu VPLs → %llu shaded, %.0f rows a "
                      "pool, %s matrix %.2f s, clustering %.2f s",
                      job.cluster ? " on rank 0" : "", static_cast<unsigned long long>(m.pools),
                      static_cast<unsigned long long>(m.columns),
                      static_cast<unsigned long long>(m.representatives),
                      double(m.rows) / double(m.pools), r.stats.gpu_matrix ? "GPU" : "CPU",
                      m.matrix_seconds, m.cluster_seconds);
        pass_times += buf;
    }
    if (job.cluster) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "; %d ranks, images summed in %.1f ms (%.1f MB a rank)",
                      job.cluster->size(), 1e3 * r.stats.reduce_seconds,
                      double(r.stats.reduce_bytes) / 1e6);
        pass_times += buf;
    }
    char line[512];
    std::snprintf(
        line, sizeof line,
        "render: %zu VPLs from %llu %s, %ux%u: sampling %.2f s, shading %.2f s (%s), "
        "total %.2f s, %.1f VPL/s%s%s\n",
        r.stats.vpls, static_cast<unsigned long long>(r.stats.units),
        job.estimate.sampler == "mc" ? "paths" : "steps", job.estimate.render.width,
        job.estimate.render.height, r.stats.sampling_seconds, r.stats.shading_seconds,
        pass_times.c_str(), total_seconds,
        double(r.stats.vpls) / std::max(r.stats.shading_seconds + r.stats.sampling_seconds, 1e-9),
        r.statistics.empty() ? "" : "; ", r.statistics.c_str());
    std::string text = line;
    // The image holds what the chunks before the signal converged to.
    if (interrupted()) text.insert(text.size() - 1, "; interrupted");
    return text;
}

}  // namespace mvpl::cli

#include "tools/cli/convergence_runs.h"

#include <algorithm>
#include <memory>

#include "engine/core/image_metrics.h"
#include "engine/core/interrupt.h"
#include "engine/core/progress.h"
#include "engine/core/subpixel.h"
#include "engine/core/timer.h"
#include "engine/integrator/vpl_integrator.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::cli {

namespace {

// Progress over the budget in tenths of a second.
int64_t tenths(double seconds) {
    return int64_t(seconds * 10.0);
}

cluster::Cluster& ranks_of(const ConvergenceRun& run) {
    return run.cluster ? *run.cluster : cluster::single_process();
}

// Rank 0's decision on every rank (a collective call: every rank asks, rank 0's answer wins), so
// that its clock alone says when the budget is spent and the ranks stop together.
bool root_says(cluster::Cluster& ranks, bool yes) {
    std::vector<double> v(1, ranks.root() && yes ? 1.0 : 0.0);
    ranks.sum_all(v);
    return v[0] > 0.0;
}

// The first agreement point of a run, so that the ranks' clocks start together: the time a rank
// waits here for the others (still loading) is not the run's.
void start_together(cluster::Cluster& ranks) {
    cluster::together(ranks, [] {});
}

}  // namespace

ConvergencePoint measure(const std::string& method, double seconds, uint64_t samples,
                         const Image& image, const Image& reference) {
    const ImageError e = compare_images(image, reference);
    ConvergencePoint p;
    p.method = method;
    p.seconds = seconds;
    p.samples = samples;
    p.rel_mse = e.rel_mse;
    p.rmse = e.rmse;
    p.mean_ratio = (e.mean_ratio.x + e.mean_ratio.y + e.mean_ratio.z) / 3.0;
    return p;
}

std::vector<ConvergencePoint> run_path_tracer(const ConvergenceRun& run) {
    cluster::Cluster& ranks = ranks_of(run);
    const auto rank = uint64_t(ranks.rank()), size = uint64_t(ranks.size());
    const session::SceneSession& s = *run.session;
    const reference::PathTracer tracer(s.scene(), s.accel(), s.lights());
    const int w = run.reference->width(), h = run.reference->height();
    std::vector<ConvergencePoint> points;
    Image sum(w, h);
    // One sample per pixel per rank to begin with, so that every rank works from the first chunk.
    uint64_t spp = 0, chunk = size;
    Progress progress("pt", tenths(run.budget_seconds), run.quiet);
    start_together(ranks);
    Timer timer;
    double per_spp = 0.0, last = 0.0;
    for (uint64_t round = 0;; ++round) {
        // Stop before a chunk that would overrun the budget (its time extrapolated per spp).
        // Or on SIGINT/SIGTERM (interrupt.h): the points so far are written.
        if (root_says(ranks, interrupted() ||
                                 (spp > 0 &&
                                  timer.seconds() + per_spp * double(chunk) > run.budget_seconds)))
            break;
        // This rank's share of the chunk's samples, under a seed of its own: the sum over ranks
        // is the image of all of them. On one process the seed is the chunk's as ever.
        const cluster::Share share = cluster::share_of(chunk, int(rank), int(size));
        Image part(w, h);
        cluster::together(ranks, [&] {
            if (share.last == share.first) return;
            reference::PathTracerOptions o;
            o.width = w;
            o.height = h;
            o.spp = int(share.last - share.first);
            o.max_depth = run.max_depth;
            o.seed = (run.seed * 1000003 + round) * size + rank;
            o.quiet = true;
            part = tracer.render(o);
            for (Rgb& c : part.pixels())
                c = c * float(o.spp);
        });
        ranks.sum_to_root(part.channels());
        spp += chunk;
        chunk = spp;  // doubling
        if (!ranks.root()) continue;
        for (size_t i = 0; i < sum.pixels().size(); ++i)
            sum.pixels()[i] += part.pixels()[i];
        const double seconds = timer.seconds();
        per_spp = seconds / double(spp);
        Image mean = sum;
        for (Rgb& c : mean.pixels())
            c = c / float(spp);
        points.push_back(measure("pt", seconds, spp, mean, *run.reference));
        progress.advance(tenths(std::min(seconds, run.budget_seconds)) -
                         tenths(std::min(last, run.budget_seconds)));
        last = seconds;
    }
    progress.finish();
    return points;
}

std::vector<ConvergencePoint> run_vpl_sampler(const ConvergenceRun& run, const std::string& name,
                                              const sampler::SamplerSettings& settings,
                                              integrator::VplIntegrator& integrator,
                                              const render::RenderOptions& options) {
    cluster::Cluster& ranks = ranks_of(run);
    start_together(ranks);
    Timer timer;
    const session::SceneSession& s = *run.session;
    integrator::Estimate e;
    e.sampler = name;
    e.sampling = settings;
    e.sampling.seed = run.seed;
    e.sampling.tracer.max_depth = run.max_depth;
    e.render = options;
    e.render.width = uint32_t(run.reference->width());
    e.render.height = uint32_t(run.reference->height());
    e.render.subpixel_rotation = subpixel_rotation(run.seed);
    e.render.chain_seed = run.seed;
    e.compensate = run.compensate;
    e.compensation_passes = run.compensation_passes;
    e.caustics = run.caustics;
    e.many_lights = run.many_lights;
    integrator.begin(s.view(), e, integrator::Pacing::OpenEnded);
    const sampler::VplStream& stream = integrator.stream();
    std::vector<ConvergencePoint> points;
    Progress progress(name, tenths(run.budget_seconds), run.quiet);
    uint64_t work = 16;
    double per_work = 0.0, last = 0.0;
    while (true) {
        const double now = timer.seconds();
        if (root_says(ranks, interrupted() || (stream.work_done() > 0 &&
                                               now + per_work * double(work) > run.budget_seconds)))
            break;
        integrator.advance(work);
        const Image image = integrator.image();
        work = stream.work_done();  // doubling
        if (!ranks.root()) continue;
        const double seconds = timer.seconds();
        per_work = seconds / double(stream.work_done());
        points.push_back(measure(name, seconds, integrator.stats().vpls, image, *run.reference));
        progress.set_status(stream.statistics());
        progress.advance(tenths(std::min(seconds, run.budget_seconds)) -
                         tenths(std::min(last, run.budget_seconds)));
        last = seconds;
    }
    progress.finish();
    return points;
}

}  // namespace mvpl::cli

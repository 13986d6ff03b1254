#include "tools/cli/convergence_runs.h"

#include <algorithm>
#include <memory>

#include "engine/core/image_metrics.h"
#include "engine/core/progress.h"
#include "engine/core/subpixel.h"
#include "engine/core/timer.h"
#include "engine/reference/caustic_tracer.h"
#include "engine/reference/clamp_compensation.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/vpl_renderer.h"
#include "tools/cli/compensation_thread.h"

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
        if (root_says(ranks,
                      spp > 0 && timer.seconds() + per_spp * double(chunk) > run.budget_seconds))
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

namespace {

// The image of a VPL run shared by ranks, on rank 0 (others: empty): the ranks' contributions
// and the CPU images' pass sums (compensation, caustics; null: none) added there and resolved,
// as render_runs.cpp's finish_shared does.
Image shared_image(cluster::Cluster& ranks, render::VplRenderer& renderer, double scale,
                   uint64_t vpls, const std::vector<const CompensationThread*>& threads) {
    Image sum;
    std::vector<Image> parts(threads.size());
    std::vector<double> passes(threads.size(), 0.0);
    cluster::together(ranks, [&] {
        sum = renderer.contributions();
        for (size_t t = 0; t < threads.size(); ++t) {
            if (!threads[t]) continue;
            uint32_t n = 0;
            parts[t] = threads[t]->snapshot(&n);
            passes[t] = double(n);
            for (Rgb& c : parts[t].pixels())
                c *= float(n);
        }
    });
    ranks.sum_to_root(sum.channels());
    for (size_t t = 0; t < threads.size(); ++t) {
        if (threads[t]) ranks.sum_to_root(parts[t].channels());
    }
    ranks.sum_all(passes);
    Image image;
    cluster::together(ranks, [&] {
        if (!ranks.root()) return;
        image = renderer.resolve(scale, sum, vpls);
        for (size_t t = 0; t < threads.size(); ++t) {
            if (!threads[t] || !(passes[t] > 0.0)) continue;
            for (size_t i = 0; i < image.pixels().size(); ++i)
                image.pixels()[i] += parts[t].pixels()[i] * float(1.0 / passes[t]);
        }
    });
    return image;
}

}  // namespace

std::vector<ConvergencePoint> run_vpl_sampler(const ConvergenceRun& run, const std::string& name,
                                              const sampler::SamplerSettings& settings,
                                              render::VplRenderer& renderer,
                                              const render::RenderOptions& options) {
    cluster::Cluster& ranks = ranks_of(run);
    const bool shared = ranks.size() > 1;
    start_together(ranks);
    Timer timer;
    const session::SceneSession& s = *run.session;
    render::RenderOptions o = options;
    o.width = uint32_t(run.reference->width());
    o.height = uint32_t(run.reference->height());
    o.subpixel_rotation = subpixel_rotation(run.seed);
    o.chain_seed = run.seed;
    std::unique_ptr<CompensationThread> compensation, caustics;
    // Passes of the job allowed so far: each rank runs every R-th (rank_passes).
    auto allow = [&](uint32_t passes) {
        const uint32_t mine = rank_passes(passes, ranks.rank(), ranks.size());
        if (compensation) compensation->allow(mine);
        if (caustics) caustics->allow(mine);
    };
    // First the caustic tracer, which decides the light tracer's VPLs (path_partition.h).
    cluster::together(ranks, [&] {
        if (run.caustics) {
            reference::CausticOptions k;
            k.width = int(o.width);
            k.height = int(o.height);
            k.max_depth = run.max_depth;
            k.rr_depth = settings.tracer.rr_depth;
            k.specular = o.chains;
            k.clamp = run.compensate ? o.clamp : 0.0f;  // the compensation's share (see there)
            k.vsl_radius = o.vsl_radius;                // lobe-wise or all (caustic_tracer.h)
            k.seed = run.seed;
            k.first_pass = uint32_t(ranks.rank());
            k.pass_stride = uint32_t(ranks.size());
            auto tracer =
                std::make_unique<reference::CausticTracer>(s.scene(), s.accel(), s.lights(), k);
            if (tracer->active())
                caustics = std::make_unique<CompensationThread>(std::move(tracer));
        }
    });
    sampler::SamplerSettings sampler_settings = settings;
    if (shared) sampler_settings.cluster = &ranks;
    if (caustics) sampler_settings.tracer.specular = o.chains;
    std::unique_ptr<sampler::VplStream> stream;
    // The Metropolis bootstrap meets the other ranks inside (its own agreement points).
    cluster::together(ranks, [&] {
        stream = sampler::make_vpl_stream(name, s.scene(), s.accel(), s.lights(), s.camera(),
                                          sampler_settings);
    });
    cluster::together(ranks, [&] {
        renderer.begin(s.camera(), o);
        if (!run.compensate) return;
        reference::CompensationOptions c;
        c.width = int(o.width);
        c.height = int(o.height);
        c.clamp = o.clamp;
        c.vsl_radius = o.vsl_radius;
        c.max_depth = run.max_depth;
        c.chains = o.chains;  // compensated where the VPLs light: at the chains' ends
        c.seed = run.seed;
        c.first_pass = uint32_t(ranks.rank());
        c.pass_stride = uint32_t(ranks.size());
        auto passes =
            std::make_unique<reference::ClampCompensation>(s.scene(), s.accel(), s.lights(), c);
        if (passes->active())
            compensation = std::make_unique<CompensationThread>(std::move(passes));
    });
    if (run.compensation_passes > 0) allow(run.compensation_passes);

    std::vector<ConvergencePoint> points;
    Progress progress(name, tenths(run.budget_seconds), run.quiet);
    uint64_t work = 16, vpls = 0;
    double per_work = 0.0, last = 0.0;
    std::vector<light::Vpl> chunk;
    while (true) {
        const double now = timer.seconds();
        if (root_says(ranks, stream->work_done() > 0 &&
                                 now + per_work * double(work) > run.budget_seconds))
            break;
        chunk.clear();
        stream->next(work, chunk);  // over ranks: an agreement point inside
        cluster::together(ranks, [&] {
            if (shared) {
                renderer.accumulate(chunk, stream->last_index());
            } else {
                renderer.accumulate(chunk);
            }
        });
        vpls = shared ? stream->vpls_total() : vpls + chunk.size();
        if ((compensation || caustics) && run.compensation_passes == 0)
            allow(paced_compensation_passes(vpls));
        Image image;
        if (shared) {
            image = shared_image(ranks, renderer, stream->scale(), vpls,
                                 {compensation.get(), caustics.get()});
        } else {
            image = renderer.resolve(stream->scale());
            for (const CompensationThread* thread : {compensation.get(), caustics.get()}) {
                if (!thread) continue;
                const Image part = thread->snapshot();
                for (size_t i = 0; i < image.pixels().size(); ++i)
                    image.pixels()[i] += part.pixels()[i];
            }
        }
        work = stream->work_done();  // doubling
        if (!ranks.root()) continue;
        const double seconds = timer.seconds();
        per_work = seconds / double(stream->work_done());
        points.push_back(measure(name, seconds, vpls, image, *run.reference));
        progress.set_status(stream->statistics());
        progress.advance(tenths(std::min(seconds, run.budget_seconds)) -
                         tenths(std::min(last, run.budget_seconds)));
        last = seconds;
    }
    progress.finish();
    return points;
}

}  // namespace mvpl::cli

#include "tools/cli/convergence_runs.h"

#include <algorithm>

#include "engine/core/image_metrics.h"
#include "engine/core/progress.h"
#include "engine/core/subpixel.h"
#include "engine/core/timer.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/vpl_renderer.h"
#include "tools/cli/compensation_thread.h"

namespace mvpl::cli {

namespace {

// Progress over the budget in tenths of a second.
int64_t tenths(double seconds) {
    return int64_t(seconds * 10.0);
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
    const session::SceneSession& s = *run.session;
    const reference::PathTracer tracer(s.scene(), s.accel(), s.lights());
    const int w = run.reference->width(), h = run.reference->height();
    std::vector<ConvergencePoint> points;
    Image sum(w, h);
    int spp = 0, chunk = 1;
    Progress progress("pt", tenths(run.budget_seconds), run.quiet);
    Timer timer;
    double per_spp = 0.0, last = 0.0;
    for (uint64_t round = 0;; ++round) {
        // Stop before a chunk that would overrun the budget (its time extrapolated per spp).
        if (spp > 0 && timer.seconds() + per_spp * chunk > run.budget_seconds) break;
        reference::PathTracerOptions o;
        o.width = w;
        o.height = h;
        o.spp = chunk;
        o.max_depth = run.max_depth;
        o.seed = run.seed * 1000003 + round;
        o.quiet = true;
        const Image part = tracer.render(o);
        for (size_t i = 0; i < sum.pixels().size(); ++i)
            sum.pixels()[i] += part.pixels()[i] * float(chunk);
        spp += chunk;
        const double seconds = timer.seconds();
        per_spp = seconds / spp;
        Image mean = sum;
        for (Rgb& c : mean.pixels())
            c = c / float(spp);
        points.push_back(measure("pt", seconds, uint64_t(spp), mean, *run.reference));
        progress.advance(tenths(std::min(seconds, run.budget_seconds)) -
                         tenths(std::min(last, run.budget_seconds)));
        last = seconds;
        chunk = spp;  // doubling
    }
    progress.finish();
    return points;
}

std::vector<ConvergencePoint> run_vpl_sampler(const ConvergenceRun& run, const std::string& name,
                                              const sampler::SamplerSettings& settings,
                                              render::VplRenderer& renderer,
                                              const render::RenderOptions& options) {
    Timer timer;
    const session::SceneSession& s = *run.session;
    const std::unique_ptr<sampler::VplStream> stream =
        sampler::make_vpl_stream(name, s.scene(), s.accel(), s.lights(), s.camera(), settings);
    render::RenderOptions o = options;
    o.width = uint32_t(run.reference->width());
    o.height = uint32_t(run.reference->height());
    o.subpixel_rotation = subpixel_rotation(run.seed);
    o.chain_seed = run.seed;
    renderer.begin(s.camera(), o);
    std::unique_ptr<CompensationThread> compensation;
    if (run.compensate) {
        reference::CompensationOptions c;
        c.width = int(o.width);
        c.height = int(o.height);
        c.clamp = o.clamp;
        c.max_depth = run.max_depth;
        c.seed = run.seed;
        auto passes =
            std::make_unique<reference::ClampCompensation>(s.scene(), s.accel(), s.lights(), c);
        if (passes->active())
            compensation = std::make_unique<CompensationThread>(std::move(passes));
        if (compensation && run.compensation_passes > 0)
            compensation->allow(run.compensation_passes);
    }

    std::vector<ConvergencePoint> points;
    Progress progress(name, tenths(run.budget_seconds), run.quiet);
    uint64_t work = 16, vpls = 0;
    double per_work = 0.0, last = 0.0;
    std::vector<light::Vpl> chunk;
    while (true) {
        const double now = timer.seconds();
        if (stream->work_done() > 0 && now + per_work * work > run.budget_seconds) break;
        chunk.clear();
        stream->next(work, chunk);
        renderer.accumulate(chunk);
        vpls += chunk.size();
        Image image = renderer.resolve(stream->scale());
        if (compensation) {
            if (run.compensation_passes == 0) compensation->allow(paced_compensation_passes(vpls));
            const Image part = compensation->snapshot();
            for (size_t i = 0; i < image.pixels().size(); ++i)
                image.pixels()[i] += part.pixels()[i];
        }
        const double seconds = timer.seconds();
        per_work = seconds / double(stream->work_done());
        points.push_back(measure(name, seconds, vpls, image, *run.reference));
        progress.set_status(stream->statistics());
        progress.advance(tenths(std::min(seconds, run.budget_seconds)) -
                         tenths(std::min(last, run.budget_seconds)));
        last = seconds;
        work = stream->work_done();  // doubling
    }
    progress.finish();
    return points;
}

}  // namespace mvpl::cli

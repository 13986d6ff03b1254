#include "tools/cli/render_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "sampler/metropolis_stream.h"
#include "sampler/monte_carlo_sampler.h"

namespace mvpl::cli {

namespace {

// Seconds of sampling + shading aimed at per progressive chunk under --time-budget: long enough
// that a Metropolis chain merges its repeats over several steps, short enough that the last
// chunk overshoots the budget by little.
constexpr double kChunkSeconds = 0.5;

// Warns when the Metropolis bootstrap found no light on anything the camera sees; returns
// whether it did not (then sampling longer cannot change the black image).
bool warn_if_unlit(const sampler::VplStream& stream, const std::string& scene_path) {
    const auto* metropolis = dynamic_cast<const sampler::MetropolisStream*>(&stream);
    if (metropolis && metropolis->no_visible_light()) {
        std::fprintf(stderr,
                     "mvpl: warning: %s: no light reaches anything the camera sees; the image "
                     "is black\n",
                     scene_path.c_str());
        return true;
    }
    return false;
}

// The next chunk of work units: about kChunkSeconds at the rate measured so far, never past the
// remaining budget's worth, at least one unit.
uint64_t next_chunk(uint64_t done, double elapsed, double remaining, uint64_t first) {
    if (done == 0 || !(elapsed > 0.0)) return first;
    const double per_unit = elapsed / double(done);
    const double seconds = std::min(kChunkSeconds, remaining);
    // At most 2^20 units a chunk, however cheap they were so far.
    return std::clamp<uint64_t>(uint64_t(std::min(seconds / per_unit, 1e9)), 1, uint64_t(1) << 20);
}

std::unique_ptr<sampler::VplStream> make_stream(const RenderJob& job) {
    const session::SceneSession& s = *job.session;
    return sampler::make_vpl_stream(job.sampler, s.scene(), s.accel(), s.lights(), s.camera(),
                                    job.settings);
}

// The VPLs of `units` at once. Monte Carlo traces them in one parallel call (with its own
// progress bar); Metropolis runs its chains.
light::VplSet sample_once(const RenderJob& job, uint64_t units, RenderOutcome& result) {
    const session::SceneSession& s = *job.session;
    if (job.sampler == "mc") {
        sampler::MonteCarloOptions mc;
        mc.paths = units;
        mc.seed = job.settings.seed;
        mc.qmc = job.settings.qmc;
        mc.per_path = job.settings.per_path;
        mc.tracer = job.settings.tracer;
        mc.quiet = job.quiet;
        result.units = units;
        return sampler::MonteCarloSampler(s.scene(), s.accel(), s.lights()).generate(mc);
    }
    const std::unique_ptr<sampler::VplStream> stream = make_stream(job);
    warn_if_unlit(*stream, s.path());
    light::VplSet set;
    stream->next(units, set.vpls);
    set.scale = stream->scale();
    result.units = stream->work_done();
    result.statistics = stream->statistics();
    return set;
}

// Adds `part` into `sum`, pixel by pixel.
void add_image(Image& sum, const Image& part, float scale = 1.0f) {
    for (size_t i = 0; i < sum.pixels().size(); ++i)
        sum.pixels()[i] += part.pixels()[i] * scale;
}

}  // namespace

RenderOutcome render_once(const RenderJob& job, uint64_t units) {
    RenderOutcome result;
    Timer sampling;
    const light::VplSet set = sample_once(job, units, result);
    result.sampling_seconds = sampling.seconds();
    result.vpls = set.vpls.size();
    Timer shading;
    if (!job.renderer) {
        const session::SceneSession& s = *job.session;
        result.image = reference::gather_vpls(s.scene(), s.accel(), set, job.gather);
    } else {
        Progress progress("render", int64_t(set.vpls.size()), job.quiet);
        render::RenderOptions ro = job.render;
        ro.on_batch = [&progress](size_t count) { progress.advance(int64_t(count)); };
        result.image = job.renderer->render(set, ro, &result.timings);
        progress.finish();
    }
    result.shading_seconds = shading.seconds();
    return result;
}

RenderOutcome render_for(const RenderJob& job, double seconds) {
    const session::SceneSession& s = *job.session;
    RenderOutcome result;
    Timer budget;
    if (job.renderer) job.renderer->begin(s.camera(), job.render);
    Timer setup;
    const std::unique_ptr<sampler::VplStream> stream = make_stream(job);
    result.sampling_seconds += setup.seconds();
    const bool unlit = warn_if_unlit(*stream, s.path());
    // Progress in tenths of the budget.
    const int64_t tenths = int64_t(std::ceil(seconds * 10.0));
    int64_t shown = 0;
    Progress progress("render", tenths, job.quiet);
    std::vector<light::Vpl> chunk;
    // The oracle gathers each chunk at once (VPL light only, unscaled) so that the budget counts
    // the CPU shading too; the emitted radiance is added once at the end.
    reference::GatherOptions g_chunk = job.gather;
    g_chunk.max_depth = 0;
    g_chunk.quiet = true;
    Image sum(job.gather.width, job.gather.height);
    const uint64_t first = uint64_t(job.render.batch);
    while (!unlit && budget.seconds() < seconds) {
        const uint64_t work =
            next_chunk(stream->work_done(), budget.seconds(), seconds - budget.seconds(), first);
        chunk.clear();
        Timer sampling;
        stream->next(work, chunk);
        result.sampling_seconds += sampling.seconds();
        Timer shading;
        if (job.renderer) {
            job.renderer->accumulate(chunk);
        } else if (!chunk.empty()) {
            add_image(sum, reference::gather_vpls(s.scene(), s.accel(), {chunk}, g_chunk));
        }
        result.shading_seconds += shading.seconds();
        result.vpls += chunk.size();
        progress.set_status(stream->statistics());
        const int64_t now = std::min(tenths, int64_t(budget.seconds() * 10.0));
        progress.advance(now - shown);
        shown = now;
    }
    progress.finish();
    result.units = stream->work_done();
    result.statistics = stream->statistics();
    Timer shading;
    if (job.renderer) {
        result.image = job.renderer->resolve(stream->scale());
        result.timings = job.renderer->timings();
    } else {
        result.image = reference::gather_vpls(s.scene(), s.accel(), {}, job.gather);  // emission
        add_image(result.image, sum, float(stream->scale()));
    }
    result.shading_seconds += shading.seconds();
    return result;
}

std::string summary_line(const RenderJob& job, const RenderOutcome& r, double total_seconds) {
    std::string pass_times = "CPU oracle";
    if (job.renderer) {
        char buf[160];
        std::snprintf(
            buf, sizeof buf, "G-buffer %.1f ms, shadow %.1f ms, shading %.1f ms, %u batches",
            r.timings.g_buffer_ms, r.timings.shadow_ms, r.timings.shading_ms, r.timings.batches);
        pass_times = buf;
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

#pragma once
// The two loops of `mvpl render` over the VPL integrator (engine/integrator/vpl_integrator.h): a
// fixed amount of sampler work, and chunks until a time budget is spent.
#include <cstdint>
#include <functional>
#include <string>

#include "engine/cluster/cluster.h"
#include "engine/core/image.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/vpl_integrator.h"
#include "engine/render/vpl_renderer.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

// What to render: everything but the amount of work.
struct RenderJob {
    const session::SceneSession* session = nullptr;
    integrator::Estimate estimate;
    integrator::VplIntegrator* integrator = nullptr;  // the scene's; begun by each run
    bool quiet = false;
    // The ranks that share the render (engine/cluster): each samples and shades its share, rank 0
    // sums the images and alone gets the outcome's image. Null: this process alone. The
    // integrator was made for the same ranks.
    cluster::Cluster* cluster = nullptr;
    // --write-every: between chunks, once `write_every` seconds (0: never) have passed since the
    // last time, the estimate so far goes to `checkpoint` on rank 0 (which rewrites the outputs),
    // so that a long render's files follow it. The estimate is not changed by it.
    double write_every = 0.0;
    std::function<void(const Image& image, uint64_t vpls)> checkpoint;
};

// What a render produced, for the summary line.
struct RenderOutcome {
    Image image;  // empty on ranks other than 0
    integrator::IntegratorStats stats;
    std::string statistics;         // the sampler's, may be empty
    render::RenderTimings timings;  // GPU only
};

// `units` light paths or chain steps, sampled and shaded chunk by chunk.
RenderOutcome render_once(const RenderJob& job, uint64_t units);

// As many units as fit `seconds` of sampling + shading (the sampler's set-up, e.g. the Metropolis
// bootstrap, and the G-buffer count too), in chunks of about half a second.
RenderOutcome render_for(const RenderJob& job, double seconds);

// "render: N VPLs from U paths, WxH: sampling …, shading … (PASSES), total …, … VPL/s; STATS",
// PASSES the GPU pass times or "CPU oracle".
std::string summary_line(const RenderJob& job, const RenderOutcome& result, double total_seconds);

}  // namespace mvpl::cli

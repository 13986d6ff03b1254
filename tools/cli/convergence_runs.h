#pragma once
// The measurement runs of `mvpl convergence`: one progressive run per method, its error against
// the reference recorded after every chunk of work, chunks doubling so that the points are spaced
// evenly on a log time axis, until the time budget is spent. Under mpirun (engine/cluster) the
// ranks share every chunk, rank 0 sums their images, measures and alone returns the points; its
// clock decides for all when the budget is spent, so that they stop together.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engine/cluster/cluster.h"
#include "engine/core/image.h"
#include "engine/integrator/vpl_integrator.h"
#include "engine/light/path_depth.h"
#include "engine/manylights/row_column_options.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/sampler_factory.h"
#include "tools/cli/convergence_analysis.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

struct ConvergenceRun {
    const session::SceneSession* session = nullptr;
    const Image* reference = nullptr;  // its size is the image size
    double budget_seconds = 10.0;
    int max_depth = light::kDefaultMaxDepth;
    uint64_t seed = 0;
    bool quiet = false;
    // VPL runs add clamping compensation (engine/integrator/cpu_estimator_thread.h):
    // compensation_passes samples per pixel, or 0: paced by the VPLs shaded.
    bool compensate = false;
    uint32_t compensation_passes = 0;
    // And caustics (integrator/caustic_tracer.h), paced as the compensation, with the chains' class
    // of the run's render options (the light tracer then leaves no VPL there).
    bool caustics = false;
    // Matrix row-column sampling for the VPL methods (engine/manylights); off by default.
    manylights::RowColumnOptions many_lights;
    // The ranks that share each chunk (every rank runs the same calls); null: this process alone.
    // The points' seconds are rank 0's wall time, and only rank 0 gets points (others: none).
    cluster::Cluster* cluster = nullptr;
};

// The reference path tracer, spp doubling per chunk (independent seeds), the running average.
// Over R ranks each chunk's spp are split among them, each with a seed of its own, and the
// first chunk is R spp.
std::vector<ConvergencePoint> run_path_tracer(const ConvergenceRun& run);

// A VPL sampler (sampler_factory.h) through the progressive GPU renderer: light paths or chain
// steps doubling per chunk, resolved after each. The time counts the sampler's start-up (the
// Metropolis bootstrap) and the G-buffer, not the renderer's construction (shader compilation),
// which `mvpl bench` reports. `options` gives all but the image size (the reference's). Over
// ranks they share each chunk as `mvpl render` does (engine/sampler/vpl_stream.h: Monte Carlo path
// ranges, Metropolis chains), so that each point's image is the one-process run's at that work.
std::vector<ConvergencePoint> run_vpl_sampler(const ConvergenceRun& run, const std::string& name,
                                              const sampler::SamplerSettings& settings,
                                              integrator::VplIntegrator& integrator,
                                              const render::RenderOptions& options);

// The error of `image` against the reference as a point of `method`.
ConvergencePoint measure(const std::string& method, double seconds, uint64_t samples,
                         const Image& image, const Image& reference);

}  // namespace mvpl::cli

#pragma once
// The measurement runs of `mvpl convergence`: one progressive run per method, its error against
// the reference recorded after every chunk of work, chunks doubling so that the points are spaced
// evenly on a log time axis, until the time budget is spent.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/render/vpl_renderer.h"
#include "sampler/sampler_factory.h"
#include "tools/cli/convergence_analysis.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

struct ConvergenceRun {
    const session::SceneSession* session = nullptr;
    const Image* reference = nullptr;  // its size is the image size
    double budget_seconds = 10.0;
    int max_depth = 6;
    uint64_t seed = 0;
    bool quiet = false;
    // VPL runs add clamping compensation (compensation_thread.h): compensation_passes samples per
    // pixel, or 0: paced by the VPLs shaded.
    bool compensate = false;
    uint32_t compensation_passes = 0;
};

// The reference path tracer, spp doubling per chunk (independent seeds), the running average.
std::vector<ConvergencePoint> run_path_tracer(const ConvergenceRun& run);

// A VPL sampler (sampler_factory.h) through the progressive GPU renderer: light paths or chain
// steps doubling per chunk, resolved after each. The time counts the sampler's start-up (the
// Metropolis bootstrap) and the G-buffer, not the renderer's construction (shader compilation),
// which `mvpl bench` reports. `options` gives all but the image size (the reference's).
std::vector<ConvergencePoint> run_vpl_sampler(const ConvergenceRun& run, const std::string& name,
                                              const sampler::SamplerSettings& settings,
                                              render::VplRenderer& renderer,
                                              const render::RenderOptions& options);

// The error of `image` against the reference as a point of `method`.
ConvergencePoint measure(const std::string& method, double seconds, uint64_t samples,
                         const Image& image, const Image& reference);

}  // namespace mvpl::cli

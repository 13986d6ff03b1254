#pragma once
// One measured render of `mvpl bench`: a configuration's renderer options and estimate, the VPLs
// sampled once a repeat, and one progressive render of them through the integrator, with the
// renderer's pass times (summed over the ranks under mpirun).
#include "engine/cluster/cluster.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/scene_view.h"
#include "engine/integrator/vpl_integrator.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/sampler/recorded_vpl_stream.h"
#include "tools/cli/bench_report.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

render::RenderOptions render_options(const BenchConfig& config, float clamp, bool shadows);

// The estimate a configuration renders: the recorded VPLs alone (no compensation, no caustics:
// bench measures the VPL shading), through row-column sampling where the configuration has a
// pool.
integrator::Estimate estimate_of(const BenchConfig& config, float clamp, bool shadows);

// The VPLs of mc.paths light paths (this rank's share under mpirun, the ranks sharing the paths
// as `mvpl render` does), sampled once a repeat and shaded with every configuration.
sampler::VplRecording sample(const session::SceneSession& session, sampler::MonteCarloOptions mc,
                             cluster::Cluster& ranks);

// One progressive render of all VPLs; over ranks, from a meeting of all to rank 0's image.
RenderSample render_once(integrator::VplIntegrator& integrator, const integrator::SceneView& view,
                         const sampler::VplRecording& vpls, const integrator::Estimate& estimate,
                         cluster::Cluster& ranks);

}  // namespace mvpl::cli

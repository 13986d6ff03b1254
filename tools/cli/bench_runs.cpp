#include "tools/cli/bench_runs.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/timer.h"
#include "engine/sampler/monte_carlo_stream.h"

namespace mvpl::cli {

render::RenderOptions render_options(const BenchConfig& c, float clamp, bool shadows) {
    render::RenderOptions ro;
    ro.width = uint32_t(c.width);
    ro.height = uint32_t(c.height);
    ro.shadow_resolution = uint32_t(c.shadow_resolution);
    ro.batch = uint32_t(c.batch);
    ro.jitter = c.jitter;
    ro.batches_per_position = uint32_t(std::max(c.batches_per_position, 1));
    ro.clamp = clamp;
    ro.shadows = shadows;
    ro.shadow_culling = c.shadow_culling;
    ro.shadow_proxy = c.shadow_proxy;
    ro.shadow_lod = c.shadow_lod;
    ro.backface_culling = c.backface_culling;
    ro.interleave = uint32_t(c.interleave);
    ro.hemicube = c.hemicube;
    ro.vpl_culling = c.vpl_culling;
    ro.chains.max_roughness = c.chain_roughness;
    ro.chains.max_depth = c.max_depth;
    ro.vsl_radius = c.vsl_radius;
    return ro;
}

sampler::VplRecording sample(const session::SceneSession& session, sampler::MonteCarloOptions mc,
                             cluster::Cluster& ranks) {
    if (ranks.size() > 1) mc.cluster = &ranks;
    sampler::MonteCarloStream stream(session.scene(), session.accel(), session.lights(), mc);
    return sampler::record(stream, mc.paths);
}

namespace {

// The job's GPU times and work, summed over the ranks, so that per VPL they are the job's cost
// (row-column sampling: every rank's representatives, and the CPU seconds of every rank's pools).
void sum_over_ranks(RenderSample& s, cluster::Cluster& ranks) {
    std::vector<double> sums{s.g_buffer_ms,
                             s.shadow_ms,
                             s.shading_ms,
                             double(s.batches),
                             double(s.shadow_triangles),
                             double(s.g_buffers),
                             double(s.shadow_front_only_triangles),
                             double(s.shaded),
                             s.matrix_s,
                             s.cluster_s};
    ranks.sum_all(sums);
    s.g_buffer_ms = sums[0];
    s.shadow_ms = sums[1];
    s.shading_ms = sums[2];
    s.batches = uint32_t(sums[3]);
    s.shadow_triangles = uint64_t(sums[4]);
    s.g_buffers = uint32_t(sums[5]);
    s.shadow_front_only_triangles = uint64_t(sums[6]);
    s.shaded = uint64_t(sums[7]);
    s.matrix_s = sums[8];
    s.cluster_s = sums[9];
}

}  // namespace

integrator::Estimate estimate_of(const BenchConfig& config, float clamp, bool shadows) {
    integrator::Estimate e;
    e.render = render_options(config, clamp, shadows);
    e.compensate = false;
    e.caustics = false;
    e.many_lights = config.many_lights;
    return e;
}

RenderSample render_once(integrator::VplIntegrator& integrator, const integrator::SceneView& view,
                         const sampler::VplRecording& vpls, const integrator::Estimate& estimate,
                         cluster::Cluster& ranks) {
    cluster::together(ranks, [] {});
    Timer wall;
    integrator.begin(view, estimate, integrator::Pacing::Fixed,
                     std::make_unique<sampler::RecordedVplStream>(vpls));
    integrator.advance(vpls.work);
    const Image image = integrator.image();  // the read-back costs too
    RenderSample s;
    s.wall_s = wall.seconds();
    const render::RenderTimings& t = integrator.renderer()->timings();
    s.g_buffer_ms = t.g_buffer_ms;
    s.shadow_ms = t.shadow_ms;
    s.shading_ms = t.shading_ms;
    s.batches = t.batches;
    s.shadow_triangles = t.shadow_triangles;
    s.shadow_front_only_triangles = t.shadow_front_only_triangles;
    s.shadow_texels = t.shadow_texels;
    s.culled_vpls = t.culled_vpls;
    s.g_buffers = t.g_buffers;
    s.chain_ms = t.chain_ms;
    s.chain_rays = t.chain_rays;
    // With row-column sampling the VPLs shaded are the representatives.
    const integrator::IntegratorStats& stats = integrator.stats();
    s.shaded = stats.shaded;
    s.matrix_s = stats.many_lights.matrix_seconds;
    s.cluster_s = stats.many_lights.cluster_seconds;
    s.gpu_matrix = stats.gpu_matrix;
    if (ranks.size() > 1) sum_over_ranks(s, ranks);
    return s;
}

}  // namespace mvpl::cli

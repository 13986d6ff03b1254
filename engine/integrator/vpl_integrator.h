#pragma once
// The VPL estimator, whole: a sampler's stream of VPLs, shaded as they come by the GPU renderer
// (or, without one, by the CPU oracle), with the CPU estimators that run beside it — clamping
// compensation and caustics (cpu_estimator_thread.h) — and the ranks of a job under mpirun
// (engine/cluster), which share the light paths and sum their images to rank 0. Its image's
// expectation is the estimate's (estimate.h) whatever the loop around it: `mvpl render` advances
// it by a fixed count or a time budget, `mvpl convergence` by doubling chunks, `mvpl bench` by
// one fixed set of VPLs, the preview by frames; each reads the image when it likes. It lives as
// long as its scene (the renderer's pipelines and maps), an estimate from begin() to finish().
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/cluster/cluster.h"
#include "engine/core/image.h"
#include "engine/gpu/context.h"
#include "engine/integrator/cpu_estimators.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/gpu_columns.h"
#include "engine/integrator/scene_view.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/vpl_stream.h"

namespace mvpl::integrator {

// The counts and times of an estimate so far.
struct IntegratorStats {
    uint64_t units = 0;  // light paths (mc) or chain steps (metropolis)
    size_t vpls = 0;     // by every rank
    // By this process: with row-column sampling the representatives, fewer than `vpls` (and
    // `many_lights` are this process's pools).
    size_t shaded = 0;
    manylights::RowColumnStats many_lights;  // pools, rows and their seconds (in sampling)
    bool gpu_matrix = false;                 // the reduced matrix on the renderer (GpuColumns)
    double sampling_seconds = 0.0;
    double shading_seconds = 0.0;
    uint32_t compensation_passes = 0;
    uint32_t caustic_passes = 0;  // 0: no caustic tracer ran
    // Over ranks: the seconds of summing the images to rank 0 and the bytes each rank sent.
    double reduce_seconds = 0.0;
    uint64_t reduce_bytes = 0;
};

class VplIntegrator {
public:
    // Shades on `context` with a GPU renderer of `devices` devices (render::VplRenderer), or,
    // with no context, with the CPU oracle (one process only). ranks: null for this process
    // alone; every rank constructs it with the same arguments. The view's camera is begin()'s.
    VplIntegrator(const SceneView& view, gpu::Context* context, uint32_t devices,
                  cluster::Cluster* ranks);
    ~VplIntegrator();
    VplIntegrator(const VplIntegrator&) = delete;
    VplIntegrator& operator=(const VplIntegrator&) = delete;

    // Starts an estimate at the view's camera (its scene is the constructor's), from a new
    // stream of the estimate's sampler, or from `stream` when given (the preview's VPLs, drawn
    // once and shaded again after a camera move). Every rank calls it with the same arguments.
    void begin(const SceneView& view, const Estimate& estimate, Pacing pacing,
               std::unique_ptr<sampler::VplStream> stream = nullptr);
    // Samples `work` more units (light paths or chain steps; over ranks, shared) and shades
    // their VPLs. Every rank calls it with the same work.
    void advance(uint64_t work);
    // The estimate so far: scale · Σ contributions + the emitted radiance seen directly + the
    // CPU estimators' passes done so far. Every rank calls it; rank 0 gets the image, the others
    // an empty one.
    Image image();
    // The final image (as image(), the CPU estimators finished as the pacing says); once.
    Image finish();

    // One process: the CPU estimators' image so far (black where none runs), and finished as
    // `pacing` says for the VPLs shaded (Fixed: every pass `mvpl render` runs for them).
    Image cpu_image() const;
    Image finish_cpu(Pacing pacing);

    const sampler::VplStream& stream() const { return *m_stream; }
    const IntegratorStats& stats() const { return m_stats; }
    // The GPU renderer (its timings, devices, and the sums the preview presents); null when the
    // CPU oracle shades.
    render::VplRenderer* renderer() { return m_renderer.get(); }
    const render::VplRenderer* renderer() const { return m_renderer.get(); }
    // Whether the stream knows already that the image stays black however long it runs (the
    // Metropolis bootstrap found no light on anything the camera sees).
    bool unlit() const;

private:
    bool shared() const { return m_ranks.size() > 1; }
    // The VPLs shaded by every rank (row-column sampling's representatives, not its pools): they
    // pace the CPU estimators, and the emission is averaged over their sub-pixel positions.
    uint64_t shaded_by_all() const { return m_many_lights ? m_representatives : m_stats.vpls; }
    uint64_t number_pools();
    std::span<const uint64_t> index_representatives();
    Image vpl_image();
    void add_cpu_finished(Image& sum, Pacing pacing);
    Image shared_image(bool finishing);

    cluster::Cluster& m_ranks;
    std::unique_ptr<render::VplRenderer> m_renderer;
    SceneView m_view;
    Estimate m_estimate;
    Pacing m_pacing = Pacing::Fixed;
    IntegratorStats m_stats;
    std::unique_ptr<sampler::VplStream> m_stream;
    reference::GatherOptions m_gather;  // the oracle's, per chunk
    Image m_sum;                        // the oracle's Σ contributions
    std::vector<light::Vpl> m_chunk;
    std::unique_ptr<CpuEstimators> m_cpu;
    std::unique_ptr<GpuColumns> m_gpu_columns;  // the reduced matrix on the renderer, or null
    std::unique_ptr<manylights::RowColumnSampler> m_many_lights;  // null: every VPL shaded
    uint64_t m_pools = 0;            // row-column sampling's, by every rank
    uint64_t m_representatives = 0;  // shaded by every rank
    std::vector<uint64_t> m_index;   // over ranks: the last chunk's representatives' indices
};

}  // namespace mvpl::integrator

#pragma once
// The two ways `mvpl render` forms its image, apart from its options: a one-shot render of a
// fixed amount of sampler work, and a progressive loop that renders chunks until a time budget is
// spent; each shades on the GPU renderer or, without one, with the CPU oracle.
#include <cstdint>
#include <string>

#include "engine/cluster/cluster.h"
#include "engine/core/image.h"
#include "engine/reference/caustic_tracer.h"
#include "engine/reference/clamp_compensation.h"
#include "engine/reference/vpl_gather.h"
#include "engine/render/vpl_renderer.h"
#include "sampler/sampler_factory.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

// What to render: everything but the amount of work.
struct RenderJob {
    const session::SceneSession* session = nullptr;
    std::string sampler = "mc";
    sampler::SamplerSettings settings;
    render::RenderOptions render;             // the GPU renderer's options
    reference::GatherOptions gather;          // the CPU oracle's
    render::VplRenderer* renderer = nullptr;  // null: shade with the CPU oracle
    // Clamping compensation (reference/clamp_compensation.h), on a CPU thread beside the
    // shading: `compensation_passes` samples per pixel, or 0: one per 32 VPLs shaded, at most
    // kFixedRenderPasses in a render of fixed size (under a time budget, those done when it
    // ends).
    bool compensate = false;
    uint32_t compensation_passes = 0;
    reference::CompensationOptions compensation;
    // Caustics (reference/caustic_tracer.h) on another CPU thread, paced as the compensation,
    // where the scene has vertices that leave no VPL; then the sampler's light tracer leaves no
    // VPL on the chains' class either (`caustic.specular`: light/path_partition.h).
    bool caustics = false;
    reference::CausticOptions caustic;
    bool quiet = false;
    // The ranks that share the render (engine/cluster): each samples and shades its share, rank 0
    // sums the images and alone gets the outcome's image. Null: this process alone.
    cluster::Cluster* cluster = nullptr;
};

// What a render produced, for the summary line.
struct RenderOutcome {
    Image image;         // empty on ranks other than 0
    uint64_t units = 0;  // light paths (mc) or chain steps (metropolis)
    size_t vpls = 0;     // by every rank
    double sampling_seconds = 0.0;
    double shading_seconds = 0.0;
    std::string statistics;         // the sampler's, may be empty
    render::RenderTimings timings;  // GPU only
    uint32_t compensation_passes = 0;
    uint32_t caustic_passes = 0;  // 0: no caustic tracer ran
    // Over ranks: the seconds of summing the images to rank 0 and the bytes each rank sent.
    double reduce_seconds = 0.0;
    uint64_t reduce_bytes = 0;
};

// `units` light paths or chain steps, sampled at once, then shaded.
RenderOutcome render_once(const RenderJob& job, uint64_t units);

// As many units as fit `seconds` of sampling + shading (the sampler's set-up, e.g. the Metropolis
// bootstrap, and the G-buffer count too), in chunks of about half a second.
RenderOutcome render_for(const RenderJob& job, double seconds);

// "render: N VPLs from U paths, WxH: sampling …, shading … (PASSES), total …, … VPL/s; STATS",
// PASSES the GPU pass times or "CPU oracle".
std::string summary_line(const RenderJob& job, const RenderOutcome& result, double total_seconds);

}  // namespace mvpl::cli

#pragma once
// `mvpl preview`: the interactive progressive VPL preview. Each frame shades as many VPL batches
// as fit a time budget into the running sum and shows scale · Σ + emission; a camera move
// restarts the sum. Monte Carlo VPLs do not depend on the view, so they are kept and shaded
// again after a move; a Metropolis chain's target depends on the camera, so it restarts with it.
// At rest the clamping compensation and the caustic tracer run beside, so that the picture
// converges to the same image as `mvpl render` with the same seed.
#include <cstdint>
#include <string>

#include "engine/core/image_size.h"
#include "engine/light/path_depth.h"
#include "engine/manylights/row_column_options.h"
#include "engine/render/kept_shadow_maps.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/sampler_factory.h"
#include "engine/scene/camera_choice.h"
#include "engine/scene/environment_choice.h"
#include "engine/scene/scene_loader.h"

namespace mvpl::preview {

struct PreviewOptions {
    std::string scene_path;
    scene::CameraChoice camera;            // --camera, --look-at, --fov
    scene::LoadOptions load;               // -D, -a
    scene::EnvironmentChoice environment;  // --env-color, --env-scale, --no-default-light
    std::string sampler = "mc";
    int width = kThroughputImageSide;  // initial window size
    int height = kThroughputImageSide;
    double budget_ms = 50.0;       // rendering time per frame (when paths_per_frame is 0)
    uint64_t paths_per_frame = 0;  // fixed sampler work per frame instead of a time budget
    uint64_t max_paths = 0;        // stop sampling after this many units (0: never)
    uint64_t frames = 0;           // exit after this many frames (0: when the window closes)
    std::string screenshot;        // written after the last frame (.png or .exr)
    std::string script;            // --script FILE
    float clamp = render::RenderOptions{}.clamp;
    float exposure = 0.0f;
    uint64_t seed = 0;
    int max_depth = light::kDefaultMaxDepth;
    // VPLs a light path leaves (--vpl-per-path), for each sampler.
    sampler::VplsPerPath per_path = sampler::SamplerSettings{}.per_path;
    sampler::VplsPerPath metropolis_per_path = sampler::SamplerSettings{}.metropolis_per_path;
    // Matrix row-column sampling (--pool, --rows, --clusters), as `mvpl render`'s: each
    // accumulate()'s VPLs are cut into pools and shaded through their representatives; at rest
    // a call draws at least a pool's light paths (PreviewApp::pool_units).
    manylights::RowColumnOptions many_lights;
    uint32_t shadow_resolution = render::RenderOptions{}.shadow_resolution;
    uint32_t batch = render::RenderOptions{}.batch;
    bool jitter = render::RenderOptions{}.jitter;  // a new sub-pixel position per batch
    // The renderer's levers (shadow culling, proxy, hemicubes, VPL culling, interleave, indirect
    // faces), as the command line set them; its sizes, batch, jitter and clamp are the above.
    render::RenderOptions levers;
    // levers.interleave was the default (--interleave 0): 1 where the chains are traced or the
    // image (as rendered, motion scaling included) has fewer pixels than interleave_min_pixels,
    // as `mvpl render` (RendererArgs::interleave_for).
    bool interleave_auto = false;
    uint64_t interleave_min_pixels = 0;
    // levers.batches_per_position was the default (--batches-per-position 0): the scene's
    // (render::default_batches_per_position), as `mvpl render`.
    bool batches_per_position_auto = false;
    // The CPU estimators beside the VPLs at rest, as `mvpl render` runs them
    // (engine/integrator/cpu_estimators.h): clamping compensation (--no-compensate,
    // --compensation-spp) and caustics (--no-caustics).
    bool compensate = true;
    uint32_t compensation_passes = 0;
    bool caustics = true;
    // Device memory for shadow cubes kept across camera moves (render/kept_shadow_maps.h), shared
    // by the devices.
    uint64_t kept_shadow_bytes = render::kDefaultKeptBytes;
    // The renderer's devices, presented summed on the window's (VplRenderer::presented); 0: one.
    // Not `render`'s two on lavapipe: a frame's few batches keep one device busy at a time, and
    // summing the devices' images costs 1–5 ms a frame, so at rest two devices shaded 4–11 %
    // fewer VPLs than one (Cornell box, DamagedHelmet; docs/results.md, "The preview after a
    // camera move").
    uint32_t devices = 0;
    // The first frame at rest after a move shades the recorded VPLs, in whole batches, until
    // it holds 90 % of what the resting picture held before the move, for at most this many
    // seconds (0: the frame budget as any other frame).
    double catch_up_seconds = 2.0;
    bool hud = true;
    // Render at a reduced resolution while the camera moves (adapted to keep 10 fps).
    bool motion_scaling = true;
    bool quiet = false;
};

// Returns the exit code.
int run_preview(const PreviewOptions& options);

}  // namespace mvpl::preview

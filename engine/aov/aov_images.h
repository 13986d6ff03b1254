#pragma once
// The AOV images of a render or a reference (README, "AOVs"): each pixel's AOV is the mean over
// the sub-pixel positions its colour averages over, at most kMaxAovPositions of them.
//
// The cap: the AOVs are traced on the CPU (aov_tracer.h), one ray per pixel and position, about
// 0.14 s per position at 512² on two cores (the Cornell box's default 1024 paths draw 46
// positions: 6.4 s of a 43.5 s run, README "AOVs and EXR attributes"), and a render's positions
// grow with its length. 64 positions put a pixel's covered fraction within about 0.016 RMS of the
// exact one (subpixel.h: 0.026 at 32, 0.0094 at 128, on random half-planes); past them the first
// 64 of the image's positions stand for all, and the AOVs' cost stops growing.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/aov/aov_film.h"
#include "engine/aov/aov_kind.h"
#include "engine/aov/aov_tracer.h"
#include "engine/core/exr_file.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/scene_view.h"
#include "engine/reference/path_tracer.h"

namespace mvpl::aov {

inline constexpr uint64_t kMaxAovPositions = 64;

// The sub-pixel positions render_aovs averages over after `vpls` VPLs.
uint64_t aov_positions(const integrator::Estimate& estimate, uint64_t vpls);

// The AOVs of a VPL estimate after `vpls` VPLs: over the positions of its G-buffers
// (render::subpixel_schedule(estimate.render).positions_after(vpls), the first
// kMaxAovPositions), through the render's specular chains with the render's generator. Reads the
// scene only; deterministic whatever the thread count; none (and no work) for no AOVs.
std::vector<ChannelImage> render_aovs(const integrator::SceneView& view,
                                      const integrator::Estimate& estimate, uint64_t vpls,
                                      const std::vector<AovRequest>& aovs);

// The chains the reference's AOVs follow: `mvpl render`'s default (light::kDefaultChainRoughness)
// under the reference's path depth, so that the reference and the render report the same
// surfaces.
light::ChainOptions reference_chains(int max_depth);

// The AOVs of a path-traced reference, fed by PathTracer::render's camera-sample hook: its first
// kMaxAovPositions samples of each pixel, chains drawn from light::chain_rng(seed, pixel,
// sample).
class ReferenceAovs {
public:
    ReferenceAovs(const scene::Scene& scene, const trace::Accel& accel,
                  const reference::PathTracerOptions& options, std::vector<AovRequest> aovs);
    reference::CameraSampleHook hook();
    // The AOVs once every pixel has had `spp` samples (fewer than options.spp when the
    // reference was interrupted).
    std::vector<ChannelImage> images(int spp) const;

private:
    reference::PathTracerOptions m_options;
    AovTracer m_tracer;
    AovFilm m_film;
};

}  // namespace mvpl::aov

#pragma once
// What the preview's sums estimate, set as `mvpl render` sets it for the same options: the
// renderer's options for a sum of a given size and the estimate (engine/integrator/estimate.h)
// its VPL history and CPU estimators take theirs from.
#include <cstdint>
#include <string>

#include "engine/integrator/estimate.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene.h"
#include "tools/preview/preview_app.h"

namespace mvpl::preview {

// clamp: the options' or 0 (C toggles clamping in the window).
render::RenderOptions preview_render_options(const PreviewOptions& options,
                                             const scene::Scene& scene, float clamp, uint32_t width,
                                             uint32_t height);

integrator::Estimate preview_estimate(const PreviewOptions& options,
                                      const render::RenderOptions& ro, const std::string& sampler);

}  // namespace mvpl::preview

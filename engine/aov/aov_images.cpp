#include "engine/aov/aov_images.h"

#include <algorithm>
#include <utility>

#include "engine/core/parallel.h"
#include "engine/light/chain_options.h"
#include "engine/light/specular_chain.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::aov {

uint64_t aov_positions(const integrator::Estimate& estimate, uint64_t vpls) {
    return std::min(render::subpixel_schedule(estimate.render).positions_after(vpls),
                    kMaxAovPositions);
}

std::vector<ChannelImage> render_aovs(const integrator::SceneView& view,
                                      const integrator::Estimate& estimate, uint64_t vpls,
                                      const std::vector<AovRequest>& aovs) {
    if (aovs.empty()) return {};
    const render::RenderOptions& ro = estimate.render;
    const int width = int(ro.width);
    const int height = int(ro.height);
    const SubpixelSchedule schedule = render::subpixel_schedule(ro);
    const uint64_t positions = aov_positions(estimate, vpls);
    const AovTracer tracer(*view.scene, *view.accel, *view.camera, width, height, ro.chains);
    AovFilm film(aovs, width, height);
    parallel_for(height, 1, [&](int64_t y0, int64_t y1) {
        for (int64_t y = y0; y < y1; ++y) {
            for (int x = 0; x < width; ++x) {
                const uint64_t pixel = uint64_t(y) * uint64_t(width) + uint64_t(x);
                for (uint64_t p = 0; p < positions; ++p) {
                    const Vec2 offset = schedule.position(p);
                    Rng chain = light::chain_rng(ro.chain_seed, pixel, p);
                    film.add(x, int(y),
                             tracer.sample(Vec2(float(x) + offset.x, float(y) + offset.y), chain));
                }
            }
        }
    });
    return film.images(positions);
}

light::ChainOptions reference_chains(int max_depth) {
    light::ChainOptions chains;
    chains.max_roughness = light::kDefaultChainRoughness;
    chains.max_depth = max_depth;
    return chains;
}

ReferenceAovs::ReferenceAovs(const scene::Scene& scene, const trace::Accel& accel,
                             const reference::PathTracerOptions& options,
                             std::vector<AovRequest> aovs)
    : m_options(options),
      m_tracer(scene, accel, scene.camera, options.width, options.height,
               reference_chains(options.max_depth)),
      m_film(std::move(aovs), options.width, options.height) {}

reference::CameraSampleHook ReferenceAovs::hook() {
    return [this](int x, int y, int sample, const Vec2& film) {
        if (uint64_t(sample) >= kMaxAovPositions) return;
        const uint64_t pixel = uint64_t(y) * uint64_t(m_options.width) + uint64_t(x);
        Rng chain = light::chain_rng(m_options.seed, pixel, uint64_t(sample));
        m_film.add(x, y, m_tracer.sample(film, chain));
    };
}

std::vector<ChannelImage> ReferenceAovs::images(int spp) const {
    return m_film.images(std::min<uint64_t>(uint64_t(std::max(spp, 0)), kMaxAovPositions));
}

}  // namespace mvpl::aov

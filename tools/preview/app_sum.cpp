// PreviewApp's running sum: the estimate each restart begins over the kept VPLs, and the frame's
// shading within its budget.
#include <algorithm>
#include <memory>

#include "engine/sampler/sampler_factory.h"
#include "tools/preview/app.h"
#include "tools/preview/preview_estimate.h"

namespace mvpl::preview {
namespace {

// Time-budget mode draws at most this many units ahead of what it measured would fit, and never
// more than this in one accumulate(): a wrong estimate costs one frame, not seconds.
constexpr uint64_t kMaxUnitsPerCall = 64;

}  // namespace

render::RenderOptions PreviewApp::render_options(uint32_t width, uint32_t height) const {
    return preview_render_options(m_options, m_session->scene(), clamp(), width, height);
}

integrator::Estimate PreviewApp::estimate(const render::RenderOptions& ro,
                                          const std::string& sampler) const {
    return preview_estimate(m_options, ro, sampler);
}

integrator::SceneView PreviewApp::view() const {
    return {&m_session->scene(), &m_session->accel(), &m_session->lights(), &m_controller.camera()};
}

std::unique_ptr<VplHistory> PreviewApp::make_history(const std::string& sampler,
                                                     const render::RenderOptions& ro) const {
    const integrator::Estimate e = estimate(ro, sampler);
    sampler::SamplerSettings s = integrator::sampler_settings(e);
    // Where the caustic tracer runs at rest, the light tracer leaves no VPL on the chains' class
    // (whose light it carries), moving or not: the same VPLs as `mvpl render`.
    if (integrator::caustics_needed(view(), e)) s.tracer.specular = ro.chains;
    return std::make_unique<VplHistory>(
        sampler::make_vpl_stream(sampler, m_session->scene(), m_session->accel(),
                                 m_session->lights(), m_controller.camera(), s),
        m_options.max_paths);
}

void PreviewApp::restart(uint32_t width, uint32_t height, uint32_t divisor, bool moving) {
    m_present.set_cpu_image(Image());  // its pixels were the old view's (or size's)
    m_window_width = width;
    m_window_height = height;
    m_render_width = std::max(width / divisor, 1u);
    m_render_height = std::max(height / divisor, 1u);
    const render::RenderOptions ro = render_options(m_render_width, m_render_height);
    if (!m_mc_history) m_mc_history = make_history("mc", ro);
    const bool chain = m_sampler != "mc";
    if (moving) m_chain.reset();  // its target was what the old view saw
    if (chain && !moving && !m_chain) m_chain = make_history(m_sampler, ro);
    m_history = chain && !moving ? m_chain.get() : m_mc_history.get();
    m_motion_sum = moving;
    integrator::Estimate e = estimate(ro, m_sampler);
    e.compensate = e.compensate && !moving;
    e.caustics = e.caustics && !moving;
    auto replay = std::make_unique<HistoryReplay>(*m_history);
    m_replay = replay.get();
    m_integrator->begin(view(), e, integrator::Pacing::OpenEnded, std::move(replay));
    m_cpu_on = !moving;
    m_scale = 0.0;
    m_moved = false;
    m_hud_dirty = true;
}

void PreviewApp::catch_up() {
    const Timer timer;
    const uint64_t target = std::min(m_catch_up, m_replay->vpls_recorded());
    m_catch_up = 0;
    while (m_replay->vpls_total() < target && timer.seconds() < m_options.catch_up_seconds) {
        // As many units as the rest of the time holds at the frames' measured rate (which drew
        // their maps: an upper bound on the kept VPLs' cost), so that the last call ends near it.
        const double left_ms = 1e3 * (m_options.catch_up_seconds - timer.seconds());
        const uint64_t units =
            m_ms_per_unit > 0.0
                ? uint64_t(std::clamp(left_ms / m_ms_per_unit, 1.0, double(kMaxUnitsPerCall)))
                : 1;
        const uint64_t vpls = m_integrator->stats().vpls;
        m_integrator->advance(units);
        m_scale = m_replay->scale();
        m_stats.add_vpls(size_t(m_integrator->stats().vpls - vpls));
    }
}

uint64_t PreviewApp::pool_units() const {
    const manylights::RowColumnOptions& rc = m_options.many_lights;
    if (!rc.enabled() || m_motion_sum) return 0;
    // A unit leaves at least one VPL (a light path its emitter VPL), until measured.
    const uint64_t work = m_replay->work_done();
    const double per_unit = work > 0 ? double(m_replay->vpls_total()) / double(work) : 1.0;
    return std::max<uint64_t>(1, uint64_t(double(rc.pool) / std::max(per_unit, 1.0)));
}

void PreviewApp::render_work() {
    if (m_catch_up > 0) catch_up();
    const Timer timer;
    const bool fixed = m_options.paths_per_frame > 0;
    for (bool first = true;; first = false) {
        uint64_t units = m_options.paths_per_frame;
        if (!fixed) {
            // As many units as the rest of the budget holds at the measured rate (one at first).
            const double left = m_options.budget_ms - 1e3 * timer.seconds();
            if (!first && (m_ms_per_unit <= 0.0 || left < m_ms_per_unit)) break;
            units = m_ms_per_unit > 0.0 ? uint64_t(std::max(left / m_ms_per_unit, 1.0)) : 1;
            units = std::min(units, kMaxUnitsPerCall);
        }
        units = std::max(units, pool_units());
        // Whole segments: replayed ones first (after a move), then new ones from the stream.
        const uint64_t vpls = m_integrator->stats().vpls, work = m_replay->work_done();
        const Timer shading;
        m_integrator->advance(units);
        const uint64_t drawn = m_replay->work_done() - work;
        if (drawn == 0) break;  // converged: nothing left to draw
        const double ms = 1e3 * shading.seconds();
        const double per_unit = ms / double(drawn);
        m_ms_per_unit = m_ms_per_unit > 0.0 ? 0.7 * m_ms_per_unit + 0.3 * per_unit : per_unit;
        m_scale = m_replay->scale();
        m_stats.add_vpls(size_t(m_integrator->stats().vpls - vpls));
        if (fixed) break;
    }
}

void PreviewApp::update_cpu_image(bool force) {
    if (!m_cpu_on || (!force && m_cpu_timer.seconds() < kHudInterval)) return;
    m_cpu_timer.reset();
    m_present.set_cpu_image(m_integrator->cpu_image());
}

}  // namespace mvpl::preview

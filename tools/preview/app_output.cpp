// PreviewApp's output besides the picture: the HUD's text and the images it writes.
#include <cstdio>

#include "engine/core/file_extension.h"
#include "engine/core/image.h"
#include "engine/core/png.h"
#include "engine/integrator/cpu_estimators.h"
#include "engine/light/specular_chain.h"
#include "tools/preview/app.h"

namespace mvpl::preview {
namespace {

void write_rgba_png(const std::string& path, const std::vector<uint8_t>& rgba, uint32_t width,
                    uint32_t height) {
    std::vector<uint8_t> rgb(size_t(width) * height * 3);
    for (size_t i = 0; i < size_t(width) * height; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + size_t(c)] = rgba[4 * i + size_t(c)];
    write_png_rgb8(path, rgb, int(width), int(height));
}

}  // namespace

EstimatorParts PreviewApp::estimator_parts() const {
    const render::RenderOptions ro = render_options(m_render_width, m_render_height);
    const integrator::Estimate e = estimate(ro, m_sampler);
    EstimatorParts p;
    p.clamp = ro.clamp;
    p.compensation = e.compensate && ro.clamp > 0.0f;
    p.caustics = integrator::caustics_needed(view(), e);
    p.chains = light::scene_may_chain(m_session->scene(), ro.chains);
    p.vsl_radius = ro.vsl_radius;
    p.moving = !m_cpu_on;
    p.pool = e.many_lights.pool;
    p.clusters = e.many_lights.clusters_per_pool();
    return p;
}

void PreviewApp::update_hud(bool force) {
    if (!m_options.hud) return;
    if (!force && !m_hud_dirty && m_hud_timer.seconds() < kHudInterval) return;
    m_hud_timer.reset();
    m_hud_dirty = false;
    if (force) m_parts = estimator_parts();  // a new sum
    HudState h;
    h.chain = m_history != m_mc_history.get();
    h.sampler = m_sampler == "mc" || h.chain ? m_sampler : m_sampler + " (mc while moving)";
    if (m_view != "image") h.sampler += "  view " + m_view;
    h.width = m_render_width;
    h.height = m_render_height;
    h.vpls = m_replay->vpls_total();
    h.work = m_history->work_done();
    h.seconds = m_since_restart.seconds();
    h.exposure = m_exposure;
    h.statistics = m_history->statistics();
    h.converged = m_replay->converged();
    h.parts = m_parts;
    std::vector<std::string> lines = m_stats.hud_lines(h);
    if (!m_message.empty()) lines.push_back(m_message);  // a dropped file that was not read
    m_present.set_hud(m_font.render(lines, 8, 8, m_render_width > 16 ? m_render_width - 16 : 0));
}

void PreviewApp::save(const std::string& path, bool png_from_display) {
    if (lower_extension(path) == ".exr") {
        // scale · Σ + emission + the CPU estimators' image: what the window shows at rest; or
        // the view's (an AOV's values, the picture with the VPLs).
        write_exr(m_view != "image" ? m_view_image : m_integrator->image(), path);
    } else if (png_from_display) {
        uint32_t w = 0, h = 0;
        const std::vector<uint8_t> rgba = m_present.captured(w, h);
        write_rgba_png(path, rgba, w, h);
    } else {
        write_png(m_integrator->image(), path, m_exposure);
    }
    if (!m_options.quiet) std::printf("preview: wrote %s\n", path.c_str());
}

void PreviewApp::print_kept_maps() const {
    const render::KeptMapStats kept = m_integrator->renderer()->kept_maps();
    if (kept.capacity == 0) return;
    std::printf(
        "preview: kept shadow maps: %u of at most %u (%.0f MiB budget); %llu copied back "
        "instead of drawn; beyond the budget, maps of VPLs not shaded since the last "
        "restart are evicted first\n",
        kept.maps, kept.capacity, double(kept.budget_bytes) / (1 << 20),
        (unsigned long long)kept.restored);
}

}  // namespace mvpl::preview

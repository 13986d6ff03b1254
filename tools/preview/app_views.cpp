// PreviewApp's views (V, or the script's `view NAME`): the picture, one of the AOVs `render --aov`
// writes (engine/aov/aov_images.h) over the current sum's sub-pixel positions, traced on the CPU,
// or the picture with the sum's VPLs drawn over it as `mvpl vpls --view camera` draws them.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "engine/aov/aov_images.h"
#include "engine/scene/camera.h"
#include "tools/preview/app.h"
#include "tools/preview/frame_variance.h"
#include "tools/preview/views.h"
#include "tools/session/vpl_dots.h"

namespace mvpl::preview {
namespace {

// The AOVs are traced on the window's thread, about 0.14 s per sub-pixel position at 512² on two
// cores (aov_images.h): a view follows the sum's first four positions, not all of them.
constexpr uint64_t kViewPositions = 4;

// What the window shows of an AOV: albedo as it is, a normal n as n/2 + 1/2, a depth over the
// largest in the picture (black: nothing hit).
Image display(const ChannelImage& aov, const std::string& view) {
    Image image(aov.width, aov.height);
    const size_t c = aov.channels.size();
    float far = 0.0f;
    if (view == "depth")
        for (float v : aov.values)
            if (std::isfinite(v)) far = std::max(far, v);
    for (size_t i = 0; i < image.pixels().size(); ++i) {
        Rgb& p = image.pixels()[i];
        for (int k = 0; k < 3; ++k) {
            const float v = aov.values[i * c + std::min(size_t(k), c - 1)];
            if (view == "normal")
                p[k] = 0.5f * v + 0.5f;
            else if (view == "depth")
                p[k] = std::isfinite(v) && far > 0.0f ? v / far : 0.0f;
            else
                p[k] = v;
        }
    }
    return image;
}

}  // namespace

bool PreviewApp::set_view(const std::string& name) {
    if (!is_view_name(name)) return false;
    m_view = name;
    m_variance.reset();
    m_view_positions = 0;  // traced at the next frame
    m_hud_dirty = true;
    if (m_view == "image") m_present.set_cpu_image(Image());  // the estimators' again
    return true;
}

void PreviewApp::next_view() {
    const auto at = std::find(kViewNames.begin(), kViewNames.end(), m_view);
    set_view(at + 1 == kViewNames.end() ? kViewNames[0] : *(at + 1));
}

void PreviewApp::update_error_view(bool restarted) {
    // Read back every frame: each read after the first adds an increment to the variance.
    if (restarted) m_variance.reset();
    m_variance.add(m_integrator->image(), m_integrator->stats().units);
    m_view_image = m_variance.relative_error();
    m_present.set_cpu_image(heat_map(m_view_image));
}

void PreviewApp::update_view(bool restarted, bool last) {
    if (m_view == "error") {
        update_error_view(restarted);
        return;
    }
    restarted = restarted || last;  // the others are brought up to date for the screenshot
    if (m_view == "vpls") {
        // The picture is read back from the GPU: at the HUD's pace.
        if (!restarted && m_cpu_timer.seconds() < kHudInterval) return;
        m_cpu_timer.reset();
        m_view_image = m_integrator->image();
        const std::vector<light::Vpl>& all = m_history->vpls();
        const std::vector<light::Vpl> shaded(all.begin(),
                                             all.begin() + long(m_replay->vpls_total()));
        const scene::Camera& camera = m_controller.camera();
        const int w = m_view_image.width(), h = m_view_image.height();
        session::draw_vpls(
            m_view_image,
            [&](const Vec3& p, Vec2& film) {
                const std::optional<scene::FilmPoint> f = scene::project_to_film(camera, w, h, p);
                if (f) film = f->film;
                return f.has_value();
            },
            shaded);
        m_present.set_cpu_image(m_view_image);
        return;
    }
    const render::RenderOptions ro = render_options(m_render_width, m_render_height);
    const integrator::Estimate e = estimate(ro, m_sampler);
    // The VPLs shaded name the positions, up to the first of position kViewPositions; traced
    // again only when they grew.
    const uint64_t vpls = std::min<uint64_t>(
        m_integrator->stats().vpls, render::subpixel_schedule(ro).first_of(kViewPositions));
    const uint64_t positions = aov::aov_positions(e, vpls);
    if (!restarted && positions == m_view_positions) return;
    m_view_positions = positions;
    const std::vector<ChannelImage> aovs =
        aov::render_aovs(view(), e, vpls, aov::parse_aov_list(m_view, "view"));
    const ChannelImage& aov = aovs.at(0);
    m_view_image = Image(aov.width, aov.height);  // the values (a depth in all three channels)
    const size_t c = aov.channels.size();
    for (size_t i = 0; i < m_view_image.pixels().size(); ++i)
        for (int k = 0; k < 3; ++k)
            m_view_image.pixels()[i][k] = aov.values[i * c + std::min(size_t(k), c - 1)];
    m_present.set_cpu_image(display(aov, m_view));
}

}  // namespace mvpl::preview

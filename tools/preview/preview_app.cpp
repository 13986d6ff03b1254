#include "tools/preview/preview_app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/light/chain_options.h"
#include "tools/preview/app.h"
#include "tools/preview/screenshot_name.h"

namespace mvpl::preview {
namespace {

// Frame time to stay under while the camera moves (10 fps, the interactive target), and the
// coarsest motion resolution (1/4 per axis) used to get there.
constexpr double kMovingFrameSeconds = 0.09;
constexpr uint32_t kMaxMotionDivisor = 4;

}  // namespace

PreviewApp::PreviewApp(const PreviewOptions& options)
    : m_options(options),
      m_environment(options.environment),
      m_session(std::make_unique<session::SceneSession>(options.scene_path, options.camera,
                                                        options.environment, options.load)),
      m_sampler(options.sampler),
      m_script(options.script.empty() ? std::vector<ScriptEvent>{} : load_script(options.script)),
      m_window("mvpl preview: " + std::filesystem::path(options.scene_path).filename().string(),
               options.width, options.height),
      m_context(context_options()),
      m_integrator(make_integrator()),
      m_swapchain(m_context, m_window.create_surface(m_context.instance()), uint32_t(options.width),
                  uint32_t(options.height)),
      m_present(m_context, m_swapchain.srgb()),
      m_controller(m_session->camera(), m_session->scene().bounds()),
      m_exposure(options.exposure),
      m_motion_divisor(options.motion_scaling ? 2 : 1),
      m_chain_roughness(options.levers.chains.max_roughness >= 0.0f
                            ? options.levers.chains.max_roughness
                            : light::kDefaultChainRoughness) {}

std::unique_ptr<integrator::VplIntegrator> PreviewApp::make_integrator() {
    return std::make_unique<integrator::VplIntegrator>(m_session->view(), &m_context,
                                                       std::max(m_options.devices, 1u), nullptr);
}

gpu::ContextOptions PreviewApp::context_options() {
    gpu::ContextOptions co;
    co.instance_extensions = Window::required_instance_extensions();
    co.can_present = &Window::can_present;
    return co;
}

int PreviewApp::run(const Timer& start) {
    if (m_options.frames == 0) toggle_panel();  // interactive: the panel shown from the start
    m_frame_timer.reset();
    for (uint64_t index = 0; m_options.frames == 0 || index < m_options.frames; ++index)
        if (!frame(index, start)) break;
    for (const std::string& message : m_context.validation_messages())
        std::fprintf(stderr, "mvpl: validation: %s\n", message.c_str());
    if (!m_options.quiet) {
        std::printf("%s\n", m_stats.summary().c_str());
        const std::string recovery = m_recovery.summary();
        if (!recovery.empty()) std::printf("preview: %s\n", recovery.c_str());
        print_kept_maps();
    }
    return 0;
}

bool PreviewApp::frame(uint64_t index, const Timer& start) {
    const double dt = m_frame_timer.seconds();
    m_frame_timer.reset();
    m_window.poll();
    apply(m_window.take_input(), dt);
    apply_script(index);
    if (m_panel)
        for (const ScriptEvent& e : m_panel->build(panel_values()))
            apply_event(e);
    if (m_quit || m_window.close_requested()) return false;
    uint32_t width = 0, height = 0;
    m_window.framebuffer_size(width, height);
    if (width == 0 || height == 0) {  // minimised: nothing to render or present
        m_window.wait(0.05);
        return true;
    }
    // A camera move or resize restarts the sum at the motion resolution; the first frame at
    // rest restarts it at full resolution.
    const bool moving = m_moved || width != m_window_width || height != m_window_height;
    const bool refine = !moving && m_motion_sum;
    const Timer phase;
    if (moving || refine) {
        restart(width, height, moving ? m_motion_divisor : 1, moving);
        m_since_restart.reset();
    }
    if (refine && m_options.catch_up_seconds > 0.0)
        m_catch_up = uint64_t(std::ceil(MoveRecovery::kRecoveredShare * double(m_resting_vpls)));
    const double restarted = phase.seconds();
    render_work();
    const double shaded = phase.seconds();
    update_hud(moving || refine);
    const bool last = m_options.frames > 0 && index + 1 == m_options.frames;
    if (m_view != "image") {
        update_view(moving || refine, last);
    } else if (last && !m_options.screenshot.empty() && m_cpu_on) {
        // The passes `mvpl render` runs for the VPLs shaded, all of them: its image.
        m_present.set_cpu_image(m_integrator->finish_cpu(integrator::Pacing::Fixed));
    } else {
        update_cpu_image(moving || refine);
    }
    present(width, height, moving, index == 0, last, phase, restarted, shaded - restarted, start);
    // A converged picture and no input: sleep instead of spinning.
    if (m_options.frames == 0 && m_replay->converged()) m_window.wait(0.05);
    return true;
}

void PreviewApp::present(uint32_t width, uint32_t height, bool moving, bool first, bool last,
                         const Timer& phase, double restart, double shading, const Timer& start) {
    const bool shot = last && !m_options.screenshot.empty();
    const bool capture = m_screenshot_key || shot;
    PresentParams params;
    params.scale = m_scale;
    params.exposure = m_exposure;
    params.hud = m_options.hud;
    params.cpu_image_only = m_view != "image";
    gpu::SwapchainFrame sc;
    if (!m_swapchain.begin_frame(width, height, sc)) {
        if (shot) save(m_options.screenshot, false);  // no image to present to: resolve instead
        return;
    }
    // Summed over the renderer's devices (device 0's own images on one).
    const render::VplRenderer::Presented sum = m_integrator->renderer()->presented();
    m_present.record(sc, *sum.accumulation, *sum.emission, params, capture);
    if (m_panel) m_panel->record(sc);  // after the capture: screenshots are the picture alone
    m_swapchain.end_frame();
    const double seconds = m_frame_timer.seconds();
    m_recovery.frame(moving, m_replay->vpls_total(), start.seconds() - seconds, start.seconds());
    if (!moving && !m_motion_sum) m_resting_vpls = m_replay->vpls_total();
    // The first frame is the first image (reported on its own), not a camera move.
    const bool moved = moving && !first;
    m_stats.frame_presented(seconds, start.seconds(), moved);
    if (moved) m_stats.moving_phases(restart, shading, phase.seconds() - restart - shading);
    if (moved && m_options.motion_scaling) {
        if (seconds > kMovingFrameSeconds && m_motion_divisor < kMaxMotionDivisor)
            ++m_motion_divisor;
        else if (seconds < 0.4 * kMovingFrameSeconds && m_motion_divisor > 1)
            --m_motion_divisor;
    }
    if (m_screenshot_key) {
        m_screenshot_key = false;
        const std::string stem = std::filesystem::path(m_session->path()).stem().string();
        const std::string base = next_screenshot({}, stem, &m_screenshots).string();
        save(base + ".png", true);
        save(base + ".exr", true);
    }
    if (shot) save(m_options.screenshot, true);
}

int run_preview(const PreviewOptions& options) {
    const Timer start;
    PreviewApp app(options);
    return app.run(start);
}

}  // namespace mvpl::preview

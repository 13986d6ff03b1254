#include "tools/preview/preview_app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "engine/core/image.h"
#include "engine/core/png.h"
#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/gpu/swapchain.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/vpl_integrator.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/sampler_factory.h"
#include "tools/preview/camera_controller.h"
#include "tools/preview/hud.h"
#include "tools/preview/move_recovery.h"
#include "tools/preview/present_pass.h"
#include "tools/preview/preview_estimate.h"
#include "tools/preview/preview_stats.h"
#include "tools/preview/script.h"
#include "tools/preview/vpl_history.h"
#include "tools/preview/window.h"
#include "tools/session/scene_session.h"

namespace mvpl::preview {
namespace {

// Interaction speeds: degrees per dragged pixel, scroll step as a distance factor, scene
// diagonals per second of a held fly key.
constexpr float kDegreesPerPixel = 0.3f;
constexpr float kWheelFactor = 0.9f;
constexpr float kFlySpeed = 0.5f;
constexpr float kExposureStep = 0.5f;
constexpr double kHudInterval = 0.25;  // seconds between HUD redraws
// Frame time to stay under while the camera moves (10 fps, the interactive target), and the
// coarsest motion resolution (1/4 per axis) used to get there.
constexpr double kMovingFrameSeconds = 0.09;
constexpr uint32_t kMaxMotionDivisor = 4;
// Time-budget mode draws at most this many units ahead of what it measured would fit, and never
// more than this in one accumulate(): a wrong estimate costs one frame, not seconds.
constexpr uint64_t kMaxUnitsPerCall = 64;

void write_rgba_png(const std::string& path, const std::vector<uint8_t>& rgba, uint32_t width,
                    uint32_t height) {
    std::vector<uint8_t> rgb(size_t(width) * height * 3);
    for (size_t i = 0; i < size_t(width) * height; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + size_t(c)] = rgba[4 * i + size_t(c)];
    write_png_rgb8(path, rgb, int(width), int(height));
}

class PreviewApp {
public:
    explicit PreviewApp(const PreviewOptions& options)
        : m_options(options),
          m_session(options.scene_path, options.camera, options.environment, options.load),
          m_sampler(options.sampler),
          m_script(options.script.empty() ? std::vector<ScriptEvent>{}
                                          : load_script(options.script)),
          m_window("mvpl preview: " + std::filesystem::path(options.scene_path).filename().string(),
                   options.width, options.height),
          m_context(context_options()),
          m_integrator(m_session.view(), &m_context, 1, nullptr),
          m_swapchain(m_context, m_window.create_surface(m_context.instance()),
                      uint32_t(options.width), uint32_t(options.height)),
          m_present(m_context, m_swapchain.srgb()),
          m_controller(m_session.camera(), m_session.scene().bounds()),
          m_exposure(options.exposure),
          m_motion_divisor(options.motion_scaling ? 2 : 1) {}

    int run(const Timer& start);

private:
    static gpu::ContextOptions context_options() {
        gpu::ContextOptions co;
        co.instance_extensions = Window::required_instance_extensions();
        co.can_present = &Window::can_present;
        return co;
    }
    float clamp() const { return m_clamping ? m_options.clamp : 0.0f; }
    render::RenderOptions render_options(uint32_t width, uint32_t height) const;
    integrator::Estimate estimate(const render::RenderOptions& ro,
                                  const std::string& sampler) const;
    integrator::SceneView view() const;
    std::unique_ptr<VplHistory> make_history(const std::string& sampler,
                                             const render::RenderOptions& ro) const;
    void apply(const Input& input, double dt);
    void apply_key(const std::string& key);
    void apply_script(uint64_t frame);
    // Starts a new sum for the window's framebuffer, at 1/divisor of its size.
    void restart(uint32_t width, uint32_t height, uint32_t divisor, bool moving);
    void render_work();
    // The first frame at rest after a move: the recorded VPLs up to m_catch_up.
    void catch_up();
    void update_cpu_image(bool force);
    void update_hud(bool force);
    void save(const std::string& path, bool png_from_display);
    void print_kept_maps() const;
    // After a moving frame of `frame_seconds`: a coarser or finer motion resolution.
    void adapt_motion_divisor(double frame_seconds);

    PreviewOptions m_options;
    session::SceneSession m_session;
    std::string m_sampler;
    std::vector<ScriptEvent> m_script;
    size_t m_next_event = 0;
    Window m_window;
    gpu::Context m_context;
    // The estimate `mvpl render` makes, begun anew at each restart over the VPLs of m_history.
    integrator::VplIntegrator m_integrator;
    gpu::Swapchain m_swapchain;
    PresentPass m_present;
    HudFont m_font;
    CameraController m_controller;
    // Monte Carlo VPLs, kept for the whole run (they do not depend on the view), and the chain
    // of a view-dependent sampler (Metropolis), started when the camera comes to rest: while it
    // moves the Monte Carlo VPLs give an immediate picture instead of a bootstrap per frame.
    std::unique_ptr<VplHistory> m_mc_history;
    std::unique_ptr<VplHistory> m_chain;
    VplHistory* m_history = nullptr;    // the one the current sum draws from
    HistoryReplay* m_replay = nullptr;  // its replay in the current estimate (the integrator's)
    // The compensation and caustics run for the picture at rest (not while the camera moves),
    // their image uploaded to the present pass every kHudInterval.
    bool m_cpu_on = false;
    Timer m_cpu_timer;

    float m_exposure;
    bool m_clamping = true;
    bool m_quit = false;
    bool m_moved = true;  // restart the sum before the next frame
    // The current sum was started while the camera moved: coarse, or Monte Carlo, and without
    // the CPU estimators; the first frame at rest starts the resting sum.
    bool m_motion_sum = false;
    bool m_screenshot_key = false;
    uint32_t m_render_width = 0, m_render_height = 0;  // the current sum's
    uint32_t m_window_width = 0, m_window_height = 0;  // framebuffer the sum was started for
    // While the camera moves the sum is rendered at 1/m_motion_divisor of the window's size per
    // axis (nearest-neighbour upscaled by the present pass), adapted to keep moving frames within
    // kMovingFrameSeconds; at rest the next frame restarts at full size.
    uint32_t m_motion_divisor;
    double m_scale = 0.0;        // of the current sum
    double m_ms_per_unit = 0.0;  // measured shading time per sampler unit (EMA)
    uint32_t m_screenshots = 0;
    PreviewStats m_stats;
    MoveRecovery m_recovery;
    uint64_t m_resting_vpls = 0;  // in the sum of the last frame at rest
    uint64_t m_catch_up = 0;      // VPLs the next frame shades before presenting
    Timer m_hud_timer;
    bool m_hud_dirty = true;
};

render::RenderOptions PreviewApp::render_options(uint32_t width, uint32_t height) const {
    return preview_render_options(m_options, m_session.scene(), clamp(), width, height);
}

integrator::Estimate PreviewApp::estimate(const render::RenderOptions& ro,
                                          const std::string& sampler) const {
    return preview_estimate(m_options, ro, sampler);
}

integrator::SceneView PreviewApp::view() const {
    return {&m_session.scene(), &m_session.accel(), &m_session.lights(), &m_controller.camera()};
}

std::unique_ptr<VplHistory> PreviewApp::make_history(const std::string& sampler,
                                                     const render::RenderOptions& ro) const {
    const integrator::Estimate e = estimate(ro, sampler);
    sampler::SamplerSettings s = integrator::sampler_settings(e);
    // Where the caustic tracer runs at rest, the light tracer leaves no VPL on the chains' class
    // (whose light it carries), moving or not: the same VPLs as `mvpl render`.
    if (integrator::caustics_needed(view(), e)) s.tracer.specular = ro.chains;
    return std::make_unique<VplHistory>(
        sampler::make_vpl_stream(sampler, m_session.scene(), m_session.accel(), m_session.lights(),
                                 m_controller.camera(), s),
        m_options.max_paths);
}

void PreviewApp::apply_key(const std::string& key) {
    if (key == "r") {
        m_controller.reset();
        m_moved = true;
    } else if (key == "plus" || key == "minus") {
        m_exposure += key == "plus" ? kExposureStep : -kExposureStep;
        m_hud_dirty = true;
    } else if (key == "m") {
        m_sampler = m_sampler == "mc" ? "metropolis" : "mc";
        m_moved = true;
    } else if (key == "c") {
        m_clamping = !m_clamping;
        m_moved = true;  // a chain's target depends on it too: it starts again at rest
    } else if (key == "p") {
        m_screenshot_key = true;
    } else if (key == "escape") {
        m_quit = true;
    }
}

void PreviewApp::apply(const Input& in, double dt) {
    if (in.orbit_x != 0.0f || in.orbit_y != 0.0f) {
        m_controller.orbit(-in.orbit_x * kDegreesPerPixel, in.orbit_y * kDegreesPerPixel);
        m_moved = true;
    }
    if (in.pan_x != 0.0f || in.pan_y != 0.0f) {
        const float h = float(std::max<uint32_t>(m_window_height, 1));
        m_controller.pan(-in.pan_x / h, in.pan_y / h);
        m_moved = true;
    }
    if (in.look_x != 0.0f || in.look_y != 0.0f) {
        m_controller.look(-in.look_x * kDegreesPerPixel, in.look_y * kDegreesPerPixel);
        m_moved = true;
    }
    if (in.wheel != 0.0f) {
        m_controller.zoom(std::pow(kWheelFactor, in.wheel));
        m_moved = true;
    }
    if (in.fly_forward || in.fly_right || in.fly_up) {
        const float step = kFlySpeed * float(std::min(dt, 0.1));
        m_controller.fly(float(in.fly_forward) * step, float(in.fly_right) * step,
                         float(in.fly_up) * step);
        m_moved = true;
    }
    for (const std::string& key : in.keys)
        apply_key(key);
}

void PreviewApp::apply_script(uint64_t frame) {
    for (; m_next_event < m_script.size() && m_script[m_next_event].frame <= frame;
         ++m_next_event) {
        const ScriptEvent& e = m_script[m_next_event];
        const std::vector<float>& v = e.values;
        if (e.action == "key") {
            apply_key(e.key);
            continue;
        }
        if (e.action == "resize") {
            m_window.set_size(int(v[0]), int(v[1]));
            continue;
        }
        if (e.action == "orbit") m_controller.orbit(v[0], v[1]);
        if (e.action == "pan") m_controller.pan(v[0], v[1]);
        if (e.action == "zoom") m_controller.zoom(v[0]);
        if (e.action == "fly") m_controller.fly(v[0], v[1], v[2]);
        if (e.action == "look") m_controller.look(v[0], v[1]);
        m_moved = true;
    }
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
    m_integrator.begin(view(), e, integrator::Pacing::OpenEnded, std::move(replay));
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
        const uint64_t vpls = m_integrator.stats().vpls;
        m_integrator.advance(units);
        m_scale = m_replay->scale();
        m_stats.add_vpls(size_t(m_integrator.stats().vpls - vpls));
    }
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
        // Whole segments: replayed ones first (after a move), then new ones from the stream.
        const uint64_t vpls = m_integrator.stats().vpls, work = m_replay->work_done();
        const Timer shading;
        m_integrator.advance(units);
        const uint64_t drawn = m_replay->work_done() - work;
        if (drawn == 0) break;  // converged: nothing left to draw
        const double ms = 1e3 * shading.seconds();
        const double per_unit = ms / double(drawn);
        m_ms_per_unit = m_ms_per_unit > 0.0 ? 0.7 * m_ms_per_unit + 0.3 * per_unit : per_unit;
        m_scale = m_replay->scale();
        m_stats.add_vpls(size_t(m_integrator.stats().vpls - vpls));
        if (fixed) break;
    }
}

void PreviewApp::update_cpu_image(bool force) {
    if (!m_cpu_on || (!force && m_cpu_timer.seconds() < kHudInterval)) return;
    m_cpu_timer.reset();
    m_present.set_cpu_image(m_integrator.cpu_image());
}

void PreviewApp::update_hud(bool force) {
    if (!m_options.hud) return;
    if (!force && !m_hud_dirty && m_hud_timer.seconds() < kHudInterval) return;
    m_hud_timer.reset();
    m_hud_dirty = false;
    const bool chain = m_history != m_mc_history.get();
    const std::string name =
        m_sampler == "mc" || chain ? m_sampler : m_sampler + " (mc while moving)";
    std::vector<std::string> lines =
        m_stats.hud_lines(name, chain, m_render_width, m_render_height, m_replay->vpls_total(),
                          m_history->work_done(), clamp(), m_exposure, m_history->statistics(),
                          m_replay->converged());
    m_present.set_hud(m_font.render(lines, 8, 8, m_render_width > 16 ? m_render_width - 16 : 0));
}

void PreviewApp::save(const std::string& path, bool png_from_display) {
    if (lower_extension(path) == ".exr") {
        // scale · Σ + emission + the CPU estimators' image: what the window shows at rest.
        write_exr(m_integrator.image(), path);
    } else if (png_from_display) {
        uint32_t w = 0, h = 0;
        const std::vector<uint8_t> rgba = m_present.captured(w, h);
        write_rgba_png(path, rgba, w, h);
    } else {
        write_png(m_integrator.image(), path, m_exposure);
    }
    if (!m_options.quiet) std::printf("preview: wrote %s\n", path.c_str());
}

void PreviewApp::adapt_motion_divisor(double frame_seconds) {
    if (frame_seconds > kMovingFrameSeconds && m_motion_divisor < kMaxMotionDivisor)
        ++m_motion_divisor;
    else if (frame_seconds < 0.4 * kMovingFrameSeconds && m_motion_divisor > 1)
        --m_motion_divisor;
}

void PreviewApp::print_kept_maps() const {
    const render::KeptMapStats kept = m_integrator.renderer()->kept_maps();
    if (kept.capacity == 0) return;
    std::printf(
        "preview: kept shadow maps: %u of at most %u (%.0f MiB budget); %llu copied back "
        "instead of drawn; beyond the budget, maps of VPLs not shaded since the last "
        "restart are evicted first\n",
        kept.maps, kept.capacity, double(m_options.kept_shadow_bytes) / (1 << 20),
        (unsigned long long)kept.restored);
}

int PreviewApp::run(const Timer& start) {
    Timer frame_timer;
    for (uint64_t frame = 0; m_options.frames == 0 || frame < m_options.frames; ++frame) {
        const double dt = frame_timer.seconds();
        frame_timer.reset();
        m_window.poll();
        apply(m_window.take_input(), dt);
        apply_script(frame);
        if (m_quit || m_window.close_requested()) break;
        uint32_t width = 0, height = 0;
        m_window.framebuffer_size(width, height);
        if (width == 0 || height == 0) {  // minimised: nothing to render or present
            m_window.wait(0.05);
            continue;
        }
        // A camera move or resize restarts the sum at the motion resolution; the first frame at
        // rest restarts it at full resolution.
        const bool moving = m_moved || width != m_window_width || height != m_window_height;
        const bool refine = !moving && m_motion_sum;
        const Timer phase;
        if (moving || refine) restart(width, height, moving ? m_motion_divisor : 1, moving);
        if (refine && m_options.catch_up_seconds > 0.0)
            m_catch_up =
                uint64_t(std::ceil(MoveRecovery::kRecoveredShare * double(m_resting_vpls)));
        const double restarted = phase.seconds();
        render_work();
        const double shaded = phase.seconds();
        update_hud(moving || refine);
        const bool last = m_options.frames > 0 && frame + 1 == m_options.frames;
        if (last && !m_options.screenshot.empty() && m_cpu_on) {
            // The passes `mvpl render` runs for the VPLs shaded, all of them: its image.
            m_present.set_cpu_image(m_integrator.finish_cpu(integrator::Pacing::Fixed));
        } else {
            update_cpu_image(moving || refine);
        }

        const bool capture = m_screenshot_key || (last && !m_options.screenshot.empty());
        PresentParams params;
        params.scale = m_scale;
        params.exposure = m_exposure;
        params.hud = m_options.hud;
        gpu::SwapchainFrame sc;
        if (m_swapchain.begin_frame(width, height, sc)) {
            const render::VplRenderer& renderer = *m_integrator.renderer();
            m_present.record(sc, renderer.accumulation(), renderer.emission(), params, capture);
            m_swapchain.end_frame();
            const double seconds = frame_timer.seconds();
            m_recovery.frame(moving, m_replay->vpls_total(), start.seconds() - seconds,
                             start.seconds());
            if (!moving && !m_motion_sum) m_resting_vpls = m_replay->vpls_total();
            // The first frame is the first image (reported on its own), not a camera move.
            const bool moved = moving && frame > 0;
            m_stats.frame_presented(seconds, start.seconds(), moved);
            if (moved)
                m_stats.moving_phases(restarted, shaded - restarted, phase.seconds() - shaded);
            if (moved && m_options.motion_scaling) adapt_motion_divisor(seconds);
            if (m_screenshot_key) {
                m_screenshot_key = false;
                const std::string base = "mvpl-preview-" + std::to_string(m_screenshots++);
                save(base + ".png", true);
                save(base + ".exr", true);
            }
            if (last && !m_options.screenshot.empty()) save(m_options.screenshot, true);
        } else if (last && !m_options.screenshot.empty()) {
            save(m_options.screenshot, false);  // no image to present to: resolve instead
        }
        // A converged picture and no input: sleep instead of spinning.
        if (m_options.frames == 0 && m_replay->converged()) m_window.wait(0.05);
    }
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

}  // namespace

int run_preview(const PreviewOptions& options) {
    const Timer start;
    PreviewApp app(options);
    return app.run(start);
}

}  // namespace mvpl::preview

#pragma once
// The preview window's state (PreviewApp), its member functions spread over files by concern:
// preview_app.cpp the frame loop, app_sum.cpp the running sum (restart and shading),
// app_input.cpp the user's and the script's input, app_settings.cpp the settings' changes,
// app_scene.cpp a scene or environment replaced (dropped files), app_output.cpp the HUD and the
// screenshots.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/gpu/swapchain.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/vpl_integrator.h"
#include "tools/preview/camera_controller.h"
#include "tools/preview/frame_variance.h"
#include "tools/preview/hud.h"
#include "tools/preview/move_recovery.h"
#include "tools/preview/present_pass.h"
#include "tools/preview/preview_app.h"
#include "tools/preview/preview_stats.h"
#include "tools/preview/script.h"
#include "tools/preview/settings.h"
#include "tools/preview/settings_panel.h"
#include "tools/preview/vpl_history.h"
#include "tools/preview/window.h"
#include "tools/session/scene_session.h"

namespace mvpl::preview {

// How often (seconds) the HUD is redrawn and the CPU estimators' image uploaded.
constexpr double kHudInterval = 0.25;

class PreviewApp {
public:
    explicit PreviewApp(const PreviewOptions& options);

    int run(const Timer& start);

private:
    static gpu::ContextOptions context_options();
    // The estimate's integrator on m_options.devices devices of m_context's kind, for m_session.
    std::unique_ptr<integrator::VplIntegrator> make_integrator();
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
    // One event of the script's format (script.h), from the script or the settings panel.
    void apply_event(const ScriptEvent& event);
    // Sets a setting of settings.h (values: its numbers; word: the sampler's name), then throws
    // away what it must (Redo). The script and the panel both change settings through it.
    void change(const std::string& name, const std::vector<float>& values,
                const std::string& word = {});
    void redo(Redo what);
    bool change_environment(const std::string& name, const std::vector<float>& values);
    // The file's camera N (scene::choose_camera, as `render --camera N`); the vertical field of
    // view in degrees.
    void select_camera(int index);
    void set_fov(float degrees);
    // Views (app_views.cpp): "image" (the estimate), "albedo", "normal", "depth", "vpls";
    // false for another name. next_view: V's cycle.
    bool set_view(const std::string& name);
    void next_view();
    // Traces the view's AOV again when the sum restarted or its positions grew (the VPLs' view:
    // the picture read back at the HUD's pace).
    // The view's image after this frame's shading: restarted, a new sum; last, the run's last
    // frame (its screenshot).
    void update_view(bool restarted, bool last);
    void update_error_view(bool restarted);
    // The settings as the panel shows them.
    PanelValues panel_values() const;
    // Tab: the panel shown (made the first time) or hidden.
    void toggle_panel();
    // A dropped file: a scene (every format the loader reads) replaces the scene, an .hdr or
    // .exr the environment. A file that cannot be read leaves all as it was, its one-line error
    // on stderr and in the HUD.
    void drop(const std::string& path);
    void set_environment(const scene::EnvironmentChoice& environment);
    // Sets up `path` under `environment` (throws InputError or UsageError, leaving all as it
    // was) and replaces the scene, its renderer and VPLs with it; keep_camera: the same scene
    // (a new environment) keeps the view.
    void load_scene(const std::string& path, const scene::EnvironmentChoice& environment,
                    bool keep_camera);
    void report(const std::string& message);
    // Starts a new sum for the window's framebuffer, at 1/divisor of its size.
    void restart(uint32_t width, uint32_t height, uint32_t divisor, bool moving);
    void render_work();
    // With row-column sampling, at rest: the light paths (or steps) of about one pool at the VPLs
    // a unit has left so far, the least a call draws, so that its pools are full rather than a
    // frame's few VPLs (which measured worse than shading every VPL: docs/results.md,
    // "Row-column sampling"); 0 otherwise.
    uint64_t pool_units() const;
    // The first frame at rest after a move: the recorded VPLs up to m_catch_up.
    void catch_up();
    void update_cpu_image(bool force);
    void update_hud(bool force);
    // What the current sum's estimate has on (for the HUD, once a restart).
    EstimatorParts estimator_parts() const;
    void save(const std::string& path, bool png_from_display);
    void print_kept_maps() const;
    // One frame: input, the sum, the present; false when the window is to close.
    bool frame(uint64_t index, const Timer& start);
    // The present and what it measures. moving: the sum restarted for a move or resize; first:
    // the first frame (the first image, reported on its own, not a move); phase: started with
    // the frame's sum, restart and shading its seconds in it.
    void present(uint32_t width, uint32_t height, bool moving, bool first, bool last,
                 const Timer& phase, double restart, double shading, const Timer& start);

    // The command line's options; the settings (settings.h) change their fields as they run.
    PreviewOptions m_options;
    scene::EnvironmentChoice m_environment;
    std::unique_ptr<session::SceneSession> m_session;
    std::string m_sampler;
    std::vector<ScriptEvent> m_script;
    size_t m_next_event = 0;
    Window m_window;
    gpu::Context m_context;
    // The estimate `mvpl render` makes, begun anew at each restart over the VPLs of m_history.
    std::unique_ptr<integrator::VplIntegrator> m_integrator;
    gpu::Swapchain m_swapchain;
    PresentPass m_present;
    // Made when first shown: at the start of an interactive run, or at Tab (a scripted run
    // without it never sets Dear ImGui up).
    std::unique_ptr<SettingsPanel> m_panel;
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
    uint32_t m_screenshots = 1;  // the next screenshot number to try
    PreviewStats m_stats;
    MoveRecovery m_recovery;
    uint64_t m_resting_vpls = 0;  // in the sum of the last frame at rest
    uint64_t m_catch_up = 0;      // VPLs the next frame shades before presenting
    Timer m_hud_timer;
    bool m_hud_dirty = true;
    // What specular_chains 1 turns on: the command line's roughness, or the default.
    float m_chain_roughness;
    std::string m_message;  // the last dropped file's error, shown in the HUD
    EstimatorParts m_parts;
    std::string m_view = "image";
    FrameVariance m_variance;       // the error view's reads of the current sum
    uint64_t m_view_positions = 0;  // the sub-pixel positions the AOV view covers
    Image m_view_image;             // what an .exr screenshot of the view holds
    Timer m_since_restart;
    Timer m_frame_timer;
};

}  // namespace mvpl::preview

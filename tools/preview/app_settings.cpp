// PreviewApp's settings (settings.h): each change sets its field, then throws away only what
// depends on it.
#include <glm/glm.hpp>

#include "engine/core/error.h"
#include "tools/preview/app.h"

namespace mvpl::preview {

void PreviewApp::change(const std::string& name, const std::vector<float>& v,
                        const std::string& word) {
    const SettingSpec* spec = find_setting(name);
    if (!spec) return;
    const bool on = !v.empty() && v[0] != 0.0f;
    if (name == "exposure") m_exposure = v[0];
    if (name == "paths_per_frame") m_options.paths_per_frame = uint64_t(v[0]);
    if (name == "budget_ms") m_options.budget_ms = v[0];
    if (name == "sampler") m_sampler = word;
    if (name == "clamp") {
        // C toggles between the two: clamp 0 is off, another distance is on at that distance.
        m_clamping = on;
        if (on) m_options.clamp = v[0];
    }
    if (name == "compensate") m_options.compensate = on;
    if (name == "shadow_resolution") m_options.shadow_resolution = uint32_t(v[0]);
    if (name == "max_depth") m_options.max_depth = int(v[0]);
    if (name == "caustics") m_options.caustics = on;
    if (name == "specular_chains")
        m_options.levers.chains.max_roughness = on ? m_chain_roughness : -1.0f;
    if (name == "vsl") m_options.levers.vsl_radius = v[0];
    if (change_environment(name, v)) return;
    redo(spec->redo);
}

bool PreviewApp::change_environment(const std::string& name, const std::vector<float>& v) {
    scene::EnvironmentChoice environment = m_environment;
    if (name == "env_color") {
        environment.has_color = true;
        environment.color = Rgb(v[0], v[1], v[2]);
    } else if (name == "env_scale") {
        environment.scale = v[0];
    } else if (name == "env_rotation") {
        environment.rotation_degrees = v[0];
    } else {
        return false;
    }
    set_environment(environment);
    return true;
}

void PreviewApp::redo(Redo what) {
    m_hud_dirty = true;
    if (what == Redo::nothing) return;
    m_moved = true;  // a Metropolis chain's target depends on each of the others
    if (what == Redo::vpls) m_mc_history.reset();
}

void PreviewApp::select_camera(int index) {
    scene::CameraChoice choice;
    choice.index = index;
    try {
        m_controller = CameraController(scene::choose_camera(m_session->scene(), choice),
                                        m_session->scene().bounds());
        m_moved = true;
    } catch (const UsageError& e) {
        report(e.what());
    }
}

PanelValues PreviewApp::panel_values() const {
    PanelValues v;
    v.sampler = m_sampler;
    v.paths_per_frame = m_options.paths_per_frame;
    v.budget_ms = float(m_options.budget_ms);
    v.clamping = m_clamping;
    v.clamp = m_options.clamp;
    v.compensate = m_options.compensate;
    v.caustics = m_options.caustics;
    v.chains = m_options.levers.chains.max_roughness >= 0.0f;
    v.vsl = m_options.levers.vsl_radius;
    v.max_depth = m_options.max_depth;
    v.shadow_resolution = m_options.shadow_resolution;
    v.exposure = m_exposure;
    v.env_color = m_environment.color;
    v.env_scale = m_environment.scale;
    v.env_rotation = m_environment.rotation_degrees;
    v.env_map = m_environment.map;
    v.cameras = int(m_session->scene().cameras.size());
    v.fov_degrees = glm::degrees(m_controller.camera().yfov);
    v.view = m_view;
    return v;
}

void PreviewApp::toggle_panel() {
    if (!m_panel) {
        m_panel = std::make_unique<SettingsPanel>(m_context, m_window, m_swapchain.format(), true);
        return;
    }
    m_panel->toggle();
}

void PreviewApp::set_fov(float degrees) {
    m_controller.set_fov(glm::radians(degrees));  // as scene::choose_camera converts --fov
    m_moved = true;
}

}  // namespace mvpl::preview

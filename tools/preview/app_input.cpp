// PreviewApp's input: the user's drags, wheel, held and pressed keys, and the script's events.
#include <algorithm>
#include <cmath>

#include "tools/preview/app.h"

namespace mvpl::preview {
namespace {

// Interaction speeds: degrees per dragged pixel, scroll step as a distance factor, scene
// diagonals per second of a held fly key, stops per exposure key.
constexpr float kDegreesPerPixel = 0.3f;
constexpr float kWheelFactor = 0.9f;
constexpr float kFlySpeed = 0.5f;
constexpr float kExposureStep = 0.5f;

}  // namespace

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
    } else if (key == "tab") {
        toggle_panel();
    } else if (key == "v") {
        next_view();
    } else if (key == "escape") {
        m_quit = true;
    }
}

void PreviewApp::apply(const Input& input, double dt) {
    Input in = input;
    if (m_panel && m_panel->wants_mouse()) {  // a drag or scroll over the panel is its own
        in.orbit_x = in.orbit_y = in.pan_x = in.pan_y = in.look_x = in.look_y = in.wheel = 0.0f;
    }
    if (m_panel && m_panel->wants_keyboard()) {  // typing in it: only Tab leaves it
        std::erase_if(in.keys, [](const std::string& key) { return key != "tab"; });
        in.fly_forward = in.fly_right = in.fly_up = 0;
    }
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
    for (const std::string& path : in.drops)
        drop(path);
}

void PreviewApp::apply_script(uint64_t frame) {
    for (; m_next_event < m_script.size() && m_script[m_next_event].frame <= frame; ++m_next_event)
        apply_event(m_script[m_next_event]);
}

void PreviewApp::apply_event(const ScriptEvent& e) {
    const std::vector<float>& v = e.values;
    if (e.action == "key") {
        apply_key(e.key);
    } else if (e.action == "resize") {
        m_window.set_size(int(v[0]), int(v[1]));
    } else if (e.action == "set") {
        change(e.key, v, e.word);
    } else if (e.action == "drop") {
        drop(e.word);
    } else if (e.action == "camera") {
        select_camera(int(v[0]));
    } else if (e.action == "fov") {
        set_fov(v[0]);
    } else if (e.action == "view") {
        set_view(e.word);
    } else {
        if (e.action == "orbit") m_controller.orbit(v[0], v[1]);
        if (e.action == "pan") m_controller.pan(v[0], v[1]);
        if (e.action == "zoom") m_controller.zoom(v[0]);
        if (e.action == "fly") m_controller.fly(v[0], v[1], v[2]);
        if (e.action == "look") m_controller.look(v[0], v[1]);
        m_moved = true;
    }
}

}  // namespace mvpl::preview

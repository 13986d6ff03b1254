#include "tools/session/scene_session.h"

#include <cstdio>

#include "engine/light/default_sky.h"
#include "engine/scene/camera.h"
#include "engine/scene/environment_map.h"
#include "engine/scene/scene_loader.h"

namespace mvpl::session {

namespace {

// "P %" of the unit sky's flux, for the warnings.
std::string share_text(const light::SceneLighting& l) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g %%", 100.0 * l.emitted_share());
    return text;
}

// The scene with the environment the command asked for. A scene that does not light itself
// (light::SceneLighting::lights_itself: no punctual light, no environment, and emissive surfaces
// below kMinEmittedShare of the flux a unit sky would send in) gets the default sky unless the
// command said no; either way one line says why the picture looks as it does.
scene::Scene load_with_environment(const std::string& path, const EnvironmentChoice& choice,
                                   const scene::LoadOptions& load) {
    scene::Scene scene = scene::load_scene(path, load);
    scene.environment.rotation += choice.rotation_degrees * (kPi / 180.0f);
    if (!choice.map.empty()) {
        scene.environment.map = scene::load_environment_map(choice.map);
        scene.environment.radiance = choice.color * choice.scale;
        return scene;
    }
    if (choice.has_color) {
        scene.environment.radiance = choice.color * choice.scale;
        return scene;
    }
    const light::SceneLighting lighting = light::scene_lighting(scene);
    if (lighting.lights_itself()) return scene;
    const bool emits = lighting.emitted > 0.0;
    const std::string what = emits ? "the scene's only light is its emissive surfaces, " +
                                         share_text(lighting) + " of what a unit sky would send in"
                                   : "the scene has no light";
    char line[320];
    if (choice.default_light) {
        scene.environment.radiance = Rgb(choice.scale);
        std::snprintf(line, sizeof line,
                      "%s: it is lit by a uniform white sky of radiance %g%s (--env-color sets "
                      "another, --no-default-light none)",
                      what.c_str(), double(choice.scale), emits ? " as well" : "");
        scene.warnings.emplace_back(line);
    } else if (emits) {
        scene.warnings.push_back(what +
                                 ": the image is dark (without --no-default-light a "
                                 "uniform white sky lights it)");
    }
    return scene;
}
}  // namespace

SceneSession::SceneSession(const std::string& path, const scene::CameraChoice& camera,
                           const EnvironmentChoice& environment, const scene::LoadOptions& load)
    : m_path(path),
      m_scene(load_with_environment(path, environment, load)),
      m_load_seconds(m_clock.seconds()),
      m_accel(m_scene),
      m_bvh_seconds(m_clock.seconds() - m_load_seconds),
      m_lights(m_scene),
      m_setup_seconds(m_clock.seconds()) {
    // Neither the BVH nor the lights depend on the camera; the samplers read it later.
    m_scene.camera = scene::choose_camera(m_scene, camera);
    for (const std::string& w : m_scene.warnings)
        std::fprintf(stderr, "mvpl: warning: %s: %s\n", m_path.c_str(), w.c_str());
}

bool SceneSession::warn_if_no_light(const std::string& consequence) const {
    if (!m_lights.empty()) return false;
    warn("the scene has no light; " + consequence);
    return true;
}

void SceneSession::warn(const std::string& what) const {
    if (m_warned) return;
    m_warned = true;
    std::fprintf(stderr, "mvpl: warning: %s: %s\n", m_path.c_str(), what.c_str());
}

bool SceneSession::warn_if_clipped(int width, int height) const {
    constexpr int kGrid = 32;  // rays a side: finds any surface wider than 1/32 of the image
    const scene::Camera& camera = m_scene.camera;
    const Vec3 eye = camera.position();
    bool nearer = false;
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            const Vec2 film((float(i) + 0.5f) * float(width) / kGrid,
                            (float(j) + 0.5f) * float(height) / kGrid);
            const scene::CameraRay r = scene::generate_camera_ray(camera, width, height, film);
            if (m_accel.intersect_camera({r.origin, r.direction})) return false;
            nearer =
                nearer || m_accel.intersect_camera({eye, r.direction, glm::length(r.origin - eye)});
        }
    }
    if (!nearer) return false;
    char line[200];
    std::snprintf(line, sizeof line,
                  "the image is black: everything the camera sees is nearer than its znear (%g), "
                  "which clips it away",
                  double(camera.znear));
    warn(line);
    return true;
}

void SceneSession::warn_if_black(const Image& image) const {
    for (const Rgb& p : image.pixels()) {
        if (p.r != 0.0f || p.g != 0.0f || p.b != 0.0f) return;
    }
    if (warn_if_clipped(image.width(), image.height())) return;
    warn("the image is black: no light reaches what the camera sees");
}

}  // namespace mvpl::session

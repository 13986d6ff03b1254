#include "tools/session/scene_session.h"

#include <cstdio>

#include "engine/scene/environment_map.h"
#include "engine/scene/scene_loader.h"

namespace mvpl::session {

namespace {

// The scene with the environment the command asked for; a scene without emitters gets the
// default sky unless the command said no.
scene::Scene load_with_environment(const std::string& path, const EnvironmentChoice& choice,
                                   const scene::LoadOptions& load) {
    scene::Scene scene = scene::load_scene(path, load);
    scene.environment.rotation += choice.rotation_degrees * (kPi / 180.0f);
    if (!choice.map.empty()) {
        scene.environment.map = scene::load_environment_map(choice.map);
        scene.environment.radiance = choice.color * choice.scale;
    } else if (choice.has_color) {
        scene.environment.radiance = choice.color * choice.scale;
    } else if (choice.default_light && light::LightSampler(scene).empty()) {
        scene.environment.radiance = Rgb(choice.scale);
        char line[160];
        std::snprintf(line, sizeof line,
                      "the scene has no light: it is lit by a uniform white sky of radiance %g "
                      "(--env-color sets another, --no-default-light none)",
                      double(choice.scale));
        scene.warnings.emplace_back(line);
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

void SceneSession::warn_if_black(const Image& image) const {
    for (const Rgb& p : image.pixels()) {
        if (p.r != 0.0f || p.g != 0.0f || p.b != 0.0f) return;
    }
    warn("the image is black: no light reaches what the camera sees");
}

}  // namespace mvpl::session

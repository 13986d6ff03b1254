#include "tools/session/scene_session.h"

#include <cstdio>

#include "engine/scene/scene_loader.h"

namespace mvpl::session {

SceneSession::SceneSession(const std::string& path)
    : m_path(path),
      m_scene(scene::load_scene(path)),
      m_load_seconds(m_clock.seconds()),
      m_accel(m_scene),
      m_bvh_seconds(m_clock.seconds() - m_load_seconds),
      m_lights(m_scene),
      m_setup_seconds(m_clock.seconds()) {}

bool SceneSession::warn_if_no_light(const std::string& consequence, bool quiet) const {
    if (!m_lights.empty()) return false;
    if (!quiet) {
        std::fprintf(stderr, "mvpl: warning: %s: the scene has no light; %s\n", m_path.c_str(),
                     consequence.c_str());
    }
    return true;
}

}  // namespace mvpl::session

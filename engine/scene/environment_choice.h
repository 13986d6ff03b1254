#pragma once
// The environment a command asks for (--env-color, --env-scale, --no-default-light), applied by
// the scene session (tools/session/scene_session.cpp) once the scene is loaded.
#include "engine/core/color.h"

namespace mvpl::scene {

struct EnvironmentChoice {
    bool has_color = false;  // --env-color given
    Rgb color{1.0f};
    float scale = 1.0f;
    // A scene without any emitter gets a uniform white sky of radiance `scale` (and one line on
    // stderr saying so), as glTF viewers light such models; false keeps it black.
    bool default_light = true;
};

}  // namespace mvpl::scene

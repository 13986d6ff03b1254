#pragma once
// The environment a command asks for (--env, --env-color, --env-scale, --env-rotate,
// --no-default-light), applied by
// the scene session (tools/session/scene_session.cpp) once the scene is loaded.
#include <string>

#include "engine/core/color.h"

namespace mvpl::scene {

struct EnvironmentChoice {
    std::string map;         // --env: a latitude-longitude .hdr or .exr (environment_map.h)
    bool has_color = false;  // --env-color given: the constant, or the map's tint
    Rgb color{1.0f};
    float scale = 1.0f;
    float rotation_degrees = 0.0f;  // --env-rotate, about +Y
    // A scene that does not light itself (light::SceneLighting::lights_itself: no punctual
    // light or environment, and emission below light::kMinEmittedShare of a unit sky's) gets a
    // uniform white sky of radiance `scale` (and one line on stderr saying so), as glTF viewers
    // light such models; false keeps it dark.
    bool default_light = true;
};

}  // namespace mvpl::scene

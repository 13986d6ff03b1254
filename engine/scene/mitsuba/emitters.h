#pragma once
// Mitsuba's emitters: `area` (on a shape: the shape's material emits `radiance` from its front
// face, as in Mitsuba), `point`, `spot` and `directional` (scene::Light), `constant` and `envmap`
// (the scene's Environment).
#include <pugixml.hpp>

#include "engine/core/color.h"

namespace mvpl::scene::mitsuba {

class Context;

// The radiance of a shape's `area` emitter; fails for any other type or a textured radiance.
Rgb area_radiance(Context& ctx, pugi::xml_node emitter);

// A scene-level emitter into ctx.scene(): point, spot, directional → Scene::lights; constant and
// envmap → Scene::environment (one environment per scene). Fails at it on an unsupported type.
void add_emitter(Context& ctx, pugi::xml_node emitter);

}  // namespace mvpl::scene::mitsuba

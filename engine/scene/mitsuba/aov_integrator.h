#pragma once
// Mitsuba 3's `<integrator type="aov">`: its `aovs` string ("name:type, …") becomes the scene's
// FileAov list (Scene::aovs), which render and reference write as EXR channels under the file's
// names (engine/aov/aov_kind.h); its nested integrators are read as any integrator is (the
// image's max_depth). Types mvpl does not write (uv, geo_normal, …) are warned about; a type
// Mitsuba does not know either, or a malformed or repeated name, refuses the file.
#include <pugixml.hpp>

namespace mvpl::scene::mitsuba {

class Context;

void read_aov_integrator(Context& ctx, pugi::xml_node integrator);

}  // namespace mvpl::scene::mitsuba

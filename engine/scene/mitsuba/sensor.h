#pragma once
// Mitsuba's sensor, film and integrator as what mvpl renders by default: a `perspective` (or
// `thinlens`, as a pinhole: warned) sensor → a Scene::cameras entry; its film's width and height
// → the default --res; the integrator's max_depth (Mitsuba's convention is mvpl's) → the default
// --max-depth. The sampler (sample count) and the reconstruction filter are dropped with one
// warning each where they would change the image (mvpl's pixels are box-filtered).
#include <pugixml.hpp>

namespace mvpl::scene::mitsuba {

class Context;

void add_sensor(Context& ctx, pugi::xml_node sensor);
void read_integrator(Context& ctx, pugi::xml_node integrator);

}  // namespace mvpl::scene::mitsuba

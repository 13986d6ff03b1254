#pragma once
// Mitsuba's shapes as world-space triangle meshes: obj, ply, serialized, rectangle, cube, sphere,
// disk, cylinder, and instances of shapegroups (their meshes copied under the instance's
// transform). Meshes without normals get Mitsuba's smooth vertex normals (angle-weighted face
// normals) unless `face_normals` asks for flat ones; `flip_normals` turns the surface round.
#include <pugixml.hpp>

#include <functional>

#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace mvpl::scene::mitsuba {

class Context;

// The Scene::materials index of a shape element (its BSDF and area emitter).
using MaterialOf = std::function<int(pugi::xml_node shape)>;

// Appends the meshes of `shape` under `parent` to ctx.scene().meshes. A shapegroup adds nothing
// by itself. Fails at the shape on an unknown type, a bad parameter (negative radius, a singular
// transform) or an unreadable mesh file (the file's own message).
void add_shape(Context& ctx, pugi::xml_node shape, const DMat4& parent,
               const MaterialOf& material_of);

}  // namespace mvpl::scene::mitsuba

#pragma once
// Mitsuba's BSDFs onto mvpl's closures (the glTF metallic-roughness material that
// engine/material/gltf_graph.cpp turns into a node graph):
//   diffuse → Lambertian; roughdiffuse → Lambertian (warned: Oren-Nayar is not modelled);
//   conductor, roughconductor → GGX conductor with Schlick's Fresnel from F0 = the normal-incidence
//     reflectance of η, k (or a named material) × specular_reflectance; α = roughness²; Beckmann
//     α taken as GGX α; anisotropic α as the mean of α_u, α_v (warned);
//   plastic, roughplastic → GGX dielectric layer (ior = int_ior / ext_ior) over a Lambertian base;
//   dielectric, roughdielectric, thindielectric → the interface's reflection lobe (warned: mvpl
//     does not refract, the transmitted light is lost);
//   a textured α → the metallic-roughness texture's G as √α;
//   twosided → double-sided; normalmap → normal texture; bumpmap → a height map (the bump_map
//   node, Blinn 1978); mask → hashed transparency (a textured opacity as the base alpha);
//   blendbsdf → the heavier of the two (warned) unless both are diffuse with constant colours;
//   principled → metal-rough where its parameters map (warned for the rest).
// A BSDF that is not twosided is one-sided as in Mitsuba: the camera does not see its back faces
// (mvpl's one-sided convention; Mitsuba shows them black) and light paths end there.
#include <pugixml.hpp>

#include "engine/scene/scene.h"

namespace mvpl::scene::mitsuba {

class Context;

// The material of a bsdf element (read once; later calls return the same index).
int material_index(Context& ctx, pugi::xml_node bsdf);
// The material a shape without a BSDF gets: Mitsuba's default, diffuse of reflectance 0.5.
int default_material_index(Context& ctx);

// The bsdf element as a material; fails at it for an unsupported type or parameter.
Material read_bsdf(Context& ctx, pugi::xml_node bsdf);

}  // namespace mvpl::scene::mitsuba

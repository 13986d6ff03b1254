#pragma once
// Mitsuba's textures where a BSDF takes one: `bitmap` (filter_type, wrap_mode, raw, to_uv) and
// `checkerboard` (baked into a 2×2 nearest-filtered repeating texture, exact for any uv) become
// Scene::textures, referenced with to_uv's scale, rotation and offset as KHR_texture_transform.
#include <pugixml.hpp>

#include <functional>
#include <string>

#include "engine/core/color.h"
#include "engine/scene/texture.h"

namespace mvpl::scene::mitsuba {

class Context;

// A colour parameter: its constant, or a texture (factor 1).
struct ColorInput {
    Rgb value{1.0f};
    TextureRef texture;
};

// The BSDF's colour parameter `name` (rgb, srgb, spectrum, float, or a texture), `fallback`
// when absent. `raw` is the default colour space of a bitmap here (Mitsuba decodes sRGB for
// colours, and reads data raw).
ColorInput color_input(Context& ctx, pugi::xml_node bsdf, const std::string& name,
                       const Rgb& fallback, bool raw = false);
// A scalar parameter that must be constant (a texture fails at it, naming the parameter).
float scalar_input(Context& ctx, pugi::xml_node bsdf, const std::string& name, float fallback);

// The Scene::textures reference of a texture element.
TextureRef texture_ref(Context& ctx, pugi::xml_node texture, bool raw);

// A copy of `ref`'s texture with every texel mapped by `texel` (same size, wrap, filter and uv
// transform): how a Mitsuba parameter becomes the channel mvpl reads it from (a roughness α in
// the metallic-roughness texture's G as √α, a mask's opacity in the base colour's alpha).
TextureRef derived_texture(Context& ctx, pugi::xml_node at, const TextureRef& ref,
                           const std::function<Vec4(const Vec4&)>& texel);

}  // namespace mvpl::scene::mitsuba

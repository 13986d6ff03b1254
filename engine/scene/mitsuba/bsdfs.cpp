#include "engine/scene/mitsuba/bsdfs.h"

#include <algorithm>
#include <cmath>

#include "engine/scene/mitsuba/ior_tables.h"
#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/textures.h"

namespace mvpl::scene::mitsuba {

namespace {

constexpr int kMaxNesting = 16;

Material diffuse(const ColorInput& reflectance) {
    Material m;
    m.base_color = reflectance.value;
    m.base_color_texture = reflectance.texture;
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.specular = 0.0f;
    return m;
}

// A textured α (Mitsuba reads a texture's mean channel) as the metallic-roughness texture mvpl
// reads: G = √α (roughness, times the factor 1), B = 1 (metallic, times the material's factor).
void textured_roughness(Context& ctx, pugi::xml_node bsdf, Material& m) {
    const pugi::xml_node p = ctx.property(bsdf, "alpha");
    if (!p || std::string(p.name()) != "texture") return;
    const TextureRef alpha = texture_ref(ctx, p, true);
    m.metallic_roughness_texture = derived_texture(ctx, p, alpha, [](const Vec4& v) {
        const float a = std::clamp((v.r + v.g + v.b) / 3.0f, 0.0f, 1.0f);
        return Vec4(1.0f, std::sqrt(a), 1.0f, 1.0f);
    });
    m.roughness = 1.0f;
}

// A microfacet α as mvpl's perceptual roughness (α = roughness²).
float roughness_of(Context& ctx, pugi::xml_node bsdf, float fallback_alpha) {
    const std::string distribution = ctx.get_string(bsdf, "distribution", "beckmann");
    if (distribution != "beckmann" && distribution != "ggx")
        ctx.fail(ctx.property(bsdf, "distribution"),
                 "distribution '" + distribution + "' is not supported (beckmann, ggx)");
    float alpha = fallback_alpha;
    if (ctx.property(bsdf, "alpha_u") || ctx.property(bsdf, "alpha_v")) {
        const float u = scalar_input(ctx, bsdf, "alpha_u", fallback_alpha);
        const float v = scalar_input(ctx, bsdf, "alpha_v", fallback_alpha);
        alpha = 0.5f * (u + v);
        if (u != v)
            ctx.warn(bsdf, "anisotropic roughness (alpha_u " + std::to_string(u) + ", alpha_v " +
                               std::to_string(v) + ") is rendered isotropic with their mean");
    } else if (const pugi::xml_node p = ctx.property(bsdf, "alpha");
               p && std::string(p.name()) == "texture") {
        return 1.0f;  // textured_roughness supplies it
    } else {
        alpha = scalar_input(ctx, bsdf, "alpha", fallback_alpha);
    }
    if (!(alpha >= 0.0f)) ctx.fail(bsdf, "alpha must not be negative");
    return std::sqrt(std::min(alpha, 1.0f));
}

float ior_input(Context& ctx, pugi::xml_node bsdf, const std::string& name, float fallback) {
    const pugi::xml_node p = ctx.property(bsdf, name);
    if (!p) return fallback;
    if (std::string(p.name()) == "string") {
        const std::string named = p.attribute("value").as_string();
        if (const std::optional<float> ior = dielectric_ior(named)) return *ior;
        ctx.fail(p, "unknown index of refraction '" + named + "'");
    }
    const float v = float(ctx.number(p, "value"));
    if (!(v > 0.0f)) ctx.fail(p, name + " must be positive");
    return v;
}

// roughconductor's alpha_u and alpha_v where either is a texture: rendered isotropic with their
// mean (as roughness_of does for constants), texel by texel into the metallic-roughness texture
// (G = √α, as textured_roughness). Two textures must share size, sampler and uv transform, so
// that the mean of their lookups is the lookup of their mean. False when neither is a texture.
bool textured_anisotropic_roughness(Context& ctx, pugi::xml_node bsdf, Material& m) {
    const pugi::xml_node pu = ctx.property(bsdf, "alpha_u"), pv = ctx.property(bsdf, "alpha_v");
    const auto textured = [](pugi::xml_node p) { return p && std::string(p.name()) == "texture"; };
    if (!textured(pu) && !textured(pv)) return false;
    const std::string distribution = ctx.get_string(bsdf, "distribution", "beckmann");
    if (distribution != "beckmann" && distribution != "ggx")
        ctx.fail(ctx.property(bsdf, "distribution"),
                 "distribution '" + distribution + "' is not supported (beckmann, ggx)");
    const pugi::xml_node first = textured(pu) ? pu : pv, second = textured(pu) ? pv : pu;
    const auto alpha = [](const Vec4& v) { return std::max(0.0f, (v.r + v.g + v.b) / 3.0f); };
    const TextureRef a = texture_ref(ctx, first, true);
    std::vector<float> other;  // the other α at each texel of the first texture
    if (textured(second)) {
        const TextureRef b = texture_ref(ctx, second, true);
        const Texture& ta = ctx.scene().textures[size_t(a.texture)];
        const Texture& tb = ctx.scene().textures[size_t(b.texture)];
        if (tb.width != ta.width || tb.height != ta.height || tb.filter != ta.filter ||
            tb.wrap_s != ta.wrap_s || tb.wrap_t != ta.wrap_t || b.scale != a.scale ||
            b.offset != a.offset || b.rotation != a.rotation)
            ctx.fail(second,
                     "textured alpha_u and alpha_v of different sizes, filters or uv transforms "
                     "are not supported");
        for (const Vec4& v : tb.texels)
            other.push_back(alpha(v));
    } else {
        const float constant = scalar_input(ctx, bsdf, textured(pu) ? "alpha_v" : "alpha_u", 0.1f);
        other.assign(ctx.scene().textures[size_t(a.texture)].texels.size(), constant);
    }
    std::vector<Vec4> texels = ctx.scene().textures[size_t(a.texture)].texels;
    for (size_t i = 0; i < texels.size(); ++i)
        texels[i] =
            Vec4(1.0f, std::sqrt(std::min(0.5f * (alpha(texels[i]) + other[i]), 1.0f)), 1.0f, 1.0f);
    m.metallic_roughness_texture = derived_texture(ctx, first, a, [](const Vec4& v) { return v; });
    ctx.scene().textures[size_t(m.metallic_roughness_texture.texture)].texels = std::move(texels);
    m.roughness = 1.0f;
    ctx.warn(bsdf,
             "textured anisotropic roughness (alpha_u, alpha_v) is rendered isotropic "
             "with their mean");
    return true;
}

Material conductor(Context& ctx, pugi::xml_node bsdf, bool rough) {
    const float outside = ior_input(ctx, bsdf, "ext_eta", 1.0f);
    ComplexIor ior{Rgb(0.0f), Rgb(1.0f)};
    if (ctx.property(bsdf, "eta") || ctx.property(bsdf, "k")) {
        const std::optional<Rgb> eta = ctx.get_color(bsdf, "eta");
        const std::optional<Rgb> k = ctx.get_color(bsdf, "k");
        ior = {eta.value_or(Rgb(0.0f)), k.value_or(Rgb(1.0f))};
    } else {
        const std::string name = ctx.get_string(bsdf, "material", "none");
        const std::optional<ComplexIor> named = conductor_ior(name);
        if (!named)
            ctx.fail(ctx.property(bsdf, "material"), "conductor material '" + name +
                                                         "' is not in mvpl's table (" +
                                                         conductor_names() + ")");
        ior = *named;
    }
    const ColorInput specular = color_input(ctx, bsdf, "specular_reflectance", Rgb(1.0f));
    Material m;
    m.base_color = conductor_f0(ior, outside) * specular.value;
    m.base_color_texture = specular.texture;
    m.metallic = 1.0f;
    if (rough && textured_anisotropic_roughness(ctx, bsdf, m)) return m;
    m.roughness = rough ? roughness_of(ctx, bsdf, 0.1f) : 0.0f;
    if (rough) textured_roughness(ctx, bsdf, m);
    return m;
}

Material plastic(Context& ctx, pugi::xml_node bsdf, bool rough) {
    Material m = diffuse(color_input(ctx, bsdf, "diffuse_reflectance", Rgb(0.5f)));
    const ColorInput specular = color_input(ctx, bsdf, "specular_reflectance", Rgb(1.0f));
    if (specular.texture.valid())
        ctx.fail(ctx.property(bsdf, "specular_reflectance"),
                 "a textured specular_reflectance is not supported");
    m.specular = 1.0f;
    m.specular_color = specular.value;
    m.ior = ior_input(ctx, bsdf, "int_ior", 1.49f) / ior_input(ctx, bsdf, "ext_ior", 1.000277f);
    m.roughness = rough ? roughness_of(ctx, bsdf, 0.1f) : 0.0f;
    if (rough) textured_roughness(ctx, bsdf, m);
    return m;
}

// dielectric and roughdielectric: a solid that refracts with int_ior / ext_ior (glTF's
// transmission with a volume); thindielectric: a thin sheet (glTF's default, thin-walled).
// specular_transmittance tints the transmitted light as glTF's base colour does.
Material dielectric(Context& ctx, pugi::xml_node bsdf, const std::string& type) {
    Material m = diffuse(color_input(ctx, bsdf, "specular_transmittance", Rgb(1.0f)));
    m.metallic = 0.0f;
    m.transmission = 1.0f;
    m.thickness = type == "thindielectric" ? 0.0f : 1.0f;
    m.specular = 1.0f;
    const ColorInput specular = color_input(ctx, bsdf, "specular_reflectance", Rgb(1.0f));
    m.specular_color = specular.value;
    m.ior = ior_input(ctx, bsdf, "int_ior", 1.5046f) / ior_input(ctx, bsdf, "ext_ior", 1.000277f);
    m.roughness = type == "roughdielectric" ? roughness_of(ctx, bsdf, 0.1f) : 0.0f;
    if (type == "roughdielectric") textured_roughness(ctx, bsdf, m);
    return m;
}

Material principled(Context& ctx, pugi::xml_node bsdf) {
    Material m = diffuse(color_input(ctx, bsdf, "base_color", Rgb(0.5f)));
    m.metallic = scalar_input(ctx, bsdf, "metallic", 0.0f);
    m.roughness = scalar_input(ctx, bsdf, "roughness", 0.5f);
    // Mitsuba: F0 = 0.08 · specular for the dielectric lobe, or from eta when given.
    float f0 = 0.08f * scalar_input(ctx, bsdf, "specular", 0.5f);
    if (ctx.property(bsdf, "eta")) {
        const float eta = scalar_input(ctx, bsdf, "eta", 1.5f);
        f0 = ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f));
    }
    const float r = std::sqrt(std::clamp(f0, 0.0f, 0.99f));
    m.ior = (1.0f + r) / (1.0f - r);
    m.specular = 1.0f;
    // spec_trans: glTF's transmission; Mitsuba's principled is a solid that refracts with eta.
    m.transmission = scalar_input(ctx, bsdf, "spec_trans", 0.0f);
    m.thickness = 1.0f;
    for (const char* ignored : {"anisotropic", "clearcoat", "sheen", "spec_tint", "flatness"}) {
        if (ctx.property(bsdf, ignored) && scalar_input(ctx, bsdf, ignored, 0.0f) != 0.0f)
            ctx.warn(bsdf, std::string("principled: '") + ignored + "' is not modelled");
    }
    return m;
}

Material read(Context& ctx, pugi::xml_node bsdf, int depth);

// The one nested BSDF of a wrapper (twosided, normalmap, mask).
Material inner(Context& ctx, pugi::xml_node bsdf, int depth) {
    const std::vector<pugi::xml_node> nested = ctx.objects(bsdf, "bsdf");
    const std::string type = bsdf.attribute("type").as_string();
    if (nested.empty()) ctx.fail(bsdf, type + " needs a nested bsdf");
    if (nested.size() > 1 && type == "twosided")
        ctx.warn(bsdf, "twosided with two BSDFs: the front one is used on both sides");
    return read(ctx, nested.front(), depth + 1);
}

Material blend(Context& ctx, pugi::xml_node bsdf, int depth) {
    const std::vector<pugi::xml_node> nested = ctx.objects(bsdf, "bsdf");
    if (nested.size() != 2) ctx.fail(bsdf, "blendbsdf needs two nested bsdfs");
    const pugi::xml_node w = ctx.property(bsdf, "weight");
    const float weight =
        w && std::string(w.name()) == "texture" ? 0.5f : scalar_input(ctx, bsdf, "weight", 0.5f);
    if (w && std::string(w.name()) == "texture")
        ctx.warn(bsdf, "blendbsdf: a textured weight is taken as 0.5");
    Material a = read(ctx, nested[0], depth + 1), b = read(ctx, nested[1], depth + 1);
    const auto plain_diffuse = [](const Material& m) {
        return m.metallic == 0.0f && m.specular == 0.0f && !m.base_color_texture.valid();
    };
    if (plain_diffuse(a) && plain_diffuse(b)) {
        a.base_color = a.base_color * (1.0f - weight) + b.base_color * weight;
        return a;
    }
    ctx.warn(bsdf, "blendbsdf of unlike BSDFs: the one of larger weight is used");
    return weight > 0.5f ? b : a;
}

Material read(Context& ctx, pugi::xml_node bsdf, int depth) {
    if (depth > kMaxNesting) ctx.fail(bsdf, "BSDFs nest too deeply");
    const std::string type = bsdf.attribute("type").as_string();
    Material m;
    if (type == "diffuse") {
        m = diffuse(color_input(ctx, bsdf, "reflectance", Rgb(0.5f)));
    } else if (type == "roughdiffuse") {
        ctx.warn(bsdf, "roughdiffuse is rendered as diffuse (Lambertian)");
        m = diffuse(color_input(ctx, bsdf, "reflectance", Rgb(0.5f)));
    } else if (type == "conductor" || type == "roughconductor") {
        m = conductor(ctx, bsdf, type == "roughconductor");
    } else if (type == "plastic" || type == "roughplastic") {
        m = plastic(ctx, bsdf, type == "roughplastic");
    } else if (type == "dielectric" || type == "roughdielectric" || type == "thindielectric") {
        m = dielectric(ctx, bsdf, type);
    } else if (type == "principled") {
        m = principled(ctx, bsdf);
    } else if (type == "twosided") {
        m = inner(ctx, bsdf, depth);
        m.double_sided = true;
    } else if (type == "normalmap") {
        m = inner(ctx, bsdf, depth);
        const pugi::xml_node map = ctx.property(bsdf, "normalmap");
        if (!map || std::string(map.name()) != "texture")
            ctx.fail(bsdf, "normalmap needs a 'normalmap' texture");
        m.normal_texture = texture_ref(ctx, map, true);
    } else if (type == "bumpmap") {
        m = inner(ctx, bsdf, depth);
        pugi::xml_node height;
        for (pugi::xml_node t : ctx.objects(bsdf, "texture"))
            height = height ? height : t;
        if (!height) ctx.fail(bsdf, "bumpmap needs a height texture");
        m.bump_texture = texture_ref(ctx, height, true);
        m.bump_scale = ctx.get_float(bsdf, "scale", 1.0f);
    } else if (type == "mask") {
        m = inner(ctx, bsdf, depth);
        const pugi::xml_node opacity = ctx.property(bsdf, "opacity");
        if (opacity && std::string(opacity.name()) == "texture") {
            // Mitsuba reads the opacity's mean channel; as the opacity texture's A, beside any
            // texture of the nested BSDF (scene::Material::opacity_texture).
            const TextureRef o = texture_ref(ctx, opacity, true);
            m.opacity_texture = derived_texture(ctx, opacity, o, [](const Vec4& v) {
                return Vec4(1.0f, 1.0f, 1.0f, std::clamp((v.r + v.g + v.b) / 3.0f, 0.0f, 1.0f));
            });
            m.base_alpha = 1.0f;
        } else {
            m.base_alpha = scalar_input(ctx, bsdf, "opacity", 0.5f);
        }
        m.alpha_mode = AlphaMode::Blend;
    } else if (type == "blendbsdf") {
        m = blend(ctx, bsdf, depth);
    } else {
        ctx.fail(bsdf, "bsdf type '" + type + "' is not supported");
    }
    if (pugi::xml_attribute id = bsdf.attribute("id")) m.name = id.value();
    if (m.name.empty()) m.name = type;
    return m;
}

}  // namespace

Material read_bsdf(Context& ctx, pugi::xml_node bsdf) {
    return read(ctx, bsdf, 0);
}

int material_index(Context& ctx, pugi::xml_node bsdf) {
    const auto found = ctx.material_of_bsdf.find(bsdf.internal_object());
    if (found != ctx.material_of_bsdf.end()) return found->second;
    ctx.scene().materials.push_back(read_bsdf(ctx, bsdf));
    const int index = int(ctx.scene().materials.size()) - 1;
    ctx.material_of_bsdf[bsdf.internal_object()] = index;
    return index;
}

int default_material_index(Context& ctx) {
    const auto found = ctx.material_of_bsdf.find(nullptr);
    if (found != ctx.material_of_bsdf.end()) return found->second;
    Material m = diffuse(ColorInput{Rgb(0.5f), {}});
    m.name = "default";
    ctx.scene().materials.push_back(m);
    const int index = int(ctx.scene().materials.size()) - 1;
    ctx.material_of_bsdf[nullptr] = index;
    return index;
}

}  // namespace mvpl::scene::mitsuba

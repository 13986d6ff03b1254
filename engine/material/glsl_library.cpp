#include "engine/material/glsl_library.h"

#include <array>
#include <vector>

#include "engine/material/node_kind.h"
#include "shaders/shared/closure.h"

namespace mvpl::material {

// shading_math_glsl.cpp.in
extern const std::string_view kShadingConstantsGlsl;
extern const std::string_view kShadingMathGlsl;

namespace {

using Deps = std::array<std::string_view, 5>;

struct Entry {
    std::string_view name;
    Deps deps;
    std::string_view code;
};

// Fresnel and the GGX terms are shaders/shared/shading_math.h's, which C++ compiles too; the
// closures' evaluation below is line for line the C++ of lambertian.h, conductor.*,
// dielectric_diffuse.*, bsdf.cpp and closure.h, in world space where the CPU uses the local frame
// (shading_math.h says why).
const Entry kEntries[] = {
    // shaders/shared/shading_constants.h and shading_math.h, as C++ compiles them: the
    // functions by name below.
    {"constants", {}, kShadingConstantsGlsl},
    {"shading_math", {"constants"}, kShadingMathGlsl},
    {"schlick_weight", {"shading_math"}, ""},
    {"fresnel_schlick", {"shading_math"}, ""},
    {"f0_from_ior", {"shading_math"}, ""},
    {"roughness_to_alpha", {"shading_math"}, ""},
    {"ggx_d", {"shading_math"}, ""},
    {"ggx_visibility", {"shading_math"}, ""},
    {"Closure", {}, shared::kClosureGlsl},
    {"SurfacePoint",
     {},
     R"(// What value and normal nodes read (node_kind.h, SurfacePoint): t, b, n is the tangent frame.
struct SurfacePoint {
    vec2 uv0;
    vec2 uv1;
    vec4 color;
    vec3 t;
    vec3 b;
    vec3 n;
};
)"},
    {"alpha_hash",
     {},
     R"(// A uniform number in [0, 1) from a position and a seed: glTF BLEND as hashed
// transparency (engine/trace/accel.cpp hashes the ray instead).
float alpha_hash(vec3 p, uint seed) {
    const uvec3 v = floatBitsToUint(p);
    uint h = seed * 747796405u + 2891336453u;
    h = (h ^ v.x) * 0x9E3779B9u;
    h ^= h >> 16;
    h = (h ^ v.y) * 0x85EBCA6Bu;
    h ^= h >> 13;
    h = (h ^ v.z) * 0xC2B2AE35u;
    h ^= h >> 16;
    h *= 0x27D4EB2Du;
    h ^= h >> 15;
    return float(h >> 8) * (1.0 / 16777216.0);
}
)"},
    {"max_component", {}, R"(float max_component(vec3 v) {
    return max(v.r, max(v.g, v.b));
}
)"},
    {"ggx_reflection",
     {"ggx_d", "ggx_visibility"},
     R"(// microfacet.h ggx_reflection: (D·V, wo·h), or false where h is undefined.
bool ggx_reflection(vec3 n, vec3 wo, vec3 wi, float alpha, out float dv, out float cos_oh) {
    const vec3 sum = wo + wi;
    const float len2 = dot(sum, sum);
    if (!(len2 > 1e-30)) return false;
    const vec3 h = sum / sqrt(len2);
    dv = ggx_d(n, h, alpha) * ggx_visibility(n, wo, wi, alpha);
    cos_oh = clamp(dot(wo, h), 0.0, 1.0);
    return true;
}
)"},
    {"clamp_closure",
     {"Closure"},
     R"(// closure.h: clamp_to_valid_ranges and closure_type.
float clamp_unit(float x) { return x > 0.0 ? min(x, 1.0) : 0.0; }
float clamp_non_negative(float x) { return x > 0.0 ? min(x, 1e6) : 0.0; }
Closure clamp_closure(vec3 base_color, float metallic, float roughness, float specular,
                      vec3 specular_color, float ior) {
    Closure c;
    c.base_color = vec3(clamp_unit(base_color.r), clamp_unit(base_color.g), clamp_unit(base_color.b));
    c.metallic = clamp_unit(metallic);
    c.roughness = clamp_unit(roughness);
    c.specular = clamp_unit(specular);
    c.specular_color = vec3(clamp_non_negative(specular_color.r),
                            clamp_non_negative(specular_color.g),
                            clamp_non_negative(specular_color.b));
    c.ior = clamp_non_negative(ior);
    if (c.metallic <= 0.0 && c.specular <= 0.0) c.type = 0u;
    else if (c.metallic >= 1.0) c.type = 1u;
    else if (c.metallic <= 0.0) c.type = 2u;
    else c.type = 3u;
    return c;
}
)"},
    // The closure types' evaluation f(wo, wi) without the cosine (shading).
    {"lambertian_eval",
     {"Closure", "constants"},
     R"(vec3 lambertian_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    if (dot(n, wo) <= 0.0 || dot(n, wi) <= 0.0) return vec3(0.0);
    return c.base_color * kInvPi;
}
)"},
    {"ggx_conductor_eval",
     {"Closure", "roughness_to_alpha", "fresnel_schlick", "ggx_reflection"},
     R"(vec3 ggx_conductor_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    if (dot(n, wo) <= 0.0 || dot(n, wi) <= 0.0) return vec3(0.0);
    float dv, cos_oh;
    if (!ggx_reflection(n, wo, wi, roughness_to_alpha(c.roughness), dv, cos_oh)) return vec3(0.0);
    return fresnel_schlick(c.base_color, vec3(1.0), cos_oh) * dv;
}
)"},
    {"dielectric_diffuse_eval",
     {"metal_rough_eval"},
     R"(// dielectric_diffuse.h: the metal-rough lobe without its metal part.
vec3 dielectric_diffuse_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    Closure d = c;
    d.metallic = 0.0;
    return metal_rough_eval(d, n, wo, wi);
}
)"},
    {"metal_rough_f0",
     {"Closure", "f0_from_ior"},
     R"(// bsdf.cpp, dielectric_layer(): the dielectric's normal-incidence reflectance, clamped to 1
// before the multiplication by specular.
vec3 metal_rough_f0(Closure c) {
    return min(f0_from_ior(c.ior) * c.specular_color, vec3(1.0)) * c.specular;
}
)"},
    {"metal_rough_diffuse_eval",
     {"Closure", "metal_rough_f0", "dielectric_helpers"},
     R"(// bsdf.cpp, Bsdf::eval_diffuse: the diffuse lobe of metal_rough_eval alone (all of a
// Lambertian closure's f, none of a conductor's); independent of the roughness.
vec3 metal_rough_diffuse_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    const float co = dot(n, wo);
    const float ci = dot(n, wi);
    if (co <= 0.0 || ci <= 0.0) return vec3(0.0);
    if (c.metallic <= 0.0 && c.specular <= 0.0) return c.base_color * kInvPi;
    const float f90 = c.specular;
    const float f0_max = max_component(metal_rough_f0(c));
    const bool has_diffuse = c.metallic < 1.0 && max_component(c.base_color) > 0.0 && f0_max < 1.0;
    if (!has_diffuse) return vec3(0.0);
    const float w_d = (1.0 - fresnel_schlick(f0_max, f90, co)) *
                      (1.0 - fresnel_schlick(f0_max, f90, ci));
    return (1.0 - c.metallic) * w_d * (c.base_color * kInvPi);
}
)"},
    {"metal_rough_eval",
     {"Closure", "roughness_to_alpha", "metal_rough_f0", "metal_rough_diffuse_eval",
      "dielectric_helpers"},
     R"(// bsdf.cpp, Bsdf::eval with the derived members of its constructor; a Lambertian closure
// (metallic and specular 0) is its diffuse lobe alone.
vec3 metal_rough_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    if (dot(n, wo) <= 0.0 || dot(n, wi) <= 0.0) return vec3(0.0);
    const vec3 f0 = metal_rough_f0(c);
    const float f90 = c.specular;
    const float alpha = roughness_to_alpha(c.roughness);
    const bool has_specular = c.metallic > 0.0 || f90 > 0.0;
    vec3 f = metal_rough_diffuse_eval(c, n, wo, wi);
    float dv, cos_oh;
    if (has_specular && ggx_reflection(n, wo, wi, alpha, dv, cos_oh)) {
        const vec3 fresnel = (1.0 - c.metallic) * fresnel_schlick(f0, vec3(f90), cos_oh) +
                             c.metallic * fresnel_schlick(c.base_color, vec3(1.0), cos_oh);
        f += fresnel * dv;
    }
    return f;
}
)"},
    {"dielectric_helpers", {"constants", "max_component", "fresnel_schlick", "ggx_reflection"}, ""},
};

}  // namespace

const GlslFunction* find_glsl_function(std::string_view name) {
    static const auto functions = [] {
        std::vector<GlslFunction> out;
        for (const Entry& e : kEntries) {
            size_t n = 0;
            while (n < e.deps.size() && !e.deps[n].empty())
                ++n;
            out.push_back({e.name, std::span<const std::string_view>(e.deps.data(), n), e.code});
        }
        // Each node kind's own function (nodes/*.cpp); constants have none.
        for (const NodeKind* kind : node_kinds()) {
            if (!kind->glsl.empty())
                out.push_back({kind->name, kind->glsl_dependencies, kind->glsl});
        }
        return out;
    }();
    for (const GlslFunction& f : functions) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

}  // namespace mvpl::material

#include "engine/material/glsl_library.h"

#include <array>
#include <vector>

#include "engine/material/node_kind.h"
#include "shaders/shared/closure.h"

namespace mvpl::material {

// shading_math_glsl.cpp.in
extern const std::string_view kShadingConstantsGlsl;
extern const std::string_view kShadingMathGlsl;
extern const std::string_view kLambertianGlsl;
extern const std::string_view kClosureEvalGlsl;
extern const std::string_view kClosureRangesGlsl;

namespace {

using Deps = std::array<std::string_view, 5>;

struct Entry {
    std::string_view name;
    Deps deps;
    std::string_view code;
};

// Fresnel, the GGX terms and the closures' reflection are shaders/shared/*.h's, which C++
// compiles too (the CPU in its local frame, n = (0, 0, 1); shading_math.h says why); the closure
// types' functions below only read a Closure into them.
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
    {"ggx_reflection", {"ggx_d", "ggx_visibility"}, ""},
    // shaders/shared/lambertian.h, closure_eval.h and closure_ranges.h.
    {"lambertian_reflection", {"constants"}, kLambertianGlsl},
    {"closure_ranges", {"constants"}, kClosureRangesGlsl},
    {"closure_eval",
     {"Closure", "max_component", "lambertian_reflection", "fresnel_schlick", "ggx_reflection"},
     kClosureEvalGlsl},
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
    {"clamp_closure",
     {"Closure", "closure_ranges"},
     R"(// closure.h: make_closure, clamp_to_valid_ranges and closure_type.
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
    c.type = closure_type_of(c.metallic, c.specular);
    return c;
}
)"},
    // The closure types' evaluation f(wo, wi) without the cosine (shading), the shared
    // functions of closure_eval.h applied to a Closure.
    {"lambertian_eval",
     {"Closure", "lambertian_reflection"},
     R"(vec3 lambertian_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    return lambertian_reflection(c.base_color, n, wo, wi);
}
)"},
    {"ggx_conductor_eval",
     {"closure_eval"},
     R"(vec3 ggx_conductor_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    return conductor_reflection(c.base_color, roughness_to_alpha(c.roughness), n, wo, wi);
}
)"},
    {"closure_lobes",
     {"closure_eval"},
     R"(// A clamped closure's lobes, as Bsdf's constructor derives them (no transmission here).
ReflectionLobes closure_lobes(Closure c) {
    return reflection_lobes(c.base_color, c.metallic, roughness_to_alpha(c.roughness),
                            dielectric_f0(c.specular_color, c.specular, c.ior), c.specular, false);
}
)"},
    {"metal_rough_diffuse_eval",
     {"closure_lobes"},
     R"(// Bsdf::eval_diffuse: the diffuse lobe of metal_rough_eval alone.
vec3 metal_rough_diffuse_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    return metal_rough_diffuse(closure_lobes(c), n, wo, wi);
}
)"},
    {"metal_rough_eval",
     {"closure_lobes"},
     R"(// Bsdf::eval outside a solid; a Lambertian closure is its diffuse lobe alone.
vec3 metal_rough_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    return metal_rough_reflection(closure_lobes(c), n, wo, wi);
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

#include "engine/material/glsl_library.h"

#include <array>
#include <vector>

namespace mvpl::material {
namespace {

using Deps = std::array<std::string_view, 4>;

struct Entry {
    std::string_view name;
    Deps deps;
    std::string_view code;
};

// Line for line the C++ of fresnel.h, microfacet.*, lambertian.h, conductor.*,
// dielectric_diffuse.*, bsdf.cpp and node_eval.*, in world space where the CPU uses the local
// frame: w.z = dot(n, w) and w.x² + w.y² = |n × w|² (the cross product keeps the small sines of
// glossy lobes free of the cancellation in 1 − cos²).
const Entry kEntries[] = {
    {"constants", {}, R"(const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kMinAlpha = 1e-4;  // microfacet.h
const float kMinCos = 1e-7;    // microfacet.h
)"},
    {"Closure",
     {},
     R"(// A resolved closure (engine/material/closure.h) and its type (node_eval.h, ClosureType).
struct Closure {
    uint type;
    vec3 base_color;
    float metallic;
    vec3 specular_color;
    float specular;
    float roughness;
    float ior;
};
)"},
    {"SurfacePoint",
     {},
     R"(// What value and normal nodes read (node_eval.h, SurfacePoint): t, b, n is the tangent frame.
struct SurfacePoint {
    vec2 uv0;
    vec2 uv1;
    vec4 color;
    vec3 t;
    vec3 b;
    vec3 n;
};
)"},
    {"max_component", {}, R"(float max_component(vec3 v) {
    return max(v.r, max(v.g, v.b));
}
)"},
    {"schlick_weight", {}, R"(float schlick_weight(float cos_theta) {
    const float m = clamp(1.0 - abs(cos_theta), 0.0, 1.0);
    const float m2 = m * m;
    return m2 * m2 * m;
}
)"},
    {"fresnel_schlick",
     {"schlick_weight"},
     R"(vec3 fresnel_schlick(vec3 f0, vec3 f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}
float fresnel_schlick(float f0, float f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}
)"},
    {"f0_from_ior", {}, R"(float f0_from_ior(float ior) {
    const float n = max(ior, 0.0);
    const float r = (n - 1.0) / (n + 1.0);
    return r * r;
}
)"},
    {"roughness_to_alpha", {"constants"}, R"(float roughness_to_alpha(float roughness) {
    const float r = clamp(roughness, 0.0, 1.0);
    return max(r * r, kMinAlpha);
}
)"},
    {"sin2_about", {}, R"(float sin2_about(vec3 n, vec3 w) {
    const vec3 c = cross(n, w);
    return dot(c, c);
}
)"},
    {"ggx_d", {"constants", "sin2_about"}, R"(float ggx_d(vec3 n, vec3 h, float alpha) {
    const float a2 = alpha * alpha;
    const float hz = dot(n, h);
    const float denom = sin2_about(n, h) + a2 * hz * hz;
    if (!(denom > 0.0)) return 0.0;
    return a2 / (kPi * denom * denom);
}
)"},
    {"ggx_stretched_length",
     {"sin2_about"},
     R"(float ggx_stretched_length(vec3 n, vec3 w, float alpha) {
    const float z = dot(n, w);
    return sqrt(z * z + alpha * alpha * sin2_about(n, w));
}
)"},
    {"ggx_visibility",
     {"constants", "ggx_stretched_length"},
     R"(float ggx_visibility(vec3 n, vec3 wo, vec3 wi, float alpha) {
    const float co = max(dot(n, wo), kMinCos);
    const float ci = max(dot(n, wi), kMinCos);
    return 0.5 / (ci * ggx_stretched_length(n, wo, alpha) + co * ggx_stretched_length(n, wi, alpha));
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
     R"(// closure.h clamp_to_valid_ranges and node_eval.h closure_type.
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
    // Value nodes.
    {"image_texture",
     {},
     R"(// scene::Texture::sample after TextureRef::transform, with texelFetch so that the wrap modes
// (0 repeat, 1 clamp to edge, 2 mirrored repeat) and the bilinear filter (filter 1) are those of
// the CPU bit for bit rather than the sampler's.
float texture_reduce(float u, int wrap) {
    if (isnan(u) || isinf(u)) return 0.0;
    if (wrap == 0) return u - floor(u);
    if (wrap == 2) return u - 2.0 * floor(0.5 * u);
    return clamp(u, -1.0, 2.0);
}
int texture_wrap_index(int i, int size, int wrap) {
    if (wrap == 0) {
        const int m = i % size;
        return m < 0 ? m + size : m;
    }
    if (wrap == 2) {
        const int period = 2 * size;
        int m = i % period;
        if (m < 0) m += period;
        return m < size ? m : period - 1 - m;
    }
    return clamp(i, 0, size - 1);
}
vec4 texture_texel(sampler2D tex, int i, int j, ivec2 size, int wrap_s, int wrap_t) {
    return texelFetch(tex, ivec2(texture_wrap_index(i, size.x, wrap_s),
                                 texture_wrap_index(j, size.y, wrap_t)), 0);
}
vec4 image_texture(sampler2D tex, vec2 uv, vec2 offset, float rotation, vec2 scale, int wrap_s,
                   int wrap_t, int filter_mode, vec4 factor) {
    vec2 st = uv * scale;
    if (rotation != 0.0) {
        const float c = cos(rotation);
        const float s = sin(rotation);
        st = vec2(c * st.x + s * st.y, -s * st.x + c * st.y);
    }
    st += offset;
    const ivec2 size = textureSize(tex, 0);
    const float x = texture_reduce(st.x, wrap_s) * float(size.x);
    const float y = texture_reduce(st.y, wrap_t) * float(size.y);
    if (filter_mode == 0) {
        return factor * texture_texel(tex, int(floor(x)), int(floor(y)), size, wrap_s, wrap_t);
    }
    const float fx = x - 0.5;
    const float fy = y - 0.5;
    const int x0 = int(floor(fx));
    const int y0 = int(floor(fy));
    const float tx = fx - float(x0);
    const float ty = fy - float(y0);
    const vec4 top = mix(texture_texel(tex, x0, y0, size, wrap_s, wrap_t),
                         texture_texel(tex, x0 + 1, y0, size, wrap_s, wrap_t), tx);
    const vec4 bottom = mix(texture_texel(tex, x0, y0 + 1, size, wrap_s, wrap_t),
                            texture_texel(tex, x0 + 1, y0 + 1, size, wrap_s, wrap_t), tx);
    return factor * mix(top, bottom, ty);
}
)"},
    {"vertex_color", {}, R"(vec4 vertex_color(vec4 factor, vec4 color) {
    return factor * color;
}
)"},
    {"mix_node", {}, R"(vec4 mix_node(vec4 a, vec4 b, float t) {
    const float f = clamp(t, 0.0, 1.0);
    return a + (b - a) * f;
}
)"},
    {"emission", {}, R"(vec4 emission(vec4 colour, float strength) {
    return vec4(colour.rgb * strength, 1.0);
}
)"},
    {"normal_map", {"SurfacePoint"}, R"(vec3 normal_map(vec3 texel, float scale, SurfacePoint s) {
    vec3 n_ts = 2.0 * texel - vec3(1.0);
    n_ts.xy *= scale;
    const vec3 n = s.t * n_ts.x + s.b * n_ts.y + s.n * n_ts.z;
    const float len2 = dot(n, n);
    if (!(len2 > 1e-12) || isinf(len2)) return s.n;
    return n / sqrt(len2);
}
)"},
    {"bump_map",
     {"SurfacePoint"},
     R"(vec3 bump_map(float h, float h_u, float h_v, float du, float dv, float scale, SurfacePoint s) {
    const float dh_du = du > 0.0 ? (h_u - h) / du : 0.0;
    const float dh_dv = dv > 0.0 ? (h_v - h) / dv : 0.0;
    const vec3 n = s.n - scale * (dh_du * s.t + dh_dv * s.b);
    const float len2 = dot(n, n);
    if (!(len2 > 1e-12) || isinf(len2)) return s.n;
    return n / sqrt(len2);
}
)"},
    // Closure nodes: resolution (G-buffer) ...
    {"lambertian", {"clamp_closure"}, R"(Closure lambertian(vec3 base_color) {
    return clamp_closure(base_color, 0.0, 1.0, 0.0, vec3(1.0), 1.5);
}
)"},
    {"ggx_conductor", {"clamp_closure"}, R"(Closure ggx_conductor(vec3 f0, float roughness) {
    return clamp_closure(f0, 1.0, roughness, 1.0, vec3(1.0), 1.5);
}
)"},
    {"dielectric_diffuse",
     {"clamp_closure"},
     R"(Closure dielectric_diffuse(vec3 base_color, float roughness, float specular,
                           vec3 specular_color, float ior) {
    return clamp_closure(base_color, 0.0, roughness, specular, specular_color, ior);
}
)"},
    {"metal_rough",
     {"clamp_closure"},
     R"(Closure metal_rough(vec3 base_color, float metallic, float roughness, float specular,
                    vec3 specular_color, float ior) {
    return clamp_closure(base_color, metallic, roughness, specular, specular_color, ior);
}
)"},
    {"rough_dielectric",
     {"clamp_closure"},
     R"(// The reflection lobe only: a dielectric layer over a black base (node_graph.h).
Closure rough_dielectric(float roughness, float specular, vec3 specular_color, float ior) {
    return clamp_closure(vec3(0.0), 0.0, roughness, specular, specular_color, ior);
}
)"},
    // ... and evaluation f(wo, wi) without the cosine (shading), for the closure types.
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
    {"metal_rough_eval",
     {"Closure", "roughness_to_alpha", "f0_from_ior", "dielectric_helpers"},
     R"(// bsdf.cpp, Bsdf::eval with the derived members of its constructor.
vec3 metal_rough_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    const float co = dot(n, wo);
    const float ci = dot(n, wi);
    if (co <= 0.0 || ci <= 0.0) return vec3(0.0);
    if (c.metallic <= 0.0 && c.specular <= 0.0) return c.base_color * kInvPi;
    // dielectric_layer(): the clamp to 1 before the multiplication by specular.
    const vec3 f0 = min(f0_from_ior(c.ior) * c.specular_color, vec3(1.0)) * c.specular;
    const float f90 = c.specular;
    const float f0_max = max_component(f0);
    const float alpha = roughness_to_alpha(c.roughness);
    const bool has_specular = c.metallic > 0.0 || f90 > 0.0;
    const bool has_diffuse = c.metallic < 1.0 && max_component(c.base_color) > 0.0 && f0_max < 1.0;
    vec3 f = vec3(0.0);
    if (has_diffuse) {
        const float w_d = (1.0 - fresnel_schlick(f0_max, f90, co)) *
                          (1.0 - fresnel_schlick(f0_max, f90, ci));
        f += (1.0 - c.metallic) * w_d * (c.base_color * kInvPi);
    }
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
        return out;
    }();
    for (const GlslFunction& f : functions) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

}  // namespace mvpl::material

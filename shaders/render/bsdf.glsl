// The glTF metallic-roughness BRDF of engine/material (bsdf.cpp, lambertian.h, microfacet.cpp,
// fresnel.h, conductor.h, dielectric_diffuse.*), line for line, evaluated in world space: every
// local-frame quantity the CPU reads from a direction w in the frame of n is w.z = dot(n, w) and
// w.x² + w.y² = |n × w|² (the cross product keeps the small sines of glossy lobes free of the
// cancellation in 1 − cos²). Parameters are clamped on the host (clamp_to_valid_ranges), as the
// CPU Bsdf constructor does. Directions point away from the surface; f excludes the cosine.

const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kMinAlpha = 1e-4;  // microfacet.h
const float kMinCos = 1e-7;    // microfacet.h

struct Closure {
    vec3 base_color;
    float metallic;
    vec3 specular_color;
    float specular;
    float roughness;
    float ior;
};

float max_component(vec3 v) {
    return max(v.r, max(v.g, v.b));
}

// fresnel.h
float schlick_weight(float cos_theta) {
    const float m = clamp(1.0 - abs(cos_theta), 0.0, 1.0);
    const float m2 = m * m;
    return m2 * m2 * m;
}
vec3 fresnel_schlick(vec3 f0, vec3 f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}
float fresnel_schlick(float f0, float f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}
float f0_from_ior(float ior) {
    const float n = max(ior, 0.0);
    const float r = (n - 1.0) / (n + 1.0);
    return r * r;
}

// microfacet.h / microfacet.cpp
float roughness_to_alpha(float roughness) {
    const float r = clamp(roughness, 0.0, 1.0);
    return max(r * r, kMinAlpha);
}
float sin2_about(vec3 n, vec3 w) {
    const vec3 c = cross(n, w);
    return dot(c, c);
}
float ggx_d(vec3 n, vec3 h, float alpha) {
    const float a2 = alpha * alpha;
    const float hz = dot(n, h);
    const float denom = sin2_about(n, h) + a2 * hz * hz;
    if (!(denom > 0.0)) return 0.0;
    return a2 / (kPi * denom * denom);
}
float ggx_stretched_length(vec3 n, vec3 w, float alpha) {
    const float z = dot(n, w);
    return sqrt(z * z + alpha * alpha * sin2_about(n, w));
}
float ggx_visibility(vec3 n, vec3 wo, vec3 wi, float alpha) {
    const float co = max(dot(n, wo), kMinCos);
    const float ci = max(dot(n, wi), kMinCos);
    return 0.5 / (ci * ggx_stretched_length(n, wo, alpha) + co * ggx_stretched_length(n, wi, alpha));
}

// bsdf.cpp, Bsdf::eval with the derived members of its constructor.
vec3 bsdf_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {
    const float co = dot(n, wo);
    const float ci = dot(n, wi);
    if (co <= 0.0 || ci <= 0.0) return vec3(0.0);
    const bool lambertian = c.metallic <= 0.0 && c.specular <= 0.0;
    if (lambertian) return c.base_color * kInvPi;

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
    if (has_specular) {
        const vec3 sum = wo + wi;
        const float len2 = dot(sum, sum);
        if (len2 > 1e-30) {
            const vec3 h = sum / sqrt(len2);
            const float dv = ggx_d(n, h, alpha) * ggx_visibility(n, wo, wi, alpha);
            const float cos_oh = clamp(dot(wo, h), 0.0, 1.0);
            const vec3 fresnel = (1.0 - c.metallic) * fresnel_schlick(f0, vec3(f90), cos_oh) +
                                 c.metallic * fresnel_schlick(c.base_color, vec3(1.0), cos_oh);
            f += fresnel * dv;
        }
    }
    return f;
}

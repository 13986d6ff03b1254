#include "engine/sampler/mitsuba_clamping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/math.h"
#include "engine/core/sampling.h"
#include "engine/sampler/light_tracer.h"
#include "engine/sampler/sample_stream.h"
#include "engine/trace/ray.h"

namespace mvpl::sampler {

namespace {

constexpr int kRays = 250;     // Mitsuba's sampleCount
constexpr int kPaths = 256;    // light paths whose VPLs are averaged
constexpr uint64_t kSeed = 0;  // fixed: the clamp is the scene's, not the render seed's

// Sobol's second dimension (Kollig and Keller's sobol2), the other half of Mitsuba's sample02.
double sobol2(uint32_t i) {
    uint32_t r = 0;
    for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
        if (i & 1u) r ^= v;
    return double(r) / 4294967296.0;
}

}  // namespace

float mitsuba_min_distance(const light::Vpl& vpl, const scene::Scene& scene,
                           const trace::Accel& accel, float clamping) {
    if (vpl.type == light::VplType::Directional) return -1.0f;
    // Point and spot lights see the whole sphere; surface and area VPLs their lit hemisphere.
    const bool sphere = vpl.type == light::VplType::Point || vpl.type == light::VplType::Spot;
    const Vec3 up = vpl.type == light::VplType::Surface ? vpl.shading_normal : vpl.normal;
    const Frame frame(up);
    float t_min = std::numeric_limits<float>::infinity(), t_max = 0.0f;
    for (int i = 0; i < kRays; ++i) {
        const Vec2 u(float(radical_inverse(uint64_t(i), 2)), float(sobol2(uint32_t(i))));
        const Vec3 dir =
            sphere ? sample_uniform_sphere(u) : frame.to_world(sample_cosine_hemisphere(u));
        const trace::Ray ray =
            sphere ? trace::Ray{vpl.position, dir}
                   : trace::spawn_ray(vpl.position, vpl.normal, dir, accel.coordinate_scale());
        if (const auto hit = accel.intersect(ray)) {
            t_min = std::min(t_min, hit->t);
            t_max = std::max(t_max, hit->t);
        }
    }
    float n = 0.0f, f = 0.0f;
    if (t_max > 0.0f && t_min < t_max) {
        f = 1.5f * t_max;
        n = std::max(t_min / 1.5f, 1e-5f * f);
    } else {
        const scene::Bounds bounds = scene.bounds();
        const float r = 0.5f * bounds.diagonal();
        const float outside = std::max(glm::length(vpl.position - bounds.center()) - r, 0.0f);
        f = outside + 2.25f * r;
        n = std::max(outside - 0.25f * r, 1e-5f * f);
    }
    return n + clamping * (f - n);
}

float mitsuba_clamp(const scene::Scene& scene, const trace::Accel& accel,
                    const light::LightSampler& lights, float clamping, int max_depth) {
    LightTracerOptions options;
    options.max_depth = max_depth;
    const LightTracer tracer(scene, accel, lights, options);
    std::vector<light::Vpl> vpls;
    for (uint64_t path = 0; path < kPaths; ++path) {
        RandomStream u(kSeed, path);
        tracer.trace(u, vpls);
    }
    double sum = 0.0;
    int count = 0;
    for (const light::Vpl& vpl : vpls) {
        const float d = mitsuba_min_distance(vpl, scene, accel, clamping);
        if (d < 0.0f) continue;
        sum += d;
        ++count;
    }
    const float diagonal = scene.bounds().diagonal();
    if (count == 0 || !(diagonal > 0.0f)) return light::kDefaultClamp;
    return std::clamp(float(sum / count) / diagonal, 0.0f, 1.0f);
}

}  // namespace mvpl::sampler

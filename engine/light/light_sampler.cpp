#include "engine/light/light_sampler.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/core/sampling.h"
#include "engine/trace/interaction.h"
#include "shaders/shared/spot_falloff.h"

namespace mvpl::light {

float spot_attenuation(const scene::Light& light, float cos_angle) {
    return shared::spot_falloff(std::cos(light.inner_cone), std::cos(light.outer_cone), cos_angle);
}

namespace {

struct TrianglePoints {
    Vec3 p0, p1, p2;
};

TrianglePoints triangle_points(const scene::Mesh& mesh, int triangle) {
    const uint32_t* idx = &mesh.indices[3 * size_t(triangle)];
    return {mesh.positions[idx[0]], mesh.positions[idx[1]], mesh.positions[idx[2]]};
}

// The emitter of scene light `l`, its power the light's flux (a directional light's through the
// disk of the scene's bounding sphere, radius `scene_radius`).
Emitter punctual_emitter(const scene::Light& light, int l, float scene_radius) {
    Emitter e;
    e.light = l;
    const double y = luminance(light.intensity);
    constexpr double pi = std::numbers::pi;
    switch (light.type) {
        case scene::LightType::Point:
            e.type = EmitterType::Point;
            e.power = float(4.0 * pi * y);
            break;
        case scene::LightType::Spot:
            e.type = EmitterType::Spot;
            // pbrt-v3's estimate of the flux inside the smooth cone.
            e.power = float(2.0 * pi * y *
                            (1.0 - 0.5 * (std::cos(double(light.inner_cone)) +
                                          std::cos(double(light.outer_cone)))));
            break;
        case scene::LightType::Directional:
            e.type = EmitterType::Directional;
            e.power = float(pi * double(scene_radius) * double(scene_radius) * y);
            break;
    }
    return e;
}

}  // namespace

LightSampler::LightSampler(const scene::Scene& scene) : m_scene(scene), m_materials(scene) {
    const float diagonal = scene.bounds().diagonal();
    m_scene_radius = diagonal > 0.0f ? 0.5f * diagonal : 1.0f;
    if (!scene.bounds().empty()) m_scene_center = scene.bounds().center();
    add_triangle_emitters();
    for (size_t l = 0; l < scene.lights.size(); ++l)
        m_emitters.push_back(punctual_emitter(scene.lights[l], int(l), m_scene_radius));
    if (scene.environment.active()) {
        // The flux through the bounding sphere's disk, π r² ∫ L dω (4π² r² L when uniform), as
        // a directional light's π r² E.
        m_environment_sampler = EnvironmentSampler(scene.environment);
        Emitter e;
        e.type = EmitterType::Environment;
        const double r = double(m_scene_radius);
        e.power = float(std::numbers::pi * r * r * m_environment_sampler.integrated_luminance());
        m_environment = int(m_emitters.size());
        m_emitters.push_back(e);
    }
    build_cdf();
}

void LightSampler::add_triangle_emitters() {
    const scene::Scene& scene = m_scene;
    m_first_emitter.assign(scene.meshes.size(), -1);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        if (!m_materials.is_emissive(mesh.material)) continue;
        m_first_emitter[m] = int(m_emitters.size());
        // Selection by flux, a weight only (sample_li and sample_le read the graph's emission
        // where they land). Untextured: the emission factor's. Textured: the emission read at
        // seven points of the triangle, plus 1 % of the factor's so that no triangle whose
        // texture glows only between those points becomes unreachable. Weighing by the factor
        // alone picked mostly black texels of DamagedHelmet's emissive map: 134 VPLs from 4096
        // light paths.
        const double radiance = luminance(scene.materials[mesh.material].emission());
        const bool textured = scene.materials[mesh.material].emission_texture().texture >= 0;
        for (size_t t = 0; t < mesh.triangle_count(); ++t) {
            const TrianglePoints tri = triangle_points(mesh, int(t));
            double weight = radiance;
            if (textured) {
                constexpr Vec2 kPoints[7] = {{1.0f / 3.0f, 1.0f / 3.0f},
                                             {0.05f, 0.05f},
                                             {0.9f, 0.05f},
                                             {0.05f, 0.9f},
                                             {0.5f, 0.0f},
                                             {0.0f, 0.5f},
                                             {0.5f, 0.5f}};
                double sum = 0.0;
                for (const Vec2& b : kPoints)
                    sum += luminance(m_materials.emission(
                        mesh.material, trace::surface_attributes(mesh, int(t), b)));
                weight = sum / 7.0 + 0.01 * radiance;
            }
            Emitter e;
            e.type = EmitterType::Triangle;
            e.mesh = int(m);
            e.triangle = int(t);
            // In double: the float cross product of a large triangle can overflow where its
            // area, and the power, still fit a float.
            const DVec3 p0(tri.p0);
            const double area =
                0.5 * glm::length(glm::cross(DVec3(tri.p1) - p0, DVec3(tri.p2) - p0));
            e.area = float(area);
            e.power = float(std::numbers::pi * area * weight);
            m_emitters.push_back(e);
        }
    }
}

void LightSampler::build_cdf() {
    // Emitters with no power cannot be sampled; they stay in the list so that indices are stable.
    // A power beyond float is not dropped (that would render black without a word): the loaders
    // refuse such scenes (scene::check_emitted_power), so one here is a bug.
    m_cdf.reserve(m_emitters.size());
    double sum = 0.0;
    for (const Emitter& e : m_emitters) {
        if (!std::isfinite(e.power)) {
            throw std::logic_error("an emitter's power is not finite (" + std::to_string(e.power) +
                                   "); scene::check_emitted_power should have refused the scene");
        }
        sum += e.power > 0.0f ? e.power : 0.0f;
        m_cdf.push_back(float(sum));
    }
    if (!std::isfinite(float(sum))) {
        throw std::logic_error(
            "the emitters' total power overflows float; "
            "scene::check_emitted_power should have refused the scene");
    }
    m_total_power = float(sum);
    if (!(m_total_power > 0.0f)) {
        m_emitters.clear();
        m_cdf.clear();
        m_total_power = 0.0f;
        m_environment = -1;
    }
}

int LightSampler::emitter_of(int mesh, int triangle) const {
    if (mesh < 0 || size_t(mesh) >= m_first_emitter.size() || m_first_emitter[mesh] < 0) return -1;
    return m_first_emitter[mesh] + triangle;
}

Rgb LightSampler::emitted_radiance(int mesh, int triangle, const Vec2& barycentric,
                                   const Vec3& w) const {
    const scene::Mesh& m = m_scene.meshes[mesh];
    const TrianglePoints tri = triangle_points(m, triangle);
    const Vec3 n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    if (glm::dot(n, w) <= 0.0f) return Rgb(0.0f);
    return m_materials.emission(m.material, trace::surface_attributes(m, triangle, barycentric));
}

Rgb LightSampler::environment_radiance(const Vec3& w) const {
    return m_environment >= 0 ? m_scene.environment.lookup(w) : Rgb(0.0f);
}

float LightSampler::pdf_environment(const Vec3& w) const {
    if (m_environment < 0) return 0.0f;
    return pick_probability(m_environment) * m_environment_sampler.pdf(w);
}

std::optional<LightSample> LightSampler::sample_li(const Vec3& ref, float u_pick,
                                                   const Vec2& u) const {
    if (m_emitters.empty()) return std::nullopt;
    const float target = u_pick * m_total_power;
    const size_t index =
        std::min<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), target) - m_cdf.begin(),
                         m_emitters.size() - 1);
    const Emitter& e = m_emitters[index];
    const float pick = e.power / m_total_power;
    if (!(pick > 0.0f)) return std::nullopt;

    LightSample s;
    if (e.type == EmitterType::Triangle) {
        const scene::Mesh& mesh = m_scene.meshes[e.mesh];
        const TrianglePoints tri = triangle_points(mesh, e.triangle);
        const Vec2 b = sample_uniform_triangle(u);
        s.p = (1.0f - b.x - b.y) * tri.p0 + b.x * tri.p1 + b.y * tri.p2;
        const Vec3 cross = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
        const float cross_len = glm::length(cross);
        if (!(cross_len > 0.0f)) return std::nullopt;
        s.n = cross / cross_len;
        const Vec3 d = s.p - ref;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return std::nullopt;
        s.distance = std::sqrt(dist2);
        s.wi = d / s.distance;
        const float cos_light = -glm::dot(s.n, s.wi);
        if (cos_light <= 0.0f) return std::nullopt;  // back face: one-sided emitter
        s.pdf = pick * dist2 / (cos_light * e.area);
        s.li = m_materials.emission(mesh.material, trace::surface_attributes(mesh, e.triangle, b));
        if (!std::isfinite(s.pdf)) return std::nullopt;
        return s;
    }
    if (e.type == EmitterType::Environment) {
        const EnvironmentDirection d = m_environment_sampler.sample(u);
        if (!(d.pdf > 0.0f)) return std::nullopt;
        s.wi = d.w;
        s.distance = std::numeric_limits<float>::infinity();
        s.li = m_scene.environment.lookup(d.w);
        s.pdf = pick * d.pdf;
        return is_black(s.li) ? std::nullopt : std::optional<LightSample>(s);
    }

    std::optional<LightSample> punctual = punctual_li(m_scene.lights[e.light], ref);
    if (punctual) punctual->pdf = pick;
    return punctual;
}

std::optional<LightSample> punctual_li(const scene::Light& light, const Vec3& ref) {
    LightSample s;
    s.is_delta = true;
    s.pdf = 1.0f;
    if (light.type == scene::LightType::Directional) {
        s.wi = -light.direction;
        s.distance = std::numeric_limits<float>::infinity();
        s.li = light.intensity;
        return s;
    }
    s.p = light.position;
    const Vec3 d = light.position - ref;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return std::nullopt;
    s.distance = std::sqrt(dist2);
    s.wi = d / s.distance;
    s.li = light.intensity / dist2;
    if (light.type == scene::LightType::Spot)
        s.li *= spot_attenuation(light, glm::dot(light.direction, -s.wi));
    if (is_black(s.li)) return std::nullopt;
    return s;
}

float LightSampler::pdf_li(const Vec3& ref, int mesh, int triangle, const Vec3& p,
                           const Vec3& n) const {
    const int index = emitter_of(mesh, triangle);
    if (index < 0 || m_emitters.empty()) return 0.0f;
    const Emitter& e = m_emitters[index];
    const Vec3 d = p - ref;
    const float dist2 = glm::dot(d, d);
    const float cos_light = std::abs(glm::dot(n, d)) / std::sqrt(dist2);
    if (!(cos_light > 0.0f) || !(e.area > 0.0f)) return 0.0f;
    return (e.power / m_total_power) * dist2 / (cos_light * e.area);
}

std::optional<EmissionSample> LightSampler::sample_le(float u_pick, const Vec2& u_pos,
                                                      const Vec2& u_dir) const {
    if (m_emitters.empty()) return std::nullopt;
    const size_t index = std::min<size_t>(
        std::upper_bound(m_cdf.begin(), m_cdf.end(), u_pick * m_total_power) - m_cdf.begin(),
        m_emitters.size() - 1);
    return sample_le_from(int(index), m_emitters[index].power / m_total_power, u_pos, u_dir);
}

std::optional<EmissionSample> LightSampler::sample_le_from(int emitter, float pick,
                                                           const Vec2& u_pos,
                                                           const Vec2& u_dir) const {
    const Emitter& e = m_emitters[size_t(emitter)];
    EmissionSample s;
    s.type = e.type;
    s.emitter = emitter;
    s.pick = pick;
    if (!(s.pick > 0.0f)) return std::nullopt;

    if (e.type == EmitterType::Triangle) return triangle_le(e, s, u_pos, u_dir);
    if (e.type == EmitterType::Environment) return environment_le(s, u_pos, u_dir);
    const scene::Light& light = m_scene.lights[e.light];
    s.pdf_pos = 1.0f;
    s.le = light.intensity / s.pick;
    if (e.type == EmitterType::Directional) {
        // A disk of the bounding sphere's radius, one radius behind the centre, facing the light's
        // direction: every ray through the scene starts on it.
        const Frame frame(light.direction);
        const Vec2 d = m_scene_radius * sample_concentric_disk(u_pos);
        s.p = m_scene_center - m_scene_radius * light.direction + frame.s * d.x + frame.t * d.y;
        s.n = light.direction;
        s.direction = light.direction;
        s.pdf_pos = 1.0f / (kPi * m_scene_radius * m_scene_radius);
        s.pdf_dir = 1.0f;
        s.throughput = light.intensity / (s.pick * s.pdf_pos);
        return s;
    }
    s.p = light.position;
    if (e.type == EmitterType::Point) {
        s.direction = sample_uniform_sphere(u_dir);
        s.pdf_dir = 1.0f / (4.0f * kPi);
        s.throughput = light.intensity * (4.0f * kPi / s.pick);
        return s;
    }
    // Spot: uniform in the outer cone, the KHR falloff as a weight.
    const float cos_outer = std::cos(light.outer_cone);
    s.n = light.direction;
    s.direction = Frame(light.direction).to_world(sample_uniform_cone(u_dir, cos_outer));
    s.pdf_dir = 1.0f / (2.0f * kPi * std::max(1e-7f, 1.0f - cos_outer));
    const float falloff = spot_attenuation(light, glm::dot(light.direction, s.direction));
    s.throughput = light.intensity * (falloff / (s.pick * s.pdf_dir));
    return s;
}

std::optional<EmissionSample> LightSampler::triangle_le(const Emitter& e, EmissionSample s,
                                                        const Vec2& u_pos,
                                                        const Vec2& u_dir) const {
    const scene::Mesh& mesh = m_scene.meshes[e.mesh];
    const TrianglePoints tri = triangle_points(mesh, e.triangle);
    const Vec2 b = sample_uniform_triangle(u_pos);
    s.p = (1.0f - b.x - b.y) * tri.p0 + b.x * tri.p1 + b.y * tri.p2;
    const Vec3 cross = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    const float cross_len = glm::length(cross);
    if (!(cross_len > 0.0f) || !(e.area > 0.0f)) return std::nullopt;
    s.n = cross / cross_len;
    const Vec3 local = sample_cosine_hemisphere(u_dir);
    if (!(local.z > 0.0f)) return std::nullopt;
    s.direction = Frame(s.n).to_world(local);
    s.pdf_pos = 1.0f / e.area;
    s.pdf_dir = cosine_hemisphere_pdf(local.z);
    const Rgb radiance =
        m_materials.emission(mesh.material, trace::surface_attributes(mesh, e.triangle, b));
    s.le = radiance * (e.area / s.pick);
    // Le · cos θ / (pick · pdf_pos · cos θ/π): the cosine cancels exactly.
    s.throughput = radiance * (kPi * e.area / s.pick);
    return is_black(s.le) ? std::nullopt : std::optional<EmissionSample>(s);
}

std::optional<EmissionSample> LightSampler::environment_le(EmissionSample s, const Vec2& u_pos,
                                                           const Vec2& u_dir) const {
    // A direction towards the environment chosen by its sampler; the light travels the other
    // way, entering through a disk of the bounding sphere's radius as a directional light's.
    const EnvironmentDirection towards = m_environment_sampler.sample(u_dir);
    if (!(towards.pdf > 0.0f)) return std::nullopt;
    s.direction = -towards.w;
    const Frame frame(s.direction);
    const Vec2 d = m_scene_radius * sample_concentric_disk(u_pos);
    s.p = m_scene_center - m_scene_radius * s.direction + frame.s * d.x + frame.t * d.y;
    s.n = s.direction;
    s.pdf_pos = 1.0f / (kPi * m_scene_radius * m_scene_radius);
    s.pdf_dir = towards.pdf;
    s.le = m_scene.environment.lookup(towards.w) / (s.pick * s.pdf_dir);
    s.throughput = s.le / s.pdf_pos;
    return is_black(s.le) ? std::nullopt : std::optional<EmissionSample>(s);
}

}  // namespace mvpl::light

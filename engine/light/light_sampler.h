#pragma once
// All emitters of a scene — emissive triangles (area lights, front face only), point, spot and
// directional lights — and the light selection by power that next-event estimation and the light
// tracer share.
#include <optional>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/light/environment_sampler.h"
#include "engine/material/scene_materials.h"
#include "engine/scene/scene.h"

namespace mvpl::light {

enum class EmitterType { Triangle, Point, Spot, Directional, Environment };

struct Emitter {
    EmitterType type = EmitterType::Triangle;
    int mesh = -1;  // Triangle: the mesh and triangle
    int triangle = -1;
    int light = -1;      // Point, Spot, Directional: index into Scene::lights
    float area = 0.0f;   // Triangle only
    float power = 0.0f;  // luminance of the emitted flux, the selection weight
};

// A sampled point on an emitter as seen from a receiver: the contribution of the light to the
// receiver is f · |cos θ| · li / pdf (times visibility).
struct LightSample {
    Rgb li{0.0f};   // radiance (area), or intensity / d² (point, spot), or irradiance (dir.)
    Vec3 wi{0.0f};  // unit, receiver → light
    float distance = 0.0f;  // infinite for directional lights
    Vec3 p{0.0f};           // point on the light
    Vec3 n{0.0f};           // geometric normal at p (zero for punctual lights)
    float pdf = 0.0f;       // solid angle density × selection probability; delta lights: selection
    bool is_delta = false;
};

// A sampled start of a light path (light tracing): a point on an emitter and a direction of
// emission. `throughput` is the first segment's weight Le·|cos θ|/(pick · pdf_pos · pdf_dir)
// (punctual lights: I·falloff/(pick · pdf_dir); directional: E/(pick · pdf_pos)); `le` is the
// quantity an emitter VPL carries divided by its densities: Le/(pick · pdf_pos) for area lights,
// I/pick for point and spot lights, E/pick for directional lights.
struct EmissionSample {
    EmitterType type = EmitterType::Triangle;
    int emitter = -1;
    Vec3 p{0.0f};          // point on the light (directional: on a disk behind the scene)
    Vec3 n{0.0f};          // triangle: front-face geometric normal; spot, directional: the axis
    Vec3 direction{0.0f};  // unit direction of emission
    Rgb le{0.0f};
    Rgb throughput{0.0f};
    float pick = 0.0f;     // selection probability of the emitter
    float pdf_pos = 0.0f;  // area density of p (1 for punctual lights)
    float pdf_dir = 0.0f;  // solid-angle density of direction
};

class LightSampler {
public:
    explicit LightSampler(const scene::Scene& scene);

    bool empty() const { return m_emitters.empty(); }
    const std::vector<Emitter>& emitters() const { return m_emitters; }
    float total_power() const { return m_total_power; }

    // Picks an emitter with probability ∝ power and samples it as seen from `ref`.
    std::optional<LightSample> sample_li(const Vec3& ref, float u_pick, const Vec2& u) const;
    // Solid-angle density with which sample_li would choose point p (normal n) on the emissive
    // triangle (mesh, triangle) from ref; 0 when that triangle is not an emitter.
    float pdf_li(const Vec3& ref, int mesh, int triangle, const Vec3& p, const Vec3& n) const;
    // Emitted radiance of an emissive triangle point seen from direction w (leaving the
    // surface); zero from the back side.
    Rgb emitted_radiance(int mesh, int triangle, const Vec2& barycentric, const Vec3& w) const;
    // The environment's radiance arriving from direction w (unit, pointing away from the
    // receiver), and the solid-angle density with which sample_li picks that direction (0
    // without an environment): what a ray that leaves the scene sees, and its MIS weight.
    Rgb environment_radiance(const Vec3& w) const;
    float pdf_environment(const Vec3& w) const;

    // Picks an emitter ∝ power (u_pick), a point on it (u_pos) and a direction of emission (u_dir):
    // point lights uniformly over the sphere, spot lights uniformly within the outer cone (the
    // falloff goes into the throughput), triangles cosine-weighted around the front normal,
    // directional lights from a disk of the scene's bounding-sphere radius perpendicular to the
    // direction (pdf_pos = 1/(π r²)); the environment as a directional light of a direction
    // chosen by its EnvironmentSampler, whose `le` is the radiance over that density, an
    // irradiance (pbrt-v4's ImageInfiniteLight::SampleLe).
    std::optional<EmissionSample> sample_le(float u_pick, const Vec2& u_pos,
                                            const Vec2& u_dir) const;
    // sample_le of emitter `emitter`, chosen by the caller with probability `pick` (> 0), which
    // the sample's `pick`, `le` and `throughput` then hold instead of the power's share.
    std::optional<EmissionSample> sample_le_from(int emitter, float pick, const Vec2& u_pos,
                                                 const Vec2& u_dir) const;
    float scene_radius() const { return m_scene_radius; }
    Vec3 scene_center() const { return m_scene_center; }

    float pick_probability(int emitter) const { return m_emitters[emitter].power / m_total_power; }
    int emitter_of(int mesh, int triangle) const;

private:
    // The emissive meshes' triangles, each weighted by its flux, and m_first_emitter.
    void add_triangle_emitters();
    // m_cdf and m_total_power over m_emitters (none left where no emitter has power).
    void build_cdf();
    // sample_le_from for a triangle or the environment, `s` holding the pick.
    std::optional<EmissionSample> triangle_le(const Emitter& e, EmissionSample s, const Vec2& u_pos,
                                              const Vec2& u_dir) const;
    std::optional<EmissionSample> environment_le(EmissionSample s, const Vec2& u_pos,
                                                 const Vec2& u_dir) const;

    const scene::Scene& m_scene;
    material::SceneMaterials m_materials;  // emission graphs (textured emitters)
    std::vector<Emitter> m_emitters;
    std::vector<float> m_cdf;          // cumulative power, m_cdf.back() == m_total_power
    std::vector<int> m_first_emitter;  // per mesh: index of its triangle 0, or −1
    float m_total_power = 0.0f;
    float m_scene_radius = 1.0f;
    Vec3 m_scene_center{0.0f};
    int m_environment = -1;  // index of the environment's emitter, or −1
    EnvironmentSampler m_environment_sampler;
};

// KHR_lights_punctual spot attenuation for the cosine between the spot axis and the direction
// from the light to the receiver.
float spot_attenuation(const scene::Light& light, float cos_angle);

// What a punctual light sends to `ref`: li = intensity / d² (spot falloff included) or a
// directional light's irradiance, wi towards the light, its distance (infinite for directional)
// and position; is_delta, pdf 1. None where the light sits at ref, or a point or spot light
// sends nothing there.
std::optional<LightSample> punctual_li(const scene::Light& light, const Vec3& ref);

}  // namespace mvpl::light

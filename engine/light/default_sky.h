#pragma once
// When a scene gets the default sky (README, "Commands", SCENE): the rule that decides whether the
// scene's own emitters can light the model, as glTF viewers would show it lit.
#include "engine/scene/scene.h"

namespace mvpl::light {

// What a scene's own light gives, against the unit sky. Fluxes are luminance (W of Y).
struct SceneLighting {
    bool has_punctual = false;     // KHR_lights_punctual lights (or Mitsuba's point, spot, sun)
    bool has_environment = false;  // the file's own environment
    // Φ_e = π Σ A·L̄ over the emissive triangles (front faces, Lambertian emission; a textured
    // triangle's L̄ as LightSampler weighs it).
    double emitted = 0.0;
    // Φ_sky = 4π² r²: the flux a uniform sky of radiance 1 sends into the scene's bounding
    // sphere of radius r (irradiance π on each of its 4π r² outward-facing points), the power
    // LightSampler gives such an environment (π r² · 4π).
    double unit_sky = 0.0;

    // Φ_e / Φ_sky: how much of the unit sky's light the emissive surfaces make up.
    double emitted_share() const { return unit_sky > 0.0 ? emitted / unit_sky : 0.0; }
    // The scene has lights its author placed to light it, or emission enough (kMinEmittedShare).
    bool lights_itself() const;
};

// Below this share of the unit sky, emission alone does not light a model: the scene gets the
// default sky as well. Measured Φ_e / Φ_sky: the scenes made to be lit by their emitters are at
// 0.056 (the Cornell box) and above (textured 0.10, two-room 2.9; the self-showing emissive
// planes of MultiUVTest 0.065, UnlitTest's unlit objects 0.13); models whose emissive texture
// marks small glowing details, shown lit by an environment in glTF viewers, are at 0.0064
// (DamagedHelmet) and 0.0036 (SpecGlossVsMetalRough's WaterBottle) and render near-black
// without the sky. 0.02 is the geometric mean of the two nearest (0.0064 and 0.056): a factor
// of about 3 from each group.
inline constexpr double kMinEmittedShare = 0.02;

SceneLighting scene_lighting(const scene::Scene& scene);

}  // namespace mvpl::light

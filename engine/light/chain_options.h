#pragma once
// Which camera paths continue through glossy surfaces (light/specular_chain.h): apart from it so
// that render options can hold it without the tracing headers.

namespace mvpl::light {

// Perceptual roughness at or below which a surface with a specular lobe is continued by default
// (docs/results.md, "Specular chains": where VPL shading stops converging at the VPL counts users
// run).
inline constexpr float kDefaultChainRoughness = 0.2f;
// Sub-pixel samples of the light glossy pixels reflect directly, per position (ChainOptions::
// emission_samples) as `mvpl render` sets it (docs/results.md, "Sub-pixel samples of the chains'
// direct light").
inline constexpr int kDefaultChainEmissionSamples = 8;

struct ChainOptions {
    // Surfaces whose perceptual roughness is at most this (and that have a specular lobe) are
    // continued; negative: no chains.
    float max_roughness = -1.0f;
    // Glossy vertices at most; a chain still glossy after them ends there, black.
    int max_bounces = 8;
    // Mitsuba's max_depth (< 0 unlimited): bounds the chain and the VPLs it may use.
    int max_depth = -1;
    // Sub-pixel samples per position of the light the chains meet (their emitters, and the
    // lights their glossy vertices reflect), in pixels whose centre is continued: a highlight
    // smaller than a pixel varies within it far more than the VPL light at the chains' ends, whose
    // receiver stays the position's own (specular_chain.h, pixel_chain_emission).
    int emission_samples = 1;

    bool enabled() const { return max_roughness >= 0.0f; }
};

}  // namespace mvpl::light

#pragma once
// The AOVs mvpl writes beside the image (README, "AOVs and EXR attributes"): what each one is and
// what its channels are called. mvpl's names follow the compositors' conventions: OpenEXR's
// standard depth channel Z ("distance of the front of a sample from the viewer"; Nuke reads it as
// depth.Z), P and N for world-space position and normal (Arnold's built-in AOV names), with the
// X/Y/Z and R/G/B suffixes of Blender's and Mitsuba's layers. A Mitsuba scene's
// `<integrator type="aov">` names them itself (Mitsuba 3's aov plugin: name.R/G/B, name.T for
// depth, name.X/Y/Z).
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/scene.h"

namespace mvpl::aov {

enum class Aov {
    Albedo,    // the material's base colour (glTF baseColor; Mitsuba's eval_diffuse_reflectance)
    Normal,    // world-space shading normal on the side the camera sees, normal maps applied
    Depth,     // distance from the eye along the camera ray (Mitsuba's depth, OpenEXR's Z)
    Position,  // world-space position
};

struct AovRequest {
    Aov kind = Aov::Albedo;
    std::string name;                   // the image's name ("albedo", or the Mitsuba file's)
    std::vector<std::string> channels;  // the EXR channels, in component order
};

// mvpl's names, for --aov: albedo, normal, depth, position.
std::vector<std::string_view> aov_names();
// A comma-separated list of mvpl's names (each at most once, in any order) with mvpl's channels.
// Throws UsageError "OPTION: unknown AOV 'x' (albedo, normal, depth, position)" or "… given twice".
std::vector<AovRequest> parse_aov_list(std::string_view text, const std::string& option);
// The AOVs a scene file asks for (scene::Scene::aovs), with its names for the channels.
std::vector<AovRequest> file_aovs(const scene::Scene& scene);
// Components of an AOV: 3, or 1 for depth.
int components(Aov kind);

}  // namespace mvpl::aov

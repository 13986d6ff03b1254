#include "tools/preview/settings.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace mvpl::preview {
namespace {

// The ranges are the command line's (tools/cli/option_groups.cpp) for the same options.
constexpr std::array<SettingSpec, 14> kSettings{{
    {"exposure", 1, -20.0f, 20.0f, false, Redo::nothing, "exposure in stops"},
    {"paths_per_frame", 1, 0.0f, 1e6f, true, Redo::nothing,
     "light paths / chain steps a frame (0: --budget-ms)"},
    {"budget_ms", 1, 1.0f, 10000.0f, false, Redo::nothing, "shading time a frame"},
    {"sampler", 0, 0.0f, 0.0f, false, Redo::sum, "mc or metropolis"},
    {"clamp", 1, 0.0f, 1.0f, false, Redo::sum, "clamping distance / scene diagonal (0: off)"},
    {"compensate", 1, 0.0f, 1.0f, true, Redo::sum, "clamping compensation on (1) or off (0)"},
    {"shadow_resolution", 1, 4.0f, 4096.0f, true, Redo::sum, "side of a shadow cube face"},
    {"max_depth", 1, -1.0f, 1024.0f, true, Redo::vpls,
     "path segments from the camera to the light (-1: unlimited)"},
    {"caustics", 1, 0.0f, 1.0f, true, Redo::vpls, "caustic tracer on (1) or off (0)"},
    {"specular_chains", 1, 0.0f, 1.0f, true, Redo::vpls, "specular chains on (1) or off (0)"},
    {"vsl", 1, 0.0f, 1.0f, false, Redo::sum,
     "virtual spherical lights' radius / scene diagonal (0: points)"},
    {"env_color", 3, 0.0f, 1e6f, false, Redo::scene, "environment colour (a map's tint)"},
    {"env_scale", 1, 0.0f, 1e6f, false, Redo::scene, "environment radiance scale"},
    {"env_rotation", 1, -360.0f, 360.0f, false, Redo::scene, "environment rotation about +Y"},
}};

}  // namespace

std::span<const SettingSpec> setting_specs() {
    return kSettings;
}

const SettingSpec* find_setting(const std::string& name) {
    for (const SettingSpec& s : kSettings)
        if (name == s.name) return &s;
    return nullptr;
}

std::string check_setting_value(const SettingSpec& spec, float value) {
    char range[96];
    std::snprintf(range, sizeof range, "%s needs %s in [%g, %g]", spec.name,
                  spec.integer ? "a whole number" : "a number", double(spec.min), double(spec.max));
    if (!(value >= spec.min && value <= spec.max)) return range;
    if (spec.integer && std::floor(value) != value) return range;
    if (spec.name == std::string("max_depth") && value == 0.0f) return range;
    return {};
}

}  // namespace mvpl::preview

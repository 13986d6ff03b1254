#pragma once
// The settings the preview changes while it runs — by `FRAME set NAME VALUE…` in a script
// (script.h) or in the settings panel, both through PreviewApp::change() — their ranges, and how
// much of the work done so far each change throws away: exposure only re-tonemaps, the others
// restart the sum over the kept VPLs, draw the VPLs anew (their light paths depend on it) or set
// the scene up again (the environment is one of its lights).
#include <span>
#include <string>

namespace mvpl::preview {

enum class Redo {
    nothing,  // the sum continues (exposure, pacing)
    sum,      // the sum restarts over the kept VPLs
    vpls,     // the VPLs are drawn anew too
    scene,    // the scene is set up again (BVH, lights) and the VPLs drawn anew
};

struct SettingSpec {
    const char* name;
    int values;  // numbers it takes; 0: one word (the sampler)
    float min, max;
    bool integer;  // values are whole numbers (flags: 0 or 1)
    Redo redo;
    const char* meaning;
};

// Every setting, in the order the help and the panel list them.
std::span<const SettingSpec> setting_specs();
// Null when there is none of that name.
const SettingSpec* find_setting(const std::string& name);
// Empty when `value` is one `spec` takes, else what is wrong (for the script's error line).
std::string check_setting_value(const SettingSpec& spec, float value);

}  // namespace mvpl::preview

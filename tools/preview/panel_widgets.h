#pragma once
// The settings panel's widgets (Dear ImGui, inside its window): one per setting of settings.h,
// the file's cameras, the field of view and an environment file to load. Each edit comes back as
// an event of the script's format. Settings that restart the sum or draw the VPLs again are sent
// when the slider is let go, not at every step of the drag; exposure and the pacing follow it.
#include <string>
#include <vector>

#include "tools/preview/script.h"
#include "tools/preview/settings_panel.h"

namespace mvpl::preview {

// env_file: the text field's contents, kept between frames.
void panel_widgets(const PanelValues& values, std::string& env_file,
                   std::vector<ScriptEvent>& events);

}  // namespace mvpl::preview

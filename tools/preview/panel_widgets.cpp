#include "tools/preview/panel_widgets.h"

#include "tools/preview/views.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <string>

namespace mvpl::preview {
namespace {

// Shadow cube face sides offered (the command line takes any of 4..4096).
constexpr std::array<int, 6> kShadowSides{64, 128, 256, 512, 1024, 2048};

ScriptEvent set(const std::string& name, std::vector<float> values, std::string word = {}) {
    ScriptEvent e;
    e.action = "set";
    e.key = name;
    e.values = std::move(values);
    e.word = std::move(word);
    return e;
}

ScriptEvent event(const std::string& action, std::vector<float> values, std::string word = {}) {
    ScriptEvent e;
    e.action = action;
    e.values = std::move(values);
    e.word = std::move(word);
    return e;
}

// Sent once the slider is let go (a restart per drag step would show nothing but restarts).
bool released() {
    return ImGui::IsItemDeactivatedAfterEdit();
}

void estimator_widgets(const PanelValues& v, std::vector<ScriptEvent>& out) {
    int sampler = v.sampler == "mc" ? 0 : 1;
    if (ImGui::Combo("sampler", &sampler, "mc\0metropolis\0\0"))
        out.push_back(set("sampler", {}, sampler == 0 ? "mc" : "metropolis"));
    int paths = int(std::min<uint64_t>(v.paths_per_frame, 1024));
    ImGui::SliderInt("paths a frame", &paths, 0, 1024, paths == 0 ? "0: time budget" : "%d");
    if (released()) out.push_back(set("paths_per_frame", {float(paths)}));
    float budget = v.budget_ms;
    if (ImGui::SliderFloat("budget ms", &budget, 5.0f, 500.0f, "%.0f"))
        out.push_back(set("budget_ms", {budget}));
    bool clamp = v.clamping;
    if (ImGui::Checkbox("clamp", &clamp)) out.push_back(set("clamp", {clamp ? v.clamp : 0.0f}));
    float distance = v.clamp;
    ImGui::SliderFloat("clamp distance", &distance, 0.001f, 0.3f, "%.3f x diagonal",
                       ImGuiSliderFlags_Logarithmic);
    if (released()) out.push_back(set("clamp", {distance}));
    bool flag = v.compensate;
    if (ImGui::Checkbox("compensation", &flag)) out.push_back(set("compensate", {float(flag)}));
    flag = v.caustics;
    if (ImGui::Checkbox("caustics", &flag)) out.push_back(set("caustics", {float(flag)}));
    flag = v.chains;
    if (ImGui::Checkbox("specular chains", &flag))
        out.push_back(set("specular_chains", {float(flag)}));
    float vsl = v.vsl;
    ImGui::SliderFloat("VSL radius", &vsl, 0.0f, 0.2f, "%.3f");
    if (released()) out.push_back(set("vsl", {vsl}));
    int depth = v.max_depth < 0 ? 32 : std::min(v.max_depth, 32);
    ImGui::SliderInt("max depth", &depth, 1, 32);
    if (released()) out.push_back(set("max_depth", {float(depth)}));
    int side = 0;
    while (side + 1 < int(kShadowSides.size()) &&
           kShadowSides[size_t(side)] < int(v.shadow_resolution))
        ++side;
    if (ImGui::Combo("shadow map", &side, "64\0128\0256\0512\0001024\0002048\0\0"))
        out.push_back(set("shadow_resolution", {float(kShadowSides[size_t(side)])}));
}

void view_widgets(const PanelValues& v, std::string& env_file, std::vector<ScriptEvent>& out) {
    int shown = int(std::find(kViewNames.begin(), kViewNames.end(), v.view) - kViewNames.begin());
    if (ImGui::Combo("view", &shown, kViewNames.data(), int(kViewNames.size())))
        out.push_back(event("view", {}, kViewNames[size_t(shown)]));
    float exposure = v.exposure;
    if (ImGui::SliderFloat("exposure", &exposure, -10.0f, 10.0f, "%+.1f stops"))
        out.push_back(set("exposure", {exposure}));
    float color[3] = {v.env_color[0], v.env_color[1], v.env_color[2]};
    ImGui::ColorEdit3("sky colour", color, ImGuiColorEditFlags_Float);
    if (released()) out.push_back(set("env_color", {color[0], color[1], color[2]}));
    float scale = v.env_scale;
    ImGui::SliderFloat("sky scale", &scale, 0.0f, 10.0f, "%.2f");
    if (released()) out.push_back(set("env_scale", {scale}));
    float rotation = v.env_rotation;
    ImGui::SliderFloat("sky rotation", &rotation, -180.0f, 180.0f, "%.0f deg");
    if (released()) out.push_back(set("env_rotation", {rotation}));
    ImGui::InputTextWithHint("##env", v.env_map.empty() ? ".hdr or .exr" : v.env_map.c_str(),
                             &env_file);
    ImGui::SameLine();
    if (ImGui::Button("load") && !env_file.empty()) out.push_back(event("drop", {}, env_file));
    for (int i = 0; i < v.cameras; ++i) {
        if (i > 0) ImGui::SameLine();
        if (ImGui::Button(("camera " + std::to_string(i)).c_str()))
            out.push_back(event("camera", {float(i)}));
    }
    float fov = v.fov_degrees;
    ImGui::SliderFloat("field of view", &fov, 5.0f, 150.0f, "%.1f deg");
    if (released()) out.push_back(event("fov", {fov}));
}

}  // namespace

void panel_widgets(const PanelValues& values, std::string& env_file,
                   std::vector<ScriptEvent>& events) {
    estimator_widgets(values, events);
    ImGui::Separator();
    view_widgets(values, env_file, events);
    ImGui::TextUnformatted("drop a scene or an .hdr/.exr on the window; Tab hides this");
}

}  // namespace mvpl::preview

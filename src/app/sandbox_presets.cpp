// Sandbox presets from assets/sandbox-presets.json: see sandbox_presets.h.
#include "app/sandbox_presets.h"

#include <algorithm>

#include <fmt/core.h>

#include "app/sandbox_settings.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/scene_json.h"

namespace polyroll::app {

namespace {
const nlohmann::ordered_json& presets_json() { return assets::file("sandbox-presets.json").at("presets"); }
}  // namespace

std::vector<std::string> sandbox_preset_names() {
    std::vector<std::string> names;
    for (const auto& [name, entry] : presets_json().items()) names.push_back(name);
    return names;
}

SandboxPreset sandbox_preset(const std::string& name) {
    const auto& all = presets_json();
    const auto it = all.find(name);
    if (it == all.end()) {
        std::string allowed;
        for (const std::string& n : sandbox_preset_names()) allowed += (allowed.empty() ? "" : ", ") + n;
        throw InputError(fmt::format("--preset {}: unknown sandbox preset (allowed: {})", name, allowed));
    }
    SandboxPreset p;
    p.name = name;
    p.description = it->value("description", "");
    for (const auto& lane : it->at("lanes")) p.lanes.push_back(lane);
    if (p.lanes.empty() || static_cast<int>(p.lanes.size()) > kMaxLanes)
        throw InputError(fmt::format("sandbox preset {}: {} lanes (allowed: 1 to {})", name, p.lanes.size(), kMaxLanes));
    return p;
}

std::vector<Scene> resolve_preset(const SandboxPreset& preset) {
    std::vector<Scene> scenes;
    int k = 0;
    for (const auto& doc : preset.lanes)
        scenes.push_back(resolve_scene({SceneLayer{doc, fmt::format("sandbox preset {} lane {}", preset.name, ++k), {}}}));
    return scenes;
}

PresetPanel preset_panel() {
    PresetPanel panel;
    for (const auto& [name, entry] : presets_json().items()) {
        const SandboxPreset preset = sandbox_preset(name);
        const std::vector<Scene> lanes = resolve_preset(preset);
        PresetButton button{name, name, fmt::format("Preset '{}': {}", name, preset.description),
                            lanes.front().ramp.angle_deg, lanes.front().fill.ratio};
        if (entry.contains("demo")) {
            button.label = entry.at("demo").get<std::string>();
            panel.demos.push_back(button);
            continue;
        }
        if (!entry.contains("row")) {
            panel.others.push_back(button);
            continue;
        }
        if (entry.contains("button")) button.label = entry.at("button").get<std::string>();
        else button.label = assets::material_look(lanes.front().fill.material.preset).label;
        const std::string row = entry.at("row").get<std::string>();
        auto it = std::find_if(panel.rows.begin(), panel.rows.end(), [&](const PresetRow& r) { return r.label == row; });
        if (it == panel.rows.end()) it = panel.rows.insert(panel.rows.end(), PresetRow{row, {}});
        it->buttons.push_back(button);
    }
    return panel;
}

std::string row_button_text(const PresetButton& b) {
    if (b.fill_ratio == kRowFillRatio) return fmt::format("{} {:g}\u00B0", b.label, b.angle_deg);
    const std::string fill = b.fill_ratio >= 1.0 ? "full" : b.fill_ratio <= 0.0 ? "empty" : fmt::format("r = {:g}", b.fill_ratio);
    return fmt::format("{} {} {:g}\u00B0", b.label, fill, b.angle_deg);
}

std::string preset_rows_heading(const PresetPanel& panel) {
    bool all_half = true;
    for (const PresetRow& row : panel.rows)
        for (const PresetButton& b : row.buttons) all_half = all_half && b.fill_ratio == kRowFillRatio;
    return all_half ? "the experiment's polygons, half full:" : "the experiment's polygons, half full unless the button says:";
}

}  // namespace polyroll::app

// Sandbox presets from assets/sandbox-presets.json: see sandbox_presets.h.
#include "app/sandbox_presets.h"

#include <algorithm>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/scene/scene_json.h"

namespace polyroll::app {

namespace {
const nlohmann::ordered_json& presets_json() { return assets::file("sandbox-presets.json").at("presets"); }
}  // namespace

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

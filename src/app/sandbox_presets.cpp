// Sandbox presets from assets/sandbox-presets.json: see sandbox_presets.h.
#include "app/sandbox_presets.h"

#include <fmt/format.h>

#include "app/sandbox_settings.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene_json.h"

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

}  // namespace polyroll::app

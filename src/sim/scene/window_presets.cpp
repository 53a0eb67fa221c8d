// The window's presets from assets/sandbox-presets.json: see window_presets.h.
#include "sim/scene/window_presets.h"

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/scene_json.h"

namespace polyroll {

namespace {
const nlohmann::ordered_json& presets_json() { return assets::file("sandbox-presets.json").at("presets"); }
}  // namespace

std::vector<std::string> window_preset_names() {
    std::vector<std::string> names;
    for (const auto& [name, entry] : presets_json().items()) names.push_back(name);
    return names;
}

WindowPreset window_preset(const std::string& name, const std::string& label) {
    const auto& all = presets_json();
    const auto it = all.find(name);
    if (it == all.end()) {
        std::string allowed;
        for (const std::string& n : window_preset_names()) allowed += (allowed.empty() ? "" : ", ") + n;
        throw InputError(fmt::format("{}: unknown window preset (allowed: {}; polyroll presets describes them)",
                                     label.empty() ? "--preset " + name : label, allowed));
    }
    WindowPreset p;
    p.name = name;
    p.description = it->value("description", "");
    for (const auto& lane : it->at("lanes")) p.lanes.push_back(lane);
    if (p.lanes.empty() || static_cast<int>(p.lanes.size()) > kMaxRaceLanes)
        throw InputError(
            fmt::format("sandbox preset {}: {} lanes (allowed: 1 to {})", name, p.lanes.size(), kMaxRaceLanes));
    return p;
}

SceneLayer window_preset_lane(const WindowPreset& preset, int k, const std::string& label) {
    const int n = static_cast<int>(preset.lanes.size());
    const std::string said = label.empty() ? fmt::format("--lane {}", k) : label;
    if (k < 1 || k > n)
        throw InputError(n == 1 ? fmt::format("{}: the preset {} has one lane (allowed: 1)", said, preset.name)
                                : fmt::format("{}: the preset {} has {} lanes (allowed: 1 to {})", said, preset.name, n, n));
    return SceneLayer{preset.lanes[static_cast<size_t>(k - 1)],
                      fmt::format("sandbox preset {} lane {}", preset.name, k), {}};
}

std::vector<Scene> resolve_window_preset(const WindowPreset& preset) {
    std::vector<Scene> scenes;
    for (int k = 1; k <= static_cast<int>(preset.lanes.size()); ++k)
        scenes.push_back(resolve_scene({window_preset_lane(preset, k)}));
    return scenes;
}

}  // namespace polyroll

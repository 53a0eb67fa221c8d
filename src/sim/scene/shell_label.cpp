// The shell's name: see shell_label.h.
#include "sim/scene/shell_label.h"

#include <array>
#include <exception>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/scene/scene_json.h"

namespace polyroll {

std::string polygon_name(int sides) {
    static constexpr std::array<const char*, 10> kNames = {"triangle", "square",  "pentagon", "hexagon",
                                                          "heptagon", "octagon", "nonagon",  "decagon",
                                                          "hendecagon", "dodecagon"};
    if (sides >= 3 && sides < 3 + static_cast<int>(kNames.size())) return kNames[static_cast<std::size_t>(sides - 3)];
    if (sides == 18) return "octadecagon";
    return fmt::format("{}-gon", sides);
}

std::string shell_label(const Scene& scene) {
    const ShellParams& s = scene.shell;
    const std::string shape = fmt::format("{} (n = {})", polygon_name(s.sides), s.sides);
    if (s.preset.empty()) return "custom " + shape;
    nlohmann::ordered_json preset;
    try {
        preset = assets::preset_values(assets::Kind::polygon, s.preset);
    } catch (const std::exception&) {
        return "custom " + shape;  // a preset the assets no longer have: the values are all there is
    }
    const nlohmann::ordered_json shell = scene_to_json(scene).at("shell");
    bool sides_differ = false, others_differ = false;
    for (const auto& [key, value] : preset.items()) {
        if (shell.contains(key) && shell.at(key) == value) continue;
        (key == "sides" ? sides_differ : others_differ) = true;
    }
    if (!sides_differ && !others_differ) return fmt::format("{} (n = {})", s.preset, s.sides);
    if (!others_differ) return fmt::format("{} with {}'s size, walls and mass", shape, s.preset);
    return fmt::format("custom {}, from {}", shape, s.preset);
}

bool has_presets_sides(const ShellParams& shell) {
    if (shell.preset.empty()) return false;
    try {
        const nlohmann::ordered_json preset = assets::preset_values(assets::Kind::polygon, shell.preset);
        return !preset.contains("sides") || preset.at("sides").get<int>() == shell.sides;
    } catch (const std::exception&) {
        return true;
    }
}

}  // namespace polyroll

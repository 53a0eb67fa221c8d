// Sandbox presets (assets/sandbox-presets.json): named whole scenes, each a list of one to four
// lanes, every lane a scene document resolved over the defaults like a scene file.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene.h"

namespace polyroll::app {

struct SandboxPreset {
    std::string name;
    std::string description;
    std::vector<nlohmann::ordered_json> lanes;  // scene documents, 1 to kMaxLanes
};

// In the file's order (the panel's order).
std::vector<std::string> sandbox_preset_names();

// Throws InputError naming the choices for an unknown name, or a lane count out of range.
SandboxPreset sandbox_preset(const std::string& name);

// Each lane's document resolved over assets/defaults.json (throws InputError).
std::vector<Scene> resolve_preset(const SandboxPreset& preset);

// The panel's preset buttons (GL-free, so the tests check them): the demonstrations first (presets
// with a "demo", labelled by it: "stops abruptly", "rolls to a terminal velocity"), then the presets
// with a "row" as a grid, one row per row name in order of first appearance, each button labelled by
// its material's label (assets/materials.json "look") or its own "button" text; the others as plain
// buttons.
struct PresetButton {
    std::string preset;   // the sandbox preset it loads
    std::string label;    // the button's text
    std::string tooltip;  // "Preset 'hexagon-bb': the hexagon (small) half full of BBs ..."
    double angle_deg = 0.0;  // the first lane's ramp angle, shown on the button beside the label
};
struct PresetRow {
    std::string label;  // "hexagon"
    std::vector<PresetButton> buttons;
};
struct PresetPanel {
    std::vector<PresetButton> demos;  // the presets with a "demo": named for what they show, first
    std::vector<PresetRow> rows;
    std::vector<PresetButton> others;
};
// Throws InputError for a preset that does not resolve.
PresetPanel preset_panel();

inline constexpr const char* kDefaultSandboxPreset = "default";

}  // namespace polyroll::app

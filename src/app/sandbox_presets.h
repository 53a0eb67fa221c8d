// Sandbox presets (assets/sandbox-presets.json): named whole scenes, each a list of one to four
// lanes, every lane a scene document resolved over the defaults like a scene file (read by
// sim/scene/window_presets.h); here the window's panel of them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scene.h"
#include "sim/scene/window_presets.h"

namespace polyroll::app {

// The presets themselves are the core's (sim/scene/window_presets.h: the command line and Python
// read them too); these are the window's names for them.
using SandboxPreset = WindowPreset;

// In the file's order (the panel's order).
inline std::vector<std::string> sandbox_preset_names() { return window_preset_names(); }

// Throws InputError naming the choices for an unknown name, or a lane count out of range.
inline SandboxPreset sandbox_preset(const std::string& name) { return window_preset(name); }

// Each lane's document resolved over assets/defaults.json (throws InputError).
inline std::vector<Scene> resolve_preset(const SandboxPreset& preset) { return resolve_window_preset(preset); }

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
    double fill_ratio = 0.0;  // the first lane's fill ratio
};
// The rows' fill ratio the heading names: the rows show the experiment's polygons half full, and
// a button whose fill differs says its own.
inline constexpr double kRowFillRatio = 0.5;
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

// A row button's text: its label and angle ("rice 20°"), and its fill where it is not the rows'
// ("rice full 20°", "BBs r = 0.375 14°").
std::string row_button_text(const PresetButton& b);

// The heading over the rows: "half full" only where every row button is.
std::string preset_rows_heading(const PresetPanel& panel);

inline constexpr const char* kDefaultSandboxPreset = "default";

}  // namespace polyroll::app

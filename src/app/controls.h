// The panel's controls as plain data, and their mapping to scene parameters: one row per control
// (control_rows) naming its scene field, whose row in sim/scene/scene_fields.cpp gives the limits, unit,
// label and help. Setting a control changes exactly the parameters its row names, clamped to the
// field's limits; a lane's scene is its preset document with the controls as one more layer, resolved
// by the core. No GLFW or ImGui here: the mapping is unit-tested without a window.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sim/scene/scene.h"
#include "sim/scene/scene_fields.h"

namespace polyroll::app {

// The values the panel's controls edit, held in a scene: each control's row (control_rows) names the
// scene field it edits, as MuJoCo simulate's rows point into mjOption, so no member here mirrors a
// field. A lane's controls carry what each lane chooses for itself (the polygon and its fill: the race
// is between these); the shared controls what all lanes share (the ramp and how the physics is
// computed). Only the fields of their scope's rows are read; equal when those fields are.
struct LaneControls {
    Scene values;
    bool operator==(const LaneControls& other) const;
};
struct SharedControls {
    Scene values;
    bool operator==(const SharedControls& other) const;
};

// Which controls a row's value belongs to: each lane's own, or the one set all lanes share.
enum class Scope { lane, shared };

// Where the panel shows a control (app/sandbox_ui.cpp draws the sections in this order).
enum class PanelSection { lane, ramp, physics, advanced };

// A choice shown as a radio button: the value's name (scene_names.h), its text and its tooltip.
struct RadioOption {
    std::string_view name, text, tip;
};

// One panel control, MuJoCo simulate's way: a row names the scene field it edits and whose value it
// is; the field's row (sim/scene/scene_fields.cpp) gives its type (which widget), limits (the clamping),
// unit, label and help (the tooltip). What the panel adds is the note after the help, the number's
// format and, for a slider whose useful range is shorter than the field's, where the slider stops
// (Ctrl+click types up to the limit). Choosing a preset also sets the controls of its section that the
// preset gives a value for (a polygon sets n, a material its friction and restitution).
struct ControlRow {
    std::string_view path = {};                 // the scene field: "fill.material.friction"
    Scope scope = Scope::lane;                  // whose value: the selected lane's or all lanes'
    PanelSection section = PanelSection::lane;
    std::string_view note = {};                 // added to the field's tooltip: "All lanes."
    std::string_view format = {};               // a number's: "%.2f"
    std::optional<double> slider_max = {};      // the slider's end when less than the field's maximum
    std::vector<RadioOption> radio = {};        // a choice shown as radio buttons; empty: a combo
    // A choice's names the combo offers when fewer than the field's (the model: window_model_names).
    const std::vector<std::string>& (*offered)() = nullptr;
    std::string_view label = {};                // the panel's label where the field's row has none
};

// Every control, in the panel's order.
const std::vector<ControlRow>& control_rows();

// The row of the field at `path`; throws std::logic_error for a field with no control (a code defect).
const ControlRow& control_row(std::string_view path);

// The label a row shows: the field's, or the row's own.
std::string_view control_label(const ControlRow& row);

// The control's value.
FieldValue control_value(const ControlRow& row, const LaneControls& lane, const SharedControls& shared);

// Sets a control: numbers clamped to the field's limits (a NaN to the lowest), preset names checked
// (InputError naming the value and the choices) and the preset's values given to the controls of its
// section. The overloads of one scope take a row of that scope (std::logic_error otherwise).
void set_control(LaneControls& lane, SharedControls& shared, std::string_view path, const FieldValue& value);
void set_control(LaneControls& lane, std::string_view path, const FieldValue& value);
void set_control(SharedControls& shared, std::string_view path, const FieldValue& value);

// Choosing a material preset: its grains, friction and restitution.
inline void set_material(LaneControls& c, const std::string& preset) {
    set_control(c, "fill.material.preset", FieldValue(preset));
}

// The controls showing a resolved scene.
LaneControls lane_controls_from(const Scene& s);
SharedControls shared_controls_from(const Scene& s);

// The controls as a scene document (the layer over a lane's preset document), in scene-file order.
nlohmann::ordered_json controls_layer(const LaneControls& lane, const SharedControls& shared);

// The lane's scene: assets/defaults.json, then `base` (the sandbox preset's document for the lane),
// then the controls. Throws InputError if the result is out of range (e.g. too many grains).
Scene lane_scene(const nlohmann::ordered_json& base, const LaneControls& lane, const SharedControls& shared);

// The model of a name the window offers: one of window_model_names() (InputError otherwise).
Model model_from(const std::string& name);

// What the closed polygon box says: the preset's name while n is the preset's own, else
// "custom (n = N)": the preset's size, wall and mass with another number of sides (the list still
// marks the preset; the box is too narrow for both names).
std::string polygon_combo_text(const std::string& polygon, int sides);

}  // namespace polyroll::app

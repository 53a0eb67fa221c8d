// The panel's controls and their mapping to scene parameters: see controls.h.
#include "app/controls.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <fmt/core.h>

#include "app/sandbox_settings.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/scene_names.h"
#include "sim/scene/shell_label.h"

namespace polyroll::app {

using json = nlohmann::ordered_json;

namespace {

using S = PanelSection;
constexpr Scope kLane = Scope::lane;
constexpr Scope kShared = Scope::shared;

// The panel's rows, in its order: each names its scene field and whose value it is; the field's row
// gives the widget, limits, label and help, the row what the panel adds.
std::vector<ControlRow> make_rows() {
    return {
        // --- this lane: the polygon and its fill
        {.path = "shell.preset", .scope = kLane, .section = S::lane,
         .note = "This lane's shell; n below can change its number of sides."},
        {.path = "shell.sides", .scope = kLane, .section = S::lane, .format = "%d", .slider_max = kSidesSliderMax},
        {.path = "fill.ratio", .scope = kLane, .section = S::lane, .format = "%.3g"},
        {.path = "fill.material.preset", .scope = kLane, .section = S::lane,
         .note = "Friction and restitution can be changed under Advanced."},
        // --- all lanes: the ramp and the physics
        {.path = "ramp.angle_deg", .scope = kShared, .section = S::ramp, .note = "All lanes.",
         .format = "%.1f\u00B0", .slider_max = kAngleSliderMaxDeg},
        {.path = "run.seed", .scope = kShared, .section = S::ramp,
         .note = "All lanes: the same seed gives the same run (as polyroll run --seed and the page's ?seed= do); "
                 "another seed, another packing of the same fill, to see how much the outcome varies.",
         .label = "seed"},
        {.path = "ramp.preset", .scope = kShared, .section = S::physics, .note = "All lanes roll on it."},
        {.path = "release.pose", .scope = kShared, .section = S::physics,
         .radio = {{"vertex", "on a vertex",
                    "Held on a vertex with the centre straight above it, then let go (as in the experiment)."},
                   {"face", "on a face", "Set down flat on a face, then let go."},
                   {"tipped", "tipped", "Filled lying on a face, then stood on its vertex with the pile as it lay, "
                                        "and let go."}}},
        {.path = "run.model", .scope = kShared, .section = S::physics,
         .note = "All lanes. The window offers all but dem3d, the 3D reference (about a minute of CPU a run); the "
                 "reduced models compute a whole run in under a millisecond and draw the shell only.",
         .offered = window_model_names},
        {.path = "fidelity.preset", .scope = kShared, .section = S::physics},
        // --- Advanced: friction and restitution, reset by choosing a material or a ramp
        {.path = "fill.material.friction", .scope = kLane, .section = S::advanced,
         .note = "This lane. Choosing a material resets it.", .format = "%.2f"},
        {.path = "fill.material.restitution", .scope = kLane, .section = S::advanced,
         .note = "This lane. Choosing a material resets it.", .format = "%.2f"},
        {.path = "ramp.friction", .scope = kShared, .section = S::advanced,
         .note = "All lanes. Choosing a ramp resets it.", .format = "%.2f"},
        {.path = "ramp.restitution", .scope = kShared, .section = S::advanced,
         .note = "All lanes. Choosing a ramp resets it.", .format = "%.2f"},
    };
}

// The scene holding a row's value: the lane's or the shared controls' (const or not, as given).
template <class Lane, class Shared>
auto& values_of(const ControlRow& row, Lane& lane, Shared& shared) {
    return row.scope == Scope::lane ? lane.values : shared.values;
}

void put(const ControlRow& row, LaneControls& lane, SharedControls& shared, const FieldValue& value) {
    scene_field(row.path).access.set(values_of(row, lane, shared), value);
}

// Whether two scenes agree on the fields of a scope's rows.
bool same_controls(const Scene& a, const Scene& b, Scope scope) {
    for (const ControlRow& r : control_rows()) {
        if (r.scope != scope) continue;
        const FieldAccess& access = scene_field(r.path).access;
        if (!(access.get(a) == access.get(b))) return false;
    }
    return true;
}

double clamp_finite(double v, double lo, double hi) {
    if (std::isnan(v)) return lo;  // a NaN from a typed field: the lowest valid value, never NaN
    return std::clamp(v, lo, hi);
}

// A whole number given for a number field or a seed (0.5 for r is a double already; 5 for a seed an int).
FieldValue as_field_type(const SceneField& f, const FieldValue& v) {
    const int* whole = std::get_if<int>(&v);
    if (whole && f.type == FieldType::number) return static_cast<double>(*whole);
    if (whole && f.type == FieldType::seed && *whole >= 0) return static_cast<std::uint64_t>(*whole);
    return v;
}

// The value as the field allows it: a number clamped to the field's limits (the panel's fields all
// have fixed, closed ones), a preset's name checked.
FieldValue checked(const SceneField& f, const FieldValue& given) {
    FieldValue v = as_field_type(f, given);
    switch (f.type) {
        case FieldType::integer:
            return std::clamp(std::get<int>(v), static_cast<int>(f.min), static_cast<int>(f.max));
        case FieldType::number: return clamp_finite(std::get<double>(v), f.min, f.max);
        case FieldType::preset:
            assets::preset_values(*f.kind, std::get<std::string>(v));  // throws for an unknown name
            return v;
        case FieldType::optional_number:
        case FieldType::seed:  // every 64-bit seed is one the core accepts: nothing to clamp
        case FieldType::choice: break;
    }
    return v;
}

// A preset's value for a field, as the field's type.
FieldValue preset_value(const SceneField& f, const json& v) {
    if (f.type == FieldType::integer) return v.get<int>();
    if (f.type == FieldType::number) return v.get<double>();
    throw std::logic_error(fmt::format("a preset sets control '{}', which is not a number", f.path));
}

// "fill.material.friction" -> "/fill/material/friction".
json::json_pointer pointer_to(std::string_view path) {
    std::string p = "/" + std::string(path);
    std::replace(p.begin(), p.end(), '.', '/');
    return json::json_pointer(p);
}

json json_of(const FieldValue& value) {
    return std::visit(
        [](const auto& v) -> json {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, std::optional<double>>) return v ? json(*v) : json(nullptr);
            else if constexpr (std::is_same_v<V, ReleasePose> || std::is_same_v<V, Model> || std::is_same_v<V, EngineFrame> || std::is_same_v<V, GrainContacts>) return to_string(v);
            else return v;
        },
        value);
}

}  // namespace

const std::vector<ControlRow>& control_rows() {
    static const std::vector<ControlRow> rows = make_rows();
    return rows;
}

const ControlRow& control_row(std::string_view path) {
    for (const ControlRow& r : control_rows())
        if (r.path == path) return r;
    throw std::logic_error(fmt::format("'{}' has no panel control", path));
}

std::string_view control_label(const ControlRow& row) {
    const std::string_view label = scene_field(row.path).label;
    return label.empty() ? row.label : label;
}

bool LaneControls::operator==(const LaneControls& other) const {
    return same_controls(values, other.values, Scope::lane);
}
bool SharedControls::operator==(const SharedControls& other) const {
    return same_controls(values, other.values, Scope::shared);
}

FieldValue control_value(const ControlRow& row, const LaneControls& lane, const SharedControls& shared) {
    return scene_field(row.path).access.get(values_of(row, lane, shared));
}

void set_control(LaneControls& lane, SharedControls& shared, std::string_view path, const FieldValue& value) {
    const ControlRow& row = control_row(path);
    const SceneField& f = scene_field(path);
    put(row, lane, shared, checked(f, value));
    if (f.type != FieldType::preset) return;
    // The preset's values for the controls of its section, clamped as typed ones are.
    const std::string_view section = section_of(path);
    const json& values = assets::preset_values(*f.kind, std::get<std::string>(value));
    for (const ControlRow& other : control_rows()) {
        if (other.scope != row.scope || section_of(other.path) != section) continue;
        const auto it = values.find(std::string(key_of(other.path)));
        if (it != values.end()) set_control(lane, shared, other.path, preset_value(scene_field(other.path), *it));
    }
}

void set_control(LaneControls& lane, std::string_view path, const FieldValue& value) {
    if (control_row(path).scope != Scope::lane) throw std::logic_error(fmt::format("'{}' is not a lane's control", path));
    SharedControls unused;
    set_control(lane, unused, path, value);
}

void set_control(SharedControls& shared, std::string_view path, const FieldValue& value) {
    if (control_row(path).scope != Scope::shared)
        throw std::logic_error(fmt::format("'{}' is not a control all lanes share", path));
    LaneControls unused;
    set_control(unused, shared, path, value);
}

LaneControls lane_controls_from(const Scene& s) { return {s}; }
SharedControls shared_controls_from(const Scene& s) { return {s}; }

json controls_layer(const LaneControls& lane, const SharedControls& shared) {
    json doc = json::object();
    // In the scene table's order, so each section's preset comes before the values over it.
    for (const SceneField& f : scene_fields()) {
        const auto row = std::find_if(control_rows().begin(), control_rows().end(),
                                      [&](const ControlRow& r) { return r.path == f.path; });
        if (row == control_rows().end()) continue;
        const FieldValue v = control_value(*row, lane, shared);
        // A preset name only when there is one: a scene file with a custom section has none, and its
        // values then stay as the base document gave them.
        if (const auto* name = std::get_if<std::string>(&v); name && name->empty()) continue;
        doc[pointer_to(f.path)] = json_of(v);
    }
    return doc;
}

Scene lane_scene(const json& base, const LaneControls& lane, const SharedControls& shared) {
    return resolve_scene({SceneLayer{base, "sandbox preset", {}}, SceneLayer{controls_layer(lane, shared), "panel", {}}});
}

Model model_from(const std::string& name) {
    // The window offers the everyday models: the 3D reference takes a minute of CPU a run.
    const std::vector<std::string>& allowed = window_model_names();
    if (auto model = model_named(name); model && std::find(allowed.begin(), allowed.end(), name) != allowed.end())
        return *model;
    throw InputError(fmt::format("model '{}' is not one the window runs (allowed: {})", name, comma_list(allowed)));
}

std::string polygon_combo_text(const std::string& polygon, int sides) {
    ShellParams shell;
    shell.preset = polygon;
    shell.sides = sides;
    if (polygon.empty() || has_presets_sides(shell)) return polygon;
    return fmt::format("custom (n = {})", sides);
}

}  // namespace polyroll::app

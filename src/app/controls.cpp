// The panel's controls and their mapping to scene parameters: see controls.h.
#include "app/controls.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "app/sandbox_settings.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/scene_names.h"
#include "sim/scene/shell_label.h"

namespace polyroll::app {

using json = nlohmann::ordered_json;

namespace {

// The struct a member pointer belongs to: LaneControls or SharedControls.
template <class Pointer>
struct MemberOf;
template <class Owner, class Value>
struct MemberOf<Value Owner::*> {
    using type = Owner;
};

// Of the two structs, the one holding `Owner`'s members (const or not, as given).
template <class Owner, class Lane, class Shared>
auto& holder(Lane& lane, Shared& shared) {
    if constexpr (std::is_same_v<std::remove_const_t<Lane>, Owner>) return lane;
    else return shared;
}

// A row whose value is a member of LaneControls (a lane's control) or of SharedControls (shared).
template <auto Member>
ControlRow row(std::string_view path, PanelSection section) {
    using Owner = typename MemberOf<decltype(Member)>::type;
    static_assert(std::is_same_v<Owner, LaneControls> || std::is_same_v<Owner, SharedControls>);
    ControlRow r;
    r.path = path;
    r.scope = std::is_same_v<Owner, LaneControls> ? Scope::lane : Scope::shared;
    r.section = section;
    r.get = [](const LaneControls& l, const SharedControls& c) { return FieldValue(holder<Owner>(l, c).*Member); };
    r.put = [](LaneControls& l, SharedControls& c, const FieldValue& v) {
        auto& member = holder<Owner>(l, c).*Member;
        member = std::get<std::decay_t<decltype(member)>>(v);
    };
    return r;
}

// The row with the panel's additions, named.
struct With {
    std::string_view note = {}, format = {};
    std::optional<double> slider_max = {};
    std::vector<RadioOption> radio = {};
    std::string_view label = {};
};
ControlRow with(ControlRow r, With w) {
    r.note = w.note;
    r.format = w.format;
    r.slider_max = w.slider_max;
    r.radio = std::move(w.radio);
    r.label = w.label;
    return r;
}

using S = PanelSection;

std::vector<ControlRow> make_rows() {
    return {
        // --- this lane: the polygon and its fill
        with(row<&LaneControls::polygon>("shell.preset", S::lane),
             {.note = "This lane's shell; n below can change its number of sides."}),
        with(row<&LaneControls::sides>("shell.sides", S::lane),
             {.format = "%d", .slider_max = kSidesSliderMax}),
        with(row<&LaneControls::fill_ratio>("fill.ratio", S::lane), {.format = "%.3g"}),
        with(row<&LaneControls::material>("fill.material.preset", S::lane),
             {.note = "Friction and restitution can be changed under Advanced."}),
        // --- all lanes: the ramp and the physics
        with(row<&SharedControls::angle_deg>("ramp.angle_deg", S::ramp),
             {.note = "All lanes.", .format = "%.1f\u00B0", .slider_max = kAngleSliderMaxDeg}),
        with(row<&SharedControls::seed>("run.seed", S::ramp),
             {.note = "All lanes: the same seed gives the same run (as polyroll run --seed and the page's ?seed= "
                      "do); another seed, another packing of the same fill, to see how much the outcome varies.",
              .label = "seed"}),
        with(row<&SharedControls::ramp>("ramp.preset", S::physics), {.note = "All lanes roll on it."}),
        with(row<&SharedControls::pose>("release.pose", S::physics),
             {.radio = {{"vertex", "on a vertex",
                         "Held on a vertex with the centre straight above it, then let go (as in the experiment)."},
                        {"face", "on a face", "Set down flat on a face, then let go."},
                        {"tipped", "tipped", "Filled lying on a face, then stood on its vertex with the pile as it "
                                             "lay, and let go."}}}),
        row<&SharedControls::model>("run.model", S::physics),
        row<&SharedControls::fidelity>("fidelity.preset", S::physics),
        // --- Advanced: friction and restitution, reset by choosing a material or a ramp
        with(row<&LaneControls::grain_friction>("fill.material.friction", S::advanced),
             {.note = "This lane. Choosing a material resets it.", .format = "%.2f"}),
        with(row<&LaneControls::grain_restitution>("fill.material.restitution", S::advanced),
             {.note = "This lane. Choosing a material resets it.", .format = "%.2f"}),
        with(row<&SharedControls::ramp_friction>("ramp.friction", S::advanced),
             {.note = "All lanes. Choosing a ramp resets it.", .format = "%.2f"}),
        with(row<&SharedControls::ramp_restitution>("ramp.restitution", S::advanced),
             {.note = "All lanes. Choosing a ramp resets it.", .format = "%.2f"}),
    };
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
            else if constexpr (std::is_same_v<V, ReleasePose> || std::is_same_v<V, Model>) return to_string(v);
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

FieldValue control_value(const ControlRow& row, const LaneControls& lane, const SharedControls& shared) {
    return row.get(lane, shared);
}

void set_control(LaneControls& lane, SharedControls& shared, std::string_view path, const FieldValue& value) {
    const ControlRow& row = control_row(path);
    const SceneField& f = scene_field(path);
    row.put(lane, shared, checked(f, value));
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

namespace {
template <class Controls>
Controls controls_from(const Scene& s, Scope scope) {
    LaneControls lane;
    SharedControls shared;
    for (const ControlRow& r : control_rows())
        if (r.scope == scope) r.put(lane, shared, scene_field(r.path).access.get(s));
    if constexpr (std::is_same_v<Controls, LaneControls>) return lane;
    else return shared;
}
}  // namespace

LaneControls lane_controls_from(const Scene& s) { return controls_from<LaneControls>(s, Scope::lane); }
SharedControls shared_controls_from(const Scene& s) { return controls_from<SharedControls>(s, Scope::shared); }

json controls_layer(const LaneControls& lane, const SharedControls& shared) {
    json doc = json::object();
    // In the scene table's order, so each section's preset comes before the values over it.
    for (const SceneField& f : scene_fields()) {
        const auto row = std::find_if(control_rows().begin(), control_rows().end(),
                                      [&](const ControlRow& r) { return r.path == f.path; });
        if (row == control_rows().end()) continue;
        const FieldValue v = row->get(lane, shared);
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

namespace {
std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}
}  // namespace

Model model_from(const std::string& name) {
    // The window offers the everyday models: the 3D reference takes a minute of CPU a run.
    const std::vector<std::string>& allowed = window_model_names();
    if (auto model = model_named(name); model && std::find(allowed.begin(), allowed.end(), name) != allowed.end())
        return *model;
    throw InputError(fmt::format("model '{}' is not one the window runs (allowed: {})", name, join(allowed)));
}

std::string polygon_combo_text(const std::string& polygon, int sides) {
    ShellParams shell;
    shell.preset = polygon;
    shell.sides = sides;
    if (polygon.empty() || has_presets_sides(shell)) return polygon;
    return fmt::format("custom (n = {})", sides);
}

}  // namespace polyroll::app

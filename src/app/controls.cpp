// The panel's controls and their mapping to scene parameters: see controls.h.
#include "app/controls.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene_fields.h"
#include "sim/scene_json.h"
#include "sim/scene_names.h"

namespace polyroll::app {

using json = nlohmann::ordered_json;

namespace {

double clamp_finite(double v, double lo, double hi) {
    if (std::isnan(v)) return lo;  // a NaN from a typed field: the lowest valid value, never NaN
    return std::clamp(v, lo, hi);
}

// Clamps to the field's limits (sim/scene_fields.cpp): the panel's fields all have fixed, closed ones.
double clamp_to_field(std::string_view path, double v) {
    const SceneField& f = scene_field(path);
    return clamp_finite(v, f.min, f.max);
}
int clamp_to_field(std::string_view path, int v) {
    const SceneField& f = scene_field(path);
    return std::clamp(v, static_cast<int>(f.min), static_cast<int>(f.max));
}

// The preset's values; throws InputError naming the choices for an unknown name.
const json& values_of(assets::Kind kind, const std::string& name) { return assets::preset_values(kind, name); }

}  // namespace

void set_polygon(LaneControls& c, const std::string& preset) {
    const json& v = values_of(assets::Kind::polygon, preset);
    c.polygon = preset;
    c.sides = clamp_to_field("shell.sides", v.at("sides").get<int>());
}
void set_sides(LaneControls& c, int sides) { c.sides = clamp_to_field("shell.sides", sides); }
void set_fill_ratio(LaneControls& c, double ratio) { c.fill_ratio = clamp_to_field("fill.ratio", ratio); }
void set_material(LaneControls& c, const std::string& preset) {
    const json& v = values_of(assets::Kind::material, preset);
    c.material = preset;
    // Through the Advanced sliders' setters: the preset's values get the sliders' clamping.
    set_grain_friction(c, v.at("friction").get<double>());
    set_grain_restitution(c, v.at("restitution").get<double>());
}
void set_grain_friction(LaneControls& c, double f) { c.grain_friction = clamp_to_field("fill.material.friction", f); }
void set_grain_restitution(LaneControls& c, double e) {
    c.grain_restitution = clamp_to_field("fill.material.restitution", e);
}

void set_ramp(SharedControls& c, const std::string& preset) {
    const json& v = values_of(assets::Kind::ramp, preset);
    c.ramp = preset;
    set_ramp_friction(c, v.at("friction").get<double>());
    set_ramp_restitution(c, v.at("restitution").get<double>());
}
void set_angle_deg(SharedControls& c, double a) { c.angle_deg = clamp_to_field("ramp.angle_deg", a); }
void set_ramp_friction(SharedControls& c, double f) { c.ramp_friction = clamp_to_field("ramp.friction", f); }
void set_ramp_restitution(SharedControls& c, double e) {
    c.ramp_restitution = clamp_to_field("ramp.restitution", e);
}
void set_release_pose(SharedControls& c, ReleasePose pose) { c.pose = pose; }
void set_model(SharedControls& c, Model model) { c.model = model; }
void set_fidelity(SharedControls& c, const std::string& preset) {
    values_of(assets::Kind::fidelity, preset);  // checks the name
    c.fidelity = preset;
}

// Every 64-bit seed is one the core accepts (run.seed: 0 to 2^64-1): nothing to clamp.
void set_seed(SharedControls& c, std::uint64_t seed) { c.seed = seed; }

LaneControls lane_controls_from(const Scene& s) {
    LaneControls c;
    c.polygon = s.shell.preset;
    c.sides = s.shell.sides;
    c.fill_ratio = s.fill.ratio;
    c.material = s.fill.material.preset;
    c.grain_friction = s.fill.material.friction;
    c.grain_restitution = s.fill.material.restitution;
    return c;
}

SharedControls shared_controls_from(const Scene& s) {
    SharedControls c;
    c.ramp = s.ramp.preset;
    c.angle_deg = s.ramp.angle_deg;
    c.ramp_friction = s.ramp.friction;
    c.ramp_restitution = s.ramp.restitution;
    c.pose = s.release.pose;
    c.model = s.run.model;
    c.fidelity = s.fidelity.preset;
    c.seed = s.run.seed;
    return c;
}

json controls_layer(const LaneControls& lane, const SharedControls& shared) {
    // A preset name only when there is one: a scene file with a custom section has none, and its
    // values then stay as the base document gave them.
    auto with_preset = [](const std::string& preset) {
        json j = json::object();
        if (!preset.empty()) j["preset"] = preset;
        return j;
    };
    json doc = json::object();
    json shell = with_preset(lane.polygon);
    shell["sides"] = lane.sides;
    doc["shell"] = shell;
    json material = with_preset(lane.material);
    material["friction"] = lane.grain_friction;
    material["restitution"] = lane.grain_restitution;
    doc["fill"] = json{{"ratio", lane.fill_ratio}, {"material", material}};
    json ramp = with_preset(shared.ramp);
    ramp["angle_deg"] = shared.angle_deg;
    ramp["friction"] = shared.ramp_friction;
    ramp["restitution"] = shared.ramp_restitution;
    doc["ramp"] = ramp;
    doc["release"] = json{{"pose", to_string(shared.pose)}};
    if (!shared.fidelity.empty()) doc["fidelity"] = json{{"preset", shared.fidelity}};
    doc["run"] = json{{"model", to_string(shared.model)}, {"seed", shared.seed}};
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

ReleasePose release_pose_from(const std::string& name) {
    if (auto pose = release_pose_named(name)) return *pose;
    throw InputError(fmt::format("release pose '{}' is unknown (allowed: {})", name, join(release_pose_names())));
}

Model model_from(const std::string& name) {
    // The window offers the everyday models: the 3D reference takes a minute of CPU a run.
    const std::vector<std::string>& allowed = window_model_names();
    if (auto model = model_named(name); model && std::find(allowed.begin(), allowed.end(), name) != allowed.end())
        return *model;
    throw InputError(fmt::format("model '{}' is not one the window runs (allowed: {})", name, join(allowed)));
}

}  // namespace polyroll::app

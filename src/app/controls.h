// The panel's controls as plain data, and their mapping to scene parameters. Each setter changes
// exactly the parameters its control names and clamps to the field's limits (sim/scene_fields.h); a
// lane's scene is its preset document with the controls as one more layer, resolved by the core.
// No GLFW or ImGui here: the mapping is unit-tested without a window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene.h"

namespace polyroll::app {

// What each lane chooses for itself: the polygon and its fill (the race is between these).
struct LaneControls {
    std::string polygon;        // polygon preset the shell starts from (assets/polygons.json)
    int sides = 6;              // n, overriding the preset's
    double fill_ratio = 0.0;    // r
    std::string material;       // material preset (assets/materials.json)
    double grain_friction = 0.0;     // advanced: grain on grain
    double grain_restitution = 0.0;  // advanced: grain on grain and on walls
};

// What all lanes share: the ramp they race on and how the physics is computed.
struct SharedControls {
    std::string ramp;           // ramp preset (assets/ramps.json)
    double angle_deg = 0.0;     // theta
    double ramp_friction = 0.0;      // advanced: shell on ramp
    double ramp_restitution = 0.0;   // advanced: shell on ramp
    ReleasePose pose = ReleasePose::vertex;
    Model model = Model::grains;
    std::string fidelity;       // fidelity preset (assets/fidelity.json)
    std::uint64_t seed = 1;     // the grain packing's seed: the same seed, the same run
};

// Setters: clamp numbers, check names (InputError naming the value and the choices).
void set_polygon(LaneControls& c, const std::string& preset);  // also n = the preset's sides
void set_sides(LaneControls& c, int sides);
void set_fill_ratio(LaneControls& c, double ratio);
void set_material(LaneControls& c, const std::string& preset);  // also its friction and restitution
void set_grain_friction(LaneControls& c, double friction);
void set_grain_restitution(LaneControls& c, double restitution);
void set_ramp(SharedControls& c, const std::string& preset);    // also its friction and restitution
void set_angle_deg(SharedControls& c, double angle_deg);
void set_ramp_friction(SharedControls& c, double friction);
void set_ramp_restitution(SharedControls& c, double restitution);
void set_release_pose(SharedControls& c, ReleasePose pose);
void set_model(SharedControls& c, Model model);
void set_fidelity(SharedControls& c, const std::string& preset);
void set_seed(SharedControls& c, std::uint64_t seed);

// The controls showing a resolved scene.
LaneControls lane_controls_from(const Scene& s);
SharedControls shared_controls_from(const Scene& s);

// The controls as a scene document (the layer over a lane's preset document).
nlohmann::ordered_json controls_layer(const LaneControls& lane, const SharedControls& shared);

// The lane's scene: assets/defaults.json, then `base` (the sandbox preset's document for the lane),
// then the controls. Throws InputError if the result is out of range (e.g. too many grains).
Scene lane_scene(const nlohmann::ordered_json& base, const LaneControls& lane, const SharedControls& shared);

// Parsing and naming the enumerations the panel offers.
ReleasePose release_pose_from(const std::string& name);  // "vertex", "face"
Model model_from(const std::string& name);              // one of window_model_names()

}  // namespace polyroll::app

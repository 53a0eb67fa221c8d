// What `--model auto` chose for a scene, and why (the rule is choose_model in auto_rule.cpp; its
// reasons rest on the trade study, docs/tradeoff/tradeoff.md). Box2D-free: a RunResult carries it
// into summary.json ("model_choice"), the run printout and the panel.
#pragma once

#include <optional>
#include <string>

#include "sim/scene/scene.h"

namespace polyroll {

struct ModelChoice {
    Model model = Model::grains;       // the model the run starts with
    std::optional<Model> then;         // the model it hands over to when the first stops holding
    std::string reason;
    // For an empty shell: the tracker step before the rigid model's shell would lift off or slip (the
    // friction its rolling needs above the ramp's coefficient), from which
    // the free rigid body (sim/reduced/free_body.h) carries it on, flying, landing on vertices,
    // rolling and sliding.
    std::optional<double> lift_off_time_s;
    // When the hand-over to `then` happened (a tracker step), if it did, and why; empty when the
    // first model (with its flights) ran alone.
    std::optional<double> hand_over_time_s;
    std::string hand_over_why;
    // The model that computed the end of the run.
    Model last() const { return hand_over_time_s && then ? *then : model; }
};

// A full shell: the grains have no room to move, so shell and fill turn as one rigid polygon (the
// experiment's full polygons roll as solid ones do). The Box2D discs of a full 2D fill still rattle
// in their packing's gaps at every impact (docs/studies/full-shells.md).
bool fill_is_solid(const Scene& scene);

// The cheapest model the scene requires (scene.run.model is ignored): see auto_rule.cpp.
ModelChoice choose_model(const Scene& scene);
// choose_model's rule in a line, for --model's help and the window's tooltip (model_help).
const char* auto_rule_description();

}  // namespace polyroll

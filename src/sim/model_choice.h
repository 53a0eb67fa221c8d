// What `--model auto` chose for a scene, and why (the rule is choose_model in auto_run.cpp; its
// reasons rest on the trade study, docs/tradeoff/tradeoff.md). Box2D-free: a RunResult carries it
// into summary.json ("model_choice"), the run printout and the panel.
#pragma once

#include <optional>
#include <string>

#include "sim/scene.h"

namespace polyroll {

struct ModelChoice {
    Model model = Model::grains;       // the model the run starts with
    std::optional<Model> then;         // the model it hands over to when the first stops holding
    std::string reason;
    // When the hand-over happened (a tracker step), if it did; empty when the first model ran alone.
    std::optional<double> hand_over_time_s;
    // The model that computed the end of the run.
    Model last() const { return hand_over_time_s && then ? *then : model; }
};

// The cheapest model the scene requires (scene.run.model is ignored): see auto_run.cpp.
ModelChoice choose_model(const Scene& scene);

}  // namespace polyroll

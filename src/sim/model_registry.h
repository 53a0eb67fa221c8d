// The models a scene can run with, one row each: what it is called in the run printout, what its
// files hold, and how to start it or continue another model's run with it. The only place that asks
// which model a scene names; everything else starts runs here and reads the traits.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sim/model_run.h"
#include "sim/run_result.h"
#include "sim/scene.h"

namespace polyroll {

struct ModelTraits {
    Model model = Model::grains;
    // Box2D computes it: the fidelity (step, iterations) means something, and summary.json has an
    // "engine" block with the engine's units and step.
    bool engine = false;
    bool has_grains = false;  // the fill as grains; otherwise as a continuum without grains
    // What the run printout says the fill is, for a model without grains ("" for grains).
    std::string fill_description;
    // Can carry on a run another model began (continue_run).
    bool continues_hand_over = false;
    // Cheap enough to run beside the others whenever a command runs them all (compare, bench's model
    // rows) and to offer in the window; false for the 3D reference, a minute of CPU a run.
    bool everyday = true;
    // Runs a curved track (ramp.curvature_deg_per_m, ramp_profile.h): the engines turn gravity with
    // the shell; the reduced models' closed forms assume one slope and refuse such a scene.
    bool follows_curved_track = false;
};

// Every model, in the order `compare` and `bench` list them: the grain simulation first, the
// reference the others are timed against.
const std::vector<Model>& all_models();
// The everyday ones (ModelTraits::everyday), in the same order.
const std::vector<Model>& everyday_models();
// What the window's model list offers: the everyday models' names, then "auto".
const std::vector<std::string>& window_model_names();
// The grain simulation: the reference the reduced models are compared with and timed against.
Model reference_model();
// Throws InputError for Model::automatic, which is a rule, not a model: ask the result (model_that_ran).
const ModelTraits& model_traits(Model model);

// Builds (for grains: pours and settles) a run of the scene's model; the scene must be validated.
// For Model::automatic, an AutoRun (auto_run.h) of the model choose_model picks.
std::unique_ptr<ModelRun> start_run(const Scene& scene);

// Continues with the scene's model the run `from` was handed over from (ModelRun::hand_over).
// Throws InputError if that model cannot take a run over.
std::unique_ptr<ModelRun> continue_run(const Scene& scene, const HandOver& from);

// Runs a validated scene to its end with its model, and times it (wall_time_s).
RunResult run_scene(const Scene& scene);

}  // namespace polyroll

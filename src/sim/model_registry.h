// The models a scene can run with, read from their rows (model_row.h: what each computes, what it is
// called, what its files hold, what it costs, which commands show it, and how to start it or continue
// another model's run with it). The only place that asks which model a scene names; everything else
// starts runs here and reads the traits.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sim/model_row.h"
#include "sim/model_run.h"
#include "sim/run_result.h"
#include "sim/scene/scene.h"

namespace polyroll {

// Every model, in the order `compare` and `bench` list them: the grain simulation first, the
// reference the others are timed against.
const std::vector<Model>& all_models();
// The everyday ones (ModelTraits::everyday), in the same order.
const std::vector<Model>& everyday_models();
// What the window's model list offers: the everyday models' names, then "auto".
const std::vector<std::string>& window_model_names();
// The grain simulation: the reference the reduced models are compared with and timed against.
Model reference_model();
// The names of `models`, joined: "grains, segments, rigid".
std::string model_list(const std::vector<Model>& models, const char* separator = ", ");
// What each of `models` computes, then auto's rule: "grains (Box2D simulates the shell and every
// grain), segments (...), ... or auto (the cheapest model the scene needs: ...)". --model's help lists
// every model, the window's tooltip the models it offers.
std::string model_help(const std::vector<Model>& models);
// The models a run of the scene may use, in order: the one it names, or for auto the one its choice
// starts with and the one it may hand over to.
std::vector<Model> models_a_run_may_use(const Scene& scene);
// Whether a run of the scene may use a model that reports its progress (ModelTraits::reports_progress).
bool may_report_progress(const Scene& scene);
// Whether a run of the scene may have Box2D step grains one by one in this process: it has a fill
// and one of its models has grains in the engine (ModelTraits::engine and has_grains; not the 3D
// reference, whose grains Yade steps). What the window's coarser grains apply to.
bool may_step_grains(const Scene& scene);
// Whether the run steps grains from its start: the model it starts with (auto's first) simulates
// grains in polyroll's engine. A full shell under auto does not: it starts as one rigid body and
// steps its grains only if it is handed over.
bool steps_grains_from_start(const Scene& scene);
// Throws InputError for Model::automatic, which is a rule, not a model: ask the result (model_that_ran).
const ModelTraits& model_traits(Model model);

// Builds (for grains: pours and settles) a run of the scene's model; the scene must be validated.
// For Model::automatic, an AutoRun (auto_run.h) of the models choose_model picks.
std::unique_ptr<ModelRun> start_run(const Scene& scene);

// Continues with the scene's model the run `from` was handed over from (ModelRun::hand_over).
// Throws InputError if that model cannot take a run over.
std::unique_ptr<ModelRun> continue_run(const Scene& scene, const HandOver& from);

// auto's first stage (sim/registry/auto_run.h), started here like every other run.
// The scene's model computed only while it holds: its result's model_invalid_time_s says until when.
// Throws InputError for a model without that mode.
std::unique_ptr<ModelRun> start_run_while_valid(const Scene& scene);

// Runs a validated scene to its end with its model, and times it (wall_time_s).
RunResult run_scene(const Scene& scene);

}  // namespace polyroll

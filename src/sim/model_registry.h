// The models a scene can run with, one row each: what it computes, what it is called in the run
// printout, what its files hold, what it costs, which commands show it, and how to start it or
// continue another model's run with it. The only place that asks which model a scene names;
// everything else starts runs here and reads the traits. A new model is a row here and its own files
// (and its name in scene_names.cpp's table).
#pragma once

#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "sim/model_run.h"
#include "sim/run_result.h"
#include "sim/scene/scene.h"

namespace polyroll {

namespace models {
class FreeBodyRun;
}

// How a run's wall time grows with the scene: the bound a sweep states before it starts
// (sweep/run_cost.h) computes it per class.
enum class RunCost {
    engine_bodies,   // Box2D: the shell and its grains x engine steps x a cost per body-step
    computed_whole,  // a few equations integrated at once: the process start dominates
    yade_grains,     // the 3D reference: its grains x DEM steps x Yade's cost per grain-step, plus Yade's start
};

// A trait every registry row states: it has no default, so a row that leaves one out does not compile
// (a designated initializer's missing member is built from {}, which Required refuses).
template <class T>
class Required {
public:
    // enable_if rather than requires: clang-tidy 14 sees only enable_if keeping a forwarding
    // constructor from standing in for the copy constructor.
    template <class U, std::enable_if_t<std::is_convertible_v<U, T> && !std::is_same_v<std::remove_cvref_t<U>, Required>,
                                        int> = 0>
    Required(U&& value) : value_(std::forward<U>(value)) {}  // implicit, so a row reads `.engine = true`
    operator const T&() const { return value_; }
    const T& get() const { return value_; }

private:
    T value_;
};

}  // namespace polyroll

// A required trait formats as its value.
template <class T, class Char>
struct fmt::formatter<polyroll::Required<T>, Char> : fmt::formatter<T, Char> {
    template <class FormatContext>
    auto format(const polyroll::Required<T>& r, FormatContext& ctx) const {
        return fmt::formatter<T, Char>::format(r.get(), ctx);
    }
};

namespace polyroll {

struct ModelTraits {
    Required<Model> model;
    // What it computes, in a few words: --model's help and the window's model tooltip list it
    // (model_help).
    Required<std::string> description;
    // Box2D computes it: the fidelity (step, iterations) means something, and summary.json has an
    // "engine" block with the engine's units and step.
    Required<bool> engine;
    Required<bool> has_grains;  // steps the fill grain by grain; otherwise as a continuum without grains
    // What the run printout says the fill is, for a model without grains ("" for grains).
    Required<std::string> fill_description;
    // Can carry on a run another model began (continue_run).
    Required<bool> continues_hand_over;
    // Cheap enough to run beside the others whenever a command runs them all (compare and the figures
    // of its folder, bench's model rows) and to offer in the window; false for the 3D reference, a
    // minute of CPU a run.
    Required<bool> everyday;
    // Runs a curved track (ramp.curvature_deg_per_m, ramp_profile.h): the engines turn gravity with
    // the shell, the reduced models take the local slope under the contact; a model that assumes one
    // slope refuses such a scene.
    Required<bool> follows_curved_track;
    Required<RunCost> cost;
    // auto's rule (choose_model, auto_run.cpp) may start a run with it or hand a run over to it: the
    // rule refuses to pick a model without it.
    Required<bool> auto_may_pick;
    // Its runs take minutes, so a run on a terminal says how far it has got (sim/run_progress.h).
    Required<bool> reports_progress;
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

// auto's stages (auto_run.h), started here like every other run.
// The scene's model computed only while it holds: its result's model_invalid_time_s says until when.
// Throws InputError for a model without that mode.
std::unique_ptr<ModelRun> start_run_while_valid(const Scene& scene);
// The free rigid body (sim/reduced/free_body_run.h): the rigid model's shell carried on from `from`, free to
// leave the ramp and to slide on it. The scene's fill is empty or full (fill_is_solid).
std::unique_ptr<models::FreeBodyRun> continue_as_free_body(const Scene& scene, const HandOver& from);

// Runs a validated scene to its end with its model, and times it (wall_time_s).
RunResult run_scene(const Scene& scene);

}  // namespace polyroll

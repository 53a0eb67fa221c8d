// One row of the model registry: a model's traits and how to start its run. The core declares the
// table and reads it (model_registry.h's lookups, scene_names.h's model names); the table itself is
// sim/registry/model_rows.cpp, above the model wings, because only it names their runs. A new model
// is its folder, its row there and its value in scene.h's Model enum.
#pragma once

#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "sim/scene/scene.h"

namespace polyroll {

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
    // What the model is called: --model, the scene file's run.model, the run printout, the window's
    // model list and summary.json read this name (scene_names.h looks a model up by it).
    Required<std::string> name;
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
    // auto's rule (choose_model, auto_rule.cpp) may start a run with it or hand a run over to it: the
    // rule refuses to pick a model without it.
    Required<bool> auto_may_pick;
    // Its runs take minutes, so a run on a terminal says how far it has got (sim/run_progress.h).
    Required<bool> reports_progress;
};

class ModelRun;
struct HandOver;

struct ModelRow {
    ModelTraits traits;
    std::unique_ptr<ModelRun> (*start)(const Scene& scene);
    std::unique_ptr<ModelRun> (*carry_on)(const Scene& scene, const HandOver& from);  // null: cannot
    // A run computed only while the model holds, for auto's first stage; null: none.
    std::unique_ptr<ModelRun> (*start_while_valid)(const Scene& scene);
};

// Every model's row, in the order `compare` and `bench` list them (sim/registry/model_rows.cpp).
const std::vector<ModelRow>& model_rows();

// A run of `--model auto` (sim/registry/auto_run.h): auto is a rule over the rows, not a row.
std::unique_ptr<ModelRun> start_auto_run(const Scene& scene);

}  // namespace polyroll

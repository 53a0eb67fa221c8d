// The sandbox's physics budget: what a scene costs to step at real time on this machine, and which
// cheaper model (coarser grains of the same total mass first, then a coarser step, as far as the
// trade study measured them) would keep real time. The window never applies that model by itself:
// the same scene gives the same run on any machine, a slow one only plays it slower. The budget
// offers the cheaper model in the panel, with its measured errors, and the user picks it or not.
// The cost of a lane is the one cost model's (sim/run_cost.h, assets/run-cost.json); the share of a
// frame the physics may take and each level's measured error are in assets/sandbox-budget.json. The
// cost model's seconds per cost unit are replaced by what the window measures once it has stepped a
// scene (it changes the offer only).
// Plain data and functions: no GLFW, ImGui or threads.
#pragma once

#include <string>
#include <vector>

#include "sim/run_cost.h"
#include "sim/scene/scene.h"

namespace polyroll::app {

// One cheaper model, with what the trade study measured it to cost in accuracy against the
// reference (docs/tradeoff/), and in wall time against the standard preset.
struct BudgetLevel {
    double grain_scale = 1.0;         // grain diameter x this, same fill mass
    std::string fidelity;             // a coarser fidelity preset, or "" to keep the scene's
    double terminal_velocity_error = 0.0;  // mean |Vt - Vt_ref| / Vt_ref over the scenes measured
    int wrong_behaviours = 0;         // scenes whose behaviour differed from the reference's...
    int scenes = 0;                   // ... of this many
    std::string source;               // where the numbers come from
};

struct BudgetFigures {
    // What a lane costs: a lane of G grains does engine_step_units(G, fidelity) cost units per engine
    // step, each cost.engine_step_s seconds on the measured machine (sim/run_cost.h).
    RunCostFigures cost;
    double physics_share = 0.0;             // the share of wall time the physics may take
    BudgetLevel full_detail;                // the standard preset's own error, for comparison
    std::vector<BudgetLevel> levels;        // cheapest last
};

// The figures of assets/sandbox-budget.json (throws if the file is malformed).
const BudgetFigures& budget_figures();

// A model for a set of lanes, with its estimated cost: the one stepped (the scenes as asked, or the
// level the user picked) or the one the budget offers.
struct BudgetChoice {
    int level = -1;                   // index into BudgetFigures::levels; -1: the scenes as asked
    double grains_asked = 0.0;        // estimated grains over all lanes, as asked
    double grains_chosen = 0.0;       // ... as chosen
    double cost_asked = 0.0;          // estimated physics seconds per simulated second, as asked
    double cost_chosen = 0.0;         // ... as chosen
    double s_per_cost_unit = 0.0;     // the figure the estimate used (sim/run_cost.h: engine_step_units)
    bool measured = false;            // that figure was measured in this window (else the asset's)
    bool fits = true;                 // the chosen model is expected to keep real time
    // Lanes that step no grains until auto hands them over (a full shell that lifts off or slips):
    // their grains, as chosen, and whether the lanes would still keep real time once they do.
    double grains_on_hand_over = 0.0;
    bool fits_after_hand_over = true;

    bool reduced() const { return level >= 0; }
};

// The physics seconds one simulated second of these lanes costs: cost units per engine step x engine
// steps per second x seconds per cost unit, summed over the lanes. Reduced models (rigid, segments),
// empty shells and full shells under auto (one rigid body until a hand-over) count as no grains.
double estimated_cost_s(const std::vector<Scene>& scenes, double s_per_cost_unit, const BudgetFigures& f);

// The offer: the scenes as asked if they fit the budget, else the first level that fits, else the
// cheapest level (then `fits` is false). A level that would make a scene invalid (grains too large
// for its shell) is passed over. Only ever shown: the window steps what the user picked.
BudgetChoice offered_level(const std::vector<Scene>& scenes, const BudgetFigures& f, double cost_per_grain_step,
                           bool measured);
// The model the user picked: `level` -1 (the scenes as asked) or an index into f.levels (throws
// InputError for an index out of range, or a level whose grains do not fit a lane's shell).
BudgetChoice picked_level(const std::vector<Scene>& scenes, const BudgetFigures& f, int level,
                          double s_per_cost_unit, bool measured);

// A level's short key, for --coarser: "1.5x", "2x", "2x-draft".
std::string level_key(const BudgetLevel& level);
// The level with that key (-1 for "none"); throws InputError naming the keys allowed.
int level_from_key(const std::string& key, const BudgetFigures& f);

// The scenes with the choice applied (the scenes unchanged when nothing was reduced).
std::vector<Scene> apply_choice(const std::vector<Scene>& scenes, const BudgetFigures& f, const BudgetChoice& c);

// The model row's short name of the choice: "" for the scenes as asked, "grains 2x larger",
// "grains 2x larger, draft step".
std::string level_label(const BudgetLevel& level);

// What a level costs in accuracy, from the trade study: "terminal velocity 4.7% off on average (full
// detail 5.0%), behaviour changed in 1 of 17 scenes".
std::string level_errors(const BudgetLevel& level, const BudgetFigures& f);

// The panel's statement of the model stepped and, when the scenes as asked cost more than real time
// here, of the offer: "The scene as asked (about 1010 grains) costs more than real time here: it
// plays slower, never differently. Grains 2x larger would keep real time (about 1010 -> 250 grains,
// same fill mass): terminal velocity 4.7% off on average (full detail 5.0%), ..." Or, for a picked
// level, what it is and what it costs.
std::string budget_statement(const BudgetChoice& stepped, const BudgetChoice& offer, const BudgetFigures& f);

}  // namespace polyroll::app

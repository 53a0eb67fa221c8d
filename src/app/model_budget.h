// The sandbox's physics budget (issue 13 item 3): when the scenes asked for cannot be stepped at real
// time on this machine, the closest cheaper model that can: coarser grains of the same total mass
// first, then a coarser step, as far as the trade study measured them. The figures (the machine's
// cost per grain step, the share of a frame the physics may take, and each level's measured error)
// are in assets/sandbox-budget.json; the cost per grain step is replaced by what the window
// measures once it has stepped a scene. Plain data and functions: no GLFW, ImGui or threads.
#pragma once

#include <string>
#include <vector>

#include "sim/scene.h"

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
    // Wall seconds per grain step beside the drawing, where a lane of G grains does (G + 1)^cost_exponent
    // grain steps per engine step (the +1 is the shell): a big pile costs more per grain than a few
    // loose grains (more contacts per grain and one large island for the solver).
    double physics_s_per_grain_step = 0.0;
    double cost_exponent = 1.0;
    double physics_share = 0.0;             // the share of wall time the physics may take
    double packing = 1.0;                   // grains built / estimated_grain_count (the estimate is close-packed)
    BudgetLevel full_detail;                // the standard preset's own error, for comparison
    std::vector<BudgetLevel> levels;        // cheapest last
};

// The figures of assets/sandbox-budget.json (throws if the file is malformed).
const BudgetFigures& budget_figures();

// What the budget chose for a set of lanes.
struct BudgetChoice {
    bool full_detail_asked = false;   // the user asked for full detail: nothing changed
    int level = -1;                   // index into BudgetFigures::levels; -1: the scenes as asked
    double grains_asked = 0.0;        // estimated grains over all lanes, as asked
    double grains_chosen = 0.0;       // ... as chosen
    double cost_asked = 0.0;          // estimated physics seconds per simulated second, as asked
    double cost_chosen = 0.0;         // ... as chosen
    double cost_per_grain_step = 0.0; // the figure the estimate used
    bool measured = false;            // that figure was measured in this window (else the asset's)
    bool fits = true;                 // the chosen model is expected to keep real time

    bool reduced() const { return level >= 0; }
};

// The physics seconds one simulated second of these lanes costs: (grains + 1)^exponent x engine steps
// per second x the cost per grain step, summed over the lanes. Reduced models (rigid, segments) and
// empty shells count as no grains.
double estimated_cost_s(const std::vector<Scene>& scenes, double cost_per_grain_step, const BudgetFigures& f);
// The grain steps one engine step of a lane of `grains` grains counts for (the measured cost's unit).
double grain_steps_per_engine_step(double grains, double cost_exponent);

// Chooses for the lanes: the scenes as asked if they fit the budget (or full detail is asked), else
// the first level that fits, else the cheapest level (then `fits` is false). A level that would make
// a scene invalid (grains too large for its shell) is passed over.
BudgetChoice choose_model(const std::vector<Scene>& scenes, const BudgetFigures& f, double cost_per_grain_step,
                          bool measured, bool full_detail);

// The scenes with the choice applied (the scenes unchanged when nothing was reduced).
std::vector<Scene> apply_choice(const std::vector<Scene>& scenes, const BudgetFigures& f, const BudgetChoice& c);

// The model row's short name of the choice: "" for the scenes as asked, "grains 2x larger",
// "grains 2x larger, draft step".
std::string level_label(const BudgetLevel& level);

// The panel's statement of what the budget did and what it costs, from the trade study:
// "To keep real time: grains 2x larger (about 1010 -> 250 grains, same mass). Trade study: terminal
// velocity 7.4% off on average (full detail 4.6%), behaviour changed in 1 of 17 scenes." Or that the
// scenes run as asked, or at full detail and slower than real time.
std::string budget_statement(const BudgetChoice& c, const BudgetFigures& f);

}  // namespace polyroll::app

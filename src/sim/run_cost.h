// What a run costs in wall time, for any model, from one set of figures (assets/run-cost.json, each
// measured by `polyroll bench`). Every estimate the program makes asks here: a sweep's bound before it
// starts, validate's and calibrate's time left, and the window's physics budget.
//
// - Box2D (the grain model, and the free body's engine hand-over): an engine step of G grains costs
//   engine_step_s x (G + 1)^engine_exponent x (iterations / engine_reference_iterations); a run is
//   its settling plus its simulated time in such steps. A pile costs more per grain than loose
//   grains: more contacts per grain, and Box2D keeps a contact for every pair of nearby boxes.
// - The reduced models integrate a few equations: a fixed cost a run.
// - The 3D reference: Yade's start, then its grains x DEM steps x a cost per grain-step.
#pragma once

#include "sim/scene/scene.h"

namespace polyroll {

struct RunCostFigures {
    double engine_step_s = 0.0;           // one engine step of a lone shell (G = 0) at the reference iterations
    double engine_exponent = 1.0;         // how a step's cost grows with the grains + 1 it steps
    double engine_reference_iterations = 15.0;  // velocity + position iterations the two above were measured at
    double packing = 1.0;                 // grains built / estimated_grain_count (the estimate is close-packed)
    double reduced_run_s = 0.0;           // one run of a reduced model
    double dem3d_start_s = 0.0;           // Yade's start
    double dem3d_grain_step_s = 0.0;      // Yade's cost per grain and DEM step
};

// The figures of assets/run-cost.json (throws InputError if the file is malformed).
const RunCostFigures& run_cost_figures();

// The grains the scene's Box2D world would step from the start: packing x the close-packed estimate,
// or 0 for an empty shell or a model without grains in polyroll's engine (auto: the model it starts with).
double engine_grains(const Scene& scene, const RunCostFigures& c = run_cost_figures());
// The grains a run steps only once auto hands it over to the grain engine (a full shell that lifts
// off or slips); 0 where none would be.
double engine_grains_after_hand_over(const Scene& scene, const RunCostFigures& c = run_cost_figures());

// One engine step of `grains` grains, in units of engine_step_s: (grains + 1)^exponent x iterations /
// reference iterations. The window measures its own seconds per unit and uses it in place of the asset's.
double engine_step_units(double grains, const FidelityParams& fidelity, const RunCostFigures& c = run_cost_figures());

// Engine steps per simulated second.
double engine_steps_per_s(const FidelityParams& fidelity);

// Wall seconds of a run of the scene that lasts `simulated_s` after its settling (its time limit at
// most). auto is costed as the model it starts with.
double run_seconds(const Scene& scene, double simulated_s, const RunCostFigures& c = run_cost_figures());
// The most a run of the scene may take: its whole time limit, auto costed as the last model it may
// hand over to. A sweep states this before it starts; most runs stop or reach the end sooner.
double max_run_seconds(const Scene& scene, const RunCostFigures& c = run_cost_figures());

}  // namespace polyroll

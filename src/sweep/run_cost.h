// What a sweep costs before it runs: an upper bound on one run's wall time from its scene, so the
// sweep can say "at most about 40 min" before starting instead of after.
#pragma once

#include <string>

#include "sim/scene.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

// Seconds one run takes at most on one core of a 2020s desktop if it lasts its whole time limit:
// (grains + 1) bodies x engine steps (settling plus the time limit) x a cost per body-step measured
// with the default 8 + 3 solver iterations (about 4.5 us; scaled by the iterations given). Runs that
// stop or reach the end sooner take less. The 3D reference: its grains x DEM steps x Yade's cost per
// grain-step. A reduced model costs next to nothing.
double max_run_seconds(const Scene& scene);

// The same for one run of a plan; 0 for a point that cannot run (it fails at once, a row of the table).
double max_run_seconds(const SweepPlan& plan, const PlannedRun& run);

// A cost as a person reads it: "40 s", "12 min", "3.5 h".
std::string duration_text(double seconds);

}  // namespace polyroll::sweep

// What a sweep costs before it runs: an upper bound on one run's wall time from its scene (the one
// cost model, sim/run_cost.h), so the sweep can say "at most about 40 min" before starting instead of after.
#pragma once

#include <string>

#include "sim/scene/scene.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

// The most one run of a plan may take (sim/run_cost.h: max_run_seconds); 0 for a point that cannot run (it fails at once, a row of the table).
double max_run_seconds(const SweepPlan& plan, const PlannedRun& run);

// A cost as a person reads it: "40 s", "12 min", "3.5 h".
std::string duration_text(double seconds);

}  // namespace polyroll::sweep

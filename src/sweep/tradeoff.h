// The speed/accuracy study: a fixed set of scenes (empty, partly filled and full; a small and a large
// angle; n = 6 and 18; BBs and rice) run with every model and fidelity preset, coarser grains and a
// second seed, each compared with the converged reference (grains at the reference preset, itself
// checked by halving its time step once more). Runs through the sweep engine, so it resumes.
#pragma once

#include <string>

#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

SweepPlan tradeoff_plan();

struct TradeoffReport {
    std::string markdown;    // the tables, for docs/tradeoff/tradeoff.md
    std::string points_csv;  // one row per model and preset: cost and errors, for the figure
};

// Compares every run in `table` (the plan's results) with its scene's reference.
TradeoffReport analyse_tradeoff(const SweepPlan& plan, const TableFile& table);

}  // namespace polyroll::sweep

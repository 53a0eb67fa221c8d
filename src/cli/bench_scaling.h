// The grain engine's cost against the number of grains in polyroll bench: the experiment's BB
// scenes from the small hexagon's 124 discs to the large hexagon three quarters full, the cost per
// disc and step, Box2D's contacts per disc behind it, and the power law fitted to the rows beside the
// one the cost model uses (sim/run_cost.h, assets/run-cost.json).
#pragma once

#include <string>

namespace polyroll::cli {

// Each scene built and settled, stepped bare (no tracker) to `from_s` after the release untimed, then
// `sim_s` simulated seconds timed; best of `repeats`, at the fidelity preset `fidelity`, one core.
void bench_scaling(const std::string& fidelity, double from_s, double sim_s, int repeats);

}  // namespace polyroll::cli

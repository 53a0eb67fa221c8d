// What a sweep costs before it runs: an upper bound on one run's wall time from its scene, so the
// sweep can say "at most about 40 min" before starting instead of after (issue 16).
#pragma once

#include "sim/scene.h"

namespace polyroll::sweep {

// Seconds one run takes at most on one core of a 2020s desktop if it lasts its whole time limit:
// (grains + 1) bodies x engine steps (settling plus the time limit) x a cost per body-step measured
// with the default 8 + 3 solver iterations (about 4.5 us; scaled by the iterations given). Runs that
// stop or reach the end sooner take less. A model without the engine costs next to nothing.
double max_run_seconds(const Scene& scene);

}  // namespace polyroll::sweep

// The engine with nothing watching: for `polyroll bench`, which compares a tracked grain run with
// bare Box2D stepping of the same bodies to show the project's own overhead, and measures how the
// engine's cost grows with the grains.
#pragma once

#include "sim/scene/scene.h"

namespace polyroll {

// Builds and settles the scene's world, then times `steps` tracker steps of bare engine stepping.
// Returns the stepping's wall time in seconds (building not included).
double time_bare_engine_s(const Scene& scene, long steps);

// What `steps` tracker steps of bare stepping cost, and the contact bookkeeping behind the cost.
// Box2D keeps a contact for every pair of fixtures whose enlarged boxes overlap (a margin of 0.1
// engine units plus four steps' travel), touching or not, and walks those lists every step.
struct EngineLoad {
    int grains = 0;
    double wall_s = 0.0;              // the stepping alone, building not included
    double contacts_per_grain = 0.0;  // Box2D's contacts (box pairs), mean over the steps sampled
    double touching_per_grain = 0.0;  // of those, the ones whose shapes touch
};
EngineLoad measure_engine_load(const Scene& scene, long steps);

}  // namespace polyroll

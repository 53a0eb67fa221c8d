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
    double shell_speed_m_s = 0.0;     // the shell's speed along the ramp where the timing began
    long timed_steps = 0;             // `steps`, or fewer where the shell reached the ramp's end first
};
// `skip_steps` tracker steps are stepped first, untimed: a stretch later in the roll, where the pile
// moves fast, costs differently from the first second after the release. The timing ends early where
// the shell's centre passes the run's end (beyond it the shell leaves the ramp).
EngineLoad measure_engine_load(const Scene& scene, long steps, long skip_steps = 0);

}  // namespace polyroll

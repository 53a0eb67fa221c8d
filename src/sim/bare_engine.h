// The engine with nothing watching: for `polyroll bench`, which compares a tracked grain run with
// bare Box2D stepping of the same bodies to show the project's own overhead.
#pragma once

#include "sim/scene.h"

namespace polyroll {

// Builds and settles the scene's world, then times `steps` tracker steps of bare engine stepping.
// Returns the stepping's wall time in seconds (building not included).
double time_bare_engine_s(const Scene& scene, long steps);

}  // namespace polyroll

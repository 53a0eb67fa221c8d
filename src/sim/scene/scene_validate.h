// Range checks for a resolved scene. The limits are the rows of scene_fields.h; every message names the
// field, the bad value and the allowed range.
#pragma once

#include <functional>
#include <string>

#include "sim/scene/scene.h"

namespace polyroll {

// Most grains a scene may build (memory and time stay bounded; 20,000 grains take minutes per
// simulated second on one core).
inline constexpr double kMaxGrains = 20000;

// Throws InputError for the first out-of-range value. `where(field)` may add " (from --flag)".
void validate_scene(const Scene& scene, const std::function<std::string(const std::string&)>& where = {});

// Expected grain count for the fill, from areas (a close-packed estimate, used before building).
double estimated_grain_count(const Scene& scene);

}  // namespace polyroll

// The friction, restitution and size spread the 2D grain model gives its discs: the material's values
// with the scene's closure on top (scene.h, ClosureParams; assets/closures.json). One place, so the
// discs' fixtures, the disc-on-wall contacts and the fill's deposition cannot disagree about what the
// closure does.
#pragma once

#include <algorithm>

#include "sim/scene/scene.h"

namespace polyroll {

inline double disc_friction(const Scene& s) { return s.fill.material.friction * s.closure.disc_friction_factor; }
inline double disc_wall_friction(const Scene& s) {
    return s.fill.material.wall_friction * s.closure.wall_friction_factor;
}
// The discs' diameters are uniform in d (1 +- this): the closure's spread where it gives one.
inline double disc_size_spread(const Scene& s) {
    return s.closure.disc_size_spread.value_or(s.fill.material.diameter_spread);
}
// A factor may not make an impact give back more energy than it had.
inline double disc_restitution(const Scene& s) {
    return std::min(1.0, s.fill.material.restitution * s.closure.restitution_factor);
}

}  // namespace polyroll

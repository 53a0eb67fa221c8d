// The friction and restitution the 2D grain model gives its contacts: the material's values with the
// scene's closure on top (scene.h, ClosureParams; assets/closures.json). One place, so the discs'
// fixtures and the disc-on-wall contacts cannot disagree about what the closure does.
#pragma once

#include <algorithm>

#include "sim/scene/scene.h"

namespace polyroll {

inline double disc_friction(const Scene& s) { return s.fill.material.friction * s.closure.disc_friction_factor; }
inline double disc_wall_friction(const Scene& s) {
    return s.fill.material.wall_friction * s.closure.wall_friction_factor;
}
// A factor may not make an impact give back more energy than it had.
inline double disc_restitution(const Scene& s) {
    return std::min(1.0, s.fill.material.restitution * s.closure.restitution_factor);
}

}  // namespace polyroll

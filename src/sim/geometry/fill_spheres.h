// The fill as the 3D reference builds it: spheres in the box. Core rather than the 3D reference's own,
// because a sweep bounds a run's cost from the same count before any run starts (run_cost.cpp).
#pragma once

#include "sim/scene/scene.h"

namespace polyroll {

// How many of the fill's grains the box holds: r x inside volume x packing fraction / the mean grain
// volume (diameters spread uniformly), rounded, at least one in a filled shell and none in an empty one.
// disc_size.h's fill_grain_count is the same estimate from the mean diameter alone, unrounded.
int fill_sphere_count(const Scene& scene);

}  // namespace polyroll

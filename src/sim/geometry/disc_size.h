// What one 2D disc stands for, and so how large the discs are (fill.material.grains_per_disc).
//
// The cross-section holds the fill as discs in a plane. Read as a slice of the box, one disc is a
// column of grains through the box's depth, the grain's own size (grains_per_disc unset): a small
// hexagon a quarter full of BBs is then 21 discs where the box holds about 240 BBs. A pile of so few
// discs is far stiffer than the 3D pile, whose grains pass each other along the roll axis
// (docs/physics.md). With grains_per_disc = k the discs are as many as the 3D fill's grains divided
// by k, each with k grains' mass, and as large as fits: k = 1 is one disc per grain.
#pragma once

#include <algorithm>

#include "sim/scene/scene.h"

namespace polyroll {

// Share of the fill's area that poured discs cover (sequential deposition, sim/grains/grain_deposition.h;
// measured on the small hexagon a quarter full: 0.81 with 21 discs of 6 mm, 0.88 with 253 of 1.8 mm).
inline constexpr double kDiscPackingFraction = 0.85;

// The share of the inside area the 2D pile fills (below its level): r, times the closure's bulk factor
// (the 3D box's pile stands higher than r), at most all of it. The fill's mass is r's either way.
inline double pile_bulk_share(const Scene& s) { return std::min(1.0, s.fill.ratio * s.closure.bulk_factor); }

// Grains in the 3D fill: fill volume x packing fraction / one grain's volume (mean diameter).
double fill_grain_count(const Scene& scene);

// The discs' mean diameter: the grain's diameter when grains_per_disc is unset; otherwise
// d sqrt((2/3) k (phi_2D / phi_3D) d / depth), which makes the discs' count (fill area x phi_2D /
// disc area) the 3D count (fill volume x phi_3D / grain volume) divided by k, whatever r and n.
double disc_diameter_m(const Scene& scene);

}  // namespace polyroll

// Pouring grains, in geometry: each grain in turn goes to the lowest place inside a convex polygon
// where it rests against two walls or grains without overlapping any (sequential deposition, the
// way a poured pile builds up), until the next place would be above a level free surface. The
// result is a dense random packing with a level top, and a count that follows from the fill ratio
// and the packing rather than being chosen.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "sim/geometry/geometry.h"

namespace polyroll {

struct Disc {
    geom::Vec2 centre;
    double radius = 0.0;
};

// `poly`: convex, counter-clockwise. `up`: unit vector against gravity. Grains whose centre would lie
// above `surface_level` (along `up`) are not placed; if not even the first fits below it, the lowest
// single grain is placed, so a small fill keeps its mass. `next_radius` draws each grain's radius,
// never above `max_radius`. Neighbouring grains are left a gap of 0.2% of `max_radius`. Among
// equally low places one is drawn with `tie_break` (uniform in [0, 1)), so piles have no lean.
std::vector<Disc> deposit_grains(const std::vector<geom::Vec2>& poly, geom::Vec2 up, double surface_level,
                                 const std::function<double()>& next_radius, double max_radius,
                                 std::size_t max_count, const std::function<double()>& tie_break);

}  // namespace polyroll

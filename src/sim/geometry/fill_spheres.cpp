// The fill's spheres: see fill_spheres.h.
#include "sim/geometry/fill_spheres.h"

#include <algorithm>
#include <cmath>

#include "sim/geometry/geometry.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

int fill_sphere_count(const Scene& s) {
    if (s.fill.ratio <= 0.0) return 0;
    const MaterialParams& m = s.fill.material;
    // Diameters uniform in d (1 +- spread): the mean of d^3 is d^3 (1 + spread^2).
    const double mean_volume_m3 = geom::kPi / 6.0 * std::pow(m.diameter_m, 3) * (1.0 + m.diameter_spread * m.diameter_spread);
    const double grains_volume_m3 = s.fill.ratio * shell_properties(s.shell).inside_volume_m3 * m.packing_fraction;
    return std::max(1, static_cast<int>(std::lround(grains_volume_m3 / mean_volume_m3)));
}

}  // namespace polyroll

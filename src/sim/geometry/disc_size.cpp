// Disc size from what a disc stands for: see disc_size.h.
#include "sim/geometry/disc_size.h"

#include <cmath>

#include "sim/geometry/geometry.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

double fill_grain_count(const Scene& scene) {
    const MaterialParams& m = scene.fill.material;
    const double grain_volume_m3 = geom::kPi * m.diameter_m * m.diameter_m * m.diameter_m / 6.0;
    const double fill_volume_m3 = scene.fill.ratio * shell_properties(scene.shell).inside_volume_m3;
    return fill_volume_m3 * m.packing_fraction / grain_volume_m3;
}

double disc_diameter_m(const Scene& scene) {
    const MaterialParams& m = scene.fill.material;
    if (!m.grains_per_disc) return m.diameter_m;
    const double k = *m.grains_per_disc;
    return m.diameter_m *
           std::sqrt(2.0 / 3.0 * k * (kDiscPackingFraction / m.packing_fraction) * m.diameter_m / scene.shell.depth_m);
}

}  // namespace polyroll

// Engine length unit: see engine_units.h.
#include "sim/engine_units.h"

#include <algorithm>
#include <cmath>

#include "sim/disc_size.h"
#include "sim/geometry.h"

namespace polyroll {

double EngineUnits::speed_cap_m_s(const FidelityParams& f) const {
    return 2.0 / units_per_m * f.step_hz * f.substeps;
}

double speed_bound_m_s(const Scene& s) {
    const double drop_m = s.ramp.length_m * std::sin(s.ramp.angle_deg * geom::kPi / 180.0);
    return std::sqrt(2.0 * s.run.gravity_m_s2 * std::max(drop_m, 0.0));
}

EngineUnits choose_engine_units(const Scene& s) {
    EngineUnits cm{100.0}, mm{1000.0};
    if (s.fill.ratio <= 0.0) return cm;
    const double min_radius_m = 0.5 * disc_diameter_m(s) * (1.0 - s.fill.material.diameter_spread);
    if (min_radius_m >= 0.001) return cm;
    // Margin of 2 over the bound: grains inside a spinning shell move faster than its centre.
    if (mm.speed_cap_m_s(s.fidelity) >= 2.0 * speed_bound_m_s(s)) return mm;
    return cm;
}

}  // namespace polyroll

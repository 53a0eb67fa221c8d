// Engine length unit: see engine_units.h.
#include "sim/grains/engine_units.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "sim/geometry/disc_size.h"
#include "sim/grains/contact_values.h"
#include "sim/geometry/geometry.h"

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
    if (s.fill.ratio <= 0.0) {
        // Box2D keeps every polygon a skin (0.01 units) outside its outline, so at 1 cm the shell
        // touches the ramp 0.2 mm early and rolls on corners rounded by as much, and its linear
        // slop (0.005 units) lets it sink 0.05 mm, against 5 um at 1 mm. Measured on the hopping
        // empty shells at 80 kHz (docs/studies/free-body-against-box2d.md): the 18-gon at 10, 20 and 30
        // degrees 3-7% faster than the free rigid body at 1 cm, within 0.4% at 1 mm (a thinner
        // skin alone mended 10 degrees only). The centre is the only body and it cannot pass the
        // bound; the tracker calls a run diverged at 0.8 of the cap (tracker.cpp), hence the
        // margin of 1.25.
        return mm.speed_cap_m_s(s.fidelity) >= 1.25 * speed_bound_m_s(s) ? mm : cm;
    }
    const double min_radius_m = 0.5 * disc_diameter_m(s) * (1.0 - disc_size_spread(s));
    if (min_radius_m >= 0.001) return cm;
    // Margin of 2 over the bound: grains inside a spinning shell move faster than its centre.
    if (mm.speed_cap_m_s(s.fidelity) >= 2.0 * speed_bound_m_s(s)) return mm;
    return cm;
}

nlohmann::ordered_json engine_block(const EngineUnits& units, const FidelityParams& f) {
    nlohmann::ordered_json engine;
    engine["length_unit_m"] = 1.0 / units.units_per_m;
    engine["engine_step_s"] = 1.0 / (f.step_hz * f.substeps);
    engine["speed_cap_m_s"] = units.speed_cap_m_s(f);
    return engine;
}

}  // namespace polyroll

// The length unit Box2D works in. Box2D 2.4.1 compiles its tolerances for objects of about one unit
// (linear slop 0.005, polygon skin 0.01, AABB margin 0.1, at most 2 units of travel per step), and
// the experiment's grains are millimetres across: in metres they would sit below the tolerances.
// So the engine works in centimetres, or millimetres for fine grains, and everything is converted
// back to SI (m, kg, s) at the boundary. Mass and time keep their SI units inside the engine.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "sim/scene/scene.h"

namespace polyroll {

struct EngineUnits {
    double units_per_m = 100.0;

    double to_units(double metres) const { return metres * units_per_m; }
    double to_m(double units) const { return units / units_per_m; }
    // Box2D caps travel at 2 units per engine step (b2_maxTranslation).
    double speed_cap_m_s(const FidelityParams& f) const;
};

// 1 cm, or 1 mm when the finer unit's speed cap still allows the run and either the smallest grain
// radius would be under 0.1 cm (such grains make about 85 broad-phase pairs each at 1 cm and crawl)
// or the shell is empty (Box2D's polygon skin, 0.2 mm between shell and ramp at 1 cm, biases a
// hopping shell; 0.02 mm at 1 mm). The standard step (1 kHz) caps 1 mm at 2 m/s, so it keeps 1 cm.
EngineUnits choose_engine_units(const Scene& scene);

// summary.json's "engine" block of a Box2D run (RunResult::model_blocks): the length unit, the
// engine's own step (the tracker's step over the substeps) and the speed cap.
nlohmann::ordered_json engine_block(const EngineUnits& units, const FidelityParams& f);

// An upper bound on the speed the shell can reach: sliding without loss down the whole ramp.
double speed_bound_m_s(const Scene& scene);

}  // namespace polyroll

// The scene fields a calibration fits (polyroll calibrate --params): which fields may be fitted, their
// search bounds (given, from assets/calibration.json, or the field's own limits) and start values.
#pragma once

#include <string>
#include <utility>
#include <vector>


#include "sim/scene/scene.h"
#include "sweep/observations.h"

namespace polyroll::sweep {

struct CalibrationParam {
    std::string path;         // scene field, e.g. "fill.material.restitution"
    double lo = 0.0, hi = 0.0;
    std::string bounds_from;  // "--params", "assets/calibration.json: <reason>" or "the field's limits"
    double start = 0.0;       // the scene's own value, or --start's
    std::string start_from;   // "the scene" or "--start"
};

// Parses "FIELD[=FROM:TO],FIELD..." against the scene-field table and `scene` (for limits that depend
// on other fields). Refuses (InputError, one line naming the value and what is allowed): an unknown
// field, a field that is not a continuous number, the seed, a field given twice, bounds outside the
// field's limits or not from < to, and a field an observation sets itself (its scene or grid).
std::vector<CalibrationParam> parse_calibration_params(const std::string& text, const Scene& scene,
                                                       const ObservationFile& observations);

// Start values: each field's value in `scene` (the observations' first run, with the command line's
// values on top), or --start FIELD=VALUE (inside the bounds). A scene value outside the bounds is
// refused: the objective "before" must be the scene's own.
void set_start_values(std::vector<CalibrationParam>& params, const Scene& scene,
                      const std::vector<std::pair<std::string, double>>& starts);

}  // namespace polyroll::sweep

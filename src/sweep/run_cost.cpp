// A run's cost before it runs: see run_cost.h.
#include "sweep/run_cost.h"

#include <algorithm>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sim/run_cost.h"
#include "sim/scene/scene_json.h"

namespace polyroll::sweep {

double max_run_seconds(const SweepPlan& plan, const PlannedRun& run) {
    try {
        return max_run_seconds(resolve_scene(run_layers(plan, run)));
    } catch (const InputError&) {
        return 0.0;
    }
}

std::string duration_text(double s) {
    if (s < 60.0) return fmt::format("{:.0f} s", std::max(s, 1.0));
    if (s < 3600.0) return fmt::format("{:.0f} min", s / 60.0);
    return fmt::format("{:.1f} h", s / 3600.0);
}

}  // namespace polyroll::sweep

// polyroll bench's row for the 3D reference (--model dem3d): what a Yade run of the scene costs in
// CPU seconds per simulated second, in all and per grain, beside the 2D grain run of the same scene.
#pragma once

#include <optional>

#include "sim/scene/scene.h"

namespace polyroll::cli {

// One dem3d run of `base` (they take about a minute; the outcome is the same every time, so the
// cost is not repeated). `grain_run_s`: the 2D grain run's wall time at the scene's fidelity, if
// measured, for the ratio. Prints why instead if Yade is not installed.
void bench_dem3d(const Scene& base, std::optional<double> grain_run_s);

}  // namespace polyroll::cli

// The reduced models' part of polyroll bench: wall time per run of one scene with each model and
// the speed-up over the grain simulation.
#pragma once

#include <optional>

#include "sim/scene/scene.h"

namespace polyroll::cli {

// `grain_run_s`: a grain run of this scene already timed (build, settle and run), if any; otherwise
// the grain model is run here at the scene's fidelity, best of `repeats`.
void bench_models(const Scene& scene, int repeats, std::optional<double> grain_run_s);

}  // namespace polyroll::cli

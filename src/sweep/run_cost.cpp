// A run's cost before it runs: see run_cost.h.
#include "sweep/run_cost.h"

#include "sim/model_registry.h"
#include "sim/scene_validate.h"

namespace polyroll::sweep {

namespace {

// Measured with polyroll run --json (wall_time_s over grains x engine steps): 4.3 us for 1008 grains
// of rice in the large hexagon at the draft fidelity, 5.1 us for 21 BBs in the small one at standard.
constexpr double kBodyStepS = 4.5e-6;
constexpr double kDefaultIterations = 8 + 3;
// The reduced models integrate a few equations per step: the process start dominates.
constexpr double kReducedRunS = 0.01;

}  // namespace

double max_run_seconds(const Scene& scene) {
    // auto may hand over to the engine at lift-off: costed as the engine, the bound.
    const Model model = scene.run.model == Model::automatic ? Model::grains : scene.run.model;
    if (!model_traits(model).engine) return kReducedRunS;
    const double bodies = (model_traits(model).has_grains ? estimated_grain_count(scene) : 0.0) + 1.0;
    const double steps = (scene.run.settle_time_s + scene.run.time_limit_s) * scene.fidelity.step_hz *
                         static_cast<double>(scene.fidelity.substeps);
    const double iterations =
        static_cast<double>(scene.fidelity.velocity_iterations + scene.fidelity.position_iterations) /
        kDefaultIterations;
    return bodies * steps * kBodyStepS * iterations;
}

}  // namespace polyroll::sweep

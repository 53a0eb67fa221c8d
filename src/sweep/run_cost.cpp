// A run's cost before it runs: see run_cost.h.
#include "sweep/run_cost.h"

#include <algorithm>

#include <fmt/format.h>

#include "sim/dem3d/dem3d_input.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene_json.h"
#include "sim/scene_validate.h"

namespace polyroll::sweep {

namespace {

// Measured with polyroll run --json (wall_time_s over grains x engine steps): 4.3 us for 1008 grains
// of rice in the large hexagon at the draft fidelity, 5.1 us for 21 BBs in the small one at standard.
constexpr double kBodyStepS = 4.5e-6;
constexpr double kDefaultIterations = 8 + 3;
// The reduced models integrate a few equations per step: the process start dominates.
constexpr double kReducedRunS = 0.01;
// The 3D reference: Yade's CPU time per grain and DEM step, measured on the default scene (241 BBs,
// 16.9 s poured, settled and run in 253,000 steps of 67 us: 42 CPU-s, 0.69 us), with room for a
// slower machine; plus Yade's start (about 1 s).
constexpr double kDem3dGrainStepS = 1.0e-6;
constexpr double kDem3dStartS = 1.5;

}  // namespace

double max_run_seconds(const Scene& scene) {
    // auto is costed as the last model it may use (the engine, where it may hand over at lift-off): the bound.
    const ModelTraits& traits = model_traits(models_a_run_may_use(scene).back());
    switch (traits.cost) {
        case RunCost::computed_whole: return kReducedRunS;
        case RunCost::yade_grains: {
            const double steps = (scene.run.settle_time_s + scene.run.time_limit_s) /
                                 (scene.dem3d.contact_time_s * scene.dem3d.time_step_share);
            return kDem3dStartS + (dem3d::grain_count(scene) + 1.0) * steps * kDem3dGrainStepS;
        }
        case RunCost::engine_bodies: break;
    }
    const double bodies = (traits.has_grains ? estimated_grain_count(scene) : 0.0) + 1.0;
    const double steps = (scene.run.settle_time_s + scene.run.time_limit_s) * scene.fidelity.step_hz *
                         static_cast<double>(scene.fidelity.substeps);
    const double iterations =
        static_cast<double>(scene.fidelity.velocity_iterations + scene.fidelity.position_iterations) /
        kDefaultIterations;
    return bodies * steps * kBodyStepS * iterations;
}

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

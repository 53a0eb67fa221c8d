// What a run costs: see run_cost.h.
#include "sim/run_cost.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/geometry/fill_spheres.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_validate.h"

namespace polyroll {

namespace {

RunCostFigures load_figures() {
    const auto& v = assets::file("run-cost.json").at("values");
    RunCostFigures c;
    c.engine_step_s = v.at("engine_step_s").get<double>();
    c.engine_exponent = v.at("engine_exponent").get<double>();
    c.engine_reference_iterations = v.at("engine_reference_iterations").get<double>();
    c.packing = v.at("packing").get<double>();
    c.reduced_run_s = v.at("reduced_run_s").get<double>();
    c.dem3d_start_s = v.at("dem3d_start_s").get<double>();
    c.dem3d_grain_step_s = v.at("dem3d_grain_step_s").get<double>();
    if (!(c.engine_step_s > 0) || !(c.engine_exponent >= 1.0 && c.engine_exponent <= 3.0) ||
        !(c.engine_reference_iterations >= 1) || !(c.packing > 0 && c.packing <= 1.0) || !(c.reduced_run_s > 0) ||
        !(c.dem3d_start_s >= 0) || !(c.dem3d_grain_step_s > 0))
        throw InputError("assets/run-cost.json: the costs must be positive, engine_exponent 1 to 3, "
                         "engine_reference_iterations at least 1 and packing above 0 and at most 1");
    return c;
}

double engine_run_seconds(const Scene& s, double grains, double simulated_s, const RunCostFigures& c) {
    const double steps = (s.run.settle_time_s + simulated_s) * engine_steps_per_s(s.fidelity);
    return steps * engine_step_units(grains, s.fidelity, c) * c.engine_step_s;
}

double model_run_seconds(const Scene& s, Model model, double simulated_s, const RunCostFigures& c) {
    const ModelTraits& traits = model_traits(model);
    switch (traits.cost) {
        case RunCost::computed_whole: return c.reduced_run_s;
        case RunCost::yade_grains: {
            const double steps = (s.run.settle_time_s + simulated_s) /
                                 (s.dem3d.contact_time_s * s.dem3d.time_step_share);
            return c.dem3d_start_s + (fill_sphere_count(s) + 1.0) * steps * c.dem3d_grain_step_s;
        }
        case RunCost::engine_bodies: break;
    }
    const double grains = traits.has_grains && s.fill.ratio > 0.0 ? c.packing * estimated_grain_count(s) : 0.0;
    return engine_run_seconds(s, grains, simulated_s, c);
}

}  // namespace

const RunCostFigures& run_cost_figures() {
    static const RunCostFigures c = load_figures();
    return c;
}

double engine_grains(const Scene& s, const RunCostFigures& c) {
    return steps_grains_from_start(s) ? c.packing * estimated_grain_count(s) : 0.0;
}

double engine_grains_after_hand_over(const Scene& s, const RunCostFigures& c) {
    return may_step_grains(s) && !steps_grains_from_start(s) ? c.packing * estimated_grain_count(s) : 0.0;
}

double engine_step_units(double grains, const FidelityParams& f, const RunCostFigures& c) {
    const double iterations = static_cast<double>(f.velocity_iterations + f.position_iterations);
    return std::pow(std::max(grains, 0.0) + 1.0, c.engine_exponent) * iterations / c.engine_reference_iterations;
}

double engine_steps_per_s(const FidelityParams& f) { return f.step_hz * static_cast<double>(f.substeps); }

double run_seconds(const Scene& s, double simulated_s, const RunCostFigures& c) {
    const double t = std::clamp(simulated_s, 0.0, s.run.time_limit_s);
    return model_run_seconds(s, models_a_run_may_use(s).front(), t, c);
}

double max_run_seconds(const Scene& s, const RunCostFigures& c) {
    return model_run_seconds(s, models_a_run_may_use(s).back(), s.run.time_limit_s, c);
}

}  // namespace polyroll

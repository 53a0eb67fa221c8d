// The auto model's part of polyroll bench: see bench_auto.h.
#include "cli/bench_auto.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sim/scene/fidelity_preset.h"
#include "sim/model_registry.h"
#include "sweep/scene_matrices.h"
#include "sim/reduced/reduced_models.h"
#include "sim/scene/scene_names.h"
#include "sim/scene/scene_validate.h"

namespace polyroll::cli {

namespace {

struct Timed {
    RunResult result;
    double best_s = 1e300;
};

Timed time_runs(const Scene& s, int repeats) {
    Timed t;
    for (int rep = 0; rep < repeats; ++rep) {
        t.result = run_scene(s);
        t.best_s = std::min(t.best_s, t.result.wall_time_s);
    }
    return t;
}

std::string percent_off(const std::optional<double>& v, const std::optional<double>& ref) {
    return v && ref ? fmt::format("{:.1f}%", 100.0 * std::fabs(*v - *ref) / *ref) : "-";
}

std::string speed(const std::optional<double>& v) { return v ? fmt::format("{:.3f}", *v) : "-"; }

}  // namespace

void bench_auto(const Scene& base, int repeats) {
    for (const auto& [sides, angle] : scenes::auto_shells()) {
        try {
            validate_scene(scenes::empty_shell(base, sides, angle));
        } catch (const InputError& e) {
            throw InputError(fmt::format("bench --auto: {} (each of its 16 empty shells must fit --tilt)", e.what()));
        }
    }
    fmt::print("\nauto against grains on empty shells ({} fidelity for grains; reference: one grain run at the\n"
               "reference preset), best of {} on one core\n",
               base.fidelity.preset.empty() ? "custom" : base.fidelity.preset, repeats);
    fmt::print("{:>3} {:>5} {:>9} {:>9} {:>8} {:>6} {:>6} {:>7} {:>12} {:>8} {:>8} {:>8} {:>8} {:>8} {:>6} {:>6} {:>6} {:>6} {:>6}  {}\n",
               "n", "deg", "auto_s", "grains_s", "speedup", "free", "box2d", "hops", "mu_need", "Vt_auto", "Vt_rigid", "Vt_grain",
               "Vt_ref", "Vt_fine", "a-g", "a-ref", "g-ref", "a-fine", "g-fine", "behaviour (auto / grains / reference)");
    double auto_total = 0.0, grains_total = 0.0;
    for (const auto& [sides, angle] : scenes::auto_shells()) {
        Scene s = scenes::empty_shell(base, sides, angle);
        s.run.model = Model::automatic;
        const Timed a = time_runs(s, repeats);
        s.run.model = Model::grains;
        const Timed g = time_runs(s, repeats);
        const RunResult ref = run_scene(at_fidelity_preset(s, "reference"));
        const RunResult finest = run_scene(at_finest_box2d(s));
        s.run.model = Model::rigid;
        const RunResult rigid = run_scene(s);
        // The rigid model run on past lift-off: on how many of its faces the normal force it needs
        // turns negative (where a hand-back from Box2D would hand the shell over again at once).
        const models::RollingRun roll =
            models::roll(models::rolling_body(s), models::FillMotion::frozen, models::ramp_frame(s));
        auto_total += a.best_s;
        grains_total += g.best_s;
        const auto& c = a.result.model_choice;
        const std::string free_from = c && c->lift_off_time_s ? fmt::format("{:.3f}", *c->lift_off_time_s) : "-";
        const std::string handover = c && c->hand_over_time_s ? fmt::format("{:.3f}", *c->hand_over_time_s) : "-";
        const auto& va = a.result.measured.terminal_velocity_m_s;
        const auto& vg = g.result.measured.terminal_velocity_m_s;
        const auto& vr = ref.measured.terminal_velocity_m_s;
        const auto& vf = finest.measured.terminal_velocity_m_s;
        const auto& vrig = rigid.measured.terminal_velocity_m_s;
        const std::string hops =
            fmt::format("{}/{}", roll.hop_pivots, std::max<size_t>(1, roll.measured.impacts.size()));
        const std::string mu = fmt::format("{:.2f}/{:.2f}", roll.max_friction_share, roll.max_impact_friction_share);
        fmt::print("{:>3} {:>5g} {:>9.5f} {:>9.5f} {:>7.1f}x {:>6} {:>6} {:>7} {:>12} {:>8} {:>8} {:>8} {:>8} {:>8} {:>6} {:>6} {:>6} "
                   "{:>6} {:>6}  {} / {} / {}\n",
                   sides, angle, a.best_s, g.best_s, g.best_s / a.best_s, free_from, handover, hops, mu, speed(va),
                   speed(vrig), speed(vg), speed(vr), speed(vf), percent_off(va, vg), percent_off(va, vr),
                   percent_off(vg, vr), percent_off(va, vf), percent_off(vg, vf), to_string(a.result.measured.behaviour),
                   to_string(g.result.measured.behaviour), to_string(ref.measured.behaviour));
        std::fflush(stdout);
    }
    fmt::print("all 16: auto {:.4f} s, grains {:.4f} s, {:.1f}x. free: when the rigid model, at the step before\n"
               "lift-off, handed the shell to the free rigid body (s); box2d: when that handed it to Box2D (s);\n"
               "hops: faces on which the rigid model, run on past lift-off, needs a negative normal force / its\n"
               "faces; mu_need: the friction share of the normal force the rigid model's no-slip rolling needs,\n"
               "between impacts / at an impact (the ramp's friction coefficient is {:g}); Vt_rigid: the rigid model\n"
               "alone; Vt_ref: grains at the reference preset; Vt_fine: grains at 80,000 engine steps a second (1 mm units);\n"
               "a-g = |Vt_auto - Vt_grain| / Vt_grain, a-ref and g-ref against Vt_ref, a-fine and g-fine against\n"
               "Vt_fine.\n",
               auto_total, grains_total, grains_total / auto_total, base.ramp.friction);
}

}  // namespace polyroll::cli

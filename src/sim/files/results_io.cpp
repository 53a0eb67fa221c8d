// A run's output files: see results_io.h.
#include "sim/files/results_io.h"

#include <fmt/core.h>

#include "sim/files/atomic_file.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/shell_label.h"

namespace polyroll {

using json = nlohmann::ordered_json;

double mean_impact_ratio(const Measurements& m) {
    if (m.impacts.empty()) return 0.0;
    double sum = 0.0;
    for (const FaceImpact& f : m.impacts) sum += f.ratio();
    return sum / static_cast<double>(m.impacts.size());
}

json summary_json(const RunResult& r) {
    const Measurements& m = r.measured;
    json results;
    results["model"] = to_string(r.scene.run.model);
    results["behaviour"] = to_string(m.behaviour);
    if (m.behaviour == Behaviour::diverged) results["divergence"] = m.divergence;
    if (!m.ended_early.empty()) results["ended_early"] = m.ended_early;
    results["distance_m"] = m.distance_m;
    results["terminal_velocity_m_s"] = m.terminal_velocity_m_s ? json(*m.terminal_velocity_m_s) : json(nullptr);
    results["terminal_velocity_faces"] = m.terminal_velocity_faces;
    results["stop_time_s"] = m.stop_time_s ? json(*m.stop_time_s) : json(nullptr);
    results["impacts"] = m.impacts.size();
    results["mean_impact_energy_ratio"] = m.impacts.empty() ? json(nullptr) : json(mean_impact_ratio(m));
    results["sim_time_s"] = m.end_time_s;
    results["wall_time_s"] = r.wall_time_s;
    results["grains"] = r.grains;
    results["grains_inside_at_end"] = m.grains_inside;
    results["fill_mass_kg"] = r.fill_mass_kg;
    results["settle_time_s"] = r.settle_time_s;
    results["settled"] = r.settled;
    results["release_balance_correction_deg"] = r.balance_correction_deg;
    results["max_energy_gain_J"] = m.max_energy_gain_J;
    results["steps"] = r.steps;
    results["model_valid"] = r.model_valid;
    results["model_invalid_time_s"] = r.model_invalid_time_s ? json(*r.model_invalid_time_s) : json(nullptr);
    if (r.model_choice) {
        const ModelChoice& c = *r.model_choice;
        json choice;
        choice["model"] = to_string(c.model);
        choice["then"] = c.then ? json(to_string(*c.then)) : json(nullptr);
        choice["reason"] = c.reason;
        choice["lift_off_time_s"] = c.lift_off_time_s ? json(*c.lift_off_time_s) : json(nullptr);
        choice["hand_over_time_s"] = c.hand_over_time_s ? json(*c.hand_over_time_s) : json(nullptr);
        choice["hand_over_why"] = c.hand_over_why;
        results["model_choice"] = choice;
    }

    json shell;
    shell["label"] = shell_label(r.scene);  // what it is: a preset with other sides is no longer that preset
    shell["mass_kg"] = r.shell.mass_kg;
    shell["inertia_kg_m2"] = r.shell.inertia_kg_m2;
    shell["pivot_radius_m"] = r.shell.pivot_radius_m;
    shell["outer_circumradius_m"] = r.shell.outer_circumradius_m;
    shell["outer_side_m"] = r.shell.outer_side_m;
    shell["inside_volume_m3"] = r.shell.inside_volume_m3;
    shell["lid_mass_fraction"] = r.shell.lid_mass_fraction;
    shell["lid_inertia_share"] = r.shell.lid_inertia_share;

    json engine;
    engine["length_unit_m"] = 1.0 / r.units.units_per_m;
    engine["engine_step_s"] = 1.0 / (r.scene.fidelity.step_hz * r.scene.fidelity.substeps);
    engine["speed_cap_m_s"] = r.units.speed_cap_m_s(r.scene.fidelity);

    json out;
    out["polyroll"] = "0.1.0";
    out["scene"] = scene_to_json(r.scene);
    out["results"] = results;
    out["shell"] = shell;
    // Box2D's units and step mean nothing to the reduced models, which integrate their own equations.
    if (model_traits(model_that_ran(r)).engine) out["engine"] = engine;
    if (r.dem3d) {
        json yade;
        yade["yade_version"] = r.dem3d->yade_version;
        yade["time_step_s"] = r.dem3d->time_step_s;
        yade["cpu_time_s"] = r.dem3d->cpu_time_s;
        yade["threads"] = r.dem3d->threads;
        if (const auto& c = r.dem3d->channel) {
            yade["channel"] = {{"max_offset_m", c->max_offset_m},       {"max_yaw_deg", c->max_yaw_deg},
                               {"max_tilt_deg", c->max_tilt_deg},       {"steps", c->steps},
                               {"steps_touching", c->steps_touching},   {"max_side_force_N", c->max_side_force_N},
                               {"side_impulse_N_s", c->side_impulse_N_s}};
        }
        out["dem3d_engine"] = yade;
    }
    return out;
}

namespace {
// fmt prints -0.0 as "-0"; a table reads better without it.
double tidy(double x) { return x == 0.0 ? 0.0 : x; }
}  // namespace

std::string trajectory_csv(const RunResult& r) {
    // The fill's offset is blank where the model does not move grains (or there are none).
    auto offset = [](const std::optional<double>& v) { return v ? fmt::format("{:.6f}", tidy(*v)) : std::string(); };
    std::string s = "time_s,position_m,speed_m_s,angle_deg,kinetic_J,potential_J,dissipated_J,fill_ahead_m,fill_up_m\n";
    for (const TrajectorySample& t : r.measured.trajectory)
        s += fmt::format("{:.6f},{:.6f},{:.6f},{:.4f},{:.9g},{:.9g},{:.9g},{},{}\n", t.time_s, tidy(t.position_m),
                         tidy(t.speed_m_s), tidy(t.angle_deg), tidy(t.kinetic_J), tidy(t.potential_J),
                         tidy(t.dissipated_J), offset(t.fill_ahead_m), offset(t.fill_up_m));
    return s;
}

std::string impacts_csv(const RunResult& r) {
    // The last two columns: the energy read kKineticDelay_s after the landing (empty where the model
    // has no such instant), and its ratio to the energy before.
    std::string s = "impact,time_s,position_m,kinetic_before_J,kinetic_after_J,ratio,kinetic_3ms_after_J,ratio_3ms\n";
    for (const FaceImpact& f : r.measured.impacts) {
        s += fmt::format("{},{:.6f},{:.6f},{:.9g},{:.9g},{:.6f}", f.index, f.time_s, f.position_m,
                         f.kinetic_before_J, f.kinetic_after_J, f.ratio());
        if (f.kinetic_delayed_J && f.kinetic_before_J > 0.0)
            s += fmt::format(",{:.9g},{:.6f}\n", *f.kinetic_delayed_J, *f.kinetic_delayed_J / f.kinetic_before_J);
        else
            s += ",,\n";
    }
    return s;
}

void write_run_files(const std::filesystem::path& dir, const RunResult& r) {
    write_file_atomic(dir / "trajectory.csv", trajectory_csv(r));
    write_file_atomic(dir / "impacts.csv", impacts_csv(r));
    // The summary last: its presence means the run's files are complete.
    write_file_atomic(dir / "summary.json", summary_json(r).dump(2) + "\n");
}

}  // namespace polyroll

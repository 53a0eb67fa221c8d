// A run's output files: see results_io.h.
#include "sim/files/results_io.h"

#include "sim/files/result_columns.h"

#include <fmt/core.h>

#include "sim/files/atomic_file.h"
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

    json out;
    out["polyroll"] = "0.1.0";
    // The headline first, where a reader looks (summary["behaviour"] in Python, .behaviour with jq):
    // the same value as results.behaviour.
    out["behaviour"] = to_string(r.measured.behaviour);
    out["scene"] = scene_to_json(r.scene);
    out["results"] = results;
    out["shell"] = shell;
    for (const auto& [key, block] : r.model_blocks.json().items()) out[key] = block;
    return out;
}

namespace {
// fmt prints -0.0 as "-0"; a table reads better without it.
double tidy(double x) { return x == 0.0 ? 0.0 : x; }

std::string cell(ColumnFormat format, const std::optional<double>& v) {
    if (!v) return {};
    switch (format) {
        case ColumnFormat::fixed6: return fmt::format("{:.6f}", tidy(*v));
        case ColumnFormat::fixed4: return fmt::format("{:.4f}", tidy(*v));
        case ColumnFormat::general9: return fmt::format("{:.9g}", tidy(*v));
        case ColumnFormat::integer: return fmt::format("{}", static_cast<long long>(*v));
    }
    return {};
}

// A CSV table of `rows` with the declared columns (result_columns.h).
template <class Row>
std::string table_csv(std::span<const ResultColumn<Row>> columns, const std::vector<Row>& rows) {
    std::string s;
    for (std::size_t c = 0; c < columns.size(); ++c) s += (c ? "," : "") + std::string(columns[c].name);
    s += "\n";
    for (const Row& row : rows) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (c) s += ",";
            s += cell(columns[c].format, columns[c].value(row));
        }
        s += "\n";
    }
    return s;
}
}  // namespace

std::string trajectory_csv(const RunResult& r) { return table_csv(trajectory_columns(), r.measured.trajectory); }

std::string impacts_csv(const RunResult& r) { return table_csv(impact_columns(), r.measured.impacts); }

void write_run_files(const std::filesystem::path& dir, const RunResult& r) {
    write_file_atomic(dir / "trajectory.csv", trajectory_csv(r));
    write_file_atomic(dir / "impacts.csv", impacts_csv(r));
    // The summary last: its presence means the run's files are complete.
    write_file_atomic(dir / "summary.json", summary_json(r).dump(2) + "\n");
}

}  // namespace polyroll

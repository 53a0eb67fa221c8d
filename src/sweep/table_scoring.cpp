// Scoring from results tables: see table_scoring.h.
#include "sweep/table_scoring.h"

#include <string>

#include "sim/scene/scene_json.h"
#include "sweep/results_table.h"
#include "sweep/sweep_runner.h"

namespace polyroll::sweep {

std::map<std::size_t, ScoredRun> finished_outcomes(const SweepPlan& plan, const std::filesystem::path& dir) {
    std::map<std::size_t, ScoredRun> out;
    for (const std::filesystem::path& path : table_paths(dir)) {
        const TableFile t = read_table(path);
        auto col = [&](const std::string& name) { return column_index(t, name); };
        if (t.header.empty()) continue;
        const std::size_t c_index = col("index"), c_id = col("run_id"), c_status = col("status"),
                          c_behaviour = col("behaviour"), c_distance = col("distance_m"),
                          c_terminal = col("terminal_velocity_m_s");
        const std::optional<std::size_t> c_wall = find_column(t.header, "wall_time_s");
        for (const auto& r : t.rows) {
            const std::size_t i = std::stoull(r.at(c_index));
            if (i >= plan.runs.size() || plan.runs[i].id != r.at(c_id)) continue;
            ScoredRun s;
            s.ok = r.at(c_status) == "ok";
            // A run found in two tables keeps its "ok" row, as merging does.
            if (const auto it = out.find(i); it != out.end() && (it->second.ok || !s.ok)) continue;
            s.behaviour = r.at(c_behaviour);
            if (!r.at(c_distance).empty()) s.distance_m = std::stod(r.at(c_distance));
            if (!r.at(c_terminal).empty()) s.terminal_velocity_m_s = std::stod(r.at(c_terminal));
            if (c_wall && !r.at(*c_wall).empty()) s.wall_time_s = std::stod(r.at(*c_wall));
            out[i] = s;
        }
    }
    return out;
}

std::vector<ObservationScore> score_validation(const ObservationFile& file, const ValidationPlan& vp,
                                               const std::map<std::size_t, ScoredRun>& outcomes,
                                               const std::vector<std::size_t>& table_index) {
    // Where each planned run sits: its resolved ramp angle (an observation may vary it in its grid)
    // and ramp length (the figures draw a run that rolled to the end there). Every point was
    // resolved when planned, so this cannot fail.
    std::vector<std::pair<double, double>> angle_and_length(vp.plan.runs.size());
    for (std::size_t r = 0; r < vp.plan.runs.size(); ++r) {
        const Scene scene = resolve_scene(run_layers(vp.plan, vp.plan.runs[r]));
        angle_and_length[r] = {scene.ramp.angle_deg, scene.ramp.length_m};
    }
    std::vector<std::vector<ScoredRun>> per(file.observations.size());
    for (const RunPlace& p : vp.places) {
        ScoredRun s;
        const std::size_t i = table_index.empty() ? p.run : table_index.at(p.run);
        if (const auto it = outcomes.find(i); it != outcomes.end()) s = it->second;
        s.angle_deg = angle_and_length[p.run].first;  // the place's own angle for an angle-range observation
        s.ramp_length_m = angle_and_length[p.run].second;
        s.run_id = vp.plan.runs[p.run].id;
        s.seed = p.seed;
        s.label = p.label;
        s.label_without_angle = p.label_without_angle;
        per[p.observation].push_back(s);
    }
    std::vector<ObservationScore> scores;
    for (std::size_t i = 0; i < file.observations.size(); ++i)
        scores.push_back(score_observation(file.observations[i], per[i]));
    return scores;
}

}  // namespace polyroll::sweep
